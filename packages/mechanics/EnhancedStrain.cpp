#include "mechanics/EnhancedStrain.hpp"

namespace contessa::mechanics {

EnhancedModes enhancedModes(int dim, const double* xi, const Tensor2& J0inv, double j0OverJ) {
  EnhancedModes modes;
  modes.count = dim * dim;
  for (int i = 0; i < dim; ++i)
    for (int beta = 0; beta < dim; ++beta) {
      Tensor2& G = modes.G[dim * i + beta];
      G = Tensor2{};
      for (int J = 0; J < dim; ++J) G[idx2(i, J)] = j0OverJ * xi[beta] * J0inv[idx2(beta, J)];
      modes.normSum += frobeniusNorm(G);
    }
  return modes;
}

Tensor2 enhancedGradient(const EnhancedModes& modes, const double* alpha) {
  Tensor2 H{};
  for (int m = 0; m < modes.count; ++m)
    for (int n = 0; n < 9; ++n) H[n] += alpha[m] * modes.G[m][n];
  return H;
}

void addEnhancedResidual(const EnhancedModes& modes, const Tensor2& P, double wj, double* Ralpha) {
  for (int m = 0; m < modes.count; ++m) Ralpha[m] += doubleContraction(modes.G[m], P) * wj;
}

namespace {
/// (A : G)_iJ = A_iJkL G_kL over the in-plane (or all, in 3D) indices.
Tensor2 contractRight(int dim, const Tensor4& A, const Tensor2& G) {
  Tensor2 AG{};
  for (int i = 0; i < dim; ++i)
    for (int J = 0; J < dim; ++J)
      for (int k = 0; k < dim; ++k)
        for (int L = 0; L < dim; ++L) AG[idx2(i, J)] += A[idx4(i, J, k, L)] * G[idx2(k, L)];
  return AG;
}
/// (G : A)_kL = G_iJ A_iJkL.
Tensor2 contractLeft(int dim, const Tensor2& G, const Tensor4& A) {
  Tensor2 GA{};
  for (int i = 0; i < dim; ++i)
    for (int J = 0; J < dim; ++J)
      for (int k = 0; k < dim; ++k)
        for (int L = 0; L < dim; ++L) GA[idx2(k, L)] += G[idx2(i, J)] * A[idx4(i, J, k, L)];
  return GA;
}
}  // namespace

void addEnhancedStiffness(int dim, const EnhancedModes& modes, const Tensor4& A, double wj, double* Kaa) {
  const int nm = modes.count;
  for (int n = 0; n < nm; ++n) {
    const Tensor2 AG = contractRight(dim, A, modes.G[n]);
    for (int m = 0; m < nm; ++m) Kaa[m * nm + n] += doubleContraction(modes.G[m], AG) * wj;
  }
}

void addCouplingStiffness(int dim, int nn, const PointGeometry& g, const EnhancedModes& modes, const Tensor4& A,
                          double* Kua, double* Kau) {
  const int nm = modes.count, nd = dim * nn;
  for (int m = 0; m < nm; ++m) {
    const Tensor2 AG = contractRight(dim, A, modes.G[m]);  // column m of K_uα before B
    const Tensor2 GA = contractLeft(dim, modes.G[m], A);   // row m of K_αu before B
    for (int a = 0; a < nn; ++a)
      for (int i = 0; i < dim; ++i) {
        double su = 0.0, sa = 0.0;
        for (int J = 0; J < dim; ++J) {
          su += g.dNdX[dim * a + J] * AG[idx2(i, J)];
          sa += GA[idx2(i, J)] * g.dNdX[dim * a + J];
        }
        Kua[(dim * a + i) * nm + m] += su * g.weightedVolume;
        Kau[m * nd + dim * a + i] += sa * g.weightedVolume;
      }
  }
}

}  // namespace contessa::mechanics
