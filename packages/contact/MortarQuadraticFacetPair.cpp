#include "contact/MortarQuadraticFacetPair.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "contact/MortarFacetGeometry.hpp"

namespace contessa::contact {

namespace {

using namespace mortar3d;

/// A flat piece of a quadratic face: 3 or 4 of its nodes, anticlockwise as the face.
struct FlatPiece {
  int count;
  int node[4];
};
/// The pieces (eq. M20): a Tri6's four triangles (Tri6Facet::flatPieces); a Quad8's corner triangles and
/// the quadrilateral of its mid-edge nodes (Quad8Facet::tributaryPieces, the node-to-face weights' pieces:
/// every piece through nodes of the face, none through a point the serendipity element does not have);
/// a Quad9's four quarters about its centre node.
constexpr FlatPiece kTri6Pieces[4] = {{3, {0, 3, 5, -1}}, {3, {3, 1, 4, -1}}, {3, {5, 4, 2, -1}}, {3, {3, 4, 5, -1}}};
constexpr FlatPiece kQuad8Pieces[5] = {
    {3, {0, 4, 7, -1}}, {3, {4, 1, 5, -1}}, {3, {5, 2, 6, -1}}, {3, {7, 6, 3, -1}}, {4, {4, 5, 6, 7}}};
constexpr FlatPiece kQuad9Pieces[4] = {{4, {0, 4, 8, 7}}, {4, {4, 1, 5, 8}}, {4, {8, 5, 2, 6}}, {4, {7, 8, 6, 3}}};
/// The parent coordinates of a Tri6's and of a Quad8's or Quad9's nodes.
constexpr double kTri6NodeXi[6][2] = {{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}};
constexpr double kQuadNodeXi[9][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {0, -1}, {1, 0}, {0, 1}, {-1, 0}, {0, 0}};
/// A Tri6 node's two corners (a corner twice): N_corner = L_i (2 L_i − 1), N_mid = 4 L_a L_b.
constexpr int kTri6Ends[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};
/// ∂L_i/∂ξ, ∂L_i/∂η of the area coordinates L = (1 − ξ − η, ξ, η).
constexpr double kDL[3][2] = {{-1, -1}, {1, 0}, {0, 1}};
/// A Quad9 node's 1D Lagrange polynomials along ξ and η (0: node −1, 1: node +1, 2: node 0;
/// Quad9Facet::kA, kB); a Quad8 node's shape function is its Quad9 one plus c_a times the centre's
/// (c = −1/4 at a corner, +1/2 at a mid-edge node: Quad8Facet::centreShare).
constexpr int kQuadA[9] = {0, 1, 1, 0, 2, 1, 2, 0, 2};
constexpr int kQuadB[9] = {0, 0, 1, 1, 0, 2, 1, 2, 2};
constexpr double quad8CentreShare(int a) { return a < 4 ? -0.25 : 0.5; }

/// The quadratic Lagrange polynomials through −1, +1, 0 and their derivatives.
template <class S>
std::array<S, 3> lagrange(const S& s) {
  return {0.5 * s * (s - 1.0), 0.5 * s * (s + 1.0), 1.0 - s * s};
}
template <class S>
std::array<S, 3> lagrangeDerivative(const S& s) {
  return {s - 0.5, s + 0.5, -2.0 * s};
}

/// One face of the pair (Tri3, Quad4, Tri6, Quad8 or Quad9): its nodes, its parent-coordinate shape
/// functions and weights, and its flat pieces, the linear facets the segmentation works on.
template <class T, int Slots>
struct QuadraticChart {
  int count = 6;
  std::array<Point3<T>, Slots> node{};

  bool quadratic() const { return count >= 6; }
  int pieces() const { return mortarFacePieces(count); }
  const FlatPiece& pieceNodes(int i) const { return count == 6 ? kTri6Pieces[i] : count == 8 ? kQuad8Pieces[i] : kQuad9Pieces[i]; }
  /// The parent coordinates of node a.
  const double* nodeXi(int a) const { return count == 6 ? kTri6NodeXi[a] : kQuadNodeXi[a]; }
  /// A linear facet of n nodes without nodes: its shape functions only (cheap to make).
  static LinearFacet<double> linearShapes(int n) {
    LinearFacet<double> f;
    f.count = n;
    return f;
  }
  LinearFacet<T> piece(int i) const {
    LinearFacet<T> f;
    if (!quadratic()) {
      f.count = count;
      for (int a = 0; a < count; ++a) f.node[a] = node[a];
      return f;
    }
    const FlatPiece& p = pieceNodes(i);
    f.count = p.count;
    for (int a = 0; a < p.count; ++a) f.node[a] = node[p.node[a]];
    return f;
  }
  /// The parent coordinates of a piece's local point: the piece's own (linear or bilinear) functions of
  /// its nodes' parent coordinates, affine on every piece (the Quad9 quarters and the Quad8's middle
  /// quadrilateral are parallelograms in the parent square); the identity on a linear face.
  template <class S>
  std::array<S, 2> parent(int i, const std::array<S, 2>& local) const {
    if (!quadratic()) return local;
    const FlatPiece& p = pieceNodes(i);
    const auto n = linearShapes(p.count).shape(local[0], local[1]);
    std::array<S, 2> xi{S(0.0), S(0.0)};
    for (int a = 0; a < p.count; ++a) {
      const double* at = nodeXi(p.node[a]);
      xi[0] = xi[0] + n[a] * at[0], xi[1] = xi[1] + n[a] * at[1];
    }
    return xi;
  }
  /// The geometric shape functions N_a (quadratic faces: their own; Tri3, Quad4: LinearFacet's).
  template <class S>
  std::array<S, Slots> shape(const std::array<S, 2>& xi) const {
    std::array<S, Slots> n{};
    if (!quadratic()) {
      const auto linear = linearShapes(count).shape(xi[0], xi[1]);
      for (int a = 0; a < kLinearFacetNodes; ++a) n[a] = linear[a];
      return n;
    }
    if (count == 6) {
      const std::array<S, 3> L{1.0 - xi[0] - xi[1], xi[0], xi[1]};
      for (int a = 0; a < 3; ++a) n[a] = L[a] * (2.0 * L[a] - 1.0);
      for (int a = 3; a < 6; ++a) n[a] = 4.0 * L[kTri6Ends[a][0]] * L[kTri6Ends[a][1]];
      return n;
    }
    const auto u = lagrange(xi[0]), v = lagrange(xi[1]);
    const S centre = u[2] * v[2];
    for (int a = 0; a < count; ++a) n[a] = u[kQuadA[a]] * v[kQuadB[a]] + (count == 8 ? quad8CentreShare(a) * centre : S(0.0));
    return n;
  }
  /// ∂N_a/∂ξ and ∂N_a/∂η.
  template <class S>
  std::array<std::array<S, Slots>, 2> shapeDerivatives(const std::array<S, 2>& xi) const {
    std::array<std::array<S, Slots>, 2> d{};
    if (!quadratic()) {
      const auto linear = linearShapes(count).shapeDerivatives(xi[0], xi[1]);
      for (int k = 0; k < 2; ++k)
        for (int a = 0; a < kLinearFacetNodes; ++a) d[k][a] = linear[k][a];
      return d;
    }
    if (count == 6) {
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
    const auto u = lagrange(xi[0]), v = lagrange(xi[1]);
    const auto du = lagrangeDerivative(xi[0]), dv = lagrangeDerivative(xi[1]);
    const S centre0 = du[2] * v[2], centre1 = u[2] * dv[2];
    for (int a = 0; a < count; ++a) {
      const double share = count == 8 ? quad8CentreShare(a) : 0.0;
      d[0][a] = du[kQuadA[a]] * v[kQuadB[a]] + share * centre0;
      d[1][a] = u[kQuadA[a]] * dv[kQuadB[a]] + share * centre1;
    }
    return d;
  }
  /// The weights of the weighted gaps at a point of piece i, local coordinates `local`, parent ξ: on a
  /// quadratic face the piece's linear or bilinear functions at its nodes (eq. M18: non-negative, a
  /// partition of unity); N_a(ξ) otherwise.
  template <class S>
  std::array<S, Slots> weights(int i, const std::array<S, 2>& local, const std::array<S, 2>& xi) const {
    if (!quadratic()) return shape(xi);
    const FlatPiece& p = pieceNodes(i);
    const auto hat = linearShapes(p.count).shape(local[0], local[1]);
    std::array<S, Slots> w{};
    for (int a = 0; a < p.count; ++a) w[p.node[a]] = hat[a];
    return w;
  }
  Point3<T> at(const std::array<T, Slots>& n) const {
    Point3<T> p{T(0.0), T(0.0), T(0.0)};
    for (int a = 0; a < count; ++a) p = p + times(node[a], n[a]);
    return p;
  }
  Point3<T> unitNormal(const std::array<T, 2>& xi) const {
    const auto d = shapeDerivatives(xi);
    return unit(cross(at(d[0]), at(d[1])));
  }
  /// The index of piece i's first reference measure (mortarFaceMeasures: one per triangle, three per 4-node
  /// piece).
  int measureOffset(int i) const {
    int offset = 0;
    for (int k = 0; k < i; ++k) offset += pieceNodes(k).count == 3 ? 1 : 3;
    return offset;
  }
  /// A flat piece's area (a 4-node piece's |d_1 × d_2| / 2: the area of its projection on its plane).
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

template <class T, int Slots>
QuadraticChart<T, Slots> chartOf(const QuadraticFacetPairCoordinates<T, Slots>& x, int first, int count) {
  if (count != 3 && count != 4 && count != 6 && count != 8 && count != 9)
    throw std::logic_error("mortar: a face of 3, 4, 6, 8 or 9 nodes expected");
  if (count > Slots) throw std::logic_error("mortar: a face of more nodes than the pair layout's slots");
  QuadraticChart<T, Slots> f;
  f.count = count;
  for (int a = 0; a < count; ++a) f.node[a] = {x[3 * (first + a)], x[3 * (first + a) + 1], x[3 * (first + a) + 2]};
  return f;
}

/// A piece's projected Jacobian (x_,l1 × x_,l2) · n at local coordinates l: the area of its projection on
/// the plane of normal n per unit local area.
template <class T, class S>
T projectedJacobian(const LinearFacet<T>& piece, const Point3<T>& normal, const S& l1, const S& l2) {
  const auto d = piece.shapeDerivatives(l1, l2);
  return dot(cross(piece.at(d[0]), piece.at(d[1])), normal);
}

/// The measure dA_0 / dA of a slave piece (eq. M20): a constant ratio (a triangle piece, A_0 / A; a linear
/// face, its reference area over its current one), or on a 4-node piece of a quadratic face J_0(l) / J(l),
/// the reference Jacobian (j_0 + j_1 l_1 + j_2 l_2) over the current one at the point. Pointwise, not A_0 / A
/// for the piece: a bilinear piece's nodal integrals ∫ Φ_a dA change with its shape (a parallelogram made a
/// trapezoid moves area between its nodes), so a mid-edge node sliding in the face's plane would change the
/// weighted gaps of a uniform gap; with J_0 / J they are integrals over the reference piece.
template <class T>
struct PieceMeasure {
  T ratio;
  const double* jacobian = nullptr;  ///< (j_0, j_1, j_2) of a 4-node piece of a quadratic face
  template <class Piece, class Plane>
  T at(const Piece& piece, const Plane& plane, const std::array<T, 2>& local) const {
    if (jacobian == nullptr) return ratio;
    return (jacobian[0] + jacobian[1] * local[0] + jacobian[2] * local[1]) /
           projectedJacobian(piece, plane.normal, local[0], local[1]);
  }
};

/// The committed position Σ N_a(ξ) X_a of the face point with shape values n (X_a: the committed nodes
/// first … first + count − 1, constants).
template <class T, int Slots>
Point3<T> committedPoint(const QuadraticFacetPairCommitted<Slots>& then, int first, int count, const std::array<T, Slots>& n) {
  Point3<T> p{T(0.0), T(0.0), T(0.0)};
  for (int a = 0; a < count; ++a) {
    const double* X = &then[3 * (first + a)];
    p = p + Point3<T>{n[a] * X[0], n[a] * X[1], n[a] * X[2]};
  }
  return p;
}

/// One slave piece against one master piece (eq. M13–M15 on the pieces, M19 at the Gauss points, M21 with
/// `committed`): adds to `out` and says whether they overlap.
template <class T, int Slots>
bool addPiecePair(const QuadraticChart<T, Slots>& slave, int s, const QuadraticChart<T, Slots>& master, int m,
                  const PieceMeasure<T>& measure, double size, const QuadraticFacetPairCommitted<Slots>* committed,
                  MortarQuadraticFacetPairGaps<T, Slots>& out) {
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
      const std::array<T, Slots> slaveShape = slave.shape(xi), masterShape = master.shape(eta);
      const Point3<T> xs = slave.at(slaveShape), xm = master.at(masterShape), normal = master.unitNormal(eta);
      const T g = dot(xs - xm, normal);
      const std::array<T, Slots> w = slave.weights(s, local, xi);
      const T weight = q.weight * triangleArea * measure.at(sp, plane, local);
      for (int a = 0; a < slave.count; ++a) {
        out.weightedGap[a] = out.weightedGap[a] + weight * w[a] * g;
        out.mortarArea[a] = out.mortarArea[a] + weight * w[a];
      }
      if (committed == nullptr) continue;
      // eq. M21: the relative motion over the increment of the slave point ξ and the master point η it
      // sees (material points of the quadratic faces, both moved from their committed positions), less its
      // part along n_m(η): the tangential slip, weighted with the gaps' Φ_a.
      const Point3<T> motion = (xs - committedPoint<T, Slots>(*committed, 0, slave.count, slaveShape)) -
                               (xm - committedPoint<T, Slots>(*committed, Slots, master.count, masterShape));
      const Point3<T> u = motion - times(normal, dot(motion, normal));
      std::array<T, Slots> wa{};
      for (int a = 0; a < slave.count; ++a) {
        wa[a] = weight * w[a];
        std::array<T, 3>& slip = out.weightedSlip[a];
        slip = {slip[0] + wa[a] * u.x, slip[1] + wa[a] * u.y, slip[2] + wa[a] * u.z};
      }
      if constexpr (!std::is_same_v<T, double>) {  // the virtual slips (MortarSlipVariation.hpp, eq. M11″)
        using Term = typename SlipVariationSum<T>::Term;
        std::array<Term, 2 * Slots> terms;
        int count = 0;
        for (int j = 0; j < slave.count; ++j)
          terms[count++] = {&slaveShape[j], {&slave.node[j].x, &slave.node[j].y, &slave.node[j].z}, 1.0};
        for (int l = 0; l < master.count; ++l)
          terms[count++] = {&masterShape[l], {&master.node[l].x, &master.node[l].y, &master.node[l].z}, -1.0};
        constexpr int V = kVariables<T>;
        const auto rows = tangentialProjectorRows<V>({firstOrder(normal.x), firstOrder(normal.y), firstOrder(normal.z)});
        out.slipVariation.template add<3, 3>(Slots, wa.data(), slave.count, rows, terms.data(), count);
      }
    }
  }
  return true;
}

}  // namespace

template <class T, int Slots>
MortarQuadraticFacetPairGaps<T, Slots> integrateQuadraticFacetPair(const QuadraticFacetPairCoordinates<T, Slots>& x,
                                                                   double referenceArea, const MortarFacetPairShape& shape,
                                                                   const QuadraticFacetPairCommitted<Slots>* committed) {
  MortarQuadraticFacetPairGaps<T, Slots> out;
  const QuadraticChart<T, Slots> slave = chartOf<T, Slots>(x, 0, shape.slaveNodes);
  const QuadraticChart<T, Slots> master = chartOf<T, Slots>(x, Slots, shape.masterNodes);
  const double size = std::max(slave.diameter(), master.diameter());
  // eq. M20: dA_0 = (A_0 / A) dA per flat triangle of a quadratic face, (J_0 / J) dA on its 4-node pieces
  // (a mid-edge node sliding in the face's plane then changes no weighted gap), per face otherwise.
  for (int s = 0; s < slave.pieces(); ++s) {
    PieceMeasure<T> measure{T(0.0)};
    if (!slave.quadratic())
      measure.ratio = referenceArea / slave.area();
    else if (slave.pieceNodes(s).count == 3)
      measure.ratio = shape.slavePieceAreas[slave.measureOffset(s)] / slave.pieceArea(s);
    else
      measure.jacobian = &shape.slavePieceAreas[slave.measureOffset(s)];
    for (int m = 0; m < master.pieces(); ++m)
      if (addPiecePair(slave, s, master, m, measure, size, committed, out)) out.overlaps = true;
  }
  return out;
}

namespace {
template <int Slots>
MortarQuadraticFacetPairGaps<double, Slots> gapsOf(const QuadraticFacetPairCoordinates<double, Slots>& x,
                                                    double referenceArea, const MortarFacetPairShape& shape,
                                                    const QuadraticFacetPairCommitted<Slots>* committed) {
  return integrateQuadraticFacetPair<double, Slots>(x, referenceArea, shape, committed);
}
/// The pair with its slip increments (friction) differentiated over `variables`: as
/// differentiatePairKernel (MortarDual.hpp), plus Δũ_a's three components (MortarFacetPair.cpp's
/// differentiateWithSlip on the quadratic layouts).
template <int Slots, int V>
MortarQuadraticPairDerivatives<Slots> differentiateWithSlip(const QuadraticFacetPairCoordinates<double, Slots>& x,
                                                            double referenceArea, const MortarFacetPairShape& shape,
                                                            const QuadraticFacetPairCommitted<Slots>& committed,
                                                            const KernelVariables<3 * 2 * Slots>& variables) {
  constexpr int kC = 3 * 2 * Slots;
  std::vector<std::array<HessianDual<V>, kC>> seeded(1, variables.template seed<V>(x));  // large: on the heap
  const auto g = integrateQuadraticFacetPair<HessianDual<V>, Slots>(seeded[0], referenceArea, shape, &committed);
  MortarQuadraticPairDerivatives<Slots> out;
  extractGapsAndSlips<Slots>(g, variables, out);
  extractSlipVariation<kC, V>(g.slipVariation, variables, Slots, 3, out.slipVariation, out.slipVariationGradient);
  return out;
}
template <int Slots>
MortarQuadraticPairDerivatives<Slots> derivativesOf(const QuadraticFacetPairCoordinates<double, Slots>& x,
                                                    double referenceArea, const MortarFacetPairShape& shape,
                                                    const double* masterMotion,
                                                    const QuadraticFacetPairCommitted<Slots>* committed) {
  constexpr int kC = 3 * 2 * Slots, kFirstMaster = 3 * Slots;
  if (committed != nullptr) {
    if (masterMotion == nullptr)
      return differentiateWithSlip<Slots, kC>(x, referenceArea, shape, *committed, ownVariables<kC>());
    return differentiateWithSlip<Slots, kFirstMaster + 1>(x, referenceArea, shape, *committed,
                                                          rigidBodyVariables<kC>(kFirstMaster, kFirstMaster, masterMotion));
  }
  // A rigid master: the slave's coordinates and the motion (MortarDual.hpp, KernelVariables).
  return differentiatePairKernel<MortarQuadraticPairDerivatives<Slots>, kFirstMaster>(
      x, masterMotion, [&](const auto& seeded) {
        using Number = typename std::decay_t<decltype(seeded)>::value_type;
        return integrateQuadraticFacetPair<Number, Slots>(seeded, referenceArea, shape);
      });
}
}  // namespace

MortarQuadraticFacetPairGaps<double, 6> facetPairGaps(const QuadraticFacetPairCoordinates<double, 6>& x,
                                                      double referenceArea, const MortarFacetPairShape& shape,
                                                      const QuadraticFacetPairCommitted<6>* committed) {
  return gapsOf<6>(x, referenceArea, shape, committed);
}
MortarQuadraticFacetPairGaps<double, 8> facetPairGaps(const QuadraticFacetPairCoordinates<double, 8>& x,
                                                      double referenceArea, const MortarFacetPairShape& shape,
                                                      const QuadraticFacetPairCommitted<8>* committed) {
  return gapsOf<8>(x, referenceArea, shape, committed);
}
MortarQuadraticFacetPairGaps<double, 9> facetPairGaps(const QuadraticFacetPairCoordinates<double, 9>& x,
                                                      double referenceArea, const MortarFacetPairShape& shape,
                                                      const QuadraticFacetPairCommitted<9>* committed) {
  return gapsOf<9>(x, referenceArea, shape, committed);
}
MortarQuadraticPairDerivatives<6> facetPairDerivatives(const QuadraticFacetPairCoordinates<double, 6>& x,
                                                       double referenceArea, const MortarFacetPairShape& shape,
                                                       const double* masterMotion,
                                                       const QuadraticFacetPairCommitted<6>* committed) {
  return derivativesOf<6>(x, referenceArea, shape, masterMotion, committed);
}
MortarQuadraticPairDerivatives<8> facetPairDerivatives(const QuadraticFacetPairCoordinates<double, 8>& x,
                                                       double referenceArea, const MortarFacetPairShape& shape,
                                                       const double* masterMotion,
                                                       const QuadraticFacetPairCommitted<8>* committed) {
  return derivativesOf<8>(x, referenceArea, shape, masterMotion, committed);
}
MortarQuadraticPairDerivatives<9> facetPairDerivatives(const QuadraticFacetPairCoordinates<double, 9>& x,
                                                       double referenceArea, const MortarFacetPairShape& shape,
                                                       const double* masterMotion,
                                                       const QuadraticFacetPairCommitted<9>* committed) {
  return derivativesOf<9>(x, referenceArea, shape, masterMotion, committed);
}

namespace {
using FaceChart = QuadraticChart<double, kMaxMortarFaceNodes>;
FaceChart chartOf(const MortarFaceNodes& x, int nodes) {
  QuadraticFacetPairCoordinates<double, kMaxMortarFaceNodes> flat{};
  for (int a = 0; a < nodes; ++a)
    for (int c = 0; c < 3; ++c) flat[3 * a + c] = x[a][c];
  return chartOf<double, kMaxMortarFaceNodes>(flat, 0, nodes);
}

/// ∫ Φ_a dA over flat piece i of `face` as the kernel integrates it at the reference state (measure 1):
/// over the piece's projection on its plane (eq. M13), the 6-point rule on the piece's triangle or on the
/// two triangles of a 4-node piece's parameter square, added to `out`.
void addPieceNodeAreas(const FaceChart& face, int i, std::array<double, kMaxMortarFaceNodes>& out) {
  const LinearFacet<double> piece = face.piece(i);
  const Point3<double> n0 = unit(piece.centreNormal());
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
      // (x_,ξ × x_,η) · n_0, the projected Jacobian, times the local triangle's area (1/2, or 2 for half
      // the square): a warped 4-node piece is integrated over its projection, as the kernel does.
      const double jacobian = projectedJacobian(piece, n0, local[0], local[1]) * (square ? 2.0 : 0.5);
      const auto w = face.weights(i, local, xi);
      for (int a = 0; a < face.count; ++a) out[a] += q.weight * jacobian * w[a];
    }
}
}  // namespace

double mortarFacetReferenceArea(const MortarFaceNodes& x, int nodes) { return chartOf(x, nodes).area(); }

std::array<double, kMaxMortarFaceMeasures> mortarFacetPieceMeasures(const MortarFaceNodes& x, int nodes) {
  const FaceChart face = chartOf(x, nodes);
  std::array<double, kMaxMortarFaceMeasures> out{};
  if (!face.quadratic()) {
    out[0] = face.area();
    return out;
  }
  for (int i = 0; i < face.pieces(); ++i) {
    const int k = face.measureOffset(i);
    if (face.pieceNodes(i).count == 3) {
      out[k] = face.pieceArea(i);
      continue;
    }
    // J is affine in l on a bilinear piece ((a + b l_2) × (c + b l_1) · n_0 has no l_1 l_2 term): its
    // value at the centre and its slopes from the mid-sides.
    const LinearFacet<double> piece = face.piece(i);
    const Point3<double> n0 = unit(piece.centreNormal());
    const auto J = [&](double l1, double l2) { return projectedJacobian(piece, n0, l1, l2); };
    out[k] = J(0.0, 0.0);
    out[k + 1] = 0.5 * (J(1.0, 0.0) - J(-1.0, 0.0));
    out[k + 2] = 0.5 * (J(0.0, 1.0) - J(0.0, -1.0));
  }
  return out;
}

MortarFacePiece mortarFacePiece(int nodes, int i) {
  if (nodes == 3) return {3, {0, 1, 2, -1}};
  if (nodes == 4) return {4, {0, 1, 2, 3}};
  const FlatPiece& p = nodes == 6 ? kTri6Pieces[i] : nodes == 8 ? kQuad8Pieces[i] : kQuad9Pieces[i];
  return {p.count, {p.node[0], p.node[1], p.node[2], p.node[3]}};
}

std::array<double, kMaxMortarFaceNodes> mortarFacetNodeAreas(const MortarFaceNodes& x, int nodes) {
  // The kernel's integral at the reference state of a face fully overlapped: each flat piece with the
  // same rule, in its own local coordinates.
  const FaceChart face = chartOf(x, nodes);
  std::array<double, kMaxMortarFaceNodes> out{};
  for (int i = 0; i < face.pieces(); ++i) addPieceNodeAreas(face, i, out);
  return out;
}

}  // namespace contessa::contact
