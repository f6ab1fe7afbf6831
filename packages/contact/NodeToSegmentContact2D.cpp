#include "contact/NodeToSegmentContact2D.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace contessa::contact {

namespace {

using Vec6 = Vector<6>;
using Mat6 = Matrix<6, 6>;

/// [v; −H_1 v; −H_2 v]: the slave-minus-contact-point operator of eq. (26) applied to v.
Vec6 relativeOperator(const Vector<2>& v, const Vector<2>& h) {
  return {v[0], v[1], -h[0] * v[0], -h[0] * v[1], -h[1] * v[0], -h[1] * v[1]};
}

/// [0; H_1,1 v; H_2,1 v]: its scalar product with δu is v·δā_1 (change of the covariant base vector).
Vec6 baseVectorOperator(const Vector<2>& v) {
  const auto dH = Line2Facet::shapeDerivatives(Line2Facet::center());
  return {0.0, 0.0, dH(0, 0) * v[0], dH(0, 0) * v[1], dH(1, 0) * v[0], dH(1, 0) * v[1]};
}

/// A += s (x yᵀ + y xᵀ)
void addSymmetricOuter(Mat6& a, double s, const Vec6& x, const Vec6& y) {
  addOuter(a, s, x, y);
  addOuter(a, s, y, x);
}

}  // namespace

NodeToSegmentContact2D::NodeToSegmentContact2D(const ContactLawParameters& parameters, TangentTerms terms)
    : parameters_(parameters),
      terms_(terms),
      normalLaw_(parameters.normalPenalty),
      returnMapping_(parameters.tangentialPenalty, parameters.frictionCoefficient, parameters.slipTolerance) {
  parameters_.validate();
}

NodeToSegmentResult2D NodeToSegmentContact2D::evaluate(const NodeToSegmentGeometry2D& x, int segment,
                                                       const ContactHistory<1>& committed, double facetLength,
                                                       SlipTangent slipTangent) const {
  if (committed.isInContact() && committed.segment != segment)
    throw std::logic_error("NodeToSegmentContact2D: committed history is on segment " +
                           std::to_string(committed.segment) + ", not on segment " + std::to_string(segment) +
                           "; map it with transferHistory2D first");

  NodeToSegmentResult2D out;
  // eq. (1)–(5): closest point, ā_1, ā_11, n̄, g_N. Exact after one Newton step on a straight segment.
  out.projection = SegmentProjection2D().project(x.slave, x.master);
  const auto& p = out.projection;
  out.trial = committed;
  out.trial.segment = segment;
  out.trial.xi = p.xi;
  out.trial.tangentialTraction = {0.0};
  out.trial.status = ContactStatus::Open;
  if (!p.converged || !normalLaw_.isActive(p.gap)) return out;  // eq. (6): open, no force, no stiffness

  // ---- Kinematic vectors --------------------------------------------------------------------------
  const double gN = p.gap;
  const double a11 = p.metric(0, 0);             // ā_11
  const double a11Inv = p.inverseMetric(0, 0);   // ā^11
  const Vector<2>& n = p.normal;
  const Vector<2>& a1 = p.covariantBasis[0];
  const Vec6 N = relativeOperator(n, p.shape);                  // eq. (26): N = ∂g_N/∂u
  const Vec6 T1 = relativeOperator(a1, p.shape);                // eq. (26): T_1
  const Vec6 D1 = scaled(a11Inv, T1);                           // eq. (26): D^1 = ā^11 T_1
  const Vec6 Nbar = baseVectorOperator(n);                      // N̄_1·δu = n̄·δā_1
  const Vec6 Tbar = baseVectorOperator(a1);                     // T̄_1·δu = ā_1·δā_1 = ½ δā_11
  const Vec6 dXiGeometric = scaled(gN * a11Inv, Nbar);          // ∂ξ̄/∂u − D^1: g_N ā^11 N̄_1
  const Vec6 dXi = add(D1, dXiGeometric);                       // ∂ξ̄/∂u, exact (b̄_11 = 0)

  // ---- Contact law ---------------------------------------------------------------------------------
  const double tN = normalLaw_.traction(gN);  // eq. (16), < 0
  const double epsN = normalLaw_.tractionDerivative(gN);
  out.normalTraction = tN;

  // Partial derivatives of t_T1(Δξ, ā_11, t_N); all zero without friction.
  double dT_dXi = 0.0;
  double dT_dMetric = 0.0;
  double dT_dNormal = 0.0;
  double tT = 0.0;
  if (parameters_.isFrictionless()) {
    out.status = ContactStatus::Slip;  // free sliding, t_T ≡ 0
  } else if (!committed.isInContact()) {
    // First contact: ξ_n := ξ̄, t_T,n := 0, so Δξ ≡ 0 and t_T ≡ 0 in this increment (see header).
    out.status = ContactStatus::Stick;
  } else {
    ReturnMappingInput<1> in;
    in.committedTraction = committed.tangentialTraction;
    in.slipIncrement = {p.xi[0] - committed.xi[0]};  // Δξ_{n+1}, eq. (20)
    in.metric = p.metric;
    in.normalTraction = tN;
    in.facetLength = facetLength;
    out.friction = returnMapping_.map(in);  // eq. (20)–(23)
    out.status = out.friction.status;
    tT = out.friction.traction[0];
    dT_dXi = out.friction.dTraction_dSlipIncrement(0, 0);
    if (out.status == ContactStatus::Slip && slipTangent.secant)  // a node in a slip cycle: its secant
      dT_dXi = std::min(slipTangent.stiffness, out.friction.tangentialPenalty * a11);
    dT_dMetric = out.friction.dTraction_dMetric[0](0, 0);
    dT_dNormal = out.friction.dTraction_dNormalTraction[0];
    // eq. (7), backward Euler: g_T,n+1 = g_T,n + √(Δξ ā_11 Δξ); committed only at commit().
    out.trial.accumulatedSlip = committed.accumulatedSlip + std::sqrt(a11) * std::abs(in.slipIncrement[0]);
  }
  out.tangentialTraction = tT;
  out.trial.tangentialTraction = {tT};
  out.trial.status = out.status;

  // ---- Residual: r_c = t_N N + t_T1 ∂ξ̄/∂u --------------------------------------------------------
  out.residual = add(scaled(tN, N), scaled(tT, dXi));

  // ---- Tangent, main terms of the paper ------------------------------------------------------------
  Mat6& K = out.tangent;
  // eq. (24): K_N = ε_N N Nᵀ
  addOuter(K, epsN, N, N);
  // Linearised tangential traction with ∂ξ̄/∂u ≈ D^1 and a fixed metric:
  //   dt_T1 ≈ ∂t/∂Δξ D^1·δu + ∂t/∂t_N ε_N N·δu.
  // Stick, ∂t/∂Δξ = ε_T ā_11, ∂t/∂t_N = 0:     K = ε_T ā_11 D^1 D^1ᵀ                        eq. (25)
  //   (with a slip tolerance, ε_T = μ|t_N|/(s L_k) and ∂t/∂t_N = ā_11 Δξ ∂ε_T/∂t_N = −μ ā_11 Δξ/(s L_k):
  //    the term ∂t/∂t_N ε_N D^1 Nᵀ below then also acts in stick, and is non-symmetric)
  // Slip,  ∂t/∂Δξ = eq. (27)·ε_T ā_11 (= 0 when there is one ξ: δ − n_T1 n_T^1 = 0),
  //        ∂t/∂t_N = −μ n^trial_T1:            K = −μ ε_N n^trial_T1 D^1 Nᵀ + (eq. 27 term)   eq. (26)
  // eq. (26) is printed with the penetration counted positive; with g_N < 0 (eq. 6) the first slip
  // term carries the minus sign and the second μ ε_N |g_N|. Non-symmetric: D^1 Nᵀ ≠ N D^1ᵀ.
  const Vec6 dTractionMain = add(scaled(dT_dXi, D1), scaled(dT_dNormal * epsN, N));
  addOuter(K, 1.0, D1, dTractionMain);
  if (terms_ == TangentTerms::PaperMainTerms) return out;

  // ---- Tangent, geometric terms of a finite-size, moving segment (Wriggers 2006, §9 NTS) ------------
  // eq. (24)–(26) hold δg_N = N·δu but drop the second variations of g_N and ξ̄ and the terms of
  // order g_N/l in δξ̄. For large sliding on deforming master segments these terms carry the rotation
  // of n̄ and the stretch of ā_1 with the master nodes; without them the Newton iteration loses its
  // quadratic convergence (the FD tests show the main terms alone miss them by O(g_N/l, t_T/t_N)).
  //
  // (a) t_N ∂²g_N/∂u²: rotation of the normal and motion of the contact point along the segment
  //       ∂²g_N/∂u² = −(D^1 N̄_1ᵀ + N̄_1 D^1ᵀ) − g_N ā^11 N̄_1 N̄_1ᵀ
  addSymmetricOuter(K, -tN, D1, Nbar);
  addOuter(K, -tN * gN * a11Inv, Nbar, Nbar);
  // (b) exact variation of t_T1: the g_N ā^11 N̄_1 part of δξ̄ and the stretch δā_11 = 2 T̄_1·δu
  //     (the stretch term D^1 T̄_1ᵀ makes even the consistent stick tangent slightly non-symmetric when
  //     Δξ ≠ 0: the covariant t_T,n is held fixed while the segment stretches)
  const Vec6 dTractionGeometric = add(scaled(dT_dXi, dXiGeometric), scaled(2.0 * dT_dMetric, Tbar));
  addOuter(K, 1.0, D1, dTractionGeometric);
  addOuter(K, 1.0, dXiGeometric, add(dTractionMain, dTractionGeometric));
  // (c) t_T1 ∂²ξ̄/∂u²:
  //       ∂²ξ̄/∂u² = ā^11 (N N̄_1ᵀ + N̄_1 Nᵀ) − ā^11 (D^1 T̄_1ᵀ + T̄_1 D^1ᵀ) − 2 g_N (ā^11)² (N̄_1 T̄_1ᵀ + T̄_1 N̄_1ᵀ)
  if (tT != 0.0) {
    addSymmetricOuter(K, tT * a11Inv, N, Nbar);
    addSymmetricOuter(K, -tT * a11Inv, D1, Tbar);
    addSymmetricOuter(K, -2.0 * tT * gN * a11Inv * a11Inv, Nbar, Tbar);
  }
  return out;
}

}  // namespace contessa::contact
