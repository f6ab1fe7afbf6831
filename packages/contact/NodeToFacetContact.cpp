#include "contact/NodeToFacetContact.hpp"

#include <algorithm>
#include <cmath>
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
    SlipTangent slipTangent) const {
  constexpr int M = kSurfaceDim;
  using Op = Operators<Facet>;
  using Column = typename Op::Column;
  using Weights = typename Op::Weights;
  using Point = typename Facet::Point;

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
  if (!p.converged || !normalLaw_.isActive(p.gap)) return out;  // eq. (6): open, no force, no stiffness

  // ---- Surface geometry at ξ̄ --------------------------------------------------------------------------
  const double gN = p.gap;
  const Point& n = p.normal;
  const auto& a = p.covariantBasis;        // ā_α
  const auto& aInv = p.inverseMetric;      // ā^αβ
  const auto dH = Facet::shapeDerivatives(p.xi);
  const auto d2H = Facet::shapeSecondDerivatives(p.xi);
  Weights relative{};                              // [1, −H_i]: x^k − x̄ (eq. 26)
  std::array<Weights, M> base{};                   // [0, H_i,α]: δā_α at fixed ξ
  std::array<std::array<Weights, M>, M> curve{};   // [0, H_i,αβ]: δx̄,αβ
  std::array<std::array<Point, M>, M> xbar2{};     // x̄,αβ = Σ H_i,αβ x_i
  relative[0] = 1.0;
  for (int i = 0; i < Facet::kNodes; ++i) {
    relative[1 + i] = -p.shape[i];
    for (int al = 0; al < M; ++al) {
      base[al][1 + i] = dH(i, al);
      for (int be = 0; be < M; ++be) {
        curve[al][be][1 + i] = d2H[i](al, be);
        addScaled(xbar2[al][be], d2H[i](al, be), x.master[i]);
      }
    }
  }
  Matrix<M, M> b;      // b̄_αβ = x̄,αβ·n̄
  Matrix<M, M> A;      // A_αβ = ā_αβ − g_N b̄_αβ
  std::array<std::array<std::array<double, M>, M>, M> gamma{};  // Γ_αβγ = x̄,αβ·ā_γ
  for (int al = 0; al < M; ++al)
    for (int be = 0; be < M; ++be) {
      b(al, be) = dot(xbar2[al][be], n);
      A(al, be) = p.metric(al, be) - gN * b(al, be);
      for (int ga = 0; ga < M; ++ga) gamma[al][be][ga] = dot(xbar2[al][be], a[ga]);
    }
  if (!(determinant(A) > 0.0)) return out;  // the node sits at a focal point of the facet: no unique ξ̄
  const Matrix<M, M> AInv = inverse(A);

  // ---- Kinematic operators, eq. (26) and the exact first variations --------------------------------
  const Column N = Op::kron(relative, n);  // ∂g_N/∂u
  std::array<Column, M> T{}, Nbar{}, D{}, Xi{};
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

  // ---- Contact law --------------------------------------------------------------------------------
  const double tN = normalLaw_.traction(gN);  // eq. (16), < 0
  const double epsN = normalLaw_.tractionDerivative(gN);
  out.normalTraction = tN;

  // Partial derivatives of t_Tα(Δξ, ā_βγ, t_N); all zero without friction and at a first contact.
  Matrix<M, M> dT_dXi{};
  std::array<Matrix<M, M>, M> dT_dMetric{};
  Vector<M> dT_dNormal{};
  Vector<M> tT{};
  if (parameters_.isFrictionless()) {
    out.status = ContactStatus::Slip;  // free sliding, t_T ≡ 0
  } else if (!committed.isInContact()) {
    // First contact: ξ_n := ξ̄, t_T,n := 0, so Δξ ≡ 0 and t_T ≡ 0 in this increment (see header).
    out.status = ContactStatus::Stick;
  } else {
    ReturnMappingInput<M> in;
    in.committedTraction = committed.tangentialTraction;
    in.slipIncrement = subtract(p.xi, committed.xi);  // Δξ_{n+1}, eq. (20)
    in.metric = p.metric;
    in.normalTraction = tN;
    in.facetLength = facetLength;
    out.friction = returnMapping_.map(in);  // eq. (20)–(23)
    out.status = out.friction.status;
    tT = out.friction.traction;
    dT_dXi = out.friction.dTraction_dSlipIncrement;
    if (out.status == ContactStatus::Slip && slipTangent.secant) {
      // A node in a slip cycle: the secant stiffness along its slip direction (see SlipTangent).
      Vector<M> s = out.friction.trialDirection;
      s = scaled(1.0 / norm(s), s);
      const double stick = out.friction.tangentialPenalty * dot(s, multiply(p.metric, s));
      const double along = dot(s, multiply(dT_dXi, s));
      addOuter(dT_dXi, std::min(slipTangent.stiffness, stick) - along, s, s);
    }
    dT_dMetric = out.friction.dTraction_dMetric;
    dT_dNormal = out.friction.dTraction_dNormalTraction;
    // eq. (7), backward Euler: g_T,n+1 = g_T,n + √(Δξ^α ā_αβ Δξ^β); committed only at commit().
    out.trial.accumulatedSlip =
        committed.accumulatedSlip + std::sqrt(dot(in.slipIncrement, multiply(p.metric, in.slipIncrement)));
  }
  out.tangentialTraction = tT;
  out.trial.tangentialTraction = tT;
  out.trial.status = out.status;

  // ---- Residual: r_c = t_N N + t_Tα Ξ^α --------------------------------------------------------------
  out.residual = scaled(tN, N);
  for (int al = 0; al < M; ++al) addScaled(out.residual, tT[al], Xi[al]);

  auto& K = out.tangent;
  addOuter(K, epsN, N, N);  // eq. (24): K_N = ε_N N Nᵀ

  if (terms_ == TangentTerms::PaperMainTerms) {
    // ∂ξ̄/∂u ≈ D^α, fixed metric: stick ∂t_α/∂Δξ^β = ε_T ā_αβ gives eq. (25) ε_T ā_αβ D^α D^βᵀ; slip gives
    // eq. (26): ∂t_α/∂t_N ε_N = −μ ε_N n^trial_α (t_N < 0; the paper counts the penetration positive) and
    // the eq. (27) term. With a slip tolerance the ∂t/∂t_N term also acts in stick (ε_T depends on t_N).
    for (int al = 0; al < M; ++al) {
      Column dt = scaled(dT_dNormal[al] * epsN, N);
      for (int be = 0; be < M; ++be) addScaled(dt, dT_dXi(al, be), D[be]);
      addOuter(K, 1.0, D[al], dt);
    }
    return out;
  }

  // ---- Consistent tangent: K_c = ε_N N Nᵀ + t_N ∂²g_N/∂u² + Ξ^α (dt_Tα/du)ᵀ + t_Tα ∂²ξ̄^α/∂u² -------
  // Total variation of n̄·ā_α (fixed-ξ part N̄_α plus the motion of ξ̄): M_α = N̄_α + b̄_αβ Ξ^β.
  std::array<Column, M> Mv = Nbar;
  for (int al = 0; al < M; ++al)
    for (int be = 0; be < M; ++be) addScaled(Mv[al], b(al, be), Xi[be]);
  // (a) t_N ∂²g_N/∂u², from δg_N = n̄·(δx^k − H_i δx_i) with δn̄ = −(n̄·δā_α) ā^α and δH_i = H_i,β δξ^β:
  //       ∂²g_N/∂u² = −(Ξ^α N̄_αᵀ + N̄_α Ξ^αᵀ) − b̄_αβ Ξ^α Ξ^βᵀ + g_N ā^αβ M_α M_βᵀ    (symmetric)
  for (int al = 0; al < M; ++al) {
    Op::addSymmetricOuter(K, -tN, Xi[al], Nbar[al]);
    for (int be = 0; be < M; ++be) {
      addOuter(K, -tN * b(al, be), Xi[al], Xi[be]);
      addOuter(K, tN * gN * aInv(al, be), Mv[al], Mv[be]);
    }
  }
  // (b) Ξ^α (dt_Tα/du)ᵀ with the exact variation of the traction:
  //       dt_α = ∂t_α/∂Δξ^β Ξ^β + ∂t_α/∂ā_βγ dā_βγ + ∂t_α/∂t_N ε_N N,
  //       dā_βγ = [0, H_i,β] ⊗ ā_γ + [0, H_i,γ] ⊗ ā_β + (Γ_βεγ + Γ_γεβ) Ξ^ε     (Γ_αβγ = x̄,αβ·ā_γ)
  // (the stretch term makes even the stick tangent slightly non-symmetric when Δξ ≠ 0: the covariant
  //  t_T,n is held fixed while the facet stretches)
  {
    std::array<std::array<Column, M>, M> dMetric{};
    for (int be = 0; be < M; ++be)
      for (int ga = 0; ga < M; ++ga) {
        dMetric[be][ga] = add(Op::kron(base[be], a[ga]), Op::kron(base[ga], a[be]));
        for (int ep = 0; ep < M; ++ep) addScaled(dMetric[be][ga], gamma[be][ep][ga] + gamma[ga][ep][be], Xi[ep]);
      }
    for (int al = 0; al < M; ++al) {
      Column dt = scaled(dT_dNormal[al] * epsN, N);
      for (int be = 0; be < M; ++be) {
        addScaled(dt, dT_dXi(al, be), Xi[be]);
        for (int ga = 0; ga < M; ++ga) addScaled(dt, dT_dMetric[al](be, ga), dMetric[be][ga]);
      }
      addOuter(K, 1.0, Xi[al], dt);
    }
  }
  // (c) t_Tβ ∂²ξ̄^β/∂u². ξ̄(u) solves F_α(u, ξ) = (x^k − x̄)·ā_α = 0 with ∂F_α/∂ξ^β = −A_αβ, so
  //       ∂²ξ̄^β/∂u² = (A⁻¹)^βα [F_α,uu + F_α,uξ^γ Ξ^γᵀ + Ξ^γ F_α,uξ^γᵀ + F_α,ξ^γξ^δ Ξ^γ Ξ^δᵀ]
  //     with (x̄,αβγ = 0 for the multilinear facets of MasterFacet.hpp)
  //       F_α,uu      = ([1, −H_i] ⊗ I)ᵀ([0, H_i,α] ⊗ I) + transpose
  //       F_α,uξ^γ    = −[0, H_i,γ] ⊗ ā_α − [0, H_i,α] ⊗ ā_γ + [1, −H_i] ⊗ x̄,αγ + g_N [0, H_i,αγ] ⊗ n̄
  //       F_α,ξ^γξ^δ  = −(Γ_γδα + Γ_αδγ + Γ_αγδ)
  //     contracted with t_Tβ: weights w_α = t_Tβ (A⁻¹)^βα.
  if (tT != Vector<M>{}) {
    const Vector<M> w = multiply(transpose(AInv), tT);
    for (int al = 0; al < M; ++al) {
      if (w[al] == 0.0) continue;
      Op::addBlockOuter(K, w[al], relative, base[al]);
      Op::addBlockOuter(K, w[al], base[al], relative);
      for (int ga = 0; ga < M; ++ga) {
        Column fuxi = Op::kron(relative, xbar2[al][ga]);
        addScaled(fuxi, -1.0, Op::kron(base[ga], a[al]));
        addScaled(fuxi, -1.0, Op::kron(base[al], a[ga]));
        addScaled(fuxi, gN, Op::kron(curve[al][ga], n));
        Op::addSymmetricOuter(K, w[al], fuxi, Xi[ga]);
        for (int de = 0; de < M; ++de) {
          const double fxixi = -(gamma[ga][de][al] + gamma[al][de][ga] + gamma[al][ga][de]);
          addOuter(K, w[al] * fxixi, Xi[ga], Xi[de]);
        }
      }
    }
  }
  return out;
}

template class NodeToFacetContact<Line2Facet>;
template class NodeToFacetContact<Quad4Facet>;

}  // namespace contessa::contact
