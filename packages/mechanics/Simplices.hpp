#pragma once
// Triangles and tetrahedra, linear and quadratic, in the Exodus II node order, and their kernels:
// "Tri3", "Tri6" (plane strain and revolved: "Tri3 Axisymmetric", "Tri6 Axisymmetric"), "Tet4", "Tet10".
// All are DisplacementElement (no enhanced modes): the linear ones have a constant strain and lock in
// bending and near incompressibility; the quadratic ones do not lock in bending (docs/theory-solids.md §4c).
//
// Parent coordinates ξ are the last barycentric coordinates: L_0 = 1 − Σ ξ_i, L_i = ξ_i. Node order
// (Exodus TRI3/TRI6, TETRA4/TETRA10): the corners, then the mid-edge nodes of the edges
//   triangle (0,1) (1,2) (2,0);   tetrahedron (0,1) (1,2) (2,0) (0,3) (1,3) (2,3).
// Shape functions: L_a (linear); L_a (2 L_a − 1) at the corners and 4 L_a L_b on the edges (quadratic).
#include <array>
#include <memory>
#include <string>

#include "mechanics/Element.hpp"
#include "mechanics/ReferenceElement.hpp"
#include "mechanics/ShapeFunctions.hpp"

namespace contessa::mechanics {

/// A D-simplex of order 1 or 2 (Exodus order), integrated by the rule exact for the polynomial degree
/// of its stiffness on straight-sided elements: 1 point (order 1), 3 (triangle) or 4 (tetrahedron)
/// points of degree 2 (order 2). The axisymmetric linear triangle takes the 3-point rule (Points = 3):
/// with one point its hoop strain u_r / R is sampled once, and a rotation about the centroid in the
/// (r, z) plane is a second zero-energy mode besides the axial translation (the unit test counts them).
template <int D, int Order, int Points = Order == 1 ? 1 : D + 1>
struct Simplex : ShapeFromValues<Simplex<D, Order, Points>, D, Order == 1 ? D + 1 : (D + 1) * (D + 2) / 2> {
  static_assert((D == 2 || D == 3) && (Order == 1 || Order == 2));
  static constexpr int kDimension = D, kNodes = Order == 1 ? D + 1 : (D + 1) * (D + 2) / 2;
  static constexpr int kPoints = Points;
  /// The vertices of each edge, in the order of the mid-edge nodes.
  static constexpr int kEdges = D == 2 ? 3 : 6;
  static constexpr int kEdge[6][2] = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};

  static std::array<QuadraturePoint<D>, kPoints> quadrature() {
    if constexpr (D == 2)
      return triangleRule<kPoints>();
    else
      return tetrahedronRule<kPoints>();
  }
  template <class T>
  static void values(const T* xi, T* N) {
    std::array<T, D + 1> L;
    L[0] = T(1.0);
    for (int i = 0; i < D; ++i) {
      L[0] = L[0] - xi[i];
      L[i + 1] = xi[i];
    }
    if constexpr (Order == 1) {
      for (int a = 0; a <= D; ++a) N[a] = L[a];
    } else {
      for (int a = 0; a <= D; ++a) N[a] = L[a] * (2.0 * L[a] - 1.0);
      for (int e = 0; e < kEdges; ++e) N[D + 1 + e] = 4.0 * L[kEdge[e][0]] * L[kEdge[e][1]];
    }
  }
  static std::array<std::array<double, D>, kNodes> parentNodes() {
    std::array<std::array<double, D>, kNodes> x{};
    for (int i = 0; i < D; ++i) x[i + 1][i] = 1.0;
    if constexpr (Order == 2)
      for (int e = 0; e < kEdges; ++e)
        for (int i = 0; i < D; ++i) x[D + 1 + e][i] = 0.5 * (x[kEdge[e][0]][i] + x[kEdge[e][1]][i]);
    return x;
  }
};

using LinearTriangle = Simplex<2, 1>;
using LinearTriangle3Points = Simplex<2, 1, 3>;
using QuadraticTriangle = Simplex<2, 2>;
using LinearTetrahedron = Simplex<3, 1>;
using QuadraticTetrahedron = Simplex<3, 2>;

/// The kernels, under the names the registry (ElementFactory.cpp) gives them.
std::unique_ptr<ElementKernel> makeTri3(const std::string& name);
std::unique_ptr<ElementKernel> makeTri6(const std::string& name);
std::unique_ptr<ElementKernel> makeTri3Axisymmetric(const std::string& name);
std::unique_ptr<ElementKernel> makeTri6Axisymmetric(const std::string& name);
std::unique_ptr<ElementKernel> makeTet4(const std::string& name);
std::unique_ptr<ElementKernel> makeTet10(const std::string& name);

}  // namespace contessa::mechanics
