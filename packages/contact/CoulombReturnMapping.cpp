#include "contact/CoulombReturnMapping.hpp"

#include "common/Error.hpp"

#include <cmath>
#include <string>

namespace contessa::contact {

template <int NXi>
CoulombReturnMapping<NXi>::CoulombReturnMapping(double tangentialPenalty, double frictionCoefficient)
    : tangentialPenalty_(tangentialPenalty), frictionCoefficient_(frictionCoefficient) {
  requireInput(frictionCoefficient >= 0.0,
               "contact: the friction coefficient mu must be >= 0, got " + std::to_string(frictionCoefficient));
  requireInput(frictionCoefficient == 0.0 || tangentialPenalty > 0.0,
               "contact: the tangential penalty epsilon_T must be > 0 when mu > 0, got " +
                   std::to_string(tangentialPenalty));
}

template <int NXi>
ReturnMappingResult<NXi> CoulombReturnMapping<NXi>::map(const ReturnMappingInput<NXi>& in) const {
  ReturnMappingResult<NXi> out;
  const double mu = frictionCoefficient_;
  const double epsT = tangentialPenalty_;
  if (mu == 0.0) {  // frictionless path: free sliding, no tangential traction, no tangential stiffness
    out.status = ContactStatus::Slip;
    return out;
  }
  const Matrix<NXi, NXi>& a = in.metric;
  const Matrix<NXi, NXi> aInv = inverse(a);

  // eq. (20): stick predictor t^trial_α = t_α,n + ε_T ā_αβ Δξ^β
  out.trialTraction = add(in.committedTraction, scaled(epsT, multiply(a, in.slipIncrement)));
  // eq. (19): ‖t‖ = √(t_α ā^αβ t_β); eq. (21): f^trial = ‖t^trial‖ − μ|t_N|
  const Vector<NXi> trialContravariant = multiply(aInv, out.trialTraction);
  out.trialNorm = std::sqrt(dot(out.trialTraction, trialContravariant));
  const double limit = mu * std::abs(in.normalTraction);
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
  // ∂(μ|t_N|)/∂t_N = −μ for t_N < 0 (compression)
  const double dLimit = in.normalTraction > 0.0 ? mu : -mu;
  out.dTraction_dNormalTraction = scaled(dLimit, out.trialDirection);
  return out;
}

template class CoulombReturnMapping<1>;
template class CoulombReturnMapping<2>;

}  // namespace contessa::contact
