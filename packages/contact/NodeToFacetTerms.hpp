#pragma once
// The terms of the node-to-facet contact element (NodeToFacetContact) by name, so that each is checked on
// its own against central differences (tests/unit/contact/NodeToFacetTermsTest.cpp): the kinematics at the
// projection ξ̄ (eq. 1–5) with the operators N, Ξ^α of eq. (26), the gap at a vertex or edge point, and the
// three tangent terms of the consistent linearisation — (a) t_N ∂²g_N/∂u² (addGapCurvature), (b) Ξ^α
// (dt_Tα/du)ᵀ (addTractionVariation, with the metric's variation metricVariation) and (c) t_Tα ∂²ξ̄^α/∂u²
// (addProjectionCurvature). Header-only templates over the facet families (MasterFacet.hpp).
#include <algorithm>
#include <array>

#include "contact/NodeToFacetContact.hpp"  // ContactPoint, the facet families, Projection

namespace contessa::contact::terms {
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

}  // namespace contessa::contact::terms
