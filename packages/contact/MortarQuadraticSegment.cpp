#include "contact/MortarQuadraticSegment.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "contact/MortarClipping.hpp"  // PlanePoint
#include "contact/MortarDual.hpp"
#include "contact/MortarSegment.hpp"  // kMortarMinFacing

namespace contessa::contact {

namespace {

// The plane points of the 3D segmentation (MortarClipping.hpp), here the 2D coordinates themselves.
template <class T>
T dot(const PlanePoint<T>& a, const PlanePoint<T>& b) {
  return a.x * b.x + a.y * b.y;
}

/// A segment's node a's parent coordinate (Line2Facet, Line3Facet: corners −1, +1, the mid-edge node 0).
constexpr double kNodeXi[kQuadraticSegmentNodes] = {-1.0, 1.0, 0.0};
/// The flat pieces (Line3Facet::flatPieces): a Line3's chords corner 0 – mid, mid – corner 1; a Line2 itself.
constexpr int kLine3Pieces[2][2] = {{0, 2}, {2, 1}};
constexpr int kLine2Piece[2] = {0, 1};

/// One side of the pair: its nodes, shape functions and flat pieces.
template <class T>
struct SegmentChart {
  int count = 3;
  std::array<PlanePoint<T>, kQuadraticSegmentNodes> node{};

  int pieces() const { return mortarSegmentPieces(count); }
  const int* pieceNodes(int i) const { return count == 3 ? kLine3Pieces[i] : kLine2Piece; }
  /// The parent coordinate of piece i's local point l ∈ [0, 1] (affine: the chords run between nodes).
  template <class S>
  S parent(int i, const S& l) const {
    const int* p = pieceNodes(i);
    return kNodeXi[p[0]] + l * (kNodeXi[p[1]] - kNodeXi[p[0]]);
  }
  /// N_a(ξ) and N_a'(ξ): Line2Facet's or Line3Facet's (QuadraticLagrange1D).
  template <class S>
  std::array<S, kQuadraticSegmentNodes> shape(const S& xi) const {
    if (count == 2) return {0.5 * (1.0 - xi), 0.5 * (1.0 + xi), S(0.0)};
    return {0.5 * xi * (xi - 1.0), 0.5 * xi * (xi + 1.0), 1.0 - xi * xi};
  }
  template <class S>
  std::array<S, kQuadraticSegmentNodes> shapeDerivative(const S& xi) const {
    if (count == 2) return {S(-0.5), S(0.5), S(0.0)};
    return {xi - 0.5, xi + 0.5, -2.0 * xi};
  }
  PlanePoint<T> at(const std::array<T, kQuadraticSegmentNodes>& n) const {
    PlanePoint<T> p{T(0.0), T(0.0)};
    for (int a = 0; a < count; ++a) p = {p.x + n[a] * node[a].x, p.y + n[a] * node[a].y};
    return p;
  }
  double diameter() const {
    double h = 0;
    for (int a = 0; a < count; ++a)
      for (int b = a + 1; b < count; ++b) {
        const PlanePoint<T> d = node[b] - node[a];
        h = std::max(h, std::sqrt(valueOf(dot(d, d))));
      }
    return h;
  }
};

template <class T>
SegmentChart<T> chartOf(const QuadraticSegmentPairCoordinates<T>& c, int firstSlot, int count) {
  SegmentChart<T> s;
  s.count = count;
  for (int a = 0; a < count; ++a) s.node[a] = {c[2 * (firstSlot + a)], c[2 * (firstSlot + a) + 1]};
  return s;
}

/// A committed point Σ N_a x̄_a of the side starting at slot firstSlot.
template <class T>
PlanePoint<T> committedPoint(const QuadraticSegmentPairCommitted& n, int firstSlot, int count,
                       const std::array<T, kQuadraticSegmentNodes>& shape) {
  PlanePoint<T> p{T(0.0), T(0.0)};
  for (int a = 0; a < count; ++a) p = {p.x + shape[a] * n[2 * (firstSlot + a)], p.y + shape[a] * n[2 * (firstSlot + a) + 1]};
  return p;
}

/// Clip points within this fraction of a slave piece of one of its ends are taken at the end (kMortarSnap's
/// role, wider). A master end level with a slave end at a free edge of the interface (the patch test's
/// ends) has the penalty energy's edge term, a tangential force of size ε_N |g| Φ, once the clip point is
/// free to move: it shears the two bodies apart by ~ ε_N g² / E, which keeps the clip point free, a second
/// equilibrium beside the snapped, uniform one. Newton found it on Q8 2/3, 3/4, 4/3 and Tri6 2/5 patch
/// meshes with kMortarSnap (1e-9): pressures off by 1e-6, ends apart by 5e-8 of a piece. At 1e-6 of a
/// piece the snapped equilibrium is the only one (the shear would be 1e-8 to 1e-7 of a piece); the
/// overlap then changes by at most 1e-6 of a piece where a node crosses the band.
constexpr double kQuadraticSegmentSnap = 1e-6;

/// 3-point Gauss–Legendre on [−1, 1]: exact to degree 5, so on straight segments with centred mid-edge
/// nodes the weighted gaps (Φ g, quadratic in l) and their gradients (Φ_a N_b, cubic) are integrated exactly.
constexpr double kGaussPoint[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
constexpr double kGaussWeight[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};

/// Slave piece s against master piece m (eq. M2 on the chords, M19 at the Gauss points, M9 with
/// `committed`): adds to `out` and says whether they overlap.
template <class T>
bool addPiecePair(const SegmentChart<T>& slave, int s, const SegmentChart<T>& master, int m, double referenceLength,
                  double size, const QuadraticSegmentPairCommitted* committed, MortarQuadraticSegmentGaps<T>& out) {
  const int* sp = slave.pieceNodes(s);
  const int* mp = master.pieceNodes(m);
  const PlanePoint<T> p = slave.node[sp[0]], a = slave.node[sp[1]] - p;
  const PlanePoint<T> m0 = master.node[mp[0]], b = master.node[mp[1]] - m0;
  // The chords' outward normals (the right of their directions) must face each other.
  const PlanePoint<T> slaveNormal{a.y, -a.x}, masterChordNormal{b.y, -b.x};
  const double bLength = std::sqrt(valueOf(dot(b, b)));
  const double facing = valueOf(dot(slaveNormal, masterChordNormal)) / (std::sqrt(valueOf(dot(a, a))) * bLength);
  if (facing > -kMortarMinFacing) return false;
  // eq. M2: the master chord's ends on the slave chord along its normal, l = (x − p) · a / |a|².
  const T aa = dot(a, a);
  const T l0 = dot(m0 - p, a) / aa, l1 = dot(master.node[mp[1]] - p, a) / aa;
  const bool reversed = valueOf(l1) < valueOf(l0);
  const T& low = reversed ? l1 : l0;
  const T& high = reversed ? l0 : l1;
  // Flush ends snap (MortarSegment.cpp says why), both ways: a master piece that reaches a slave piece's
  // end only within the snap does not overlap it. Otherwise a master node level with a slave node (a
  // matching node, or a Line3's mid-edge node level with a corner) makes a clip of round-off length on
  // one side of it, whose moving end carries the edge term g Φ ∂l/∂x, while the clip on the other side,
  // snapped, carries none: a spurious force of the order of the penalty's penetration, which spoiled the
  // patch test's uniform pressure by 5e-6 (2 Q8 slave cells against 1).
  if (!(valueOf(high) > kQuadraticSegmentSnap) || !(valueOf(low) < 1.0 - kQuadraticSegmentSnap)) return false;
  const T begin = valueOf(low) > kQuadraticSegmentSnap ? low : T(0.0);
  const T end = valueOf(high) < 1.0 - kQuadraticSegmentSnap ? high : T(1.0);
  if (!(valueOf(end) > valueOf(begin))) return false;
  // A slave chord point's master chord coordinate along the same normal: (p + l a − m0) × n_s = t b × n_s.
  const T bn = planeCross(b, slaveNormal);
  const auto masterLocal = [&](const T& l) {
    const PlanePoint<T> xp{p.x + l * a.x, p.y + l * a.y};
    return T(planeCross(xp - m0, slaveNormal) / bn);
  };
  // Neither far behind the master chord (the other side of a thin body) nor far in front (MortarSegment).
  const auto chordGap = [&](const T& l) {
    return valueOf(dot(PlanePoint<T>{p.x + l * a.x - m0.x, p.y + l * a.y - m0.y}, masterChordNormal)) / bLength;
  };
  const double gapBegin = chordGap(begin), gapEnd = chordGap(end);
  if (std::max(gapBegin, gapEnd) < -size || std::min(gapBegin, gapEnd) > size) return false;
  const T half = 0.5 * (end - begin), mid = 0.5 * (end + begin);
  for (int q = 0; q < 3; ++q) {
    const T l = mid + kGaussPoint[q] * half;
    const T weight = kGaussWeight[q] * half * referenceLength;  // dΓ_0 = l_0 dl (eq. M20)
    const T xi = slave.parent(s, l), eta = master.parent(m, masterLocal(l));
    // eq. M19: the quadratic points, and the master's unit tangent and outward normal at η.
    const std::array<T, kQuadraticSegmentNodes> slaveShape = slave.shape(xi), masterShape = master.shape(eta);
    const PlanePoint<T> xs = slave.at(slaveShape), xm = master.at(masterShape);
    const PlanePoint<T> derivative = master.at(master.shapeDerivative(eta));
    using std::sqrt;
    const T length = sqrt(dot(derivative, derivative));
    const PlanePoint<T> tangent{derivative.x / length, derivative.y / length}, normal{tangent.y, -tangent.x};
    const T g = dot(xs - xm, normal);
    // The slave piece's hat functions Φ on its two nodes (eq. M18), zero on the third.
    std::array<T, kQuadraticSegmentNodes> w{};
    w[sp[0]] = weight * (1.0 - l);
    w[sp[1]] = weight * l;
    for (int k = 0; k < 2; ++k) {
      const int node = sp[k];
      out.weightedGap[node] = out.weightedGap[node] + w[node] * g;
      out.mortarLength[node] = out.mortarLength[node] + w[node];
    }
    if (committed == nullptr) continue;
    // eq. M9: the relative motion of the material points ξ and η over the increment along t_m(η).
    const PlanePoint<T> motion = (xs - committedPoint(*committed, 0, slave.count, slaveShape)) -
                           (xm - committedPoint(*committed, kQuadraticSegmentNodes, master.count, masterShape));
    const T u = dot(motion, tangent);
    for (int k = 0; k < 2; ++k) out.weightedSlip[sp[k]] = out.weightedSlip[sp[k]] + w[sp[k]] * u;
    if constexpr (!std::is_same_v<T, double>) {  // the virtual slips (MortarSlipVariation.hpp, eq. M11″)
      using Term = typename SlipVariationSum<T>::Term;
      std::array<Term, 2 * kQuadraticSegmentNodes> terms;
      int count = 0;
      for (int j = 0; j < slave.count; ++j) terms[count++] = {&slaveShape[j], {&slave.node[j].x, &slave.node[j].y, nullptr}, 1.0};
      for (int j = 0; j < master.count; ++j)
        terms[count++] = {&masterShape[j], {&master.node[j].x, &master.node[j].y, nullptr}, -1.0};
      const std::array<std::array<FirstOrder<kVariables<T>>, 2>, 1> row{{{firstOrder(tangent.x), firstOrder(tangent.y)}}};
      out.slipVariation.template add<2, 1>(kQuadraticSegmentNodes, w.data(), slave.count, row, terms.data(), count);
    }
  }
  return true;
}

}  // namespace

template <class T>
MortarQuadraticSegmentGaps<T> integrateQuadraticSegmentPair(const QuadraticSegmentPairCoordinates<T>& x,
                                                            const MortarFacetPairShape& shape,
                                                            const QuadraticSegmentPairCommitted* committed) {
  MortarQuadraticSegmentGaps<T> out;
  const SegmentChart<T> slave = chartOf(x, 0, shape.slaveNodes);
  const SegmentChart<T> master = chartOf(x, kQuadraticSegmentNodes, shape.masterNodes);
  const double size = std::max(slave.diameter(), master.diameter());
  for (int s = 0; s < slave.pieces(); ++s)
    for (int m = 0; m < master.pieces(); ++m)
      if (addPiecePair(slave, s, master, m, shape.slavePieceAreas[s], size, committed, out)) out.overlaps = true;
  return out;
}

MortarQuadraticSegmentGaps<double> quadraticSegmentPairGaps(const QuadraticSegmentPairCoordinates<double>& x,
                                                            const MortarFacetPairShape& shape,
                                                            const QuadraticSegmentPairCommitted* committed) {
  return integrateQuadraticSegmentPair(x, shape, committed);
}

namespace {
template <int V>
MortarQuadraticSegmentDerivatives differentiate(const QuadraticSegmentPairCoordinates<double>& x,
                                                const MortarFacetPairShape& shape,
                                                const QuadraticSegmentPairCommitted* committed,
                                                const KernelVariables<kQuadraticSegmentPairCoordinates>& variables) {
  constexpr int C = kQuadraticSegmentPairCoordinates;
  std::vector<std::array<HessianDual<V>, C>> seeded(1, variables.template seed<V>(x));  // large: on the heap
  const MortarQuadraticSegmentGaps<HessianDual<V>> g = integrateQuadraticSegmentPair(seeded[0], shape, committed);
  MortarQuadraticSegmentDerivatives out;
  extractSegmentPairDerivatives<kQuadraticSegmentNodes, C, V>(g, variables, committed != nullptr, out);
  return out;
}
}  // namespace

MortarQuadraticSegmentDerivatives quadraticSegmentPairDerivatives(const QuadraticSegmentPairCoordinates<double>& x,
                                                                  const MortarFacetPairShape& shape,
                                                                  const QuadraticSegmentPairCommitted* committed,
                                                                  const double* masterMotion) {
  constexpr int C = kQuadraticSegmentPairCoordinates, kFirstMaster = 2 * kQuadraticSegmentNodes;
  if (masterMotion == nullptr) return differentiate<C>(x, shape, committed, ownVariables<C>());
  // A rigid master: the slave's six coordinates and the motion (MortarDual.hpp, KernelVariables).
  return differentiate<kFirstMaster + 1>(x, shape, committed, rigidBodyVariables<C>(kFirstMaster, kFirstMaster, masterMotion));
}

std::array<int, 2> mortarSegmentPieceNodes(int nodes, int i) {
  const int* p = nodes == 3 ? kLine3Pieces[i] : kLine2Piece;
  return {p[0], p[1]};
}

std::array<double, 2> mortarSegmentPieceLengths(const MortarSegmentNodes& x, int nodes) {
  std::array<double, 2> out{};
  for (int i = 0; i < mortarSegmentPieces(nodes); ++i) {
    const int* p = nodes == 3 ? kLine3Pieces[i] : kLine2Piece;
    out[i] = std::hypot(x[p[1]][0] - x[p[0]][0], x[p[1]][1] - x[p[0]][1]);
  }
  return out;
}

std::array<double, kQuadraticSegmentNodes> mortarSegmentNodeLengths(const MortarSegmentNodes& x, int nodes) {
  const std::array<double, 2> pieces = mortarSegmentPieceLengths(x, nodes);
  std::array<double, kQuadraticSegmentNodes> out{};
  for (int i = 0; i < mortarSegmentPieces(nodes); ++i) {
    const int* p = nodes == 3 ? kLine3Pieces[i] : kLine2Piece;
    out[p[0]] += 0.5 * pieces[i];
    out[p[1]] += 0.5 * pieces[i];
  }
  return out;
}

}  // namespace contessa::contact
