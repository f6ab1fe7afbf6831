#include "mechanics/SaintVenantKirchhoff.hpp"

namespace contessa::mechanics {

Teuchos::RCP<const Teuchos::ParameterList> SaintVenantKirchhoff::validParameters() {
  return isotropicElasticParameters(
      kModelName, "Saint Venant-Kirchhoff: S = lambda tr(E) I + 2 mu E, E = (C - I)/2 (large rotations, small strains)");
}

std::unique_ptr<Material> SaintVenantKirchhoff::create(const Teuchos::ParameterList& params,
                                                       const std::string& where) {
  return std::make_unique<SaintVenantKirchhoff>(readLameConstants(params, where));
}

bool SaintVenantKirchhoff::firstPiolaKirchhoff(const Tensor2& F, Tensor2& P, Tensor4* A) const {
  // The energy stays finite through inversion, but an inverted F is not a deformation: reject it
  // like every finite-strain law so the solver cuts back instead of converging to it.
  if (!(determinant(F) > 0.0)) return false;
  const double lambda = lame_.lambda, mu = lame_.mu;
  const Tensor2 I = identity2();
  const Tensor2 C = multiply(transpose(F), F);
  Tensor2 E{}, S{};
  for (int n = 0; n < 9; ++n) E[n] = 0.5 * (C[n] - I[n]);
  const double trE = trace(E);
  for (int n = 0; n < 9; ++n) S[n] = lambda * trE * I[n] + 2.0 * mu * E[n];
  P = multiply(F, S);
  if (A) {
    // A_iJkL = δ_ik S_JL + F_iM ℂ_MJNL F_kN, ℂ_MJNL = λ δ_MJ δ_NL + μ (δ_MN δ_JL + δ_ML δ_JN),
    // i.e. the geometric term plus λ F_iJ F_kL + μ ((F Fᵀ)_ik δ_JL + F_iL F_kJ).
    const Tensor2 b = multiply(F, transpose(F));
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J)
        for (int k = 0; k < 3; ++k)
          for (int L = 0; L < 3; ++L)
            (*A)[idx4(i, J, k, L)] = I[idx2(i, k)] * S[idx2(J, L)] + lambda * F[idx2(i, J)] * F[idx2(k, L)] +
                                     mu * (b[idx2(i, k)] * I[idx2(J, L)] + F[idx2(i, L)] * F[idx2(k, J)]);
  }
  return true;
}

}  // namespace contessa::mechanics
