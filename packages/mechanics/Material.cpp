#include "mechanics/Material.hpp"

namespace contessa::mechanics {

bool Material::firstPiolaKirchhoffAtPoints(int count, const Matrix<3>* F, Matrix<3>* P, Tangent<3>* A) const {
  for (int q = 0; q < count; ++q)
    if (!firstPiolaKirchhoff(F[q], P[q], A ? A + q : nullptr)) return false;
  return true;
}

bool Material::firstPiolaKirchhoffAtPoints(int count, const Matrix<2>* F, Matrix<2>* P, Tangent<2>* A) const {
  // Plane strain through the 3D law: F embedded with F_33 = 1, the in-plane blocks of P and A kept.
  Tensor2 P3{};
  Tensor4 A3{};
  for (int q = 0; q < count; ++q) {
    if (!firstPiolaKirchhoff(embedIn3D<2>(F[q], 1.0), P3, A ? &A3 : nullptr)) return false;
    for (int i = 0; i < 2; ++i)
      for (int J = 0; J < 2; ++J) {
        P[q][2 * i + J] = P3[idx2(i, J)];
        if (!A) continue;
        for (int k = 0; k < 2; ++k)
          for (int L = 0; L < 2; ++L) A[q][8 * i + 4 * J + 2 * k + L] = A3[idx4(i, J, k, L)];
      }
  }
  return true;
}

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
