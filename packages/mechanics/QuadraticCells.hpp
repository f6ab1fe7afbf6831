#pragma once
// Quadratic quadrilaterals and hexahedra in the Exodus II node order, and their kernels: "Q8" (8-node
// serendipity), "Q9" (9-node Lagrange; both also revolved: "Q8 Axisymmetric", "Q9 Axisymmetric") and
// "Hex20" (20-node serendipity) and "Hex27" (27-node Lagrange). DisplacementElement with full Gauss
// integration (3 × 3, 3 × 3 × 3): no spurious zero-energy mode, no bending locking (docs/theory-solids.md §4c).
//
// Node order (Exodus QUAD8/QUAD9, HEX20): the corners as in Q4 / Hex8, then the mid-edge nodes
//   quadrilateral (0,1) (1,2) (2,3) (3,0), and for Q9 the centre;
//   hexahedron    bottom (0,1) (1,2) (2,3) (3,0), vertical (0,4) (1,5) (2,6) (3,7), top (4,5) (5,6) (6,7) (7,4),
//                 and for Hex27 the centre, then the centres of the sides z = −1, z = 1, x = −1, x = 1, y = −1, y = 1.
// Serendipity functions: corners ⅟2^D Π(1 + ξ_a ξ) (Σ ξ_a ξ − D + 1); a mid-edge node with ξ_a,k = 0
// on the edge along k: ⅟2^(D−1) (1 − ξ_k²) Π_(j≠k)(1 + ξ_a,j ξ_j).
#include <array>
#include <memory>
#include <string>

#include "mechanics/Element.hpp"
#include "mechanics/ReferenceElement.hpp"
#include "mechanics/ShapeFunctions.hpp"

namespace contessa::mechanics {

/// The corners of [−1, 1]^D in the Exodus order (Q4 / Hex8).
inline constexpr double kCubeCorner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                      {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

/// The serendipity element of [−1, 1]^D (Q8 in 2D, Hex20 in 3D), 3^D Gauss points.
template <int D>
struct SerendipityCell : ShapeFromValues<SerendipityCell<D>, D, D == 2 ? 8 : 20> {
  static constexpr int kDimension = D, kNodes = D == 2 ? 8 : 20, kPoints = D == 2 ? 9 : 27;
  static constexpr int kCorners = D == 2 ? 4 : 8;
  static constexpr int kEdge[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                                       {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  static std::array<QuadraturePoint<D>, kPoints> quadrature() { return gaussLegendreRule<D, 3>(); }
  static std::array<std::array<double, D>, kNodes> parentNodes() {
    std::array<std::array<double, D>, kNodes> x{};
    for (int a = 0; a < kCorners; ++a)
      for (int i = 0; i < D; ++i) x[a][i] = kCubeCorner[a][i];
    for (int e = 0; e < kNodes - kCorners; ++e)
      for (int i = 0; i < D; ++i) x[kCorners + e][i] = 0.5 * (x[kEdge[e][0]][i] + x[kEdge[e][1]][i]);
    return x;
  }
  template <class T>
  static void values(const T* xi, T* N) {
    const auto nodes = parentNodes();
    for (int a = 0; a < kNodes; ++a) {
      T product(a < kCorners ? 1.0 / (1 << D) : 1.0 / (1 << (D - 1)));
      T sum(1.0 - D);
      for (int i = 0; i < D; ++i) {
        const double c = nodes[a][i];
        product = product * (c == 0.0 ? 1.0 - xi[i] * xi[i] : 1.0 + c * xi[i]);
        sum = sum + c * xi[i];
      }
      N[a] = a < kCorners ? product * sum : product;
    }
  }
};

/// The complete (Lagrange) quadratic cell of [−1, 1]^D: Q9 in 2D, Hex27 in 3D. Products of the 1D
/// quadratics through −1, 0, 1; 3^D Gauss points. Nodes: Q8's / Hex20's, then Q9's centre (0, 0), or
/// Hex27's centre and the centres of its sides 5, 6, 4, 2, 1, 3 (the Exodus HEX27 order, as in
/// mesh/ShapeFunctions.cpp).
template <int D>
struct LagrangeCell : ShapeFromValues<LagrangeCell<D>, D, D == 2 ? 9 : 27> {
  static constexpr int kDimension = D, kNodes = D == 2 ? 9 : 27, kPoints = D == 2 ? 9 : 27;
  static std::array<QuadraturePoint<D>, kPoints> quadrature() { return gaussLegendreRule<D, 3>(); }
  static std::array<std::array<double, D>, kNodes> parentNodes() {
    const auto serendipity = SerendipityCell<D>::parentNodes();
    std::array<std::array<double, D>, kNodes> x{};
    for (int a = 0; a < SerendipityCell<D>::kNodes; ++a) x[a] = serendipity[a];
    if constexpr (D == 3) {
      constexpr double kCentres[7][3] = {{0, 0, 0}, {0, 0, -1}, {0, 0, 1}, {-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}};
      for (int c = 0; c < 7; ++c)
        for (int i = 0; i < 3; ++i) x[20 + c][i] = kCentres[c][i];
    }
    return x;  // Q9's node 8: the centre (0, 0)
  }
  template <class T>
  static void values(const T* xi, T* N) {
    const auto nodes = parentNodes();
    for (int a = 0; a < kNodes; ++a) {
      T product(1.0);
      for (int i = 0; i < D; ++i) product = product * lagrange(nodes[a][i], xi[i]);
      N[a] = product;
    }
  }

 private:
  /// The 1D quadratic through −1, 0, 1 that is 1 at c.
  template <class T>
  static T lagrange(double c, const T& t) {
    if (c == 0.0) return 1.0 - t * t;
    return 0.5 * t * (t + c);  // c = ±1: t (t ± 1) / 2
  }
};

using SerendipityQuadrilateral = SerendipityCell<2>;
using SerendipityHexahedron = SerendipityCell<3>;
using LagrangeQuadrilateral = LagrangeCell<2>;
using LagrangeHexahedron = LagrangeCell<3>;

std::unique_ptr<ElementKernel> makeQ8(const std::string& name);
std::unique_ptr<ElementKernel> makeQ9(const std::string& name);
std::unique_ptr<ElementKernel> makeQ8Axisymmetric(const std::string& name);
std::unique_ptr<ElementKernel> makeQ9Axisymmetric(const std::string& name);
std::unique_ptr<ElementKernel> makeHex20(const std::string& name);
std::unique_ptr<ElementKernel> makeHex27(const std::string& name);

}  // namespace contessa::mechanics
