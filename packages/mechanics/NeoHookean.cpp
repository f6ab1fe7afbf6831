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

template <int D>
bool NeoHookean::stress(const Matrix<D>& F, Matrix<D>& P, Tangent<D>* A) const {
  const double detF = determinantOf<D>(F);
  if (!(detF > 0.0)) return false;  // ln J undefined; W → ∞ as J → 0⁺
  const double lambda = lame_.lambda, mu = lame_.mu;
  const double lnJ = std::log(detF);
  const Matrix<D> Finv = inverseOf<D>(F, detF);  // F⁻ᵀ_iJ = Finv_Ji
  // P = ∂W/∂F = μ (F − F⁻ᵀ) + λ ln J F⁻ᵀ (Bonet & Wood eq. 6.28). Plane strain: J = det F_2D and
  // F⁻¹ = diag(F_2D⁻¹, 1), so the in-plane P and A below are exactly those of the 3 × 3 formula.
  for (int i = 0; i < D; ++i)
    for (int J = 0; J < D; ++J) P[D * i + J] = mu * F[D * i + J] + (lambda * lnJ - mu) * Finv[D * J + i];
  if (A) {
    // With ∂F⁻ᵀ_iJ/∂F_kL = −F⁻¹_Jk F⁻¹_Li and ∂ln J/∂F_kL = F⁻¹_Lk:
    // A_iJkL = μ δ_ik δ_JL + (μ − λ ln J) F⁻¹_Jk F⁻¹_Li + λ F⁻¹_Ji F⁻¹_Lk.
    const double c = mu - lambda * lnJ;
    for (int i = 0; i < D; ++i)
      for (int J = 0; J < D; ++J)
        for (int k = 0; k < D; ++k)
          for (int L = 0; L < D; ++L)
            (*A)[((D * i + J) * D + k) * D + L] = (i == k && J == L ? mu : 0.0) +
                                                  c * Finv[D * J + k] * Finv[D * L + i] +
                                                  lambda * Finv[D * J + i] * Finv[D * L + k];
  }
  return true;
}

template bool NeoHookean::stress<2>(const Matrix<2>&, Matrix<2>&, Tangent<2>*) const;
template bool NeoHookean::stress<3>(const Matrix<3>&, Matrix<3>&, Tangent<3>*) const;
template class MaterialLaw<NeoHookean>;

}  // namespace contessa::mechanics
