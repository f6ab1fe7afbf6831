#pragma once
// Isoparametric reference elements: shape-function gradients on the parent domain [−1, 1]^d and
// their Gauss rule. The solid kernels (DisplacementElement, EnhancedStrainElement) only see this
// interface, so a trilinear Hex8 is one more ReferenceElement (next to BilinearQuadrilateral in
// Quad4.hpp), not a new kernel.
#include <array>
#include <vector>

namespace contessa::mechanics {

inline constexpr int kMaxDimension = 3;
inline constexpr int kMaxNodes = 8;  ///< Hex8

struct QuadraturePoint {
  std::array<double, 3> xi{};  ///< parent coordinates (unused entries 0)
  double weight = 0.0;
};

/// Tensor-product Gauss–Legendre rule on [−1, 1]^dimension, n = 1, 2 or 3 points per direction
/// (exact for polynomials of degree 2n − 1 in each coordinate).
std::vector<QuadraturePoint> gaussLegendreRule(int dimension, int pointsPerDirection);

class ReferenceElement {
 public:
  virtual ~ReferenceElement() = default;
  virtual int dimension() const = 0;
  virtual int numNodes() const = 0;
  /// ∂N_a/∂ξ_β at index dimension()·a + β.
  virtual void shapeGradients(const double* xi, double* dNdxi) const = 0;
  /// The full integration rule of the element.
  virtual const std::vector<QuadraturePoint>& quadrature() const = 0;
};

}  // namespace contessa::mechanics
