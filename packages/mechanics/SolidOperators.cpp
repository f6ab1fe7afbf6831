#include "mechanics/SolidOperators.hpp"

namespace contessa::mechanics {

Tensor2 parentJacobian(const ReferenceElement& ref, const double* xi, const double* X) {
  const int dim = ref.dimension(), nn = ref.numNodes();
  std::array<double, kMaxNodes * kMaxDimension> dNdxi{};
  ref.shapeGradients(xi, dNdxi.data());
  Tensor2 J = identity2();
  for (int Jr = 0; Jr < dim; ++Jr)
    for (int b = 0; b < dim; ++b) {
      double s = 0.0;
      for (int a = 0; a < nn; ++a) s += X[dim * a + Jr] * dNdxi[dim * a + b];
      J[idx2(Jr, b)] = s;
    }
  return J;
}

bool referenceGeometry(const ReferenceElement& ref, const double* X, std::vector<PointGeometry>& points) {
  const int dim = ref.dimension(), nn = ref.numNodes();
  const auto& rule = ref.quadrature();
  points.assign(rule.size(), PointGeometry{});
  for (std::size_t q = 0; q < rule.size(); ++q) {
    const Tensor2 J = parentJacobian(ref, rule[q].xi.data(), X);
    PointGeometry& g = points[q];
    g.detJ = determinant(J);
    if (!(g.detJ > 0.0)) return false;
    g.weightedVolume = rule[q].weight * g.detJ;
    // ∂N_a/∂X_J = ∂N_a/∂ξ_β (J⁻¹)_βJ.
    const Tensor2 Jinv = inverse(J);
    std::array<double, kMaxNodes * kMaxDimension> dNdxi{};
    ref.shapeGradients(rule[q].xi.data(), dNdxi.data());
    for (int a = 0; a < nn; ++a)
      for (int Jc = 0; Jc < dim; ++Jc) {
        double s = 0.0;
        for (int b = 0; b < dim; ++b) s += dNdxi[dim * a + b] * Jinv[idx2(b, Jc)];
        g.dNdX[dim * a + Jc] = s;
      }
  }
  return true;
}

Tensor2 displacementGradient(int dim, int nn, const PointGeometry& g, const double* u) {
  Tensor2 H{};
  for (int a = 0; a < nn; ++a)
    for (int i = 0; i < dim; ++i)
      for (int J = 0; J < dim; ++J) H[idx2(i, J)] += u[dim * a + i] * g.dNdX[dim * a + J];
  return H;
}

void addInternalForce(int dim, int nn, const PointGeometry& g, const Tensor2& P, double* f) {
  for (int a = 0; a < nn; ++a)
    for (int i = 0; i < dim; ++i) {
      double s = 0.0;
      for (int J = 0; J < dim; ++J) s += P[idx2(i, J)] * g.dNdX[dim * a + J];
      f[dim * a + i] += s * g.weightedVolume;
    }
}

void addMaterialStiffness(int dim, int nn, const PointGeometry& g, const Tensor4& A, double* K) {
  const int nd = dim * nn;
  for (int a = 0; a < nn; ++a)
    for (int i = 0; i < dim; ++i) {
      // Row (a, i): first contract ∂N_a/∂X_J into A, then sweep the columns.
      double AN[3][3] = {};  // Σ_J ∂N_a/∂X_J A_iJkL, indexed [k][L]
      for (int k = 0; k < dim; ++k)
        for (int L = 0; L < dim; ++L)
          for (int J = 0; J < dim; ++J) AN[k][L] += g.dNdX[dim * a + J] * A[idx4(i, J, k, L)];
      double* row = K + static_cast<std::size_t>(dim * a + i) * nd;
      for (int b = 0; b < nn; ++b)
        for (int k = 0; k < dim; ++k) {
          double s = 0.0;
          for (int L = 0; L < dim; ++L) s += AN[k][L] * g.dNdX[dim * b + L];
          row[dim * b + k] += s * g.weightedVolume;
        }
    }
}

}  // namespace contessa::mechanics
