#pragma once
// Master facets of the node-to-segment (2D) and node-to-face (3D) contact elements, written in the
// paper's surface notation (Section 2): surface coordinates ξ^α, shape functions H_i(ξ) of the master
// facet, x̄(ξ) = Σ_i H_i(ξ) x_i, covariant bases ā_α = ∂x̄/∂ξ^α (eq. 2–3) and the unit normal (eq. 5).
// Projection<Facet> and everything downstream only use this interface, so the 3D 4-node face is a sibling
// traits class, not a rewrite.
//
// Traits interface:
//   kSpaceDim, kSurfaceDim (number of ξ^α), kNodes
//   shapeFunctions(ξ)          -> H_i
//   shapeDerivatives(ξ)        -> H_i,α           (row i, column α)
//   shapeSecondDerivatives(ξ)  -> H_i,αβ          (one kSurfaceDim² matrix per node)
//   areaNormal(ā_1[, ā_2])     -> the normal of eq. (5) before normalisation (its length is the Jacobian)
//   unitNormal(ā_1[, ā_2])     -> n̄, eq. (5), oriented out of the master body (see each facet)
//   contains(ξ, tol)           -> ξ inside the parent domain, enlarged by tol
//   flatPieces()               -> the facet as kSpaceDim-node simplices (node indices, oriented like n̄):
//                                 the segment itself, two triangles of a 4-node face. Geometry that needs
//                                 a flat facet (the swept crossing test, SweptCrossing.hpp) works on these.
#include "contact/SmallMatrix.hpp"

#include <cmath>

namespace contessa::contact {

/// 2-node straight master segment in 2D (plane strain): ξ ∈ [−1, 1], H_1 = (1 − ξ)/2, H_2 = (1 + ξ)/2.
///
/// Normal convention: eq. (5) with ā_2 := e_3, the out-of-plane unit vector, i.e.
///   n̄ = ā_1 × e_3 / ‖ā_1‖ = (a_1y, −a_1x) / ‖ā_1‖.
/// When the master boundary is ordered counter-clockwise (the master body on the left of the direction
/// node 1 → node 2), this normal points OUT of the master body, so g_N > 0 is a separated slave node and
/// g_N < 0 a penetrating one, as in eq. (6). (e_3 × ā_1 would be the inward normal of such a segment.)
struct Line2Facet {
  static constexpr int kSpaceDim = 2;
  static constexpr int kSurfaceDim = 1;
  static constexpr int kNodes = 2;
  using Point = Vector<kSpaceDim>;
  using SurfaceCoords = Vector<kSurfaceDim>;

  static Vector<kNodes> shapeFunctions(const SurfaceCoords& xi) { return {0.5 * (1.0 - xi[0]), 0.5 * (1.0 + xi[0])}; }

  static Matrix<kNodes, kSurfaceDim> shapeDerivatives(const SurfaceCoords& /*xi*/) {
    Matrix<kNodes, kSurfaceDim> d;
    d(0, 0) = -0.5;
    d(1, 0) = 0.5;
    return d;
  }

  /// A straight segment has H_i,11 = 0: no curvature, b̄_11 = 0.
  static std::array<Matrix<kSurfaceDim, kSurfaceDim>, kNodes> shapeSecondDerivatives(const SurfaceCoords& /*xi*/) {
    return {};
  }

  static Point areaNormal(const std::array<Point, kSurfaceDim>& a) { return {a[0][1], -a[0][0]}; }

  static Point unitNormal(const std::array<Point, kSurfaceDim>& a) {
    const Point n = areaNormal(a);
    const double length = norm(n);
    return {n[0] / length, n[1] / length};
  }

  static bool contains(const SurfaceCoords& xi, double tolerance) { return std::abs(xi[0]) <= 1.0 + tolerance; }

  static constexpr int kPieces = 1;
  static constexpr std::array<std::array<int, kSpaceDim>, kPieces> flatPieces() { return {{{0, 1}}}; }

  static SurfaceCoords center() { return {0.0}; }
};

/// 4-node bilinear master face in 3D: (ξ^1, ξ^2) ∈ [−1, 1]², nodes at (−1,−1), (1,−1), (1,1), (−1,1),
/// H_i = (1 + ξ_i ξ)(1 + η_i η)/4 (the H_1..H_4 of eq. (26)).
///
/// Normal convention: eq. (5), n̄ = ā_1 × ā_2 / ‖ā_1 × ā_2‖, which points out of the master body when the
/// face's nodes are ordered counter-clockwise seen from outside (right-hand rule), the 3D analogue of the
/// Line2Facet convention.
struct Quad4Facet {
  static constexpr int kSpaceDim = 3;
  static constexpr int kSurfaceDim = 2;
  static constexpr int kNodes = 4;
  using Point = Vector<kSpaceDim>;
  using SurfaceCoords = Vector<kSurfaceDim>;

  static constexpr std::array<double, 4> kNodeXi{-1.0, 1.0, 1.0, -1.0};
  static constexpr std::array<double, 4> kNodeEta{-1.0, -1.0, 1.0, 1.0};

  static Vector<kNodes> shapeFunctions(const SurfaceCoords& xi) {
    Vector<kNodes> h{};
    for (int i = 0; i < kNodes; ++i) h[i] = 0.25 * (1.0 + kNodeXi[i] * xi[0]) * (1.0 + kNodeEta[i] * xi[1]);
    return h;
  }

  static Matrix<kNodes, kSurfaceDim> shapeDerivatives(const SurfaceCoords& xi) {
    Matrix<kNodes, kSurfaceDim> d;
    for (int i = 0; i < kNodes; ++i) {
      d(i, 0) = 0.25 * kNodeXi[i] * (1.0 + kNodeEta[i] * xi[1]);
      d(i, 1) = 0.25 * kNodeEta[i] * (1.0 + kNodeXi[i] * xi[0]);
    }
    return d;
  }

  /// Bilinear: only the mixed derivative H_i,12 = ξ_i η_i / 4 is non-zero (a warped face has b̄_12 ≠ 0).
  static std::array<Matrix<kSurfaceDim, kSurfaceDim>, kNodes> shapeSecondDerivatives(const SurfaceCoords& /*xi*/) {
    std::array<Matrix<kSurfaceDim, kSurfaceDim>, kNodes> d{};
    for (int i = 0; i < kNodes; ++i) {
      d[i](0, 1) = 0.25 * kNodeXi[i] * kNodeEta[i];
      d[i](1, 0) = d[i](0, 1);
    }
    return d;
  }

  static Point areaNormal(const std::array<Point, kSurfaceDim>& a) { return cross(a[0], a[1]); }

  static Point unitNormal(const std::array<Point, kSurfaceDim>& a) {
    const Point n = areaNormal(a);
    return scaled(1.0 / norm(n), n);
  }

  static bool contains(const SurfaceCoords& xi, double tolerance) {
    return std::abs(xi[0]) <= 1.0 + tolerance && std::abs(xi[1]) <= 1.0 + tolerance;
  }

  static SurfaceCoords center() { return {0.0, 0.0}; }

  /// Two triangles split along the diagonal node 0 – node 2, each counter-clockwise seen from outside.
  static constexpr int kPieces = 2;
  static constexpr std::array<std::array<int, kSpaceDim>, kPieces> flatPieces() { return {{{0, 1, 2}, {0, 2, 3}}}; }
};

}  // namespace contessa::contact
