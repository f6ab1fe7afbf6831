#pragma once
// The plane geometry of 3D mortar segmentation (theory-contact.md §13, "3D segmentation", eq. M13–M15):
// Sutherland–Hodgman clipping of one convex polygon by another in the projection plane, and the
// triangulation of the clip polygon about its vertex centroid with a Gauss rule per triangle (Puso &
// Laursen 2004 §3; Popp et al. 2010 §3). Templated on the number type: with the nested dual numbers of
// MortarDual.hpp every clip vertex carries its exact first and second derivatives with respect to the
// nodes; the branches (which side of an edge a vertex lies) are decided on the values.
#include <array>
#include <cmath>
#include <vector>

#include "contact/MortarDual.hpp"

namespace contessa::contact {

template <class T>
struct PlanePoint {
  T x, y;
};

template <class T>
PlanePoint<T> operator-(const PlanePoint<T>& a, const PlanePoint<T>& b) {
  return {a.x - b.x, a.y - b.y};
}
template <class T>
PlanePoint<T> operator+(const PlanePoint<T>& a, const PlanePoint<T>& b) {
  return {a.x + b.x, a.y + b.y};
}
template <class T, class S>
PlanePoint<T> scaled(const PlanePoint<T>& a, const S& s) {
  return {a.x * s, a.y * s};
}
/// The z component of a × b: twice the signed area of the triangle (0, a, b).
template <class T>
T planeCross(const PlanePoint<T>& a, const PlanePoint<T>& b) {
  return a.x * b.y - a.y * b.x;
}

/// Twice the signed area of a polygon (the shoelace sum): positive when its vertices run anticlockwise.
template <class T>
T twiceSignedArea(const std::vector<PlanePoint<T>>& polygon) {
  T sum(0.0);
  for (std::size_t i = 0; i < polygon.size(); ++i)
    sum = sum + planeCross(polygon[i], polygon[(i + 1) % polygon.size()]);
  return sum;
}

/// The part of `subject` inside the convex, anticlockwise polygon `clip` (Sutherland–Hodgman, eq. M14):
/// each clip edge a → b keeps the subject's vertices on its left and adds, where a subject edge P → Q
/// crosses the edge's line, the crossing P + t (Q − P), t = d_P / (d_P − d_Q), d the signed distance
/// times |b − a|. A vertex within `snap` (a length) of the line counts as on the left: edges lying on each
/// other (two bodies cut alike, the patch test's boundary) then add no crossing of two parallel lines,
/// whose derivative would be ill-conditioned, and the answer does not switch by round-off.
///
/// A subject edge within the band (both ends snapped) lies **on** the line: its ends are kept and are the
/// polygon's own way in and out of the half-plane, so the edges from them to vertices beyond the line add
/// no crossing. Two neighbouring clip polygons that share the line then agree on the edge: the one it lies
/// just outside of keeps it (snapped in), the one it lies just inside of keeps only the segment (no area).
/// With crossings there, the second integrated a sliver of the offset's width that the first had already
/// counted — the overlap A + L |d| for an offset d within the band, a kink at d = 0 whose one-sided
/// derivatives ±g L alternated between Newton's iterates (theory-contact.md §13.2, "Coincident piece edges").
template <class T>
std::vector<PlanePoint<T>> clipConvexPolygon(std::vector<PlanePoint<T>> subject,
                                             const std::vector<PlanePoint<T>>& clip, double snap) {
  std::vector<int> side;  // −1 beyond the band outside, 0 within it, +1 beyond it inside
  for (std::size_t e = 0; e < clip.size() && !subject.empty(); ++e) {
    const PlanePoint<T>& a = clip[e];
    const PlanePoint<T> edge = clip[(e + 1) % clip.size()] - a;
    const double tolerance = snap * std::hypot(valueOf(edge.x), valueOf(edge.y));
    const std::size_t n = subject.size();
    // The sides on the values (the numbers' own values: planeCross of the values, to the bit); the
    // differentiated distances only at a crossing, where they enter the clip vertex.
    const double ex = valueOf(edge.x), ey = valueOf(edge.y);
    const auto distance = [&](std::size_t i) { return planeCross(edge, subject[i] - a); };
    side.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      const double v = ex * (valueOf(subject[i].y) - valueOf(a.y)) - ey * (valueOf(subject[i].x) - valueOf(a.x));
      side[i] = v < -tolerance ? -1 : (v > tolerance ? 1 : 0);
    }
    const auto onLine = [&](std::size_t i, std::size_t j) { return side[i] == 0 && side[j] == 0; };
    std::vector<PlanePoint<T>> kept;
    kept.reserve(n + 2);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t p = (i + n - 1) % n, q = i;
      const PlanePoint<T>& P = subject[p];
      const PlanePoint<T>& Q = subject[q];
      // A crossing needs one end outside beyond the band and the other not, d_P − d_Q ≠ 0, and not an end
      // of an edge lying on the line (that end is the crossing).
      const bool crossing = (side[p] < 0) != (side[q] < 0) &&
                            !(side[q] == 0 && onLine(q, (q + 1) % n)) && !(side[p] == 0 && onLine((p + n - 1) % n, p));
      if (crossing) {
        const T dp = distance(p), dq = distance(q);
        kept.push_back(P + scaled(Q - P, dp / (dp - dq)));
      }
      if (side[q] >= 0) kept.push_back(Q);
    }
    subject.swap(kept);
  }
  return subject;
}

/// A Gauss point of the reference triangle: barycentric coordinates of vertices 1 and 2, and the weight
/// (summing to 1: the weights are fractions of the triangle's area).
struct TrianglePoint {
  double l1, l2, weight;
};

/// The 6-point rule of degree 4 (Dunavant 1985): exact for the bilinear shape functions times the gap of
/// an affine or bilinear pair on a flat triangle (degree ≤ 4), the patch test's integrands.
inline const std::array<TrianglePoint, 6>& triangleRule() {
  static const std::array<TrianglePoint, 6> rule = [] {
    const double a = 0.445948490915965, wa = 0.223381589678011;
    const double b = 0.091576213509771, wb = 0.109951743655322;
    return std::array<TrianglePoint, 6>{{{a, a, wa},
                                         {1.0 - 2.0 * a, a, wa},
                                         {a, 1.0 - 2.0 * a, wa},
                                         {b, b, wb},
                                         {1.0 - 2.0 * b, b, wb},
                                         {b, 1.0 - 2.0 * b, wb}}};
  }();
  return rule;
}

/// The vertex centroid of a polygon: the common vertex of its triangulation (eq. M15).
template <class T>
PlanePoint<T> vertexCentroid(const std::vector<PlanePoint<T>>& polygon) {
  PlanePoint<T> c{T(0.0), T(0.0)};
  for (const auto& v : polygon) c = c + v;
  const double n = static_cast<double>(polygon.size());
  return {c.x / n, c.y / n};
}

}  // namespace contessa::contact
