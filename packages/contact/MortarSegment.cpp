#include "contact/MortarSegment.hpp"

#include <algorithm>
#include <cmath>

#include "contact/MortarDual.hpp"

namespace contessa::contact {

namespace {

using SecondOrder = Dual<Dual<double, 8>, 8>;

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
template <class T>
Point2<T> minus(const Point2<T>& a, const Point2<T>& b) {
  return {a.x - b.x, a.y - b.y};
}
template <class T>
Point2<T> along(const Point2<T>& origin, const Point2<T>& direction, const T& s) {
  return {origin.x + s * direction.x, origin.y + s * direction.y};
}

}  // namespace

template <class T>
MortarPairGaps<T> integrateSegmentPair(const SegmentPairCoordinates<T>& c, double referenceLength) {
  using std::sqrt;
  MortarPairGaps<T> out;
  const Point2<T> s0 = at(c, 0), s1 = at(c, 1), m0 = at(c, 2), m1 = at(c, 3);
  // eq. M1: slave segment x_s(ξ) = s0 + ξ a, ξ ∈ [0, 1], unit normal n_s (right of a), measure L_0 dξ.
  const Point2<T> a = minus(s1, s0), b = minus(m1, m0);
  const T length2 = dot(a, a);
  const T length = sqrt(length2);
  const Point2<T> normal{a.y / length, -a.x / length};
  const double masterLength = std::sqrt(valueOf(dot(b, b)));
  const double facing = (valueOf(normal.x) * valueOf(b.y) - valueOf(normal.y) * valueOf(b.x)) / masterLength;
  if (facing > -kMortarMinFacing) return out;  // n_m = (b_y, −b_x)/|b|: not facing the slave
  // eq. M2: the master nodes' slave coordinates (projection along n_s onto the slave line); the master line
  // maps affinely onto ξ, so the clip points are where [ξ_m0, ξ_m1] meets [0, 1].
  const T xi0 = dot(minus(m0, s0), a) / length2;
  const T xi1 = dot(minus(m1, s0), a) / length2;
  const bool reversed = valueOf(xi1) < valueOf(xi0);
  const T& low = reversed ? xi1 : xi0;
  const T& high = reversed ? xi0 : xi1;
  // A master end within kMortarSnap of a slave end is taken at it: flush edges (the patch test's, and
  // any two bodies cut alike) then do not switch between the branches by round-off, which would add or
  // drop the clip point's derivative, the penalty energy's edge term of size p |g| (§13).
  const T begin = valueOf(low) > kMortarSnap ? low : T(0.0);
  const T end = valueOf(high) < 1.0 - kMortarSnap ? high : T(1.0);
  if (!(valueOf(end) > valueOf(begin))) return out;
  // eq. M3: the gap at ξ along n_s, g(ξ) = (x_m(η(ξ)) − x_s(ξ)) · n_s, with η(ξ) = (ξ − ξ_m0)/(ξ_m1 − ξ_m0).
  const auto gapAt = [&](const T& xi) {
    const T eta = (xi - xi0) / (xi1 - xi0);
    return dot(minus(along(m0, b, eta), along(s0, a, xi)), normal);
  };
  const double size = std::max(std::sqrt(valueOf(length2)), masterLength);
  const double gapBegin = valueOf(gapAt(begin)), gapEnd = valueOf(gapAt(end));
  if (std::max(gapBegin, gapEnd) < -size || std::min(gapBegin, gapEnd) > size) return out;
  // eq. M4: g̃_a = ∫ N_a g L_0 dξ over [begin, end], N_0 = 1 − ξ, N_1 = ξ; the integrand is quadratic in ξ,
  // so 2-point Gauss is exact.
  const double r = 1.0 / std::sqrt(3.0);
  const T half = 0.5 * (end - begin);
  const T mid = 0.5 * (end + begin);
  out.overlaps = true;
  for (double q : {-r, r}) {
    const T xi = mid + q * half;
    const T weight = half * referenceLength;
    const T g = gapAt(xi);
    const T n0 = 1.0 - xi;
    out.weightedGap[0] = out.weightedGap[0] + weight * n0 * g;
    out.weightedGap[1] = out.weightedGap[1] + weight * xi * g;
    out.mortarLength[0] = out.mortarLength[0] + weight * n0;
    out.mortarLength[1] = out.mortarLength[1] + weight * xi;
  }
  return out;
}

MortarPairGaps<double> segmentPairGaps(const SegmentPairCoordinates<double>& x, double referenceLength) {
  return integrateSegmentPair(x, referenceLength);
}

MortarPairDerivatives segmentPairDerivatives(const SegmentPairCoordinates<double>& x, double referenceLength) {
  SegmentPairCoordinates<SecondOrder> seeded;
  for (int i = 0; i < 8; ++i) seeded[i] = secondOrderVariable<8>(x[i], i);
  const MortarPairGaps<SecondOrder> g = integrateSegmentPair(seeded, referenceLength);
  MortarPairDerivatives out;
  out.overlaps = g.overlaps;
  for (int a = 0; a < 2; ++a) {
    out.weightedGap[a] = g.weightedGap[a].v.v;
    out.mortarLength[a] = g.mortarLength[a].v.v;
    for (int i = 0; i < 8; ++i) {
      out.gradient[a][i] = g.weightedGap[a].d[i].v;
      for (int j = 0; j < 8; ++j) out.hessian[a][i * 8 + j] = g.weightedGap[a].d[i].d[j];
    }
  }
  return out;
}

}  // namespace contessa::contact
