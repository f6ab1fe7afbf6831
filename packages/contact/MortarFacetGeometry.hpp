#pragma once
// The 3D geometry the mortar facet-pair kernels share (MortarFacetPair.cpp for Tri3/Quad4 facets,
// MortarQuadraticFacetPair.cpp for Tri6 facets through their flat pieces): points in space, a linear facet
// (Tri3 or Quad4) with its shape functions, the projection plane of eq. M13, the inverse of eq. M16 and
// the facing test. Templated on the number type, as MortarClipping.hpp, for the nested dual numbers.
#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>
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

/// A linear facet's map in monomials, x(ξ, η) = x_0 + ξ x_ξ + η x_η + ξη x_ξη (a triangle's x_ξη = 0), for
/// the differentiated points and normals of eq. M17: each point costs six products of differentiated
/// numbers (ten when twisted) instead of the shape functions' sixteen, a term without derivatives (a rigid
/// master's edge vectors under a translation) is multiplied as a double, and where x_ξη is zero with its
/// derivatives (a triangle; a parallelogram moving affinely, as a rigid plate does) the tangents x_,ξ and
/// x_,η, and so the unit normal, are the same at every point of the facet: computed once per pair. The
/// values are those of LinearFacet's formulas in doubles, to the bit (withValue), so that the weighted
/// gaps do not depend on the number type.
template <class T>
struct FacetMap {
  LinearFacet<double> valueFacet;
  std::array<Point3<T>, 4> term;  ///< x_0, x_ξ, x_η, x_ξη
  std::array<Point3<double>, 4> termValue{};
  std::array<bool, 4> fixed{};  ///< the term has no derivatives: multiplied as doubles
  bool twisted = false;         ///< x_ξη ≠ 0 or has derivatives: the tangents vary over the facet
  Point3<T> flatNormal{};       ///< the unit normal, where not twisted

  explicit FacetMap(const LinearFacet<T>& f) {
    valueFacet.count = f.count;
    for (int a = 0; a < f.count; ++a) valueFacet.node[a] = values(f.node[a]);
    // A facet without derivatives (a motionless rigid master): its terms and normal in doubles, the same
    // values (the same formulas) and no derivatives to carry through the differentiated operations.
    bool still = true;
    for (int a = 0; a < f.count && still; ++a)
      still = hasNoDerivatives(f.node[a].x) && hasNoDerivatives(f.node[a].y) && hasNoDerivatives(f.node[a].z);
    if (still && !std::is_same_v<T, double>) {
      const auto doubles = monomialTerms(valueFacet);
      for (int k = 0; k < 4; ++k) term[k] = {T(doubles[k].x), T(doubles[k].y), T(doubles[k].z)};
    } else {
      term = monomialTerms(f);
    }
    for (int k = 0; k < 4; ++k) {
      termValue[k] = values(term[k]);
      fixed[k] = hasNoDerivatives(term[k].x) && hasNoDerivatives(term[k].y) && hasNoDerivatives(term[k].z);
    }
    const Point3<double>& c = termValue[3];
    twisted = !(fixed[3] && c.x == 0.0 && c.y == 0.0 && c.z == 0.0);
    if (twisted) return;
    if (fixed[1] && fixed[2] && !std::is_same_v<T, double>) {  // a normal without derivatives: in doubles
      const Point3<double> n = unit(cross(termValue[1], termValue[2]));
      flatNormal = {T(n.x), T(n.y), T(n.z)};
    } else {
      flatNormal = unit(cross(term[1], term[2]));
    }
  }
  /// x_0, x_ξ, x_η, x_ξη of a facet's nodes.
  template <class S>
  static std::array<Point3<S>, 4> monomialTerms(const LinearFacet<S>& f) {
    const auto& x = f.node;
    if (f.count == 3) return {x[0], x[1] - x[0], x[2] - x[0], Point3<S>{S(0.0), S(0.0), S(0.0)}};
    return {times(x[0] + x[1] + x[2] + x[3], 0.25), times(x[1] + x[2] - x[0] - x[3], 0.25),
            times(x[2] + x[3] - x[0] - x[1], 0.25), times(x[0] + x[2] - x[1] - x[3], 0.25)};
  }
  /// The point's and the normal's values (LinearFacet's formulas in doubles).
  Point3<double> valueAt(const std::array<double, 2>& s) const { return valueFacet.at(valueFacet.shape(s[0], s[1])); }
  Point3<double> valueNormal(const std::array<double, 2>& s) const { return valueFacet.unitNormal(s[0], s[1]); }
  /// Term k times s.
  Point3<T> scaledTerm(int k, const T& s) const {
    if (!fixed[k]) return times(term[k], s);
    const Point3<double>& v = termValue[k];
    return {s * v.x, s * v.y, s * v.z};
  }
  /// The point at (ξ, η) (eq. M16's x_s(ξ) or x_m(η)).
  Point3<T> at(const std::array<T, 2>& s) const {
    const Point3<double> value = valueFacet.at(valueFacet.shape(valueOf(s[0]), valueOf(s[1])));
    if constexpr (std::is_same_v<T, double>) {
      return value;
    } else {
      Point3<T> x = term[0] + scaledTerm(1, s[0]) + scaledTerm(2, s[1]);
      if (twisted) x = x + scaledTerm(3, s[0] * s[1]);
      return {withValue(x.x, value.x), withValue(x.y, value.y), withValue(x.z, value.z)};
    }
  }
  /// The normal has no derivatives (a triangle's or a parallelogram's moving by a translation, as a rigid
  /// plate does): a product with it is one of doubles (the same numbers, bar the signs of zeros).
  bool fixedNormal() const {
    return !twisted && hasNoDerivatives(flatNormal.x) && hasNoDerivatives(flatNormal.y) && hasNoDerivatives(flatNormal.z);
  }
  /// The unit normal x_,ξ × x_,η / ‖·‖ at (ξ, η) (LinearFacet::unitNormal's value).
  Point3<T> unitNormal(const std::array<T, 2>& s) const {
    const Point3<double> value = valueFacet.unitNormal(valueOf(s[0]), valueOf(s[1]));
    if constexpr (std::is_same_v<T, double>) {
      return value;
    } else {
      Point3<T> n = flatNormal;
      if (twisted) n = unit(cross(term[1] + scaledTerm(3, s[1]), term[2] + scaledTerm(3, s[0])));
      return {withValue(n.x, value.x), withValue(n.y, value.y), withValue(n.z, value.z)};
    }
  }
};

/// The parametric coordinates (ξ, η) of the facet point whose projection is p (eq. M16): the linear
/// map's inverse for a triangle; for a quadrilateral Newton's method converged on the values, then two
/// Newton steps in T from that root, which give its exact first (one step) and second (two steps)
/// derivatives by the implicit function theorem (HessianDual takes the overload below, which applies that
/// theorem directly).
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

/// The inverse map with its gradient and Hessian (eq. M16 differentiated): the root (ξ, η) of
/// F(ξ; P, p) = Σ_a N_a(ξ) P_a − p = 0 is the doubles' (the same values, to the bit, as every number type
/// gives), and its derivatives follow from the implicit function theorem at that root instead of Newton
/// steps in HessianDual arithmetic (each a few dozen products of gradient-and-Hessian numbers). With J the
/// map's Jacobian [F_,ξ F_,η], R = F(ξ_0; P, p) at the fixed root (linear in P and p: R'' = Σ N_a P_a'' − p'')
/// and J_k = F_,ξk (linear in P), differentiating F(ξ(x), x) = 0 twice gives
///     ξ' = −J⁻¹ R',
///     ξ'' = −J⁻¹ [ R'' + Σ_k (J_k' ⊗ ξ_k' + ξ_k' ⊗ J_k') + F_,ξη (ξ' ⊗ η' + η' ⊗ ξ') ],
/// F_,ξη = (P_0 − P_1 + P_2 − P_3)/4 for a quadrilateral (its only second derivative), 0 for a triangle.
template <int V>
std::array<HessianDual<V>, 2> inverseMap(const LinearFacet<HessianDual<V>>& facet,
                                         const std::vector<PlanePoint<HessianDual<V>>>& projected,
                                         const PlanePoint<HessianDual<V>>& p) {
  using H = HessianDual<V>;
  const int count = facet.count;
  LinearFacet<double> valueFacet;
  valueFacet.count = count;
  std::vector<PlanePoint<double>> valueProjected(projected.size());
  for (std::size_t a = 0; a < projected.size(); ++a) valueProjected[a] = {projected[a].x.v, projected[a].y.v};
  const std::array<double, 2> root = inverseMap(valueFacet, valueProjected, PlanePoint<double>{p.x.v, p.y.v});
  const auto n = valueFacet.shape(root[0], root[1]);
  const auto dn = valueFacet.shapeDerivatives(root[0], root[1]);
  // Per component c (x, y): R_c', R_c'', J_ck (value) and J_ck'.
  std::array<std::array<double, V>, 2> rg{}, xg{};
  std::array<std::array<double, H::kPacked>, 2> rh{};
  std::array<std::array<std::array<double, V>, 2>, 2> jg{};
  double j[2][2] = {{0.0, 0.0}, {0.0, 0.0}}, mixed[2] = {0.0, 0.0};
  for (int c = 0; c < 2; ++c) {
    const H& pc = c == 0 ? p.x : p.y;
    for (int i = 0; i < V; ++i) rg[c][i] = -pc.g[i];
    for (int k = 0; k < H::kPacked; ++k) rh[c][k] = -pc.h[k];
    for (int a = 0; a < count; ++a) {
      const H& pa = c == 0 ? projected[a].x : projected[a].y;
      for (int i = 0; i < V; ++i) {
        rg[c][i] += n[a] * pa.g[i];
        jg[c][0][i] += dn[0][a] * pa.g[i];
        jg[c][1][i] += dn[1][a] * pa.g[i];
      }
      for (int k = 0; k < H::kPacked; ++k) rh[c][k] += n[a] * pa.h[k];
      j[c][0] += dn[0][a] * pa.v;
      j[c][1] += dn[1][a] * pa.v;
    }
    if (count == 4) {
      const auto v = [&](int a) { return c == 0 ? projected[a].x.v : projected[a].y.v; };
      mixed[c] = 0.25 * (v(0) - v(1) + v(2) - v(3));
    }
  }
  const double det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
  const double inverse[2][2] = {{j[1][1] / det, -j[0][1] / det}, {-j[1][0] / det, j[0][0] / det}};
  std::array<H, 2> out{H(root[0], typename H::Unset{}), H(root[1], typename H::Unset{})};
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < V; ++i) xg[k][i] = out[k].g[i] = -(inverse[k][0] * rg[0][i] + inverse[k][1] * rg[1][i]);
  int packed = 0;
  for (int i = 0; i < V; ++i)
    for (int l = i; l < V; ++l, ++packed) {
      double q[2];
      const double cross = xg[0][i] * xg[1][l] + xg[1][i] * xg[0][l];
      for (int c = 0; c < 2; ++c)
        q[c] = rh[c][packed] + jg[c][0][i] * xg[0][l] + xg[0][i] * jg[c][0][l] + jg[c][1][i] * xg[1][l] +
               xg[1][i] * jg[c][1][l] + mixed[c] * cross;
      out[0].h[packed] = -(inverse[0][0] * q[0] + inverse[0][1] * q[1]);
      out[1].h[packed] = -(inverse[1][0] * q[0] + inverse[1][1] * q[1]);
    }
  return out;
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
  // On the values alone (the same numbers as T's values, without differentiating them).
  const auto valuesOf = [](const LinearFacet<T>& f) {
    LinearFacet<double> out;
    out.count = f.count;
    for (int a = 0; a < f.count; ++a) out.node[a] = values(f.node[a]);
    return out;
  };
  const LinearFacet<double> s = valuesOf(slave), m = valuesOf(master);
  const Point3<double> n0 = values(plane.normal), nm = unit(m.centreNormal());
  const double cosine = dot(n0, nm);
  if (cosine > -kMortarMinFacing) return false;
  const double distance = dot(m.centre() - s.centre(), nm) / cosine;
  return std::abs(distance) <= size;
}

/// Twice a polygon's signed area on the values alone (twiceSignedArea's value, not differentiated): for
/// the tests that only read it.
template <class T>
double twiceSignedAreaValue(const std::vector<PlanePoint<T>>& polygon) {
  std::vector<PlanePoint<double>> v(polygon.size());
  for (std::size_t i = 0; i < polygon.size(); ++i) v[i] = {valueOf(polygon[i].x), valueOf(polygon[i].y)};
  return twiceSignedArea(v);
}

}  // namespace contessa::contact::mortar3d
