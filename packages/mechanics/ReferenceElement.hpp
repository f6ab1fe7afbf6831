#pragma once
// Isoparametric reference elements as compile-time traits. The solid kernels (DisplacementElement,
// EnhancedStrainElement) are templates on one, so their arithmetic has fixed sizes. A shape provides
//
//   static constexpr int kDimension, kNodes, kPoints;        // D, nodes, integration points
//   static std::array<QuadraturePoint<kDimension>, kPoints> quadrature();
//   static void shapeGradients(const double* xi, double* dNdxi);  // ∂N_a/∂ξ_β at kDimension·a + β
//   static void shapeValues(const double* xi, double* N);         // N_a (axisymmetric radius, tests)
//   static std::array<std::array<double, kDimension>, kNodes> parentNodes();  // ξ of each node
//
// BilinearQuadrilateral (Quad4.hpp) is one; TrilinearHexahedron (Hex8.hpp, 2 × 2 × 2 Gauss) is another, with
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

/// Symmetric rules on the unit triangle {ξ, η ≥ 0, ξ + η ≤ 1} (area ½): n = 1 (centroid, exact for
/// degree 1) or n = 3 (the mid-edge-interior points (⅙, ⅙), (⅔, ⅙), (⅙, ⅔), exact for degree 2;
/// Zienkiewicz & Taylor vol. 1, table 6.3).
template <int n>
std::array<QuadraturePoint<2>, n> triangleRule() {
  static_assert(n == 1 || n == 3);
  std::array<QuadraturePoint<2>, n> rule{};
  if constexpr (n == 1) {
    rule[0] = {{1.0 / 3.0, 1.0 / 3.0}, 0.5};
  } else {
    rule[0] = {{1.0 / 6.0, 1.0 / 6.0}, 1.0 / 6.0};
    rule[1] = {{2.0 / 3.0, 1.0 / 6.0}, 1.0 / 6.0};
    rule[2] = {{1.0 / 6.0, 2.0 / 3.0}, 1.0 / 6.0};
  }
  return rule;
}

/// Symmetric rules on the unit tetrahedron (volume ⅙): n = 1 (centroid, degree 1) or n = 4 (the points
/// with barycentric coordinates (a, b, b, b) and permutations, a = (5 + 3√5)/20, b = (5 − √5)/20,
/// degree 2; Zienkiewicz & Taylor vol. 1, table 6.4).
template <int n>
std::array<QuadraturePoint<3>, n> tetrahedronRule() {
  static_assert(n == 1 || n == 4);
  std::array<QuadraturePoint<3>, n> rule{};
  if constexpr (n == 1) {
    rule[0] = {{0.25, 0.25, 0.25}, 1.0 / 6.0};
  } else {
    const double a = (5.0 + 3.0 * std::sqrt(5.0)) / 20.0, b = (5.0 - std::sqrt(5.0)) / 20.0;
    rule[0] = {{b, b, b}, 1.0 / 24.0};
    rule[1] = {{a, b, b}, 1.0 / 24.0};
    rule[2] = {{b, a, b}, 1.0 / 24.0};
    rule[3] = {{b, b, a}, 1.0 / 24.0};
  }
  return rule;
}

/// The product of the triangle rule (n points) in (ξ, η) and the Gauss–Legendre rule (m points) in ζ
/// ∈ [−1, 1]: rules on the wedge (prism), ζ fastest.
template <int n, int m>
std::array<QuadraturePoint<3>, n * m> wedgeRule() {
  const auto triangle = triangleRule<n>();
  const auto line = gaussLegendreRule<1, m>();
  std::array<QuadraturePoint<3>, n * m> rule{};
  for (int t = 0; t < n; ++t)
    for (int l = 0; l < m; ++l)
      rule[m * t + l] = {{triangle[t].xi[0], triangle[t].xi[1], line[l].xi[0]}, triangle[t].weight * line[l].weight};
  return rule;
}

}  // namespace contessa::mechanics
