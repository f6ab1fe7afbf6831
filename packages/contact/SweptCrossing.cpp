#include "contact/SweptCrossing.hpp"

#include <algorithm>
#include <cmath>

#include "contact/Projection.hpp"

namespace contessa::contact {

namespace {

template <class Point>
Point along(const Point& a, const Point& b, double t) {
  Point p{};
  for (std::size_t c = 0; c < p.size(); ++c) p[c] = (1.0 - t) * a[c] + t * b[c];
  return p;
}

/// One flat piece of a facet at time t: its vertices y_0 … y_{d−1}.
template <class Facet>
struct Piece {
  static constexpr int kDim = Facet::kSpaceDim;
  using Point = typename Facet::Point;
  std::array<Point, kDim> y{};

  Piece(const std::array<Point, Facet::kNodes>& facet0, const std::array<Point, Facet::kNodes>& facet1,
        const std::array<int, kDim>& nodes, double t) {
    for (int i = 0; i < kDim; ++i) y[i] = along(facet0[nodes[i]], facet1[nodes[i]], t);
  }

  std::array<Point, Facet::kSurfaceDim> edges() const {
    std::array<Point, Facet::kSurfaceDim> e{};
    for (int i = 0; i < Facet::kSurfaceDim; ++i) e[i] = subtract(y[i + 1], y[0]);
    return e;
  }

  /// φ = (x − y_0) · N: ‖N‖ times the signed distance of x from the piece's plane.
  double side(const Point& x) const { return dot(subtract(x, y[0]), Facet::areaNormal(edges())); }

  /// x projected on the piece's plane lies inside the piece (barycentric coordinates λ_i of y_1 … y_{d−1}
  /// with λ_i ≥ −tol and Σ λ_i ≤ 1 + tol).
  bool containsProjection(const Point& x, double tol) const {
    constexpr int n = Facet::kSurfaceDim;
    const auto e = edges();
    Matrix<n, n> gram;
    Vector<n> rhs{};
    const Point r = subtract(x, y[0]);
    double scale = 0.0;
    for (int i = 0; i < n; ++i) {
      rhs[i] = dot(e[i], r);
      for (int j = 0; j < n; ++j) gram(i, j) = dot(e[i], e[j]);
      scale = std::max(scale, gram(i, i));
    }
    const double det = determinant(gram);
    if (!(std::abs(det) > 1e-24 * std::pow(scale, n))) return false;  // degenerate piece
    const Vector<n> lambda = multiply(inverse(gram), rhs);
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
      if (lambda[i] < -tol) return false;
      sum += lambda[i];
    }
    return sum <= 1.0 + tol;
  }
};

/// Monomial coefficients of the polynomial of degree n − 1 through (t_i, v_i), i < n ≤ 4 (Gaussian
/// elimination with partial pivoting on the Vandermonde system; n is tiny and the t_i well spread).
std::array<double, 4> interpolate(const double* t, const double* v, int n) {
  double a[4][5] = {};
  for (int i = 0; i < n; ++i) {
    double power = 1.0;
    for (int j = 0; j < n; ++j, power *= t[i]) a[i][j] = power;
    a[i][n] = v[i];
  }
  for (int k = 0; k < n; ++k) {
    int pivot = k;
    for (int i = k + 1; i < n; ++i)
      if (std::abs(a[i][k]) > std::abs(a[pivot][k])) pivot = i;
    for (int j = 0; j <= n; ++j) std::swap(a[k][j], a[pivot][j]);
    for (int i = k + 1; i < n; ++i) {
      const double f = a[i][k] / a[k][k];
      for (int j = k; j <= n; ++j) a[i][j] -= f * a[k][j];
    }
  }
  std::array<double, 4> c{};
  for (int k = n - 1; k >= 0; --k) {
    double s = a[k][n];
    for (int j = k + 1; j < n; ++j) s -= a[k][j] * c[j];
    c[k] = s / a[k][k];
  }
  return c;
}

double evaluatePolynomial(const std::array<double, 4>& c, double t) { return ((c[3] * t + c[2]) * t + c[1]) * t + c[0]; }

/// Bisection on [a, b] where f changes sign; returns the root to round-off.
template <class F>
double bisect(const F& f, double a, double b) {
  const bool rising = f(a) < 0.0;
  for (int i = 0; i < 200 && b - a > 1e-16; ++i) {
    const double m = 0.5 * (a + b);
    if ((f(m) < 0.0) == rising)
      a = m;
    else
      b = m;
  }
  return 0.5 * (a + b);
}

/// The points of [0, 1] where the polynomial's derivative vanishes, with 0 and 1, ascending: between two
/// consecutive ones the polynomial is monotone.
std::array<double, 4> monotoneBreaks(const std::array<double, 4>& c, int& count) {
  // p'(t) = c1 + 2 c2 t + 3 c3 t²
  const double qa = 3.0 * c[3], qb = 2.0 * c[2], qc = c[1];
  std::array<double, 4> breaks{0.0};
  count = 1;
  const double scale = std::max({std::abs(qa), std::abs(qb), std::abs(qc)});
  if (scale > 0.0) {
    double r[2];
    int nr = 0;
    if (std::abs(qa) <= 1e-14 * scale) {
      if (std::abs(qb) > 0.0) r[nr++] = -qc / qb;
    } else {
      const double disc = qb * qb - 4.0 * qa * qc;
      if (disc >= 0.0) {
        // Numerically stable pair of roots.
        const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
        r[nr++] = q / qa;
        if (q != 0.0) r[nr++] = qc / q;
      }
    }
    std::sort(r, r + nr);
    for (int i = 0; i < nr; ++i)
      if (r[i] > 0.0 && r[i] < 1.0) breaks[count++] = r[i];
  }
  breaks[count++] = 1.0;
  return breaks;
}

/// The node x ends behind the facet itself, not only behind one of its flat pieces: its closest point on
/// the facet lies inside it (within `tol` in ξ) with g_N < 0 (eq. 4–6). On a curved facet (a 3-node edge,
/// a 6-, 8- or 9-node face, a warped 4-node face) the pieces are chords of the surface, and the sliver
/// between a chord and the surface, as deep as the facet's sagitta, lies in front of a facet that bulges
/// away from the slave (a master indented by the slave, theory-contact.md §12): a node resting there has
/// a positive gap and has crossed nothing. When Newton does not converge on the facet the pieces' verdict
/// stands.
template <class Facet>
bool endsBehindFacet(const typename Facet::Point& x, const std::array<typename Facet::Point, Facet::kNodes>& facet,
                     double tol) {
  if constexpr (Facet::kAffine) {
    return true;  // the facet is its one flat piece: the pieces' test was exact
  } else {
    const ProjectionResult<Facet> p = Projection<Facet>().project(x, facet);
    return !p.converged || (p.isPenetrating() && p.isInside(tol));
  }
}

}  // namespace

std::array<double, 3> signChangeRootsInUnitInterval(const std::array<double, 4>& c, int& count) {
  int nb = 0;
  const auto breaks = monotoneBreaks(c, nb);
  const auto p = [&](double t) { return evaluatePolynomial(c, t); };
  std::array<double, 3> roots{};
  count = 0;
  for (int i = 0; i + 1 < nb; ++i) {
    const double a = breaks[i], b = breaks[i + 1];
    if ((p(a) < 0.0) != (p(b) < 0.0)) roots[count++] = bisect(p, a, b);
  }
  return roots;
}

template <class Facet>
SweptCrossing sweptCrossing(const typename Facet::Point& slave0, const typename Facet::Point& slave1,
                            const std::array<typename Facet::Point, Facet::kNodes>& facet0,
                            const std::array<typename Facet::Point, Facet::kNodes>& facet1, double insideTolerance) {
  constexpr int d = Facet::kSpaceDim;
  const auto pieces = Facet::flatPieces();

  // Where the node ends: behind the facet and inside it (some piece with φ(1) < 0 contains its projection).
  bool endsBehind = false;
  for (const auto& nodes : pieces) {
    const Piece<Facet> end(facet0, facet1, nodes, 1.0);
    if (end.side(slave1) < 0.0 && end.containsProjection(slave1, insideTolerance)) endsBehind = true;
  }
  if (!endsBehind || !endsBehindFacet<Facet>(slave1, facet1, insideTolerance)) return {};

  for (int k = 0; k < Facet::kPieces; ++k) {
    const auto phi = [&](double t) {
      return Piece<Facet>(facet0, facet1, pieces[k], t).side(along(slave0, slave1, t));
    };
    const double phi0 = phi(0.0), phi1 = phi(1.0);
    if (!(phi0 >= 0.0 && phi1 < 0.0)) continue;
    // φ is a polynomial of degree d: its monomial coefficients from d + 1 samples give the points where
    // it turns, so that each monotone stretch is searched on its own.
    double ts[d + 1], vs[d + 1];
    for (int i = 0; i <= d; ++i) {
      ts[i] = static_cast<double>(i) / d;
      vs[i] = i == 0 ? phi0 : i == d ? phi1 : phi(ts[i]);
    }
    int nb = 0;
    const auto breaks = monotoneBreaks(interpolate(ts, vs, d + 1), nb);
    // The last stretch on which φ goes from ≥ 0 to < 0 holds the entry for good (φ(1) < 0).
    double entry = -1.0;
    for (int i = nb - 2; i >= 0 && entry < 0.0; --i) {
      const double a = breaks[i], b = breaks[i + 1];
      if (phi(a) >= 0.0 && phi(b) < 0.0) entry = phi(a) == 0.0 ? a : bisect(phi, a, b);
    }
    if (entry < 0.0) continue;
    const Piece<Facet> at(facet0, facet1, pieces[k], entry);
    if (at.containsProjection(along(slave0, slave1, entry), insideTolerance)) return {true, entry, k};
  }
  return {};
}

template SweptCrossing sweptCrossing<Line2Facet>(const Line2Facet::Point&, const Line2Facet::Point&,
                                                 const std::array<Line2Facet::Point, 2>&,
                                                 const std::array<Line2Facet::Point, 2>&, double);
template SweptCrossing sweptCrossing<Quad4Facet>(const Quad4Facet::Point&, const Quad4Facet::Point&,
                                                 const std::array<Quad4Facet::Point, 4>&,
                                                 const std::array<Quad4Facet::Point, 4>&, double);

template SweptCrossing sweptCrossing<Line3Facet>(const Line3Facet::Point&, const Line3Facet::Point&,
    const std::array<Line3Facet::Point, Line3Facet::kNodes>&, const std::array<Line3Facet::Point, Line3Facet::kNodes>&, double);
template SweptCrossing sweptCrossing<Tri3Facet>(const Tri3Facet::Point&, const Tri3Facet::Point&,
    const std::array<Tri3Facet::Point, Tri3Facet::kNodes>&, const std::array<Tri3Facet::Point, Tri3Facet::kNodes>&, double);
template SweptCrossing sweptCrossing<Tri6Facet>(const Tri6Facet::Point&, const Tri6Facet::Point&,
    const std::array<Tri6Facet::Point, Tri6Facet::kNodes>&, const std::array<Tri6Facet::Point, Tri6Facet::kNodes>&, double);
template SweptCrossing sweptCrossing<Quad8Facet>(const Quad8Facet::Point&, const Quad8Facet::Point&,
    const std::array<Quad8Facet::Point, Quad8Facet::kNodes>&, const std::array<Quad8Facet::Point, Quad8Facet::kNodes>&, double);
template SweptCrossing sweptCrossing<Quad9Facet>(const Quad9Facet::Point&, const Quad9Facet::Point&,
    const std::array<Quad9Facet::Point, Quad9Facet::kNodes>&, const std::array<Quad9Facet::Point, Quad9Facet::kNodes>&, double);

}  // namespace contessa::contact
