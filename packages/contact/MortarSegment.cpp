#include "contact/MortarSegment.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "contact/MortarDual.hpp"

namespace contessa::contact {

namespace {

template <class T>
struct Point2 {
  T x, y;
};
template <class T>
Point2<T> at(const SegmentPairCoordinates<T>& c, int node) {
  return {c[2 * node], c[2 * node + 1]};
}
template <class T>
T dot(const Point2<T>& a, const Point2<T>& b) {
  return a.x * b.x + a.y * b.y;
}
/// The z component of a × b.
template <class T>
T cross(const Point2<T>& a, const Point2<T>& b) {
  return a.x * b.y - a.y * b.x;
}
template <class T>
Point2<T> minus(const Point2<T>& a, const Point2<T>& b) {
  return {a.x - b.x, a.y - b.y};
}
template <class T>
Point2<T> plus(const Point2<T>& a, const Point2<T>& b) {
  return {a.x + b.x, a.y + b.y};
}
template <class T>
Point2<T> along(const Point2<T>& origin, const Point2<T>& direction, const T& s) {
  return {origin.x + s * direction.x, origin.y + s * direction.y};
}
template <class T>
Point2<T> unit(const Point2<T>& v) {
  using std::sqrt;
  const T length = sqrt(dot(v, v));
  return {v.x / length, v.y / length};
}
/// The unit normal of a segment of direction d: its right, out of the body the surface bounds.
template <class T>
Point2<T> rightNormal(const Point2<T>& d) {
  return unit(Point2<T>{d.y, -d.x});
}

/// The averaged nodal normal of slave node a (eq. M1′): the normalised sum of the unit normals of the
/// pair's slave segment and of the neighbour segment beyond node a, if any.
template <class T>
Point2<T> nodalNormal(const SegmentPairCoordinates<T>& c, const Point2<T>& segmentNormal, int a,
                      const MortarSlaveNeighbours& neighbours) {
  const int sigma = neighbours.orientation[a];
  if (sigma == 0) return segmentNormal;
  const Point2<T> y = at(c, 4 + a), s = at(c, a);
  Point2<T> direction = a == 0 ? minus(s, y) : minus(y, s);
  if (sigma < 0) direction = {-direction.x, -direction.y};
  return unit(plus(segmentNormal, rightNormal(direction)));
}

/// The slave coordinate ξ whose interpolated normal n0 + ξ dn passes through the master point m (eq. M2′):
/// (s0 + ξ a − m) × (n0 + ξ dn) = 0, a quadratic A ξ² + B ξ + C with B ≈ −‖a‖; its root near −C/B,
/// written C/q to avoid cancellation. False when the normals do not reach m (no real root).
template <class T>
bool projectOntoSlave(const Point2<T>& s0, const Point2<T>& a, const Point2<T>& n0, const Point2<T>& dn,
                      const Point2<T>& m, T& xi) {
  using std::sqrt;
  const Point2<T> r = minus(s0, m);
  const T qa = cross(a, dn), qb = cross(r, dn) + cross(a, n0), qc = cross(r, n0);
  const T discriminant = qb * qb - 4.0 * qa * qc;
  if (!(valueOf(discriminant) >= 0.0) || valueOf(qb) == 0.0) return false;
  const T root = sqrt(discriminant);
  const T q = valueOf(qb) > 0.0 ? -0.5 * (qb + root) : -0.5 * (qb - root);
  xi = qc / q;
  return true;
}

}  // namespace

template <class T>
MortarPairGaps<T> integrateSegmentPair(const SegmentPairCoordinates<T>& c, double referenceLength,
                                       const MortarSlaveNeighbours& neighbours, const SegmentPairCommitted* committed) {
  MortarPairGaps<T> out;
  const Point2<T> s0 = at(c, 0), s1 = at(c, 1), m0 = at(c, 2), m1 = at(c, 3);
  // eq. M1: slave segment x_s(ξ) = s0 + ξ a, ξ ∈ [0, 1], segment normal n_s (right of a), measure L_0 dξ;
  // eq. M1′: the interpolated normal n(ξ) = n_0 + ξ (n_1 − n_0) of the averaged nodal normals.
  const Point2<T> a = minus(s1, s0), b = minus(m1, m0);
  const Point2<T> normal = rightNormal(a);
  const Point2<T> n0 = nodalNormal(c, normal, 0, neighbours), n1 = nodalNormal(c, normal, 1, neighbours);
  const Point2<T> dn = minus(n1, n0);
  const double masterLength = std::sqrt(valueOf(dot(b, b)));
  const double facing = (valueOf(normal.x) * valueOf(b.y) - valueOf(normal.y) * valueOf(b.x)) / masterLength;
  if (facing > -kMortarMinFacing) return out;  // n_m = (b_y, −b_x)/|b|: not facing the slave
  // eq. M2′: the master nodes' slave coordinates (along the interpolated normals); the clip points are
  // where [ξ_m0, ξ_m1] meets [0, 1].
  T xi0{}, xi1{};
  if (!projectOntoSlave(s0, a, n0, dn, m0, xi0) || !projectOntoSlave(s0, a, n0, dn, m1, xi1)) return out;
  const bool reversed = valueOf(xi1) < valueOf(xi0);
  const T& low = reversed ? xi1 : xi0;
  const T& high = reversed ? xi0 : xi1;
  // A master end within kMortarSnap of a slave end is taken at it: flush edges (the patch test's, and
  // any two bodies cut alike) then do not switch between the branches by round-off, which would add or
  // drop the clip point's derivative, the penalty energy's edge term of size p |g| (§13).
  const T begin = valueOf(low) > kMortarSnap ? low : T(0.0);
  const T end = valueOf(high) < 1.0 - kMortarSnap ? high : T(1.0);
  if (!(valueOf(end) > valueOf(begin))) return out;
  // eq. M3′: the gap at ξ along the master segment's outward normal n_m, g(ξ) = (x_s(ξ) − m0) · n_m, the
  // signed distance of the slave point from the master line (negative inside the master), as node-to-
  // segment measures g_N (eq. 4–6). Not along the slave normal n(ξ): a distance along a normal that turns
  // with the slave nodes has a second derivative of order g/L in them, and the penalty's term −p ∂²g̃ then
  // of order ε_N g²/L, which at a predicted penetration outweighs the stiffness of a soft slave body and
  // makes the tangent indefinite (the tube at the first touch, verification-contact §9); along n_m the gap
  // is affine in the slave coordinates and its curvature is the master's own, as in node-to-segment
  // (Fischer & Wriggers 2005 measure the mortar gap along the master normal too).
  const Point2<T> masterNormal = rightNormal(b);
  const auto gapAt = [&](const T& xi) { return dot(minus(along(s0, a, xi), m0), masterNormal); };
  // eq. M9: the relative motion over the increment of the slave point ξ and the master point η(ξ) it sees
  // (along n(ξ), as the segmentation), both material points moved from their committed positions,
  // measured along the master's unit tangent t_m (the gap's frame).
  const Point2<T> masterTangent = unit(b);
  const auto masterPointOf = [&](const T& xi) {
    const Point2<T> xs = along(s0, a, xi), normalAt = along(n0, dn, xi);
    return T(cross(minus(xs, m0), normalAt) / cross(b, normalAt));
  };
  const auto slipAt = [&](const T& xi, const T& eta) {
    const SegmentPairCommitted& n = *committed;
    const Point2<T> xs = along(s0, a, xi);
    const Point2<T> slaveThen{n[0] + xi * (n[2] - n[0]), n[1] + xi * (n[3] - n[1])};
    const Point2<T> masterThen{n[4] + eta * (n[6] - n[4]), n[5] + eta * (n[7] - n[5])};
    const Point2<T> slaveMotion = minus(xs, slaveThen), masterMotion = minus(along(m0, b, eta), masterThen);
    return dot(minus(slaveMotion, masterMotion), masterTangent);
  };
  const double size = std::max(std::sqrt(valueOf(dot(a, a))), masterLength);
  const double gapBegin = valueOf(gapAt(begin)), gapEnd = valueOf(gapAt(end));
  if (std::max(gapBegin, gapEnd) < -size || std::min(gapBegin, gapEnd) > size) return out;
  // eq. M4: g̃_a = ∫ N_a g L_0 dξ over [begin, end], N_0 = 1 − ξ, N_1 = ξ; the integrand is quadratic in
  // ξ, so 2-point Gauss is exact.
  const double r = 1.0 / std::sqrt(3.0);
  const T half = 0.5 * (end - begin);
  const T mid = 0.5 * (end + begin);
  out.overlaps = true;
  for (double q : {-r, r}) {
    const T xi = mid + q * half;
    const T weight = half * referenceLength;
    const T g = gapAt(xi);
    const T shape0 = 1.0 - xi;
    out.weightedGap[0] = out.weightedGap[0] + weight * shape0 * g;
    out.weightedGap[1] = out.weightedGap[1] + weight * xi * g;
    out.mortarLength[0] = out.mortarLength[0] + weight * shape0;
    out.mortarLength[1] = out.mortarLength[1] + weight * xi;
    if (committed != nullptr) {
      const T eta = masterPointOf(xi);
      const T u = slipAt(xi, eta);
      const std::array<T, 2> w{weight * shape0, weight * xi};
      out.weightedSlip[0] = out.weightedSlip[0] + w[0] * u;
      out.weightedSlip[1] = out.weightedSlip[1] + w[1] * u;
      if constexpr (!std::is_same_v<T, double>) {  // the virtual slips (MortarSlipVariation.hpp, eq. M11″)
        using Term = typename SlipVariationSum<T>::Term;
        const T masterShape0 = 1.0 - eta;
        const Term terms[4] = {{&shape0, {&c[0], &c[1], nullptr}, 1.0},
                               {&xi, {&c[2], &c[3], nullptr}, 1.0},
                               {&masterShape0, {&c[4], &c[5], nullptr}, -1.0},
                               {&eta, {&c[6], &c[7], nullptr}, -1.0}};
        const std::array<std::array<FirstOrder<kVariables<T>>, 2>, 1> row{{{firstOrder(masterTangent.x), firstOrder(masterTangent.y)}}};
        out.slipVariation.template add<2, 1>(2, w.data(), 2, row, terms, 4);
      }
    }
  }
  return out;
}

MortarPairGaps<double> segmentPairGaps(const SegmentPairCoordinates<double>& x, double referenceLength,
                                       const MortarSlaveNeighbours& neighbours, const SegmentPairCommitted* committed) {
  return integrateSegmentPair(x, referenceLength, neighbours, committed);
}

namespace {
template <int V>
MortarPairDerivatives differentiateSegmentPair(const SegmentPairCoordinates<double>& x, double referenceLength,
                                               const MortarSlaveNeighbours& neighbours,
                                               const SegmentPairCommitted* committed,
                                               const KernelVariables<kMortarPairCoordinates>& variables) {
  const MortarPairGaps<HessianDual<V>> g =
      integrateSegmentPair(variables.template seed<V>(x), referenceLength, neighbours, committed);
  MortarPairDerivatives out;
  extractSegmentPairDerivatives<2, kMortarPairCoordinates, V>(g, variables, committed != nullptr, out);
  return out;
}
}  // namespace

MortarPairDerivatives segmentPairDerivatives(const SegmentPairCoordinates<double>& x, double referenceLength,
                                             const MortarSlaveNeighbours& neighbours,
                                             const SegmentPairCommitted* committed, const double* masterMotion) {
  constexpr int n = kMortarPairCoordinates;
  if (masterMotion == nullptr)
    return differentiateSegmentPair<n>(x, referenceLength, neighbours, committed, ownVariables<n>());
  // A rigid master: the eight slave coordinates and the motion (MortarDual.hpp, KernelVariables).
  return differentiateSegmentPair<n - 4 + 1>(x, referenceLength, neighbours, committed,
                                             rigidBodyVariables<n>(4, 4, masterMotion));
}

}  // namespace contessa::contact
