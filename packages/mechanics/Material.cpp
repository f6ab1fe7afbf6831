#include "mechanics/Material.hpp"

namespace contessa::mechanics {

bool Material::cauchyStress(const Tensor2& F, Tensor2& sigma) const {
  Tensor2 P{};
  if (!firstPiolaKirchhoff(F, P, nullptr)) return false;
  // Geometrically linear laws do not distinguish configurations: P is already σ(ε).
  if (isSmallStrain()) {
    sigma = P;
    return true;
  }
  const double J = determinant(F);
  if (!(J > 0.0)) return false;
  sigma = scaled(1.0 / J, multiply(P, transpose(F)));  // σ = J⁻¹ P Fᵀ
  return true;
}

}  // namespace contessa::mechanics
