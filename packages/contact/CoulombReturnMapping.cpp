#include "contact/CoulombReturnMapping.hpp"

#include "common/Error.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace contessa::contact {

template <int NXi>
CoulombReturnMapping<NXi>::CoulombReturnMapping(double tangentialPenalty, double frictionCoefficient,
                                                double slipTolerance)
    : tangentialPenalty_(tangentialPenalty), frictionCoefficient_(frictionCoefficient), slipTolerance_(slipTolerance) {
  requireInput(frictionCoefficient >= 0.0,
               "contact: the friction coefficient mu must be >= 0, got " + std::to_string(frictionCoefficient));
  requireInput(tangentialPenalty >= 0.0,
               "contact: the tangential penalty epsilon_T must be >= 0, got " + std::to_string(tangentialPenalty));
  requireInput(slipTolerance >= 0.0, "contact: the slip tolerance must be >= 0, got " + std::to_string(slipTolerance));
  requireInput(frictionCoefficient == 0.0 || slipTolerance > 0.0 || tangentialPenalty > 0.0,
               "contact: the tangential penalty epsilon_T must be > 0 when mu > 0 and the slip tolerance is 0, got " +
                   std::to_string(tangentialPenalty));
}

template <int NXi>
ReturnMappingResult<NXi> CoulombReturnMapping<NXi>::map(const ReturnMappingInput<NXi>& in) const {
  ReturnMappingResult<NXi> out;
  const double mu = frictionCoefficient_;
  if (mu == 0.0) {  // frictionless path: free sliding, no tangential traction, no tangential stiffness
    out.status = ContactStatus::Slip;
    return out;
  }
  const Matrix<NXi, NXi>& a = in.metric;
  const Matrix<NXi, NXi> aInv = inverse(a);
  const double limit = mu * std::abs(in.normalTraction);
  // ∂|t_N|/∂t_N = −1 for t_N < 0 (compression)
  const double dAbsNormal = in.normalTraction > 0.0 ? 1.0 : -1.0;

  // ε_T of eq. (17)/(20): constant, or tied to the pressure by the elastic-slip tolerance s, so that the
  // stick radius μ|t_N|/ε_T is s L_k and does not shrink to nothing on a nearly unloaded node. Tied to a
  // frozen traction (the augmented Lagrangian's λ_N) it is a constant too: an update that doubles t_N at
  // the unchanged iterate (λ_N + ε_N g_N with λ_N = t_N) must not double the stick spring that starts from
  // λ_T, or the trial λ_T + 2ε_T Δξ = 3 t_T slips past μ 2|t_N| wherever |t_T| > (2/3) μ|t_N|.
  const bool frozen = in.frozenNormalTraction < 0.0;
  double epsT = tangentialPenalty_;
  double dEpsT = 0.0;  // ∂ε_T/∂t_N
  if (slipTolerance_ > 0.0) {
    if (!(in.facetLength > 0.0))
      throw std::logic_error("CoulombReturnMapping: a slip tolerance needs the slave facet length L_k > 0");
    const double elasticSlip = slipTolerance_ * in.facetLength;  // s L_k
    const double pressurePenalty = mu * std::abs(frozen ? in.frozenNormalTraction : in.normalTraction) / elasticSlip;
    if (tangentialPenalty_ == 0.0 || pressurePenalty < tangentialPenalty_) {  // the cap ε_T,max is not active
      epsT = pressurePenalty;
      dEpsT = frozen ? 0.0 : mu * dAbsNormal / elasticSlip;
    }
  }
  out.tangentialPenalty = epsT;
  out.dTangentialPenalty_dNormalTraction = dEpsT;
  const Vector<NXi> slipCovariant = multiply(a, in.slipIncrement);  // ā_αβ Δξ^β
  const Vector<NXi> dTrial_dNormal = scaled(dEpsT, slipCovariant);   // ∂t^trial_α/∂t_N

  // eq. (20): stick predictor t^trial_α = t_α,n + ε_T ā_αβ Δξ^β
  out.trialTraction = add(in.committedTraction, scaled(epsT, slipCovariant));
  // eq. (19): ‖t‖ = √(t_α ā^αβ t_β); eq. (21): f^trial = ‖t^trial‖ − μ|t_N|
  const Vector<NXi> trialContravariant = multiply(aInv, out.trialTraction);
  out.trialNorm = std::sqrt(dot(out.trialTraction, trialContravariant));
  out.trialIndicator = out.trialNorm - limit;
  if (out.trialNorm > 0.0) out.trialDirection = scaled(1.0 / out.trialNorm, out.trialTraction);  // eq. (23)

  if (out.trialIndicator <= 0.0) {
    // eq. (22a), stick: t_α = t^trial_α
    out.status = ContactStatus::Stick;
    out.traction = out.trialTraction;
    out.dTraction_dTrial = identityMatrix<NXi>();
    out.dTraction_dSlipIncrement = scaled(epsT, a);
    for (int alpha = 0; alpha < NXi; ++alpha)
      for (int gamma = 0; gamma < NXi; ++gamma)  // ∂t^trial_α/∂ā_βγ = ε_T δ_αβ Δξ^γ
        out.dTraction_dMetric[alpha](alpha, gamma) = epsT * in.slipIncrement[gamma];
    out.dTraction_dNormalTraction = dTrial_dNormal;  // ā_αβ Δξ^β ∂ε_T/∂t_N (0 for a constant ε_T)
    return out;
  }

  // eq. (22b), slip: t_α = μ|t_N| n^trial_α
  out.status = ContactStatus::Slip;
  out.traction = scaled(limit, out.trialDirection);
  const Vector<NXi> nUp = multiply(aInv, out.trialDirection);  // n^β = ā^βγ n_γ
  // eq. (27): ∂t_α/∂t^trial_β = μ|t_N|/‖t^trial‖ (δ_α^β − n_α n^β)
  for (int alpha = 0; alpha < NXi; ++alpha)
    for (int beta = 0; beta < NXi; ++beta)
      out.dTraction_dTrial(alpha, beta) =
          limit / out.trialNorm * ((alpha == beta ? 1.0 : 0.0) - out.trialDirection[alpha] * nUp[beta]);
  // ∂t_α/∂Δξ^β = ∂t_α/∂t^trial_γ ε_T ā_γβ
  out.dTraction_dSlipIncrement = multiply(out.dTraction_dTrial, scaled(epsT, a));
  // ∂t_α/∂ā_βγ: through t^trial (ε_T δ Δξ) and through the norm ‖t^trial‖ (∂ā^δε/∂ā_βγ = −ā^δβ ā^γε),
  // which gives + ½ μ|t_N| n_α n^β n^γ.
  for (int alpha = 0; alpha < NXi; ++alpha)
    for (int beta = 0; beta < NXi; ++beta)
      for (int gamma = 0; gamma < NXi; ++gamma)
        out.dTraction_dMetric[alpha](beta, gamma) = out.dTraction_dTrial(alpha, beta) * epsT * in.slipIncrement[gamma] +
                                                    0.5 * limit * out.trialDirection[alpha] * nUp[beta] * nUp[gamma];
  // ∂t_α/∂t_N: through the Coulomb limit μ|t_N| along n^trial, and through ε_T(t_N) in t^trial (eq. 27;
  // zero with one surface coordinate, where δ − n_1 n^1 = 0)
  out.dTraction_dNormalTraction =
      add(scaled(mu * dAbsNormal, out.trialDirection), multiply(out.dTraction_dTrial, dTrial_dNormal));
  return out;
}

template class CoulombReturnMapping<1>;
template class CoulombReturnMapping<2>;

}  // namespace contessa::contact
