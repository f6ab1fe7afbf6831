#pragma once
// Master facets of the node-to-segment (2D) and node-to-face (3D) contact elements, written in the
// paper's surface notation (Section 2): surface coordinates ξ^α, shape functions H_i(ξ) of the master
// facet, x̄(ξ) = Σ_i H_i(ξ) x_i, covariant bases ā_α = ∂x̄/∂ξ^α (eq. 2–3) and the unit normal (eq. 5).
// Projection<Facet> and everything downstream only use this interface, so the 3D 4-node face is a sibling
// traits class, not a rewrite.
//
// Traits interface (FacetShape declares the dimensions and types; SegmentFacet, SquareFaceFacet and
// TriangleFaceFacet the normal, containment, clamping and centre of each parent domain; a family adds its
// shape functions, node layout and quadrature):
//   kSpaceDim, kSurfaceDim (number of ξ^α), kNodes
//   shapeFunctions(ξ)          -> H_i
//   shapeDerivatives(ξ)        -> H_i,α           (row i, column α)
//   shapeSecondDerivatives(ξ)  -> H_i,αβ          (one kSurfaceDim² matrix per node)
//   areaNormal(ā_1[, ā_2])     -> the normal of eq. (5) before normalisation (its length is the Jacobian)
//   unitNormal(ā_1[, ā_2])     -> n̄, eq. (5), oriented out of the master body (see each facet)
//   contains(ξ, tol)           -> ξ inside the parent domain, enlarged by tol
//   clampToDomain(ξ)           -> the point of the parent domain closest to ξ (in parent coordinates) and
//                                 its derivative ∂ξ_c/∂ξ (the free-edge fade, NodeToFacetContact.cpp)
//   boundarySegments()         -> the facet's boundary as node pairs, in order round it: the edges of a
//                                 linear facet, the halves (corner – mid-edge node) of a quadratic one's edges.
//                                 The facet selector finds edges and vertices shared by neighbours on them.
//   flatPieces()               -> the facet as kSpaceDim-node simplices (node indices, oriented like n̄):
//                                 the segment itself, two triangles of a 4-node face. Geometry that needs
//                                 a flat facet (the swept crossing test, SweptCrossing.hpp) works on these.
//   nodeCoords(i)              -> ξ of node i in the parent domain
//   kAffine                    -> x̄(ξ) is affine in ξ (a straight segment): the projection's Newton step is
//                                 exact, no start search is needed
//   kCubic                     -> x̄(ξ) has non-zero third derivatives (the serendipity and Lagrange 8- and
//                                 9-node faces, with their ξ²η and ξη² terms); such a facet also gives
//                                 shapeThirdDerivatives(ξ) -> H_i,αβγ, which the element's second variation
//                                 of ξ̄ needs (NodeToFacetContact.cpp, term (c)). The others are of total
//                                 degree ≤ 2 in ξ or multilinear, and their H_i,αβγ vanish.
//   quadrature()               -> points and weights in the parent domain, exact for ∫ H_i dA on an undistorted
//                                 facet (the slave nodes' tributary areas, ContactSurface.cpp)
//   kSubFacetTributary         -> the slave nodes' tributary areas come from the facet's linear sub-facets,
//                                 tributaryPieces() (3 or 4 node indices, −1 padding a triangle), not from
//                                 ∫ H_i dA, which is zero (Tri6) or negative (Quad8) at the corners
//                                 (docs/theory-contact.md, slave weights of quadratic faces)
//
// Facets of the faces of every cell family (node orders are those of mesh::sideNodes, Exodus corners first,
// then the mid-edge nodes of the side's edges in order, then a face centre):
//   2D: Line2Facet (Quad4, Tri3 edges), Line3Facet (Tri6, Q8, Q9 edges);
//   3D: Tri3Facet (Tet4, Wedge6 faces), Quad4Facet (Hex8, Wedge6 faces), Tri6Facet (Tet10, Wedge15 faces),
//       Quad8Facet (Hex20, Wedge15 faces), Quad9Facet (Hex27 faces).
#include "contact/SmallMatrix.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace contessa::contact {

/// One point of a facet's quadrature rule: parent coordinates and weight (the parent measure included).
template <int M>
struct SurfaceRulePoint {
  Vector<M> xi{};
  double weight = 0.0;
};

/// Gauss–Legendre rule of n = 2 or 3 points per direction on [−1, 1]^M, the last coordinate fastest.
template <int M, int n>
std::array<SurfaceRulePoint<M>, (M == 1 ? n : n * n)> gaussRuleOnSquare() {
  static_assert(n == 2 || n == 3);
  const std::array<double, 3> x = n == 2 ? std::array<double, 3>{-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0), 0.0}
                                         : std::array<double, 3>{-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const std::array<double, 3> w = n == 2 ? std::array<double, 3>{1.0, 1.0, 0.0}
                                         : std::array<double, 3>{5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  std::array<SurfaceRulePoint<M>, (M == 1 ? n : n * n)> rule{};
  for (int i = 0; i < n; ++i) {
    if constexpr (M == 1) {
      rule[i] = {{x[i]}, w[i]};
    } else {
      for (int j = 0; j < n; ++j) rule[n * i + j] = {{x[i], x[j]}, w[i] * w[j]};
    }
  }
  return rule;
}

/// The degree-2 rule on the unit triangle: (1/6, 1/6), (2/3, 1/6), (1/6, 2/3), weights 1/6 each.
inline std::array<SurfaceRulePoint<2>, 3> triangleRule3() {
  constexpr double w = 1.0 / 6.0;
  return {{{{1.0 / 6.0, 1.0 / 6.0}, w}, {{2.0 / 3.0, 1.0 / 6.0}, w}, {{1.0 / 6.0, 2.0 / 3.0}, w}}};
}

/// A point of a facet's parent domain closest to ξ (in parent coordinates) and ∂ξ_c/∂ξ there.
template <int M>
struct ClampedCoords {
  Vector<M> xi{};
  Matrix<M, M> derivative{};  ///< ∂ξ_c^β/∂ξ^α (row β): the identity inside, 0 across a clamped direction
};

/// The square [−1, 1]^M: each coordinate clamped on its own (the Euclidean closest point of a box).
template <int M>
ClampedCoords<M> clampToSquare(const Vector<M>& xi) {
  ClampedCoords<M> c;
  for (int al = 0; al < M; ++al) {
    c.xi[al] = std::clamp(xi[al], -1.0, 1.0);
    c.derivative(al, al) = c.xi[al] == xi[al] ? 1.0 : 0.0;
  }
  return c;
}

/// The unit triangle ξ^1, ξ^2 ≥ 0, ξ^1 + ξ^2 ≤ 1: outside it, the closest point of its three edges; along an
/// edge of direction d the derivative is the projector d dᵀ/‖d‖², at a corner 0.
inline ClampedCoords<2> clampToTriangle(const Vector<2>& xi) {
  ClampedCoords<2> c;
  if (xi[0] >= 0.0 && xi[1] >= 0.0 && xi[0] + xi[1] <= 1.0) {
    c.xi = xi;
    c.derivative(0, 0) = c.derivative(1, 1) = 1.0;
    return c;
  }
  constexpr std::array<std::array<double, 4>, 3> kEdges{{{0.0, 0.0, 1.0, 0.0}, {1.0, 0.0, -1.0, 1.0}, {0.0, 1.0, 0.0, -1.0}}};
  double best = std::numeric_limits<double>::infinity();
  for (const auto& e : kEdges) {
    const Vector<2> d{e[2], e[3]};
    const double d2 = dot(d, d);
    const double t = std::clamp(((xi[0] - e[0]) * d[0] + (xi[1] - e[1]) * d[1]) / d2, 0.0, 1.0);
    const Vector<2> at{e[0] + t * d[0], e[1] + t * d[1]};
    const double distance2 = dot(subtract(xi, at), subtract(xi, at));
    if (!(distance2 < best)) continue;
    best = distance2;
    c.xi = at;
    const double interior = t > 0.0 && t < 1.0 ? 1.0 / d2 : 0.0;
    for (int b = 0; b < 2; ++b)
      for (int a = 0; a < 2; ++a) c.derivative(b, a) = interior * d[b] * d[a];
  }
  return c;
}

/// What every facet family declares alike (the traits interface above): its dimensions, the types of its
/// points and of its shape functions' derivatives, and the defaults of the flags only some families set.
/// The families derive from it, through the domain bases below, and add their own mathematics.
template <int SpaceDim, int SurfaceDim, int Nodes>
struct FacetShape {
  static constexpr int kSpaceDim = SpaceDim;
  static constexpr int kSurfaceDim = SurfaceDim;
  static constexpr int kNodes = Nodes;
  using Point = Vector<SpaceDim>;
  using SurfaceCoords = Vector<SurfaceDim>;
  using First = Matrix<Nodes, SurfaceDim>;                                                ///< H_i,α
  using Second = std::array<Matrix<SurfaceDim, SurfaceDim>, Nodes>;                       ///< H_i,αβ
  using Third = std::array<std::array<Matrix<SurfaceDim, SurfaceDim>, SurfaceDim>, Nodes>;  ///< H_i,αβγ
  static constexpr bool kCubic = false;
  static constexpr bool kSubFacetTributary = false;
};

/// A master segment in 2D: ξ ∈ [−1, 1], the segment from its end node at ξ = −1 to the one at ξ = +1.
///
/// Normal convention: eq. (5) with ā_2 := e_3, the out-of-plane unit vector, i.e.
///   n̄ = ā_1 × e_3 / ‖ā_1‖ = (a_1y, −a_1x) / ‖ā_1‖.
/// When the master boundary is ordered counter-clockwise (the master body on the left of the direction
/// from end to end), this normal points OUT of the master body, so g_N > 0 is a separated slave node and
/// g_N < 0 a penetrating one, as in eq. (6). (e_3 × ā_1 would be the inward normal of such a segment.)
template <int Nodes>
struct SegmentFacet : FacetShape<2, 1, Nodes> {
  using Base = FacetShape<2, 1, Nodes>;
  using typename Base::First;
  using typename Base::Point;
  using typename Base::Second;
  using typename Base::SurfaceCoords;
  using typename Base::Third;

  static Point areaNormal(const std::array<Point, 1>& a) { return {a[0][1], -a[0][0]}; }
  static Point unitNormal(const std::array<Point, 1>& a) {
    const Point n = areaNormal(a);
    const double length = norm(n);
    return {n[0] / length, n[1] / length};
  }
  static bool contains(const SurfaceCoords& xi, double tolerance) { return std::abs(xi[0]) <= 1.0 + tolerance; }
  static ClampedCoords<1> clampToDomain(const SurfaceCoords& xi) { return clampToSquare<1>(xi); }
  static SurfaceCoords center() { return {0.0}; }

  /// One coordinate: the k-th derivatives d^k H_i/dξ^k in the layout of the traits interface (k = 1, 2, 3).
  static First asFirst(const Vector<Nodes>& h) {
    First d;
    d.entries = h;
    return d;
  }
  static Second asSecond(const Vector<Nodes>& h) {
    Second d{};
    for (int i = 0; i < Nodes; ++i) d[i](0, 0) = h[i];
    return d;
  }
  static Third asThird(const Vector<Nodes>& h) {
    Third d{};
    for (int i = 0; i < Nodes; ++i) d[i][0](0, 0) = h[i];
    return d;
  }
};

/// A master face in 3D. Normal convention: eq. (5), n̄ = ā_1 × ā_2 / ‖ā_1 × ā_2‖, which points out of the
/// master body when the face's corners run counter-clockwise seen from outside (right-hand rule), the 3D
/// analogue of the SegmentFacet convention.
template <int Nodes>
struct FaceFacet : FacetShape<3, 2, Nodes> {
  static Vector<3> areaNormal(const std::array<Vector<3>, 2>& a) { return cross(a[0], a[1]); }
  static Vector<3> unitNormal(const std::array<Vector<3>, 2>& a) {
    const Vector<3> n = areaNormal(a);
    return scaled(1.0 / norm(n), n);
  }
};

/// A face on the square [−1, 1]² (Quad4Facet, Quad8Facet, Quad9Facet).
template <int Nodes>
struct SquareFaceFacet : FaceFacet<Nodes> {
  static bool contains(const Vector<2>& xi, double tolerance) {
    return std::abs(xi[0]) <= 1.0 + tolerance && std::abs(xi[1]) <= 1.0 + tolerance;
  }
  static ClampedCoords<2> clampToDomain(const Vector<2>& xi) { return clampToSquare<2>(xi); }
  static Vector<2> center() { return {0.0, 0.0}; }
};

/// A face on the unit triangle ξ^1, ξ^2 ≥ 0, ξ^1 + ξ^2 ≤ 1, corners at (0,0), (1,0), (0,1) (Tri3Facet,
/// Tri6Facet).
template <int Nodes>
struct TriangleFaceFacet : FaceFacet<Nodes> {
  /// The unit triangle enlarged by `tolerance` across each of its three edges.
  static bool contains(const Vector<2>& xi, double tolerance) {
    return xi[0] >= -tolerance && xi[1] >= -tolerance && xi[0] + xi[1] <= 1.0 + tolerance;
  }
  static ClampedCoords<2> clampToDomain(const Vector<2>& xi) { return clampToTriangle(xi); }
  static Vector<2> center() { return {1.0 / 3.0, 1.0 / 3.0}; }
  static Vector<2> cornerCoords(int i) { return {i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0}; }
};

/// 2-node straight master segment in 2D (plane strain, the edges of Quad4 and Tri3): H_1 = (1 − ξ)/2,
/// H_2 = (1 + ξ)/2. Normal convention: SegmentFacet's (the master body on the left of node 1 → node 2).
struct Line2Facet : SegmentFacet<2> {
  static Vector<kNodes> shapeFunctions(const SurfaceCoords& xi) { return {0.5 * (1.0 - xi[0]), 0.5 * (1.0 + xi[0])}; }
  static First shapeDerivatives(const SurfaceCoords& /*xi*/) { return asFirst({-0.5, 0.5}); }
  /// A straight segment has H_i,11 = 0: no curvature, b̄_11 = 0.
  static Second shapeSecondDerivatives(const SurfaceCoords& /*xi*/) { return {}; }

  static constexpr std::array<std::array<int, 2>, 1> boundarySegments() { return {{{0, 1}}}; }
  static constexpr int kPieces = 1;
  static constexpr std::array<std::array<int, kSpaceDim>, kPieces> flatPieces() { return {{{0, 1}}}; }

  static SurfaceCoords nodeCoords(int i) { return {i == 0 ? -1.0 : 1.0}; }
  static constexpr bool kAffine = true;
  static std::array<SurfaceRulePoint<1>, 2> quadrature() { return gaussRuleOnSquare<1, 2>(); }
};

/// 4-node bilinear master face in 3D: (ξ^1, ξ^2) ∈ [−1, 1]², nodes at (−1,−1), (1,−1), (1,1), (−1,1),
/// H_i = (1 + ξ_i ξ)(1 + η_i η)/4 (the H_1..H_4 of eq. (26)). Normal convention: FaceFacet's.
struct Quad4Facet : SquareFaceFacet<4> {
  static constexpr std::array<double, 4> kNodeXi{-1.0, 1.0, 1.0, -1.0};
  static constexpr std::array<double, 4> kNodeEta{-1.0, -1.0, 1.0, 1.0};

  static Vector<kNodes> shapeFunctions(const SurfaceCoords& xi) {
    Vector<kNodes> h{};
    for (int i = 0; i < kNodes; ++i) h[i] = 0.25 * (1.0 + kNodeXi[i] * xi[0]) * (1.0 + kNodeEta[i] * xi[1]);
    return h;
  }

  static First shapeDerivatives(const SurfaceCoords& xi) {
    First d;
    for (int i = 0; i < kNodes; ++i) {
      d(i, 0) = 0.25 * kNodeXi[i] * (1.0 + kNodeEta[i] * xi[1]);
      d(i, 1) = 0.25 * kNodeEta[i] * (1.0 + kNodeXi[i] * xi[0]);
    }
    return d;
  }

  /// Bilinear: only the mixed derivative H_i,12 = ξ_i η_i / 4 is non-zero (a warped face has b̄_12 ≠ 0).
  static Second shapeSecondDerivatives(const SurfaceCoords& /*xi*/) {
    Second d{};
    for (int i = 0; i < kNodes; ++i) {
      d[i](0, 1) = 0.25 * kNodeXi[i] * kNodeEta[i];
      d[i](1, 0) = d[i](0, 1);
    }
    return d;
  }

  static constexpr std::array<std::array<int, 2>, 4> boundarySegments() { return {{{0, 1}, {1, 2}, {2, 3}, {3, 0}}}; }

  static SurfaceCoords nodeCoords(int i) { return {kNodeXi[i], kNodeEta[i]}; }
  /// A warped face is curved (b̄_12 ≠ 0), and even a flat non-parallelogram face has x̄,12 ≠ 0.
  static constexpr bool kAffine = false;
  /// 2 × 2 Gauss points, ξ^1 outer, ξ^2 inner (the order the 3D tributary areas have always been summed in).
  static std::array<SurfaceRulePoint<2>, 4> quadrature() { return gaussRuleOnSquare<2, 2>(); }

  /// Two triangles split along the diagonal node 0 – node 2, each counter-clockwise seen from outside.
  static constexpr int kPieces = 2;
  static constexpr std::array<std::array<int, kSpaceDim>, kPieces> flatPieces() { return {{{0, 1, 2}, {0, 2, 3}}}; }
};

/// The three quadratic Lagrange polynomials of one coordinate s ∈ [−1, 1] with nodes −1, +1, 0 (in this
/// order, as the corners come before the mid-edge node): values, first and second derivatives. The third
/// derivatives vanish.
struct QuadraticLagrange1D {
  static constexpr std::array<double, 3> values(double s) {
    return {0.5 * s * (s - 1.0), 0.5 * s * (s + 1.0), 1.0 - s * s};
  }
  static constexpr std::array<double, 3> first(double s) { return {s - 0.5, s + 0.5, -2.0 * s}; }
  static constexpr std::array<double, 3> second(double /*s*/) { return {1.0, 1.0, -2.0}; }
};

/// 3-node quadratic master segment in 2D (edges of Tri6, Q8, Q9): ξ ∈ [−1, 1], nodes at −1, +1 (the
/// corners) and 0 (the mid-edge node), H_i the quadratic Lagrange polynomials. Normal convention as
/// Line2Facet (the master body on the left of the direction node 1 → node 2). A curved segment: b̄_11 ≠ 0.
struct Line3Facet : SegmentFacet<3> {
  static Vector<kNodes> shapeFunctions(const SurfaceCoords& xi) { return QuadraticLagrange1D::values(xi[0]); }
  static First shapeDerivatives(const SurfaceCoords& xi) { return asFirst(QuadraticLagrange1D::first(xi[0])); }
  static Second shapeSecondDerivatives(const SurfaceCoords& xi) { return asSecond(QuadraticLagrange1D::second(xi[0])); }

  static constexpr std::array<std::array<int, 2>, 2> boundarySegments() { return {{{0, 2}, {2, 1}}}; }

  /// The two halves, corner → mid-edge node → corner.
  static constexpr int kPieces = 2;
  static constexpr std::array<std::array<int, kSpaceDim>, kPieces> flatPieces() { return {{{0, 2}, {2, 1}}}; }

  static SurfaceCoords nodeCoords(int i) { return {i == 0 ? -1.0 : i == 1 ? 1.0 : 0.0}; }
  static constexpr bool kAffine = false;
  /// 3 Gauss points: ∫ H_i ds and ∫ H_i 2π r ds exact on a straight edge with a centred mid-edge node. There
  /// ∫ H_i ds = (1/6, 1/6, 2/3) l, all positive, and a uniform gap gives the consistent load of a uniform
  /// pressure: the slave weights are these.
  static std::array<SurfaceRulePoint<1>, 3> quadrature() { return gaussRuleOnSquare<1, 3>(); }
};

/// 3-node flat master face in 3D (Tet4, Wedge6 faces): the unit triangle, nodes at its corners,
/// H = (1 − ξ^1 − ξ^2, ξ^1, ξ^2): x̄ is affine, the projection exact in one step. Normal convention as
/// Quad4Facet (counter-clockwise seen from outside).
struct Tri3Facet : TriangleFaceFacet<3> {
  static Vector<kNodes> shapeFunctions(const SurfaceCoords& xi) { return {1.0 - xi[0] - xi[1], xi[0], xi[1]}; }

  static First shapeDerivatives(const SurfaceCoords& /*xi*/) {
    First d;
    d.entries = {-1.0, -1.0, 1.0, 0.0, 0.0, 1.0};
    return d;
  }

  static Second shapeSecondDerivatives(const SurfaceCoords& /*xi*/) { return {}; }

  static constexpr std::array<std::array<int, 2>, 3> boundarySegments() { return {{{0, 1}, {1, 2}, {2, 0}}}; }

  static constexpr int kPieces = 1;
  static constexpr std::array<std::array<int, kSpaceDim>, kPieces> flatPieces() { return {{{0, 1, 2}}}; }

  static SurfaceCoords nodeCoords(int i) { return cornerCoords(i); }
  static constexpr bool kAffine = true;
  static std::array<SurfaceRulePoint<2>, 3> quadrature() { return triangleRule3(); }
};

/// 6-node quadratic master face in 3D (Tet10, Wedge15 faces): the unit triangle of Tri3Facet, corners 0–2,
/// mid-edge nodes 3 (edge 0–1), 4 (1–2), 5 (2–0). With the area coordinates L = (1 − ξ^1 − ξ^2, ξ^1, ξ^2):
/// H_corner = L_i (2 L_i − 1), H_mid = 4 L_a L_b. Total degree 2: H_i,αβ constant, H_i,αβγ = 0.
struct Tri6Facet : TriangleFaceFacet<6> {
  /// The corners of each node: a corner twice, a mid-edge node its edge's two ends.
  static constexpr std::array<std::array<int, 2>, kNodes> kEnds{{{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}}};
  /// ∂L_a/∂ξ^α (row a).
  static constexpr std::array<std::array<double, 2>, 3> kDL{{{-1.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}}};

  static Vector<3> areaCoordinates(const SurfaceCoords& xi) { return {1.0 - xi[0] - xi[1], xi[0], xi[1]}; }

  static Vector<kNodes> shapeFunctions(const SurfaceCoords& xi) {
    const Vector<3> L = areaCoordinates(xi);
    Vector<kNodes> h{};
    for (int i = 0; i < 3; ++i) h[i] = L[i] * (2.0 * L[i] - 1.0);
    for (int i = 3; i < kNodes; ++i) h[i] = 4.0 * L[kEnds[i][0]] * L[kEnds[i][1]];
    return h;
  }

  static First shapeDerivatives(const SurfaceCoords& xi) {
    const Vector<3> L = areaCoordinates(xi);
    First d;
    for (int al = 0; al < kSurfaceDim; ++al) {
      for (int i = 0; i < 3; ++i) d(i, al) = (4.0 * L[i] - 1.0) * kDL[i][al];
      for (int i = 3; i < kNodes; ++i) {
        const int a = kEnds[i][0], b = kEnds[i][1];
        d(i, al) = 4.0 * (kDL[a][al] * L[b] + L[a] * kDL[b][al]);
      }
    }
    return d;
  }

  /// H_i,αβ = 4 (L_a,α L_b,β + L_a,β L_b,α)/(1 + [a = b]): 4 L_i,α L_i,β at a corner.
  static Second shapeSecondDerivatives(const SurfaceCoords& /*xi*/) {
    Second d{};
    for (int i = 0; i < kNodes; ++i) {
      const int a = kEnds[i][0], b = kEnds[i][1];
      const double scale = a == b ? 2.0 : 4.0;
      for (int al = 0; al < kSurfaceDim; ++al)
        for (int be = 0; be < kSurfaceDim; ++be)
          d[i](al, be) = scale * (kDL[a][al] * kDL[b][be] + kDL[a][be] * kDL[b][al]);
    }
    return d;
  }

  static constexpr std::array<std::array<int, 2>, 6> boundarySegments() { return {{{0, 3}, {3, 1}, {1, 4}, {4, 2}, {2, 5}, {5, 0}}}; }

  /// Four triangles: one at each corner and the middle one of the mid-edge nodes, counter-clockwise.
  static constexpr int kPieces = 4;
  static constexpr std::array<std::array<int, kSpaceDim>, kPieces> flatPieces() {
    return {{{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}}};
  }

  static SurfaceCoords nodeCoords(int i) {
    const SurfaceCoords a = cornerCoords(kEnds[i][0]), b = cornerCoords(kEnds[i][1]);
    return {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])};
  }
  static constexpr bool kAffine = false;
  /// Exact for ∫ H_i dA on a flat face with straight edges, where it is (0, 0, 0, 1/3, 1/3, 1/3) A: no
  /// weight at the corners. The slave weights come from the four sub-triangles instead (A/12 at a corner,
  /// A/4 at a mid-edge node on such a face).
  static std::array<SurfaceRulePoint<2>, 3> quadrature() { return triangleRule3(); }
  static constexpr bool kSubFacetTributary = true;
  static constexpr std::array<std::array<int, 4>, 4> tributaryPieces() {
    return {{{0, 3, 5, -1}, {3, 1, 4, -1}, {5, 4, 2, -1}, {3, 4, 5, -1}}};
  }
};

/// 9-node biquadratic master face in 3D (Hex27 faces): [−1, 1]², corners 0–3 as Quad4Facet, mid-edge nodes
/// 4 (edge 0–1), 5 (1–2), 6 (2–3), 7 (3–0), centre 8; H_i = l_a(ξ^1) l_b(η) with the quadratic Lagrange
/// polynomials of QuadraticLagrange1D (a, b index their nodes −1, +1, 0). Its ξ²η, ξη², ξ²η² terms give
/// non-zero H_i,112, H_i,122 (kCubic).
struct Quad9Facet : SquareFaceFacet<9> {
  /// The 1D node index (0: −1, 1: +1, 2: 0) of each node along ξ^1 and along ξ^2.
  static constexpr std::array<int, kNodes> kA{0, 1, 1, 0, 2, 1, 2, 0, 2};
  static constexpr std::array<int, kNodes> kB{0, 0, 1, 1, 0, 2, 1, 2, 2};

  static Vector<kNodes> shapeFunctions(const SurfaceCoords& xi) {
    const auto u = QuadraticLagrange1D::values(xi[0]), v = QuadraticLagrange1D::values(xi[1]);
    Vector<kNodes> h{};
    for (int i = 0; i < kNodes; ++i) h[i] = u[kA[i]] * v[kB[i]];
    return h;
  }

  static First shapeDerivatives(const SurfaceCoords& xi) {
    const auto u = QuadraticLagrange1D::values(xi[0]), v = QuadraticLagrange1D::values(xi[1]);
    const auto du = QuadraticLagrange1D::first(xi[0]), dv = QuadraticLagrange1D::first(xi[1]);
    First d;
    for (int i = 0; i < kNodes; ++i) {
      d(i, 0) = du[kA[i]] * v[kB[i]];
      d(i, 1) = u[kA[i]] * dv[kB[i]];
    }
    return d;
  }

  static Second shapeSecondDerivatives(const SurfaceCoords& xi) {
    const auto u = QuadraticLagrange1D::values(xi[0]), v = QuadraticLagrange1D::values(xi[1]);
    const auto du = QuadraticLagrange1D::first(xi[0]), dv = QuadraticLagrange1D::first(xi[1]);
    const auto ddu = QuadraticLagrange1D::second(xi[0]), ddv = QuadraticLagrange1D::second(xi[1]);
    Second d{};
    for (int i = 0; i < kNodes; ++i) {
      d[i](0, 0) = ddu[kA[i]] * v[kB[i]];
      d[i](0, 1) = d[i](1, 0) = du[kA[i]] * dv[kB[i]];
      d[i](1, 1) = u[kA[i]] * ddv[kB[i]];
    }
    return d;
  }

  /// H_i,αβγ: only the mixed ones, H_i,112 = l_a'' l_b', H_i,122 = l_a' l_b'' (in every index order).
  static Third shapeThirdDerivatives(const SurfaceCoords& xi) {
    const auto du = QuadraticLagrange1D::first(xi[0]), dv = QuadraticLagrange1D::first(xi[1]);
    const auto ddu = QuadraticLagrange1D::second(xi[0]), ddv = QuadraticLagrange1D::second(xi[1]);
    Third d{};
    for (int i = 0; i < kNodes; ++i) {
      const double h112 = ddu[kA[i]] * dv[kB[i]], h122 = du[kA[i]] * ddv[kB[i]];
      d[i][0](0, 1) = d[i][0](1, 0) = d[i][1](0, 0) = h112;
      d[i][0](1, 1) = d[i][1](0, 1) = d[i][1](1, 0) = h122;
    }
    return d;
  }

  static constexpr std::array<std::array<int, 2>, 8> boundarySegments() { return {{{0, 4}, {4, 1}, {1, 5}, {5, 2}, {2, 6}, {6, 3}, {3, 7}, {7, 0}}}; }

  /// Four bilinear quarters, each as two triangles, counter-clockwise seen from outside.
  static constexpr int kPieces = 8;
  static constexpr std::array<std::array<int, kSpaceDim>, kPieces> flatPieces() {
    return {{{0, 4, 8}, {0, 8, 7}, {4, 1, 5}, {4, 5, 8}, {8, 5, 2}, {8, 2, 6}, {7, 8, 6}, {7, 6, 3}}};
  }

  static SurfaceCoords nodeCoords(int i) {
    constexpr std::array<double, 3> at{-1.0, 1.0, 0.0};
    return {at[kA[i]], at[kB[i]]};
  }
  static constexpr bool kAffine = false;
  static constexpr bool kCubic = true;
  /// 3 × 3 Gauss points: on a parallelogram ∫ H_i dA = (1/36, 1/9, 4/9) A at the corners, mid-edge nodes and
  /// centre, all positive, the consistent load of a uniform pressure: the slave weights are these.
  static std::array<SurfaceRulePoint<2>, 9> quadrature() { return gaussRuleOnSquare<2, 3>(); }
};

/// 8-node serendipity master face in 3D (Hex20, Wedge15 faces): Quad9Facet's nodes without the centre. Its
/// shape functions are Quad9Facet's with the centre's eliminated, H_i = H⁹_i + c_i H⁹_8, c = −1/4 at a
/// corner and +1/2 at a mid-edge node (which removes every ξ²η² term and keeps H_i(x_j) = δ_ij):
/// H_corner = (1 + ξ_i ξ)(1 + η_i η)(ξ_i ξ + η_i η − 1)/4, H_mid = (1 − ξ²)(1 + η_i η)/2 or (1 + ξ_i ξ)(1 − η²)/2.
/// The ξ²η and ξη² terms give non-zero H_i,112, H_i,122 (kCubic).
struct Quad8Facet : SquareFaceFacet<8> {
  static constexpr double centreShare(int i) { return i < 4 ? -0.25 : 0.5; }

  static Vector<kNodes> shapeFunctions(const SurfaceCoords& xi) {
    const auto h9 = Quad9Facet::shapeFunctions(xi);
    Vector<kNodes> h{};
    for (int i = 0; i < kNodes; ++i) h[i] = h9[i] + centreShare(i) * h9[8];
    return h;
  }

  static First shapeDerivatives(const SurfaceCoords& xi) {
    const auto d9 = Quad9Facet::shapeDerivatives(xi);
    First d;
    for (int i = 0; i < kNodes; ++i)
      for (int al = 0; al < kSurfaceDim; ++al) d(i, al) = d9(i, al) + centreShare(i) * d9(8, al);
    return d;
  }

  static Second shapeSecondDerivatives(const SurfaceCoords& xi) {
    const auto d9 = Quad9Facet::shapeSecondDerivatives(xi);
    Second d{};
    for (int i = 0; i < kNodes; ++i) {
      d[i] = d9[i];
      addScaled(d[i], centreShare(i), d9[8]);
    }
    return d;
  }

  static Third shapeThirdDerivatives(const SurfaceCoords& xi) {
    const auto d9 = Quad9Facet::shapeThirdDerivatives(xi);
    Third d{};
    for (int i = 0; i < kNodes; ++i)
      for (int al = 0; al < kSurfaceDim; ++al) {
        d[i][al] = d9[i][al];
        addScaled(d[i][al], centreShare(i), d9[8][al]);
      }
    return d;
  }

  static constexpr std::array<std::array<int, 2>, 8> boundarySegments() { return Quad9Facet::boundarySegments(); }

  /// A triangle at each corner (corner and its two mid-edge nodes) and the middle quadrilateral of the
  /// mid-edge nodes as two triangles, counter-clockwise seen from outside.
  static constexpr int kPieces = 6;
  static constexpr std::array<std::array<int, kSpaceDim>, kPieces> flatPieces() {
    return {{{0, 4, 7}, {4, 1, 5}, {5, 2, 6}, {7, 6, 3}, {4, 5, 6}, {4, 6, 7}}};
  }

  static SurfaceCoords nodeCoords(int i) { return Quad9Facet::nodeCoords(i); }
  static constexpr bool kAffine = false;
  static constexpr bool kCubic = true;
  /// 3 × 3 Gauss points: on a parallelogram ∫ H_i dA = (−1/12, 1/3) A at the corners and mid-edge nodes, negative
  /// at the corners. The slave weights come from the sub-facets instead: the corner triangles (corner and its
  /// two mid-edge nodes) and the bilinear quadrilateral of the four mid-edge nodes (A/24 at a corner, 5A/24
  /// at a mid-edge node on a parallelogram).
  static std::array<SurfaceRulePoint<2>, 9> quadrature() { return gaussRuleOnSquare<2, 3>(); }
  static constexpr bool kSubFacetTributary = true;
  static constexpr std::array<std::array<int, 4>, 5> tributaryPieces() {
    return {{{0, 4, 7, -1}, {4, 1, 5, -1}, {5, 2, 6, -1}, {7, 6, 3, -1}, {4, 5, 6, 7}}};
  }
};

/// One master facet as the contact search and the history transfer see it: an id, the global ids of its
/// nodes (to recognise shared vertices and edges between neighbours; rigid points carry negative ids) and
/// the positions of its nodes, in the facet's node order.
template <class Facet>
struct MasterFacetNodes {
  int id = -1;
  std::array<int, Facet::kNodes> nodes = unknownNodes();
  std::array<typename Facet::Point, Facet::kNodes> x{};

 private:
  static std::array<int, Facet::kNodes> unknownNodes() {
    std::array<int, Facet::kNodes> n{};
    n.fill(-1);
    return n;
  }
};

/// Every facet type, for the explicit instantiations of the templates written on the facet traits:
/// CONTESSA_FOR_EACH_FACET(M) expands to M(Line2Facet) M(Quad4Facet) … M(Quad9Facet), so that a new facet
/// family is named here once rather than in every translation unit that instantiates. HermiteLine4Facet (the
/// smoothed 2D master, SmoothedMasterFacet.hpp, included below) is a master facet only.
#define CONTESSA_FOR_EACH_FACET(M) \
  M(Line2Facet) M(Quad4Facet) M(Line3Facet) M(Tri3Facet) M(Tri6Facet) M(Quad8Facet) M(Quad9Facet) M(HermiteLine4Facet)

}  // namespace contessa::contact

#include "contact/SmoothedMasterFacet.hpp"
