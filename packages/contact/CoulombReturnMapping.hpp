#pragma once
// Tangential part of the contact law: Coulomb friction with a penalty (elastic) stick law, integrated by
// backward Euler with a return mapping, eq. (17)–(23), written in covariant components t_Tα on a
// master facet with NXi surface coordinates (1 in 2D, 2 in 3D).
#include "contact/ContactHistory.hpp"

namespace contessa::contact {

template <int NXi>
struct ReturnMappingInput {
  Vector<NXi> committedTraction{};  ///< t_Tα,n: covariant tangential traction at the last converged state
  Vector<NXi> slipIncrement{};      ///< Δξ^β_{n+1} = ξ^β_{n+1} − ξ^β_n on the same facet
  Matrix<NXi, NXi> metric{};        ///< ā_αβ at the current contact point
  double normalTraction = 0.0;      ///< t_N,n+1 of eq. (16) (≤ 0 in contact)
  double facetLength = 0.0;         ///< L_k, slave facet length at the node (needed when the slip tolerance > 0)
  /// The normal traction (≤ 0) that the slip tolerance's ε_T = μ|t|/(s L_k) is taken from when it is held
  /// fixed: the augmented Lagrangian's λ_N, a constant between two multiplier updates (docs/verification-contact.md
  /// §12, "The stick penalty of the augmented Lagrangian"). 0: ε_T follows t_N itself (the penalty law, and a
  /// node whose λ_N is still 0).
  double frozenNormalTraction = 0.0;
};

template <int NXi>
struct ReturnMappingResult {
  ContactStatus status = ContactStatus::Stick;
  Vector<NXi> traction{};        ///< t_Tα,n+1, eq. (22)
  Vector<NXi> trialTraction{};   ///< t^trial_Tα,n+1, eq. (20)
  double trialNorm = 0.0;        ///< ‖t^trial‖ = √(t_α ā^αβ t_β), eq. (19)
  double trialIndicator = 0.0;   ///< f^trial = ‖t^trial‖ − μ|t_N|, eq. (21)
  Vector<NXi> trialDirection{};  ///< n^trial_Tα = t^trial_α/‖t^trial‖, eq. (23) (0 when t^trial = 0)
  double tangentialPenalty = 0.0;  ///< ε_T used in eq. (20): constant, or μ|t_N|/(s L_k) (capped)
  double dTangentialPenalty_dNormalTraction = 0.0;  ///< ∂ε_T/∂t_N: −μ/(s L_k) when tied to the pressure, else 0

  // Consistent (algorithmic) linearisation of t_Tα,n+1 with respect to the inputs, used by the element
  // tangents: the paper's eq. (25)–(27) use the first two; the metric derivative is the additional
  // finite-deformation term (a stretched facet changes covariant components and norms).
  Matrix<NXi, NXi> dTraction_dTrial{};                     ///< ∂t_α/∂t^trial_β: δ (stick), eq. (27) (slip)
  Matrix<NXi, NXi> dTraction_dSlipIncrement{};             ///< ∂t_α/∂Δξ^β
  std::array<Matrix<NXi, NXi>, NXi> dTraction_dMetric{};   ///< [α](β,γ) = ∂t_α/∂ā_βγ, entries independent
  Vector<NXi> dTraction_dNormalTraction{};                 ///< ∂t_α/∂t_N (through μ|t_N| and ε_T(t_N))
};

/// Backward-Euler return mapping for Coulomb friction:
///   trial (stick predictor), eq. (20):  t^trial_α = t_α,n + ε_T ā_αβ Δξ^β
///   indicator, eq. (19)/(21):           f^trial = ‖t^trial‖ − μ|t_N|,  ‖t‖ = √(t_α ā^αβ t_β)
///   stick, eq. (17)/(22a), f ≤ 0:       t_α = t^trial_α
///   slip,  eq. (18)/(22b), f > 0:       t_α = μ|t_N| n^trial_α,  n^trial_α = t^trial_α/‖t^trial‖ (23)
/// so that in slip ‖t_T‖ = μ|t_N| exactly and t_T has the direction of the trial traction.
/// μ = 0 is the frictionless path: t_T ≡ 0, status Slip, no tangential stiffness (ε_T unused).
///
/// The stick penalty ε_T of eq. (17)/(20) is either the constant `tangentialPenalty` (slip tolerance
/// s = 0, the paper's law), or tied to the pressure by an elastic-slip tolerance (s > 0, as Abaqus'
/// SLIP TOLERANCE):
///   ε_T = μ|t_N| / (s L_k),  capped by `tangentialPenalty` when that is > 0,
/// so the stick radius μ|t_N|/ε_T = s L_k does not vanish with the pressure. ε_T then depends on t_N
/// (hence on g_N), and ∂t_α/∂t_N carries ā_αβ Δξ^β ∂ε_T/∂t_N in stick (and through eq. (27) in slip).
/// With a `frozenNormalTraction` t_f < 0 (the augmented Lagrangian's λ_N) ε_T = μ|t_f|/(s L_k) instead, a
/// constant: ∂ε_T/∂t_N = 0, and t_N enters through the Coulomb limit μ|t_N| only.
///
/// Sign convention: t_T is the traction of the stick spring, positive along the relative motion
/// Δξ of the slave over the master; the force it exerts on the slave node is −t_α ā^α, opposed to the
/// motion, which is the −ġ_T/‖ġ_T‖ of eq. (18).
template <int NXi>
class CoulombReturnMapping {
 public:
  /// `tangentialPenalty`: ε_T (s = 0) or its upper bound (s > 0; 0 = no bound); `slipTolerance`: s.
  CoulombReturnMapping(double tangentialPenalty, double frictionCoefficient, double slipTolerance = 0.0);

  ReturnMappingResult<NXi> map(const ReturnMappingInput<NXi>& input) const;

  double tangentialPenalty() const { return tangentialPenalty_; }
  double frictionCoefficient() const { return frictionCoefficient_; }
  double slipTolerance() const { return slipTolerance_; }

 private:
  double tangentialPenalty_;
  double frictionCoefficient_;
  double slipTolerance_;
};

extern template class CoulombReturnMapping<1>;
extern template class CoulombReturnMapping<2>;

}  // namespace contessa::contact
