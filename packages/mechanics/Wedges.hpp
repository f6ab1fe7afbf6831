#pragma once
// Wedges (triangular prisms) in the Exodus II node order, and their kernels "Wedge6" and "Wedge15":
// the boundary-layer cells of hybrid meshes (a triangle in (ξ, η) swept along ζ ∈ [−1, 1]).
// DisplacementElement; Wedge6 locks like the linear elements, Wedge15 does not lock in bending.
//
// Node order (Exodus WEDGE6/WEDGE15): the bottom triangle's corners 0 1 2 at ζ = −1, the top 3 4 5 above
// them, then (WEDGE15) the mid-edge nodes of the bottom edges (0,1) (1,2) (2,0), the vertical edges
// (0,3) (1,4) (2,5) and the top edges (3,4) (4,5) (5,3).
// With the triangle's barycentric L_a and ζ_± = 1 ± ζ:
//   Wedge6   ½ L_a ζ_±
//   Wedge15  corners ½ L_a [(2 L_a − 1) ζ_± − (1 − ζ²)], triangle edges 2 L_a L_b ζ_±, vertical edges
//            L_a (1 − ζ²)   (serendipity; Zienkiewicz & Taylor vol. 1, §6.6).
// Integration: the 3-point triangle rule times 2 (Wedge6) or 3 (Wedge15) Gauss points in ζ.
#include <array>
#include <memory>
#include <string>

#include "mechanics/Element.hpp"
#include "mechanics/ReferenceElement.hpp"
#include "mechanics/ShapeFunctions.hpp"

namespace contessa::mechanics {

template <int Order>
struct Wedge : ShapeFromValues<Wedge<Order>, 3, Order == 1 ? 6 : 15> {
  static_assert(Order == 1 || Order == 2);
  static constexpr int kDimension = 3, kNodes = Order == 1 ? 6 : 15, kPoints = Order == 1 ? 6 : 9;
  static constexpr int kEdge[9][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 4}, {2, 5}, {3, 4}, {4, 5}, {5, 3}};
  static std::array<QuadraturePoint<3>, kPoints> quadrature() { return wedgeRule<3, Order + 1>(); }
  static std::array<std::array<double, 3>, kNodes> parentNodes() {
    std::array<std::array<double, 3>, kNodes> x{};
    const double triangle[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    for (int a = 0; a < 6; ++a) x[a] = {triangle[a % 3][0], triangle[a % 3][1], a < 3 ? -1.0 : 1.0};
    if constexpr (Order == 2)
      for (int e = 0; e < 9; ++e)
        for (int i = 0; i < 3; ++i) x[6 + e][i] = 0.5 * (x[kEdge[e][0]][i] + x[kEdge[e][1]][i]);
    return x;
  }
  template <class T>
  static void values(const T* xi, T* N) {
    const T L[3] = {1.0 - xi[0] - xi[1], xi[0], xi[1]};
    const T zeta[2] = {1.0 - xi[2], 1.0 + xi[2]};  // ζ_−, ζ_+
    if constexpr (Order == 1) {
      for (int a = 0; a < 6; ++a) N[a] = 0.5 * L[a % 3] * zeta[a / 3];
    } else {
      const T bubble = 1.0 - xi[2] * xi[2];
      for (int a = 0; a < 6; ++a) N[a] = 0.5 * L[a % 3] * ((2.0 * L[a % 3] - 1.0) * zeta[a / 3] - bubble);
      for (int e = 0; e < 3; ++e) {
        N[6 + e] = 2.0 * L[kEdge[e][0]] * L[kEdge[e][1]] * zeta[0];
        N[9 + e] = L[e] * bubble;
        N[12 + e] = 2.0 * L[kEdge[e][0]] * L[kEdge[e][1]] * zeta[1];
      }
    }
  }
};

using LinearWedge = Wedge<1>;
using QuadraticWedge = Wedge<2>;

std::unique_ptr<ElementKernel> makeWedge6(const std::string& name);
std::unique_ptr<ElementKernel> makeWedge15(const std::string& name);

}  // namespace contessa::mechanics
