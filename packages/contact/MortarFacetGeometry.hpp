#pragma once
// The 3D geometry the mortar facet-pair kernels share (MortarFacetPair.cpp for Tri3/Quad4 facets,
// MortarQuadraticFacetPair.cpp for Tri6 facets through their flat pieces): points in space, a linear facet
// (Tri3 or Quad4) with its shape functions, the projection plane of eq. M13, the inverse of eq. M16 and
// the facing test. Templated on the number type, as MortarClipping.hpp, for the nested dual numbers.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "contact/MortarClipping.hpp"
#include "contact/MortarDual.hpp"
#include "contact/MortarSegment.hpp"  // kMortarMinFacing: the same rule as in 2D

namespace contessa::contact::mortar3d {

/// The most nodes a linear facet (a Quad4) has.
constexpr int kLinearFacetNodes = 4;

/// A slave vertex within this fraction of the facet size of a master edge's line counts as on it
/// (MortarClipping.hpp). Wider than 2D's kMortarSnap (1e-9), as measured on the 3D patch tests: where the
/// slave's and the master's outer edges are flush at the solution, a slave edge overhanging the master
/// adds the edge term p |g| L of the clip vertices (1e-6 N there) and a master edge overhanging the slave
/// none, so Newton's iterates bounce across the flush position by that force over the lateral stiffness,
/// p² / (ε_N E) ≈ 1e-9 mm = 3e-9 h, and with 1e-9 h the residual stalled at 1e-7 (3/2 faces: 10 iterations
/// instead of 2). Of order the penetration times the strain in general (p/ε_N h · p/E ≈ 1e-6); the
/// overlap it adds or drops, 1e-6 h along an edge, is far below the discretisation error.
constexpr double kMortarClipSnap = 1e-6;

template <class T>
struct Point3 {
  T x, y, z;
};
template <class T>
Point3<T> operator-(const Point3<T>& a, const Point3<T>& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
Point3<T> operator+(const Point3<T>& a, const Point3<T>& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T, class S>
Point3<T> times(const Point3<T>& a, const S& s) {
  return {a.x * s, a.y * s, a.z * s};
}
template <class T>
T dot(const Point3<T>& a, const Point3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
Point3<T> cross(const Point3<T>& a, const Point3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
Point3<T> unit(const Point3<T>& v) {
  using std::sqrt;
  const T length = sqrt(dot(v, v));
  return {v.x / length, v.y / length, v.z / length};
}
template <class T>
Point3<double> values(const Point3<T>& a) {
  return {valueOf(a.x), valueOf(a.y), valueOf(a.z)};
}

/// One linear facet (Tri3 or Quad4) of the pair: its nodes and shape functions (MasterFacet.hpp's
/// conventions: Tri3 N = (1 − ξ − η, ξ, η); Quad4 bilinear on [−1, 1]², nodes anticlockwise from (−1, −1)).
template <class T>
struct LinearFacet {
  int count = 4;
  std::array<Point3<T>, kLinearFacetNodes> node{};

  template <class S>
  std::array<S, kLinearFacetNodes> shape(const S& xi, const S& eta) const {
    if (count == 3) return {1.0 - xi - eta, xi, eta, S(0.0)};
    return {0.25 * (1.0 - xi) * (1.0 - eta), 0.25 * (1.0 + xi) * (1.0 - eta), 0.25 * (1.0 + xi) * (1.0 + eta),
            0.25 * (1.0 - xi) * (1.0 + eta)};
  }
  /// ∂N_a/∂ξ and ∂N_a/∂η.
  template <class S>
  std::array<std::array<S, kLinearFacetNodes>, 2> shapeDerivatives(const S& xi, const S& eta) const {
    if (count == 3) return {{{S(-1.0), S(1.0), S(0.0), S(0.0)}, {S(-1.0), S(0.0), S(1.0), S(0.0)}}};
    return {{{-0.25 * (1.0 - eta), 0.25 * (1.0 - eta), 0.25 * (1.0 + eta), -0.25 * (1.0 + eta)},
             {-0.25 * (1.0 - xi), -0.25 * (1.0 + xi), 0.25 * (1.0 + xi), 0.25 * (1.0 - xi)}}};
  }
  Point3<T> at(const std::array<T, kLinearFacetNodes>& n) const {
    Point3<T> p{T(0.0), T(0.0), T(0.0)};
    for (int a = 0; a < count; ++a) p = p + times(node[a], n[a]);
    return p;
  }
  Point3<T> centre() const {
    const T c = count == 3 ? T(1.0 / 3.0) : T(0.0);
    return at(shape(c, c));
  }
  /// The area normal at the centre: (x_1 − x_0) × (x_2 − x_0) for a triangle, the diagonals' cross
  /// product (x_2 − x_0) × (x_3 − x_1) for a quadrilateral (its x_,ξ × x_,η at the centre, times 2).
  Point3<T> centreNormal() const {
    if (count == 3) return cross(node[1] - node[0], node[2] - node[0]);
    return cross(node[2] - node[0], node[3] - node[1]);
  }
  /// The unit normal x_,ξ × x_,η / ‖·‖ at (ξ, η): out of the facet's body.
  Point3<T> unitNormal(const T& xi, const T& eta) const {
    const auto d = shapeDerivatives(xi, eta);
    return unit(cross(at(d[0]), at(d[1])));
  }
};

/// The parametric coordinates (ξ, η) of the facet point whose projection is p (eq. M16): the linear
/// map's inverse for a triangle; for a quadrilateral Newton's method converged on the values, then two
/// Newton steps in T from that root, which give its exact first (one step) and second (two steps)
/// derivatives by the implicit function theorem.
template <class T>
std::array<T, 2> inverseMap(const LinearFacet<T>& facet, const std::vector<PlanePoint<T>>& projected,
                            const PlanePoint<T>& p) {
  if (facet.count == 3) {
    const PlanePoint<T> a = projected[1] - projected[0], b = projected[2] - projected[0], r = p - projected[0];
    const T det = planeCross(a, b);
    return {planeCross(r, b) / det, planeCross(a, r) / det};
  }
  // Newton on the values.
  double xi = 0.0, eta = 0.0;
  for (int it = 0; it < 30; ++it) {
    const auto n = facet.shape(xi, eta);
    const auto d = facet.shapeDerivatives(xi, eta);
    double fx = -valueOf(p.x), fy = -valueOf(p.y), j00 = 0, j01 = 0, j10 = 0, j11 = 0;
    for (int a = 0; a < 4; ++a) {
      const double px = valueOf(projected[a].x), py = valueOf(projected[a].y);
      fx += n[a] * px, fy += n[a] * py;
      j00 += d[0][a] * px, j01 += d[1][a] * px, j10 += d[0][a] * py, j11 += d[1][a] * py;
    }
    const double det = j00 * j11 - j01 * j10;
    const double dxi = (j11 * fx - j01 * fy) / det, deta = (j00 * fy - j10 * fx) / det;
    xi -= dxi, eta -= deta;
    if (std::abs(dxi) + std::abs(deta) < 1e-15) break;
  }
  std::array<T, 2> s{T(xi), T(eta)};
  for (int step = 0; step < 2; ++step) {
    const auto n = facet.shape(s[0], s[1]);
    const auto d = facet.shapeDerivatives(s[0], s[1]);
    T fx = T(0.0) - p.x, fy = T(0.0) - p.y, j00(0.0), j01(0.0), j10(0.0), j11(0.0);
    for (int a = 0; a < 4; ++a) {
      fx = fx + n[a] * projected[a].x, fy = fy + n[a] * projected[a].y;
      j00 = j00 + d[0][a] * projected[a].x, j01 = j01 + d[1][a] * projected[a].x;
      j10 = j10 + d[0][a] * projected[a].y, j11 = j11 + d[1][a] * projected[a].y;
    }
    const T det = j00 * j11 - j01 * j10;
    s[0] = s[0] - (j11 * fx - j01 * fy) / det;
    s[1] = s[1] - (j00 * fy - j10 * fx) / det;
  }
  return s;
}

/// The projection plane (eq. M13): through the slave facet's centre c, normal n_0 (the slave facet's unit
/// normal there), with the in-plane basis e_1 (the slave edge 0 → 1 without its normal part), e_2 = n_0 × e_1.
template <class T>
struct ProjectionPlane {
  Point3<T> centre, normal, e1, e2;
  explicit ProjectionPlane(const LinearFacet<T>& slave)
      : centre(slave.centre()), normal(unit(slave.centreNormal())) {
    const Point3<T> edge = slave.node[1] - slave.node[0];
    e1 = unit(edge - times(normal, dot(edge, normal)));
    e2 = cross(normal, e1);
  }
  PlanePoint<T> project(const Point3<T>& x) const {
    const Point3<T> r = x - centre;
    return {dot(r, e1), dot(r, e2)};
  }
  std::vector<PlanePoint<T>> project(const LinearFacet<T>& facet) const {
    std::vector<PlanePoint<T>> out;
    for (int a = 0; a < facet.count; ++a) out.push_back(project(facet.node[a]));
    return out;
  }
};

template <class T>
double facetDiameter(const LinearFacet<T>& f) {
  double h = 0;
  for (int a = 0; a < f.count; ++a)
    for (int b = a + 1; b < f.count; ++b) {
      const Point3<double> d = values(f.node[a] - f.node[b]);
      h = std::max(h, std::sqrt(dot(d, d)));
    }
  return h;
}

/// Whether the pair can carry a force: the master faces the slave (n_m · n_0 ≤ −kMortarMinFacing) and
/// its plane lies within one facet size of the slave's centre along n_0 (not the far side of a thin body,
/// not far in front), as in 2D. Measured to the master's plane, not its centre: a large master facet (a
/// rigid plane) has its centre far to the side of a tilted slave facet that it touches.
template <class T>
bool facing(const LinearFacet<T>& slave, const LinearFacet<T>& master, const ProjectionPlane<T>& plane, double size) {
  const Point3<double> n0 = values(plane.normal), nm = values(unit(master.centreNormal()));
  const double cosine = dot(n0, nm);
  if (cosine > -kMortarMinFacing) return false;
  const double distance = dot(values(master.centre() - slave.centre()), nm) / cosine;
  return std::abs(distance) <= size;
}

}  // namespace contessa::contact::mortar3d
