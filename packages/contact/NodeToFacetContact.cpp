#include "contact/NodeToFacetContact.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace contessa::contact {

namespace {

/// Operators on the element dofs [x^k, x_1, …, x_n] that act the same on every space component: a weight
/// per node block (slave first) times a space vector, w ⊗ v.
template <class Facet>
struct Operators {
  static constexpr int kBlocks = 1 + Facet::kNodes;
  static constexpr int kDim = Facet::kSpaceDim;
  static constexpr int kDofs = kDim * kBlocks;
  using Weights = Vector<kBlocks>;
  using Column = Vector<kDofs>;
  using Square = Matrix<kDofs, kDofs>;

  /// [w_0 v; w_1 v; …]
  static Column kron(const Weights& w, const typename Facet::Point& v) {
    Column out{};
    for (int a = 0; a < kBlocks; ++a)
      for (int c = 0; c < kDim; ++c) out[a * kDim + c] = w[a] * v[c];
    return out;
  }

  /// K += s (w ⊗ I)(z ⊗ I)ᵀ: the bilinear form s Σ_c (Σ_a w_a δx_a,c)(Σ_b z_b Δx_b,c).
  static void addBlockOuter(Square& k, double s, const Weights& w, const Weights& z) {
    for (int a = 0; a < kBlocks; ++a)
      for (int b = 0; b < kBlocks; ++b)
        for (int c = 0; c < kDim; ++c) k(a * kDim + c, b * kDim + c) += s * w[a] * z[b];
  }

  /// K += s (x yᵀ + y xᵀ)
  static void addSymmetricOuter(Square& k, double s, const Column& x, const Column& y) {
    addOuter(k, s, x, y);
    addOuter(k, s, y, x);
  }
};


/// The facet at the node's projection ξ̄ (eq. 1–5) and the kinematic operators of eq. (26) with the exact
/// first variations (NodeToFacetContact.hpp): what every term of the residual and tangent is built from.
template <class Facet>
struct FacetKinematics {
  static constexpr int M = Facet::kSurfaceDim;
  using Op = Operators<Facet>;
  using Column = typename Op::Column;
  using Weights = typename Op::Weights;
  using Point = typename Facet::Point;

  double gN = 0.0;                                 // the projection's g_N (the kinematics of ξ̄)
  Point n{};                                       // n̄
  std::array<Point, M> a{};                        // ā_α
  Matrix<M, M> aInv{};                             // ā^αβ
  Weights relative{};                              // [1, −H_i]: x^k − x̄ (eq. 26)
  std::array<Weights, M> base{};                   // [0, H_i,α]: δā_α at fixed ξ
  std::array<std::array<Weights, M>, M> curve{};   // [0, H_i,αβ]: δx̄,αβ
  std::array<std::array<Point, M>, M> xbar2{};     // x̄,αβ = Σ H_i,αβ x_i
  std::array<std::array<std::array<Point, M>, M>, M> xbar3{};  // x̄,αβγ = Σ H_i,αβγ x_i (Facet::kCubic only)
  Matrix<M, M> b{};                                // b̄_αβ = x̄,αβ·n̄
  Matrix<M, M> AInv{};                             // (A⁻¹)^αβ, A_αβ = ā_αβ − g_N b̄_αβ
  std::array<std::array<std::array<double, M>, M>, M> gamma{};  // Γ_αβγ = x̄,αβ·ā_γ
  Column N{};                                      // ∂g_N/∂u at the projection
  std::array<Column, M> Nbar{}, D{}, Xi{};         // N̄_α, D^α = ā^αβ T_β, Ξ^α = ∂ξ̄^α/∂u

  /// False where the node sits at a focal point of the facet (A singular: no unique ξ̄).
  bool build(const ProjectionResult<Facet>& p, const std::array<Point, Facet::kNodes>& master) {
    gN = p.gap;
    n = p.normal;
    a = p.covariantBasis;
    aInv = p.inverseMetric;
    const auto dH = Facet::shapeDerivatives(p.xi);
    const auto d2H = Facet::shapeSecondDerivatives(p.xi);
    relative[0] = 1.0;
    for (int i = 0; i < Facet::kNodes; ++i) {
      relative[1 + i] = -p.shape[i];
      for (int al = 0; al < M; ++al) {
        base[al][1 + i] = dH(i, al);
        for (int be = 0; be < M; ++be) {
          curve[al][be][1 + i] = d2H[i](al, be);
          addScaled(xbar2[al][be], d2H[i](al, be), master[i]);
        }
      }
    }
    if constexpr (Facet::kCubic) {
      const auto d3H = Facet::shapeThirdDerivatives(p.xi);
      for (int i = 0; i < Facet::kNodes; ++i)
        for (int al = 0; al < M; ++al)
          for (int be = 0; be < M; ++be)
            for (int ga = 0; ga < M; ++ga) addScaled(xbar3[al][be][ga], d3H[i][al](be, ga), master[i]);
    }
    Matrix<M, M> A;
    for (int al = 0; al < M; ++al)
      for (int be = 0; be < M; ++be) {
        b(al, be) = dot(xbar2[al][be], n);
        A(al, be) = p.metric(al, be) - gN * b(al, be);
        for (int ga = 0; ga < M; ++ga) gamma[al][be][ga] = dot(xbar2[al][be], a[ga]);
      }
    if (!(determinant(A) > 0.0)) return false;
    AInv = inverse(A);
    N = Op::kron(relative, n);
    std::array<Column, M> T{};
    for (int al = 0; al < M; ++al) {
      T[al] = Op::kron(relative, a[al]);
      Nbar[al] = Op::kron(base[al], n);
    }
    for (int al = 0; al < M; ++al)
      for (int be = 0; be < M; ++be) {
        addScaled(D[al], aInv(al, be), T[be]);                      // D^α = ā^αβ T_β
        addScaled(Xi[al], AInv(al, be), T[be]);                     // Ξ^α = (A⁻¹)^αβ (T_β + g_N N̄_β)
        addScaled(Xi[al], AInv(al, be) * gN, Nbar[be]);
      }
    return true;
  }

  /// Tangent term (a) at the projection: t_N ∂²g_N/∂u², from δg_N = n̄·(δx^k − H_i δx_i) with
  /// δn̄ = −(n̄·δā_α) ā^α and δH_i = H_i,β δξ^β; with M_α = N̄_α + b̄_αβ Ξ^β (total variation of n̄·ā_α):
  ///   ∂²g_N/∂u² = −(Ξ^α N̄_αᵀ + N̄_α Ξ^αᵀ) − b̄_αβ Ξ^α Ξ^βᵀ + g_N ā^αβ M_α M_βᵀ    (symmetric)
  void addGapCurvature(typename Op::Square& K, double tN) const {
    std::array<Column, M> Mv = Nbar;
    for (int al = 0; al < M; ++al)
      for (int be = 0; be < M; ++be) addScaled(Mv[al], b(al, be), Xi[be]);
    for (int al = 0; al < M; ++al) {
      Op::addSymmetricOuter(K, -tN, Xi[al], Nbar[al]);
      for (int be = 0; be < M; ++be) {
        addOuter(K, -tN * b(al, be), Xi[al], Xi[be]);
        addOuter(K, tN * gN * aInv(al, be), Mv[al], Mv[be]);
      }
    }
  }
};

/// The normal part at a vertex or edge point x_b of the facet (ContactPoint): g_N = ±‖x^k − x_b‖, its
/// operator N_b and curvature (NodeToFacetContact.hpp).
template <class Facet>
struct BoundaryPointKinematics {
  using Op = Operators<Facet>;
  using Column = typename Op::Column;
  using Weights = typename Op::Weights;
  using Point = typename Facet::Point;

  double gap = 0.0;
  Column N{};           // ∂g_N/∂u = [n̄_b; −h_i n̄_b]
  Weights relative{};   // r = [1, −h_i]
  Column edgeMotion{};  // F = ∂(d·e)/∂u on an edge (zero at a vertex)
  double edgeLength2 = 0.0;

  BoundaryPointKinematics(const ContactPoint& point, const Point& slave, const std::array<Point, Facet::kNodes>& x,
                          const Point& fallbackNormal) {
    const int i = point.nodes[0];
    relative[0] = 1.0;
    Point xb = x[i];
    Point e{};
    double t = 0.0;
    if (point.kind == ContactPoint::Kind::Edge) {
      const int j = point.nodes[1];
      e = subtract(x[j], x[i]);
      edgeLength2 = dot(e, e);
      t = std::clamp(dot(subtract(slave, x[i]), e) / edgeLength2, 0.0, 1.0);
      xb = add(x[i], scaled(t, e));
      relative[1 + j] = -t;
    }
    relative[1 + i] = -(1.0 - t);
    const Point d = subtract(slave, xb);
    const double distance = norm(d);
    gap = point.side * distance;
    const Point n = distance > 0.0 ? scaled(point.side / distance, d) : fallbackNormal;
    N = Op::kron(relative, n);
    if (point.kind == ContactPoint::Kind::Edge) {
      Weights along{};
      along[1 + i] = -1.0;
      along[1 + point.nodes[1]] = 1.0;
      edgeMotion = add(Op::kron(relative, e), Op::kron(along, d));
    }
  }

  /// t_N ∂²g_N/∂u² = (t_N/g_N) [(r ⊗ I)ᵀ(r ⊗ I) − N_b N_bᵀ − F Fᵀ/‖e‖²].
  void addGapCurvature(typename Op::Square& K, double tN) const {
    if (gap == 0.0) return;
    const double s = tN / gap;
    Op::addBlockOuter(K, s, relative, relative);
    addOuter(K, -s, N, N);
    if (edgeLength2 > 0.0) addOuter(K, -s / edgeLength2, edgeMotion, edgeMotion);
  }
};

/// The tangential traction t_Tα of the contact law and its partial derivatives (all zero without friction
/// and at a first contact whose approach is unknown). The slip increment Δξ varies as
/// ∂Δξ^β/∂u = slipScale Ξ^β + slipPerGap^β N: Ξ^β for a node in contact at the commit; (1 − τ) Ξ^β and
/// −(ξ̄^β − ξ_0^β) ∂τ/∂g_N for a node that touched during the increment (CommittedApproach).
template <int M>
struct TangentialLaw {
  Vector<M> traction{};
  Matrix<M, M> dT_dXi{};                 // ∂t_α/∂Δξ^β
  std::array<Matrix<M, M>, M> dT_dMetric{};  // ∂t_α/∂ā_βγ
  Vector<M> dT_dNormal{};                // ∂t_α/∂t_N
  double slipScale = 1.0;                // ∂Δξ/∂ξ̄
  Vector<M> slipPerGap{};                // ∂Δξ^β/∂g_N
};

/// The slip increment of the return mapping (eq. 20) and how it varies with ξ̄ and g_N: against the
/// committed ξ_n for a node in contact at the commit; for a node open at the commit, against the point
/// where it touched, ξ_0 + τ(ξ̄ − ξ_0), τ = g_N,0/(g_N,0 − g_N) (CommittedApproach).
template <int M>
Vector<M> slipIncrement(const Vector<M>& xi, double gap, const ContactHistory<M>& committed,
                        const CommittedApproach<M>& approach, TangentialLaw<M>& law) {
  if (committed.isInContact()) return subtract(xi, committed.xi);
  const Vector<M> path = subtract(xi, approach.xi);
  if (!(approach.gap > 0.0)) return path;  // touching at the commit: τ = 0
  const double closing = approach.gap - gap;  // > 0: g_N < 0 ≤ g_N,0
  const double tau = approach.gap / closing;
  law.slipScale = 1.0 - tau;
  law.slipPerGap = scaled(-approach.gap / (closing * closing), path);  // −(ξ̄ − ξ_0) ∂τ/∂g_N
  return scaled(1.0 - tau, path);
}

/// The Coulomb law at the projection ξ̄: the return mapping of eq. (20)–(23) against the committed history;
/// sets the status, tractions and trial history of `out`.
template <class Facet, class Result>
TangentialLaw<Facet::kSurfaceDim> applyTangentialLaw(const ContactLawParameters& parameters,
                                                     const CoulombReturnMapping<Facet::kSurfaceDim>& returnMapping,
                                                     const ProjectionResult<Facet>& p,
                                                     const ContactHistory<Facet::kSurfaceDim>& committed,
                                                     const CommittedApproach<Facet::kSurfaceDim>& approach, double tN,
                                                     double facetLength, SlipTangent slipTangent, Result& out) {
  constexpr int M = Facet::kSurfaceDim;
  TangentialLaw<M> law;
  if (parameters.isFrictionless()) {
    out.status = ContactStatus::Slip;  // free sliding, t_T ≡ 0
  } else if (!committed.isInContact() && !approach.known) {
    // First contact, approach unknown: ξ_n := ξ̄, t_T,n := 0, so Δξ ≡ 0 and t_T ≡ 0 in this increment.
    out.status = ContactStatus::Stick;
  } else {
    ReturnMappingInput<M> in;
    // The augmented Lagrangian's trial starts from the multiplier λ_Tα instead of t_Tα,n (eq. 15.2).
    in.committedTraction = parameters.isAugmented()     ? committed.tangentialMultiplier
                           : committed.isInContact() ? committed.tangentialTraction
                                                     : Vector<M>{};
    in.slipIncrement = slipIncrement(p.xi, out.gap, committed, approach, law);  // Δξ_{n+1}, eq. (20)
    in.metric = p.metric;
    in.normalTraction = tN;
    in.facetLength = facetLength;
    // The augmented Lagrangian's slip-tolerance ε_T follows λ_N, constant between updates (eq. 15.2).
    if (parameters.isAugmented()) in.frozenNormalTraction = committed.normalMultiplier;
    out.friction = returnMapping.map(in);  // eq. (20)–(23)
    out.status = out.friction.status;
    law.traction = out.friction.traction;
    law.dT_dXi = out.friction.dTraction_dSlipIncrement;
    if (out.status == ContactStatus::Slip && slipTangent.secant) {
      // A node in a slip cycle: the secant stiffness along its slip direction (see SlipTangent).
      Vector<M> s = out.friction.trialDirection;
      s = scaled(1.0 / norm(s), s);
      const double stick = out.friction.tangentialPenalty * dot(s, multiply(p.metric, s));
      const double along = dot(s, multiply(law.dT_dXi, s));
      addOuter(law.dT_dXi, std::min(slipTangent.stiffness, stick) - along, s, s);
    }
    law.dT_dMetric = out.friction.dTraction_dMetric;
    law.dT_dNormal = out.friction.dTraction_dNormalTraction;
    // eq. (7), backward Euler: g_T,n+1 = g_T,n + √(Δξ^α ā_αβ Δξ^β); committed only at commit().
    out.trial.accumulatedSlip =
        committed.accumulatedSlip + std::sqrt(dot(in.slipIncrement, multiply(p.metric, in.slipIncrement)));
  }
  out.tangentialTraction = law.traction;
  out.trial.tangentialTraction = law.traction;
  if (parameters.isAugmented()) out.trial.tangentialMultiplier = law.traction;  // the next λ_T (eq. 15.3)
  out.trial.status = out.status;
  return law;
}

/// dā_βγ = [0, H_i,β] ⊗ ā_γ + [0, H_i,γ] ⊗ ā_β + (Γ_βεγ + Γ_γεβ) Ξ^ε (Γ_αβγ = x̄,αβ·ā_γ), the metric's variation.
template <class Facet>
std::array<std::array<typename Operators<Facet>::Column, Facet::kSurfaceDim>, Facet::kSurfaceDim> metricVariation(
    const FacetKinematics<Facet>& k) {
  constexpr int M = Facet::kSurfaceDim;
  using Op = Operators<Facet>;
  std::array<std::array<typename Op::Column, M>, M> dMetric{};
  for (int be = 0; be < M; ++be)
    for (int ga = 0; ga < M; ++ga) {
      dMetric[be][ga] = add(Op::kron(k.base[be], k.a[ga]), Op::kron(k.base[ga], k.a[be]));
      for (int ep = 0; ep < M; ++ep) addScaled(dMetric[be][ga], k.gamma[be][ep][ga] + k.gamma[ga][ep][be], k.Xi[ep]);
    }
  return dMetric;
}

/// Tangent term (b): Ξ^α (dt_Tα/du)ᵀ with the exact variation of the traction:
///   dt_α = ∂t_α/∂Δξ^β ∂Δξ^β/∂u + ∂t_α/∂ā_βγ dā_βγ + ∂t_α/∂t_N ε_N N,   (∂Δξ/∂u: TangentialLaw)
///   dā_βγ = [0, H_i,β] ⊗ ā_γ + [0, H_i,γ] ⊗ ā_β + (Γ_βεγ + Γ_γεβ) Ξ^ε     (Γ_αβγ = x̄,αβ·ā_γ)
/// (the stretch term makes even the stick tangent slightly non-symmetric when Δξ ≠ 0: the covariant
///  t_T,n is held fixed while the facet stretches). N is the contact law's ∂g_N/∂u.
template <class Facet>
void addTractionVariation(typename Operators<Facet>::Square& K, const FacetKinematics<Facet>& k,
                          const TangentialLaw<Facet::kSurfaceDim>& law, const typename Operators<Facet>::Column& N,
                          double epsN) {
  constexpr int M = Facet::kSurfaceDim;
  using Op = Operators<Facet>;
  using Column = typename Op::Column;
  const std::array<std::array<Column, M>, M> dMetric = metricVariation<Facet>(k);
  for (int al = 0; al < M; ++al) {
    Column dt = scaled(law.dT_dNormal[al] * epsN, N);
    for (int be = 0; be < M; ++be) {
      addScaled(dt, law.dT_dXi(al, be) * law.slipScale, k.Xi[be]);  // ∂Δξ/∂u (TangentialLaw)
      addScaled(dt, law.dT_dXi(al, be) * law.slipPerGap[be], N);
      for (int ga = 0; ga < M; ++ga) addScaled(dt, law.dT_dMetric[al](be, ga), dMetric[be][ga]);
    }
    addOuter(K, 1.0, k.Xi[al], dt);
  }
}

/// Tangent term (c): t_Tβ ∂²ξ̄^β/∂u². ξ̄(u) solves F_α(u, ξ) = (x^k − x̄)·ā_α = 0 with ∂F_α/∂ξ^β = −A_αβ, so
///   ∂²ξ̄^β/∂u² = (A⁻¹)^βα [F_α,uu + F_α,uξ^γ Ξ^γᵀ + Ξ^γ F_α,uξ^γᵀ + F_α,ξ^γξ^δ Ξ^γ Ξ^δᵀ]
/// with
///   F_α,uu      = ([1, −H_i] ⊗ I)ᵀ([0, H_i,α] ⊗ I) + transpose
///   F_α,uξ^γ    = −[0, H_i,γ] ⊗ ā_α − [0, H_i,α] ⊗ ā_γ + [1, −H_i] ⊗ x̄,αγ + g_N [0, H_i,αγ] ⊗ n̄
///   F_α,ξ^γξ^δ  = −(Γ_γδα + Γ_αδγ + Γ_αγδ) + g_N n̄·x̄,αγδ   (the last only on a Facet::kCubic facet)
/// contracted with t_Tβ: weights w_α = t_Tβ (A⁻¹)^βα.
template <class Facet>
void addProjectionCurvature(typename Operators<Facet>::Square& K, const FacetKinematics<Facet>& k,
                            const Vector<Facet::kSurfaceDim>& tT) {
  constexpr int M = Facet::kSurfaceDim;
  using Op = Operators<Facet>;
  using Column = typename Op::Column;
  if (tT == Vector<M>{}) return;
  const Vector<M> w = multiply(transpose(k.AInv), tT);
  for (int al = 0; al < M; ++al) {
    if (w[al] == 0.0) continue;
    Op::addBlockOuter(K, w[al], k.relative, k.base[al]);
    Op::addBlockOuter(K, w[al], k.base[al], k.relative);
    for (int ga = 0; ga < M; ++ga) {
      Column fuxi = Op::kron(k.relative, k.xbar2[al][ga]);
      addScaled(fuxi, -1.0, Op::kron(k.base[ga], k.a[al]));
      addScaled(fuxi, -1.0, Op::kron(k.base[al], k.a[ga]));
      addScaled(fuxi, k.gN, Op::kron(k.curve[al][ga], k.n));
      Op::addSymmetricOuter(K, w[al], fuxi, k.Xi[ga]);
      for (int de = 0; de < M; ++de) {
        double fxixi = -(k.gamma[ga][de][al] + k.gamma[al][de][ga] + k.gamma[al][ga][de]);
        if constexpr (Facet::kCubic) fxixi += k.gN * dot(k.n, k.xbar3[al][ga][de]);
        addOuter(K, w[al] * fxixi, k.Xi[ga], k.Xi[de]);
      }
    }
  }
}

/// The weight of the fade past a free edge, w = 1 − 3s² + 2s³ with s = d/reach (ContactPoint), and its
/// derivative ∂w/∂u (NodeToFacetContact.hpp; docs/theory-contact.md §3.2); nullopt on the facet (ξ̄ inside
/// its parent domain) or without a reach.
template <class Facet>
struct FreeEdgeFade {
  double weight = 1.0;
  typename Operators<Facet>::Column derivative{};  // ∂w/∂u
};

template <class Facet>
std::optional<FreeEdgeFade<Facet>> freeEdgeFade(const NodeToFacetGeometry<Facet>& x,
                                                const ProjectionResult<Facet>& p, double reach) {
  using Op = Operators<Facet>;
  constexpr int M = Facet::kSurfaceDim;
  if (!(reach > 0.0)) return std::nullopt;
  const auto toDomain = Facet::clampToDomain(p.xi);  // the closest point of the parent domain, ∂ξ_c/∂ξ̄
  const typename Facet::SurfaceCoords& clamped = toDomain.xi;
  if (clamped == p.xi) return std::nullopt;
  const auto c = Projection<Facet>::evaluateAt(x.slave, x.master, clamped);
  const typename Facet::Point v = subtract(p.position, c.position);
  const double d = norm(v);
  if (!(d > 0.0)) return std::nullopt;
  FreeEdgeFade<Facet> fade;
  const double s = d / reach;
  if (s >= 1.0) {
    fade.weight = 0.0;
    return fade;
  }
  fade.weight = 1.0 - s * s * (3.0 - 2.0 * s);
  const double dwdd = 6.0 * s * (s - 1.0) / reach;
  FacetKinematics<Facet> k;
  if (!k.build(p, x.master)) return fade;  // not reached: the element built it already
  const typename Facet::Point unit = scaled(1.0 / d, v);
  typename Op::Weights shapeDifference{};
  for (int i = 0; i < Facet::kNodes; ++i) shapeDifference[1 + i] = p.shape[i] - c.shape[i];
  typename Op::Column dd = Op::kron(shapeDifference, unit);
  for (int al = 0; al < M; ++al) {
    double along = dot(unit, p.covariantBasis[al]);
    for (int be = 0; be < M; ++be)
      if (toDomain.derivative(be, al) != 0.0) along -= toDomain.derivative(be, al) * dot(unit, c.covariantBasis[be]);
    addScaled(dd, along, k.Xi[al]);
  }
  fade.derivative = scaled(dwdd, dd);
  return fade;
}

}  // namespace

template <class Facet>
NodeToFacetContact<Facet>::NodeToFacetContact(const ContactLawParameters& parameters, TangentTerms terms)
    : parameters_(parameters),
      terms_(terms),
      normalLaw_(parameters.normalPenalty),
      returnMapping_(parameters.tangentialPenalty, parameters.frictionCoefficient, parameters.slipTolerance) {
  parameters_.validate();
}

template <class Facet>
typename NodeToFacetContact<Facet>::Result NodeToFacetContact<Facet>::evaluate(
    const Geometry& x, int facet, const ContactHistory<kSurfaceDim>& committed, double facetLength,
    SlipTangent slipTangent, const ContactPoint& point, const CommittedApproach<kSurfaceDim>& approach) const {
  Result out = evaluateUnfaded(x, facet, committed, facetLength, slipTangent, point, approach);
  if (out.status == ContactStatus::Open || point.kind != ContactPoint::Kind::Projection) return out;
  const auto fade = freeEdgeFade<Facet>(x, out.projection, point.freeEdgeReach);
  if (!fade) return out;
  const double w = fade->weight;
  out.freeEdgeWeight = w;
  if (w == 0.0) {  // past the reach: open
    Result open;
    open.projection = out.projection;
    open.gap = out.gap;
    open.freeEdgeWeight = 0.0;
    open.trial = out.trial;
    open.trial.tangentialTraction = {};
    open.trial.status = ContactStatus::Open;
    open.trial.normalMultiplier = 0.0;
    open.trial.tangentialMultiplier = {};
    open.trial.accumulatedSlip = committed.accumulatedSlip;
    return open;
  }
  // K = w K_c + r_c (∂w/∂u)ᵀ, r = w r_c
  for (int i = 0; i < kDofs; ++i)
    for (int j = 0; j < kDofs; ++j) out.tangent(i, j) = w * out.tangent(i, j) + out.residual[i] * fade->derivative[j];
  out.residual = scaled(w, out.residual);
  out.normalTraction *= w;
  out.tangentialTraction = scaled(w, out.tangentialTraction);
  return out;
}

template <class Facet>
typename NodeToFacetContact<Facet>::Result NodeToFacetContact<Facet>::evaluateUnfaded(
    const Geometry& x, int facet, const ContactHistory<kSurfaceDim>& committed, double facetLength,
    SlipTangent slipTangent, const ContactPoint& point, const CommittedApproach<kSurfaceDim>& approach) const {
  constexpr int M = kSurfaceDim;
  using Op = Operators<Facet>;
  using Column = typename Op::Column;

  if (committed.isInContact() && committed.segment != facet)
    throw std::logic_error("NodeToFacetContact: committed history is on facet " + std::to_string(committed.segment) +
                           ", not on facet " + std::to_string(facet) + "; map it with transferHistory first");

  Result out;
  // eq. (1)–(5): closest point, ā_α, ā_αβ, n̄, g_N (robust start and fallback on a curved facet).
  out.projection = Projection<Facet>().project(x.slave, x.master);
  const auto& p = out.projection;
  out.trial = committed;
  out.trial.segment = facet;
  out.trial.xi = p.xi;
  out.trial.tangentialTraction = {};
  out.trial.status = ContactStatus::Open;
  out.trial.normalMultiplier = 0.0;  // an open node's next multipliers (augmented Lagrangian)
  out.trial.tangentialMultiplier = {};
  out.gap = p.gap;
  if (!p.converged) return out;
  // The normal part: at the projection, or at a vertex or edge point of the facet (ContactPoint).
  std::optional<BoundaryPointKinematics<Facet>> boundary;
  if (point.kind != ContactPoint::Kind::Projection) {
    boundary.emplace(point, x.slave, x.master, p.normal);
    out.gap = boundary->gap;
  }
  const double lambdaN = parameters_.isAugmented() ? committed.normalMultiplier : 0.0;  // eq. (15.1)
  if (!normalLaw_.isActive(out.gap, lambdaN)) return out;  // eq. (6): open, no force, no stiffness

  FacetKinematics<Facet> facetKinematics;
  if (!facetKinematics.build(p, x.master)) return out;  // the node sits at a focal point of the facet
  const auto& k = facetKinematics;
  const Column& N = boundary ? boundary->N : k.N;  // ∂g_N/∂u of the contact law's gap

  // ---- Contact law: eq. (16), then the return mapping of eq. (20)–(23) ------------------------------
  const double tN = normalLaw_.traction(out.gap, lambdaN);  // eq. (16) or (15.1), < 0
  const double epsN = normalLaw_.tractionDerivative(out.gap, lambdaN);
  out.normalTraction = tN;
  if (parameters_.isAugmented()) out.trial.normalMultiplier = tN;  // the next λ_N (eq. 15.3)
  const auto tangential =
      applyTangentialLaw<Facet>(parameters_, returnMapping_, p, committed, approach, tN, facetLength, slipTangent, out);

  // ---- Residual: r_c = t_N N + t_Tα Ξ^α --------------------------------------------------------------
  const Vector<M>& tT = tangential.traction;
  out.residual = scaled(tN, N);
  for (int al = 0; al < M; ++al) addScaled(out.residual, tT[al], k.Xi[al]);

  auto& K = out.tangent;
  addOuter(K, epsN, N, N);  // eq. (24): K_N = ε_N N Nᵀ

  if (terms_ == TangentTerms::PaperMainTerms) {
    // ∂ξ̄/∂u ≈ D^α, fixed metric: stick ∂t_α/∂Δξ^β = ε_T ā_αβ gives eq. (25) ε_T ā_αβ D^α D^βᵀ; slip gives
    // eq. (26): ∂t_α/∂t_N ε_N = −μ ε_N n^trial_α (t_N < 0; the paper counts the penetration positive) and
    // the eq. (27) term. With a slip tolerance the ∂t/∂t_N term also acts in stick (ε_T depends on t_N).
    for (int al = 0; al < M; ++al) {
      Column dt = scaled(tangential.dT_dNormal[al] * epsN, N);
      for (int be = 0; be < M; ++be) {
        addScaled(dt, tangential.dT_dXi(al, be) * tangential.slipScale, k.D[be]);
        addScaled(dt, tangential.dT_dXi(al, be) * tangential.slipPerGap[be], N);
      }
      addOuter(K, 1.0, k.D[al], dt);
    }
    return out;
  }

  // ---- Consistent tangent: K_c = ε_N N Nᵀ + t_N ∂²g_N/∂u² + Ξ^α (dt_Tα/du)ᵀ + t_Tα ∂²ξ̄^α/∂u² -------
  if (boundary)
    boundary->addGapCurvature(K, tN);  // (a) at the vertex or edge point
  else
    k.addGapCurvature(K, tN);          // (a) at the projection
  addTractionVariation<Facet>(K, k, tangential, N, epsN);  // (b)
  addProjectionCurvature<Facet>(K, k, tT);                 // (c)
  return out;
}

template <class Facet>
FacetGapVariation<Facet> facetGapVariation(const NodeToFacetGeometry<Facet>& x) {
  constexpr int M = Facet::kSurfaceDim;
  FacetGapVariation<Facet> out;
  out.projection = Projection<Facet>().project(x.slave, x.master);
  if (!out.projection.converged) return out;
  FacetKinematics<Facet> k;
  if (!k.build(out.projection, x.master)) return out;
  out.valid = true;
  out.gapFirst = k.N;
  k.addGapCurvature(out.gapSecond, 1.0);  // term (a) per unit t_N
  for (int al = 0; al < M; ++al) {
    out.xiFirst[al] = k.Xi[al];
    Vector<M> unit{};
    unit[al] = 1.0;
    addProjectionCurvature<Facet>(out.xiSecond[al], k, unit);  // term (c) with t_T = e_α
  }
  out.metricFirst = metricVariation<Facet>(k);
  return out;
}

#define CONTESSA_INSTANTIATE_NODE_TO_FACET_CONTACT(F) template class NodeToFacetContact<F>;
CONTESSA_FOR_EACH_FACET(CONTESSA_INSTANTIATE_NODE_TO_FACET_CONTACT)
#undef CONTESSA_INSTANTIATE_NODE_TO_FACET_CONTACT

template FacetGapVariation<Line2Facet> facetGapVariation<Line2Facet>(const NodeToFacetGeometry<Line2Facet>&);
template FacetGapVariation<Quad4Facet> facetGapVariation<Quad4Facet>(const NodeToFacetGeometry<Quad4Facet>&);
template FacetGapVariation<Line3Facet> facetGapVariation<Line3Facet>(const NodeToFacetGeometry<Line3Facet>&);
template FacetGapVariation<Tri3Facet> facetGapVariation<Tri3Facet>(const NodeToFacetGeometry<Tri3Facet>&);
template FacetGapVariation<Tri6Facet> facetGapVariation<Tri6Facet>(const NodeToFacetGeometry<Tri6Facet>&);
template FacetGapVariation<Quad8Facet> facetGapVariation<Quad8Facet>(const NodeToFacetGeometry<Quad8Facet>&);
template FacetGapVariation<Quad9Facet> facetGapVariation<Quad9Facet>(const NodeToFacetGeometry<Quad9Facet>&);

}  // namespace contessa::contact
