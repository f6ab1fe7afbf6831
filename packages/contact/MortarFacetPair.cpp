#include "contact/MortarFacetPair.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "contact/MortarClipping.hpp"
#include "contact/MortarDual.hpp"
#include "contact/MortarSegment.hpp"  // kMortarMinFacing, kMortarSnap: the same rules as in 2D

namespace contessa::contact {

namespace {

constexpr int kN = kMortarFacetPairCoordinates;

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
  std::array<Point3<T>, kMortarFacetNodes> node{};

  template <class S>
  std::array<S, kMortarFacetNodes> shape(const S& xi, const S& eta) const {
    if (count == 3) return {1.0 - xi - eta, xi, eta, S(0.0)};
    return {0.25 * (1.0 - xi) * (1.0 - eta), 0.25 * (1.0 + xi) * (1.0 - eta), 0.25 * (1.0 + xi) * (1.0 + eta),
            0.25 * (1.0 - xi) * (1.0 + eta)};
  }
  /// ∂N_a/∂ξ and ∂N_a/∂η.
  template <class S>
  std::array<std::array<S, kMortarFacetNodes>, 2> shapeDerivatives(const S& xi, const S& eta) const {
    if (count == 3) return {{{S(-1.0), S(1.0), S(0.0), S(0.0)}, {S(-1.0), S(0.0), S(1.0), S(0.0)}}};
    return {{{-0.25 * (1.0 - eta), 0.25 * (1.0 - eta), 0.25 * (1.0 + eta), -0.25 * (1.0 + eta)},
             {-0.25 * (1.0 - xi), -0.25 * (1.0 + xi), 0.25 * (1.0 + xi), 0.25 * (1.0 - xi)}}};
  }
  Point3<T> at(const std::array<T, kMortarFacetNodes>& n) const {
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

template <class T>
LinearFacet<T> facetOf(const FacetPairCoordinates<T>& x, int first, int count) {
  LinearFacet<T> f;
  f.count = count;
  for (int a = 0; a < count; ++a) f.node[a] = {x[3 * (first + a)], x[3 * (first + a) + 1], x[3 * (first + a) + 2]};
  return f;
}

}  // namespace

template <class T>
MortarFacetPairGaps<T> integrateFacetPair(const FacetPairCoordinates<T>& x, double referenceArea,
                                          const MortarFacetPairShape& shape) {
  MortarFacetPairGaps<T> out;
  const LinearFacet<T> slave = facetOf(x, 0, shape.slaveNodes), master = facetOf(x, kMortarFacetNodes, shape.masterNodes);
  const ProjectionPlane<T> plane(slave);
  const double size = std::max(facetDiameter(slave), facetDiameter(master));
  if (!facing(slave, master, plane, size)) return out;
  // eq. M14: the projected slave polygon (anticlockwise about n_0) clipped by the projected master
  // polygon, which runs clockwise about n_0 (its normal is about −n_0): reversed first.
  const std::vector<PlanePoint<T>> slavePolygon = plane.project(slave), masterProjected = plane.project(master);
  std::vector<PlanePoint<T>> masterPolygon(masterProjected.rbegin(), masterProjected.rend());
  const T slaveArea2 = twiceSignedArea(slavePolygon);
  if (!(valueOf(twiceSignedArea(masterPolygon)) > 0.0) || !(valueOf(slaveArea2) > 0.0)) return out;
  const std::vector<PlanePoint<T>> clip = clipConvexPolygon(slavePolygon, masterPolygon, kMortarClipSnap * size);
  if (clip.size() < 3 || !(valueOf(twiceSignedArea(clip)) > kMortarSnap * valueOf(slaveArea2))) return out;
  out.overlaps = true;
  // eq. M15–M17: triangles (c, v_i, v_i+1) about the vertex centroid c, Gauss points p on each; at p the
  // slave and master points x_s(ξ), x_m(η) projecting onto p, the gap g = (x_s − x_m) · n_m(η), and
  // g̃_a += w N_a(ξ) g |T| A_0 / A_projected.
  const PlanePoint<T> c = vertexCentroid(clip);
  const T measure = referenceArea / (0.5 * slaveArea2);
  for (std::size_t i = 0; i < clip.size(); ++i) {
    const PlanePoint<T> u = clip[i] - c, v = clip[(i + 1) % clip.size()] - c;
    const T triangleArea = 0.5 * planeCross(u, v);
    for (const TrianglePoint& q : triangleRule()) {
      const PlanePoint<T> p = c + scaled(u, q.l1) + scaled(v, q.l2);
      const std::array<T, 2> xi = inverseMap(slave, slavePolygon, p), eta = inverseMap(master, masterProjected, p);
      const std::array<T, kMortarFacetNodes> ns = slave.shape(xi[0], xi[1]);
      const T g = dot(slave.at(ns) - master.at(master.shape(eta[0], eta[1])), master.unitNormal(eta[0], eta[1]));
      const T weight = q.weight * triangleArea * measure;
      for (int a = 0; a < slave.count; ++a) {
        out.weightedGap[a] = out.weightedGap[a] + weight * ns[a] * g;
        out.mortarArea[a] = out.mortarArea[a] + weight * ns[a];
      }
    }
  }
  return out;
}

MortarFacetPairGaps<double> facetPairGaps(const FacetPairCoordinates<double>& x, double referenceArea,
                                          const MortarFacetPairShape& shape) {
  return integrateFacetPair(x, referenceArea, shape);
}

namespace {
template <int V>
MortarFacetPairDerivatives differentiateFacetPair(const FacetPairCoordinates<double>& x, double referenceArea,
                                                  const MortarFacetPairShape& shape,
                                                  const KernelVariables<kN>& variables) {
  const MortarFacetPairGaps<HessianDual<V>> g = integrateFacetPair(variables.template seed<V>(x), referenceArea, shape);
  MortarFacetPairDerivatives out;
  out.overlaps = g.overlaps;
  for (int a = 0; a < kMortarFacetNodes; ++a) {
    out.weightedGap[a] = g.weightedGap[a].v;
    out.mortarArea[a] = g.mortarArea[a].v;
    variables.extract(g.weightedGap[a], out.gradient[a], out.hessian[a]);
  }
  return out;
}
}  // namespace

MortarFacetPairDerivatives facetPairDerivatives(const FacetPairCoordinates<double>& x, double referenceArea,
                                                const MortarFacetPairShape& shape, const double* masterMotion) {
  constexpr int master = 3 * kMortarFacetNodes;  // the master's first coordinate
  if (masterMotion == nullptr) return differentiateFacetPair<kN>(x, referenceArea, shape, ownVariables<kN>());
  // A rigid master: the twelve slave coordinates and the motion (MortarDual.hpp, KernelVariables).
  return differentiateFacetPair<master + 1>(x, referenceArea, shape, rigidBodyVariables<kN>(master, master, masterMotion));
}

}  // namespace contessa::contact
