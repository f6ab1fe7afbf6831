#pragma once
// Isoparametric reference elements as compile-time traits. The solid kernels (DisplacementElement,
// EnhancedStrainElement) are templates on one, so their arithmetic has fixed sizes. A shape provides
//
//   static constexpr int kDimension, kNodes, kPoints;        // D, nodes, integration points
//   static std::array<QuadraturePoint<kDimension>, kPoints> quadrature();
//   static void shapeGradients(const double* xi, double* dNdxi);  // ∂N_a/∂ξ_β at kDimension·a + β
//
// BilinearQuadrilateral (Quad4.hpp) is one; a trilinear hexahedron (2 × 2 × 2 Gauss) is another, with
// no change to the kernels. Shapes and rules are only used when an element's reference geometry is
// computed (once per element, SolidOperators.hpp), never in the residual or Jacobian loops.
#include <array>
#include <cmath>

namespace contessa::mechanics {

template <int D>
struct QuadraturePoint {
  std::array<double, D> xi{};  ///< parent coordinates
  double weight = 0.0;
};

inline constexpr int integerPower(int base, int exponent) {
  return exponent == 0 ? 1 : base * integerPower(base, exponent - 1);
}

/// Tensor-product Gauss–Legendre rule on [−1, 1]^D with n = 1, 2 or 3 points per direction (exact
/// for polynomials of degree 2n − 1 in each coordinate); ξ varies fastest, then η, then ζ.
template <int D, int n>
std::array<QuadraturePoint<D>, integerPower(n, D)> gaussLegendreRule() {
  static_assert(D >= 1 && D <= 3 && n >= 1 && n <= 3);
  const double points[3][3] = {{0.0, 0.0, 0.0},
                               {-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0), 0.0},
                               {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}};
  const double weights[3][3] = {{2.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};
  std::array<QuadraturePoint<D>, integerPower(n, D)> rule{};
  for (int q = 0; q < integerPower(n, D); ++q) {
    int rest = q;
    rule[q].weight = 1.0;
    for (int d = 0; d < D; ++d) {
      const int k = rest % n;
      rest /= n;
      rule[q].xi[d] = points[n - 1][k];
      rule[q].weight *= weights[n - 1][k];
    }
  }
  return rule;
}

}  // namespace contessa::mechanics
