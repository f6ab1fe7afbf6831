#include "contact/MortarQuadraticFacetPair.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "contact/MortarFacetGeometry.hpp"

namespace contessa::contact {

namespace {

using namespace mortar3d;
constexpr int kN = kQuadraticFacetPairCoordinates;
constexpr int kSlots = kQuadraticFacetNodes;

/// The flat pieces of a Tri6 (Tri6Facet::flatPieces, anticlockwise as the face) and the parent
/// coordinates of its nodes.
constexpr int kTri6Pieces[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};
constexpr double kTri6NodeXi[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
/// A Tri6 node's two corners (a corner twice): N_corner = L_i (2 L_i − 1), N_mid = 4 L_a L_b.
constexpr int kTri6Ends[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
/// ∂L_i/∂ξ, ∂L_i/∂η of the area coordinates L = (1 − ξ − η, ξ, η).
constexpr double kDL[3][2] = {{-1, -1}, {1, 0}, {0, 1}};

/// One face of the pair (Tri3, Quad4 or Tri6): its nodes, its parent-coordinate shape functions and
/// weights, and its flat pieces, the linear facets the segmentation works on.
template <class T>
struct QuadraticChart {
  int count = 6;
  std::array<Point3<T>, kSlots> node{};

  int pieces() const { return count == 6 ? 4 : 1; }
  /// A linear facet of this face's node count without nodes: its shape functions only (cheap to make).
  LinearFacet<double> linearShapes() const {
    LinearFacet<double> f;
    f.count = count;
    return f;
  }
  bool quadratic() const { return count == 6; }
  LinearFacet<T> piece(int i) const {
    LinearFacet<T> f;
    f.count = quadratic() ? 3 : count;
    for (int a = 0; a < f.count; ++a) f.node[a] = node[quadratic() ? kTri6Pieces[i][a] : a];
    return f;
  }
  /// The parent coordinates of a piece's local point (affine on a Tri6 piece, the identity otherwise).
  template <class S>
  std::array<S, 2> parent(int i, const std::array<S, 2>& local) const {
    if (!quadratic()) return local;
    const S l0 = 1.0 - local[0] - local[1];
    const double* p = kTri6NodeXi[kTri6Pieces[i][0]];
    const double* q = kTri6NodeXi[kTri6Pieces[i][1]];
    const double* r = kTri6NodeXi[kTri6Pieces[i][2]];
    return {l0 * p[0] + local[0] * q[0] + local[1] * r[0], l0 * p[1] + local[0] * q[1] + local[1] * r[1]};
  }
  /// The geometric shape functions N_a (Tri6: quadratic; Tri3, Quad4: LinearFacet's).
  template <class S>
  std::array<S, kSlots> shape(const std::array<S, 2>& xi) const {
    std::array<S, kSlots> n{};
    if (!quadratic()) {
      const auto linear = linearShapes().shape(xi[0], xi[1]);
      for (int a = 0; a < kLinearFacetNodes; ++a) n[a] = linear[a];
      return n;
    }
    const std::array<S, 3> L{1.0 - xi[0] - xi[1], xi[0], xi[1]};
    for (int a = 0; a < 3; ++a) n[a] = L[a] * (2.0 * L[a] - 1.0);
    for (int a = 3; a < 6; ++a) n[a] = 4.0 * L[kTri6Ends[a][0]] * L[kTri6Ends[a][1]];
    return n;
  }
  /// ∂N_a/∂ξ and ∂N_a/∂η.
  template <class S>
  std::array<std::array<S, kSlots>, 2> shapeDerivatives(const std::array<S, 2>& xi) const {
    std::array<std::array<S, kSlots>, 2> d{};
    if (!quadratic()) {
      const auto linear = linearShapes().shapeDerivatives(xi[0], xi[1]);
      for (int k = 0; k < 2; ++k)
        for (int a = 0; a < kLinearFacetNodes; ++a) d[k][a] = linear[k][a];
      return d;
    }
    const std::array<S, 3> L{1.0 - xi[0] - xi[1], xi[0], xi[1]};
    for (int k = 0; k < 2; ++k) {
      for (int a = 0; a < 3; ++a) d[k][a] = (4.0 * L[a] - 1.0) * kDL[a][k];
      for (int a = 3; a < 6; ++a) {
        const int i = kTri6Ends[a][0], j = kTri6Ends[a][1];
        d[k][a] = 4.0 * (kDL[i][k] * L[j] + L[i] * kDL[j][k]);
      }
    }
    return d;
  }
  /// The weights of the weighted gaps at a point of piece i, local coordinates `local`, parent ξ: on a
  /// Tri6 the piece's linear functions (1 − l_1 − l_2, l_1, l_2) at its three nodes (eq. M18: non-negative,
  /// a partition of unity); N_a(ξ) otherwise.
  template <class S>
  std::array<S, kSlots> weights(int i, const std::array<S, 2>& local, const std::array<S, 2>& xi) const {
    if (!quadratic()) return shape(xi);
    std::array<S, kSlots> w{};
    w[kTri6Pieces[i][0]] = 1.0 - local[0] - local[1];
    w[kTri6Pieces[i][1]] = local[0];
    w[kTri6Pieces[i][2]] = local[1];
    return w;
  }
  Point3<T> at(const std::array<T, kSlots>& n) const {
    Point3<T> p{T(0.0), T(0.0), T(0.0)};
    for (int a = 0; a < count; ++a) p = p + times(node[a], n[a]);
    return p;
  }
  Point3<T> unitNormal(const std::array<T, 2>& xi) const {
    const auto d = shapeDerivatives(xi);
    return unit(cross(at(d[0]), at(d[1])));
  }
  /// A flat piece's area (a Quad4's |d_1 × d_2| / 2).
  T pieceArea(int i) const {
    using std::sqrt;
    const Point3<T> n = piece(i).centreNormal();
    return 0.5 * sqrt(dot(n, n));
  }
  /// The summed areas of the flat pieces.
  T area() const {
    T sum(0.0);
    for (int i = 0; i < pieces(); ++i) sum = sum + pieceArea(i);
    return sum;
  }
  double diameter() const {
    double h = 0;
    for (int a = 0; a < count; ++a)
      for (int b = a + 1; b < count; ++b) {
        const Point3<double> d = values(node[a] - node[b]);
        h = std::max(h, std::sqrt(dot(d, d)));
      }
    return h;
  }
};

template <class T>
QuadraticChart<T> chartOf(const QuadraticFacetPairCoordinates<T>& x, int first, int count) {
  if (count != 3 && count != 4 && count != 6) throw std::logic_error("mortar: a face of 3, 4 or 6 nodes expected");
  QuadraticChart<T> f;
  f.count = count;
  for (int a = 0; a < count; ++a) f.node[a] = {x[3 * (first + a)], x[3 * (first + a) + 1], x[3 * (first + a) + 2]};
  return f;
}

/// One slave piece against one master piece (eq. M13–M15 on the pieces, M19 at the Gauss points): adds
/// to `out` and says whether they overlap.
template <class T>
bool addPiecePair(const QuadraticChart<T>& slave, int s, const QuadraticChart<T>& master, int m, const T& measure,
                  double size, MortarQuadraticFacetPairGaps<T>& out) {
  const LinearFacet<T> sp = slave.piece(s), mp = master.piece(m);
  const ProjectionPlane<T> plane(sp);
  if (!facing(sp, mp, plane, size)) return false;
  const std::vector<PlanePoint<T>> slavePolygon = plane.project(sp), masterProjected = plane.project(mp);
  std::vector<PlanePoint<T>> masterPolygon(masterProjected.rbegin(), masterProjected.rend());
  const T slaveArea2 = twiceSignedArea(slavePolygon);
  if (!(valueOf(twiceSignedArea(masterPolygon)) > 0.0) || !(valueOf(slaveArea2) > 0.0)) return false;
  const std::vector<PlanePoint<T>> clip = clipConvexPolygon(slavePolygon, masterPolygon, kMortarClipSnap * size);
  if (clip.size() < 3 || !(valueOf(twiceSignedArea(clip)) > kMortarSnap * valueOf(slaveArea2))) return false;
  // A triangular clip (a piece inside the master, the usual case away from the master's edges) is
  // integrated as it is, not as three triangles about its centroid: a third of the Gauss points.
  const bool triangle = clip.size() == 3;
  const PlanePoint<T> c = triangle ? clip[0] : vertexCentroid(clip);
  for (std::size_t i = triangle ? 1 : 0; i < (triangle ? 2 : clip.size()); ++i) {
    const PlanePoint<T> u = clip[i] - c, v = clip[(i + 1) % clip.size()] - c;
    const T triangleArea = 0.5 * planeCross(u, v);
    for (const TrianglePoint& q : triangleRule()) {
      const PlanePoint<T> p = c + scaled(u, q.l1) + scaled(v, q.l2);
      const std::array<T, 2> local = inverseMap(sp, slavePolygon, p), xi = slave.parent(s, local);
      const std::array<T, 2> eta = master.parent(m, inverseMap(mp, masterProjected, p));
      // eq. M19: the quadratic points and the master's normal at the parent coordinates.
      const T g = dot(slave.at(slave.shape(xi)) - master.at(master.shape(eta)), master.unitNormal(eta));
      const std::array<T, kSlots> w = slave.weights(s, local, xi);
      const T weight = q.weight * triangleArea * measure;
      for (int a = 0; a < slave.count; ++a) {
        out.weightedGap[a] = out.weightedGap[a] + weight * w[a] * g;
        out.mortarArea[a] = out.mortarArea[a] + weight * w[a];
      }
    }
  }
  return true;
}

}  // namespace

template <class T>
MortarQuadraticFacetPairGaps<T> integrateQuadraticFacetPair(const QuadraticFacetPairCoordinates<T>& x,
                                                            double referenceArea, const MortarFacetPairShape& shape) {
  MortarQuadraticFacetPairGaps<T> out;
  const QuadraticChart<T> slave = chartOf(x, 0, shape.slaveNodes), master = chartOf(x, kSlots, shape.masterNodes);
  const double size = std::max(slave.diameter(), master.diameter());
  // eq. M20: dA_0 = (A_0 / A) dA per flat piece of a Tri6 (its reference and current areas: a mid-edge
  // node sliding in the face's plane then changes no weighted gap), per face otherwise.
  for (int s = 0; s < slave.pieces(); ++s) {
    const T measure = slave.quadratic() ? shape.slavePieceAreas[s] / slave.pieceArea(s) : referenceArea / slave.area();
    for (int m = 0; m < master.pieces(); ++m)
      if (addPiecePair(slave, s, master, m, measure, size, out)) out.overlaps = true;
  }
  return out;
}

MortarQuadraticFacetPairGaps<double> facetPairGaps(const QuadraticFacetPairCoordinates<double>& x,
                                                   double referenceArea, const MortarFacetPairShape& shape) {
  return integrateQuadraticFacetPair(x, referenceArea, shape);
}

MortarQuadraticFacetPairDerivatives facetPairDerivatives(const QuadraticFacetPairCoordinates<double>& x,
                                                         double referenceArea, const MortarFacetPairShape& shape,
                                                         const double* masterMotion) {
  // A rigid master: the slave's eighteen coordinates and the motion (MortarDual.hpp, KernelVariables).
  return differentiatePairKernel<MortarQuadraticFacetPairDerivatives, 3 * kQuadraticFacetNodes>(
      x, masterMotion, [&](const auto& seeded) { return integrateQuadraticFacetPair(seeded, referenceArea, shape); });
}

namespace {
QuadraticChart<double> chartOf(const MortarFaceNodes& x, int nodes) {
  QuadraticFacetPairCoordinates<double> flat{};
  for (int a = 0; a < nodes; ++a)
    for (int c = 0; c < 3; ++c) flat[3 * a + c] = x[a][c];
  return chartOf(flat, 0, nodes);
}
}  // namespace

double mortarFacetReferenceArea(const MortarFaceNodes& x, int nodes) { return chartOf(x, nodes).area(); }

std::array<double, 4> mortarFacetPieceAreas(const MortarFaceNodes& x, int nodes) {
  const QuadraticChart<double> face = chartOf(x, nodes);
  std::array<double, 4> out{};
  for (int i = 0; i < face.pieces(); ++i) out[i] = face.pieceArea(i);
  return out;
}

std::array<double, kQuadraticFacetNodes> mortarFacetNodeAreas(const MortarFaceNodes& x, int nodes) {
  // The kernel's integral at the reference state of a face fully overlapped: each flat piece with the
  // same rule, in its own local coordinates (a Quad4 as two triangles of its parameter square).
  const QuadraticChart<double> face = chartOf(x, nodes);
  std::array<double, kQuadraticFacetNodes> out{};
  for (int i = 0; i < face.pieces(); ++i) {
    const LinearFacet<double> piece = face.piece(i);
    const bool square = piece.count == 4;
    const double corners[2][3][2] = {{{-1, -1}, {1, -1}, {1, 1}}, {{-1, -1}, {1, 1}, {-1, 1}}};
    for (int half = 0; half < (square ? 2 : 1); ++half)
      for (const TrianglePoint& q : triangleRule()) {
        std::array<double, 2> local{q.l1, q.l2};
        if (square) {
          const auto& t = corners[half];
          const double l0 = 1.0 - q.l1 - q.l2;
          local = {l0 * t[0][0] + q.l1 * t[1][0] + q.l2 * t[2][0], l0 * t[0][1] + q.l1 * t[1][1] + q.l2 * t[2][1]};
        }
        const std::array<double, 2> xi = face.parent(i, local);
        const auto d = piece.shapeDerivatives(local[0], local[1]);
        const Point3<double> n = cross(piece.at(d[0]), piece.at(d[1]));
        // |x_,ξ × x_,η| times the local triangle's area (1/2, or 2 for half the square).
        const double jacobian = std::sqrt(dot(n, n)) * (square ? 2.0 : 0.5);
        const std::array<double, kSlots> w = face.weights(i, local, xi);
        for (int a = 0; a < nodes; ++a) out[a] += q.weight * jacobian * w[a];
      }
  }
  return out;
}

}  // namespace contessa::contact
