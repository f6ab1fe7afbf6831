#include "mechanics/NeoHookean.hpp"

#include <cmath>

namespace contessa::mechanics {

Teuchos::RCP<const Teuchos::ParameterList> NeoHookean::validParameters() {
  return isotropicElasticParameters(
      kModelName, "Compressible Neo-Hookean: W = mu/2 (tr C - 3) - mu ln J + lambda/2 (ln J)^2 (Bonet & Wood)");
}

std::unique_ptr<Material> NeoHookean::create(const Teuchos::ParameterList& params, const std::string& where) {
  return std::make_unique<NeoHookean>(readLameConstants(params, where));
}

bool NeoHookean::firstPiolaKirchhoff(const Tensor2& F, Tensor2& P, Tensor4* A) const {
  const double detF = determinant(F);
  if (!(detF > 0.0)) return false;  // ln J undefined; W → ∞ as J → 0⁺
  const double lambda = lame_.lambda, mu = lame_.mu;
  const double lnJ = std::log(detF);
  const Tensor2 Finv = inverse(F);  // F⁻ᵀ_iJ = Finv_Ji
  // P = ∂W/∂F = μ (F − F⁻ᵀ) + λ ln J F⁻ᵀ (Bonet & Wood eq. 6.28).
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J)
      P[idx2(i, J)] = mu * F[idx2(i, J)] + (lambda * lnJ - mu) * Finv[idx2(J, i)];
  if (A) {
    // With ∂F⁻ᵀ_iJ/∂F_kL = −F⁻¹_Jk F⁻¹_Li and ∂ln J/∂F_kL = F⁻¹_Lk:
    // A_iJkL = μ δ_ik δ_JL + (μ − λ ln J) F⁻¹_Jk F⁻¹_Li + λ F⁻¹_Ji F⁻¹_Lk.
    const Tensor2 I = identity2();
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J)
        for (int k = 0; k < 3; ++k)
          for (int L = 0; L < 3; ++L)
            (*A)[idx4(i, J, k, L)] = mu * I[idx2(i, k)] * I[idx2(J, L)] +
                                      (mu - lambda * lnJ) * Finv[idx2(J, k)] * Finv[idx2(L, i)] +
                                      lambda * Finv[idx2(J, i)] * Finv[idx2(L, k)];
  }
  return true;
}

}  // namespace contessa::mechanics
