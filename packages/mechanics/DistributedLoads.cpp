#include "mechanics/DistributedLoads.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mechanics/QuadraticCells.hpp"
#include "mechanics/ReferenceElement.hpp"
#include "mechanics/ShapeFunctions.hpp"
#include "mechanics/Simplices.hpp"
#include "mechanics/Wedges.hpp"

namespace contessa::mechanics {
namespace {

constexpr double kPi = 3.14159265358979323846;

// What every facet point offers the load kernels, from its shape values N and gradients dN (CRTP):
// the point Σ_a N_a x_a and the tangents ∂x/∂ξ_m = Σ_a ∂N_a/∂ξ_m x_a (g[m][i]) at positions x.
template <class Cell, int M>
struct FacetPoint {
  static constexpr int kParametric = M;  ///< M = D − 1 for a facet, D for a cell
  template <int D>
  std::array<double, D> point(const double* x) const {
    const auto& c = static_cast<const Cell&>(*this);
    std::array<double, D> p{};
    for (int a = 0; a < Cell::kNodes; ++a)
      for (int i = 0; i < D; ++i) p[i] += c.N[a] * x[D * a + i];
    return p;
  }
  template <int D>
  std::array<std::array<double, D>, M> tangents(const double* x) const {
    const auto& c = static_cast<const Cell&>(*this);
    std::array<std::array<double, D>, M> g{};
    for (int a = 0; a < Cell::kNodes; ++a)
      for (int m = 0; m < M; ++m)
        for (int i = 0; i < D; ++i) g[m][i] += c.dN[M * a + m] * x[D * a + i];
    return g;
  }
};

// A multilinear cell of parametric dimension M (a 2-node edge, a 4-node quadrilateral, an 8-node
// hexahedron) with its nodes in Exodus order: the corners of [−1, 1]^M, the first two coordinates
// going round counter-clockwise, the third one (if any) −1 for the first four nodes and +1 after.
template <int M>
struct MultilinearCell : FacetPoint<MultilinearCell<M>, M> {
  static constexpr int kNodes = 1 << M;
  static double corner(int a, int i) {
    static const double kCyclic[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    if (M == 1) return a == 0 ? -1.0 : 1.0;
    if (i < 2) return kCyclic[a % 4][i];
    return a < 4 ? -1.0 : 1.0;
  }
  std::array<double, kNodes> N{};      ///< shape functions at a point
  std::array<double, kNodes * M> dN{};  ///< ∂N_a/∂ξ_m at M·a + m

  /// 2 Gauss points per direction: N_a times the area vector (degree ≤ 2 per direction) exactly, also
  /// with w = 2πr.
  static auto rule() { return gaussLegendreRule<M, 2>(); }

  explicit MultilinearCell(const std::array<double, M>& xi) {
    for (int a = 0; a < kNodes; ++a) {
      std::array<double, M> factor{};
      for (int i = 0; i < M; ++i) factor[i] = 0.5 * (1.0 + corner(a, i) * xi[i]);
      N[a] = 1.0;
      for (int i = 0; i < M; ++i) N[a] *= factor[i];
      for (int m = 0; m < M; ++m) {
        double d = 0.5 * corner(a, m);
        for (int i = 0; i < M; ++i)
          if (i != m) d *= factor[i];
        dN[M * a + m] = d;
      }
    }
  }

};

// The 1D shapes of the edges of 2D cells, in Exodus order (corners, then the mid-edge node).
struct LinearSegment : ShapeFromValues<LinearSegment, 1, 2> {
  static constexpr int kNodes = 2;
  template <class T>
  static void values(const T* xi, T* N) {
    N[0] = 0.5 * (1.0 - xi[0]);
    N[1] = 0.5 * (1.0 + xi[0]);
  }
};
struct QuadraticSegment : ShapeFromValues<QuadraticSegment, 1, 3> {
  static constexpr int kNodes = 3;
  template <class T>
  static void values(const T* xi, T* N) {
    N[0] = 0.5 * xi[0] * (xi[0] - 1.0);
    N[1] = 0.5 * xi[0] * (xi[0] + 1.0);
    N[2] = 1.0 - xi[0] * xi[0];
  }
};

/// The degree-4 rule on the unit triangle (6 points; Dunavant 1985, table for p = 4), for the quadratic
/// triangle: N_a (degree 2) times the area vector of a curved face (degree 2).
std::array<QuadraturePoint<2>, 6> triangleRuleDegree4() {
  const double a = 0.445948490915965, wa = 0.5 * 0.223381589678011;
  const double b = 0.091576213509771, wb = 0.5 * 0.109951743655322;
  return {{{{a, a}, wa}, {{1.0 - 2.0 * a, a}, wa}, {{a, 1.0 - 2.0 * a}, wa},
           {{b, b}, wb}, {{1.0 - 2.0 * b, b}, wb}, {{b, 1.0 - 2.0 * b}, wb}}};
}

/// A facet of any shape of the solid kernels (or the segments above) at one point: the interface of
/// MultilinearCell (N, dN, point, tangents), the shape's values and gradients, and its load rule.
template <int M, class Shape, class Rule>
struct ShapeCell : FacetPoint<ShapeCell<M, Shape, Rule>, M> {
  static constexpr int kNodes = Shape::kNodes;
  std::array<double, kNodes> N{};
  std::array<double, kNodes * M> dN{};

  static auto rule() { return Rule::get(); }
  explicit ShapeCell(const std::array<double, M>& xi) {
    Shape::shapeValues(xi.data(), N.data());
    Shape::shapeGradients(xi.data(), dN.data());
  }
};

// The rules, exact for N_a times the area vector on a facet of the shape (and with w = 2πr on a 2D edge):
// degree 3 on a 3-node edge (5 with w), degree 1 on a flat triangle, 4 on a 6-node one, 5 per direction
// on an 8- or 9-node face.
struct GaussLine3 {
  static auto get() { return gaussLegendreRule<1, 3>(); }
};
struct TriangleCentroid {
  static auto get() { return triangleRule<1>(); }
};
struct TriangleDegree4 {
  static auto get() { return triangleRuleDegree4(); }
};
struct GaussSquare3 {
  static auto get() { return gaussLegendreRule<2, 3>(); }
};

using Line3Cell = ShapeCell<1, QuadraticSegment, GaussLine3>;
using Tri3Cell = ShapeCell<2, LinearTriangle, TriangleCentroid>;
using Tri6Cell = ShapeCell<2, QuadraticTriangle, TriangleDegree4>;
using Quad8Cell = ShapeCell<2, SerendipityQuadrilateral, GaussSquare3>;
using Quad9Cell = ShapeCell<2, LagrangeQuadrilateral, GaussSquare3>;

template <class Cell>
struct CellTag {
  using type = Cell;
};

/// Calls f with the CellTag of the facet cell of `nodes` nodes of a D-dimensional solid: 2D edges of 2 or 3
/// nodes, 3D faces of 3, 4, 6, 8 or 9 (the Exodus sides of every cell family, mesh::sideNodes).
template <int D, class F>
auto withFacetCell(int nodes, F&& f) {
  if constexpr (D == 2) {
    if (nodes == 2) return f(CellTag<MultilinearCell<1>>{});
    if (nodes == 3) return f(CellTag<Line3Cell>{});
  } else {
    if (nodes == 4) return f(CellTag<MultilinearCell<2>>{});
    if (nodes == 3) return f(CellTag<Tri3Cell>{});
    if (nodes == 6) return f(CellTag<Tri6Cell>{});
    if (nodes == 8) return f(CellTag<Quad8Cell>{});
    if (nodes == 9) return f(CellTag<Quad9Cell>{});
  }
  throw std::logic_error("DistributedLoads: no facet of " + std::to_string(nodes) + " nodes in " +
                         std::to_string(D) + "D");
}

int permutationSign(int i, int j, int k) { return (i - j) * (j - k) * (k - i) / 2; }  // ε_ijk for 0..2

// The facet geometry, the one dimension-specific piece (theory-solids eq. 8.1): the area vector
// a = n |∂x/∂ξ| (per unit parent measure) from the facet's tangents, outward for an Exodus side,
// and its derivative ∂a_i/∂g_mj.
template <int D>
std::array<double, D> areaVector(const std::array<std::array<double, D>, D - 1>& g) {
  if constexpr (D == 2) {
    return {g[0][1], -g[0][0]};  // the tangent turned clockwise
  } else {
    return {g[0][1] * g[1][2] - g[0][2] * g[1][1], g[0][2] * g[1][0] - g[0][0] * g[1][2],
            g[0][0] * g[1][1] - g[0][1] * g[1][0]};  // g_0 × g_1
  }
}

template <int D>
std::array<std::array<double, D * D>, D - 1> areaVectorDerivative(const std::array<std::array<double, D>, D - 1>& g) {
  std::array<std::array<double, D * D>, D - 1> d{};
  if constexpr (D == 2) {
    d[0] = {0.0, 1.0, -1.0, 0.0};
  } else {
    // ∂(g_0 × g_1)_i/∂g_0j = ε_ijk g_1k and ∂(g_0 × g_1)_i/∂g_1k = ε_ijk g_0j.
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) {
          d[0][3 * i + j] += permutationSign(i, j, k) * g[1][k];
          d[1][3 * i + k] += permutationSign(i, j, k) * g[0][j];
        }
  }
  return d;
}

template <int D>
double norm(const std::array<double, D>& v) {
  double s = 0.0;
  for (double c : v) s += c * c;
  return std::sqrt(s);
}

// det ∂X/∂ξ of a cell at one point (the columns are the tangents).
template <int D>
double cellJacobian(const std::array<std::array<double, D>, D>& g) {
  if constexpr (D == 2) {
    return g[0][0] * g[1][1] - g[0][1] * g[1][0];
  } else {
    return g[0][0] * (g[1][1] * g[2][2] - g[1][2] * g[2][1]) - g[1][0] * (g[0][1] * g[2][2] - g[0][2] * g[2][1]) +
           g[2][0] * (g[0][1] * g[1][2] - g[0][2] * g[1][1]);
  }
}

}  // namespace

double RevolvedMeasure::weight(const double* x) const { return 2.0 * kPi * x[0]; }
void RevolvedMeasure::gradient(const double*, double* dwdx) const {
  dwdx[0] = 2.0 * kPi;
  dwdx[1] = 0.0;
}

namespace {

template <int D, class Cell>
void followerPressureOn(const double* x, double p, const LoadMeasure& measure, double* force, double* stiffness) {
  constexpr int M = D - 1, K = Cell::kNodes, n = D * K;
  for (int r = 0; r < n; ++r) force[r] = 0.0;
  if (stiffness)
    for (int r = 0; r < n * n; ++r) stiffness[r] = 0.0;
  // The cell's rule integrates N_a a exactly on an undistorted facet (Cell::rule).
  for (const auto& q : Cell::rule()) {
    const Cell cell(q.xi);
    const auto g = cell.template tangents<D>(x);
    const auto xq = cell.template point<D>(x);
    const auto area = areaVector<D>(g);
    const double w = measure.weight(xq.data());
    const double s = -p * q.weight;
    // eq. (8.2): f_a = −p Σ_q N_a w a (the outward area vector a = n da/dξ).
    for (int a = 0; a < K; ++a)
      for (int i = 0; i < D; ++i) force[D * a + i] += s * w * cell.N[a] * area[i];
    if (!stiffness) continue;
    // eq. (8.4): ∂f_ai/∂x_bj = −p Σ_q N_a (w Σ_m ∂N_b/∂ξ_m ∂a_i/∂g_mj + a_i ∂w/∂x_j N_b).
    const auto dArea = areaVectorDerivative<D>(g);
    std::array<double, D> dw{};
    measure.gradient(xq.data(), dw.data());
    for (int b = 0; b < K; ++b) {
      std::array<double, D * D> column{};  // ∂(w a_i)/∂x_bj
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) {
          double v = area[i] * dw[j] * cell.N[b];
          for (int m = 0; m < M; ++m) v += w * cell.dN[M * b + m] * dArea[m][D * i + j];
          column[D * i + j] = v;
        }
      for (int a = 0; a < K; ++a)
        for (int i = 0; i < D; ++i)
          for (int j = 0; j < D; ++j) stiffness[(D * a + i) * n + D * b + j] += s * cell.N[a] * column[D * i + j];
    }
  }
}

// The reference measure per unit parent measure at one point (theory-solids eqs. 8.5, 8.6): |a(X)| on a facet
// (dA = |a| dξ), det(∂X/∂ξ) on a cell (dV = det(∂X/∂ξ) dξ).
template <int D, class Cell>
double referenceJacobian(const Cell& cell, const double* X) {
  const auto g = cell.template tangents<D>(X);
  if constexpr (Cell::kParametric == D) return cellJacobian<D>(g);
  else return norm<D>(areaVector<D>(g));
}

// A dead load v (per reference area of a facet, eq. 8.5, or per reference volume of a cell, eq. 8.6):
// f_a = Σ_q W_q w(X_q) J_q N_a v, J the reference measure above.
template <int D, class Cell>
void deadLoadOn(const double* X, const double* v, const LoadMeasure& measure, double* force) {
  constexpr int K = Cell::kNodes;
  for (int r = 0; r < D * K; ++r) force[r] = 0.0;
  for (const auto& q : Cell::rule()) {
    const Cell cell(q.xi);
    const auto Xq = cell.template point<D>(X);
    const double dA = q.weight * measure.weight(Xq.data()) * referenceJacobian<D>(cell, X);
    for (int a = 0; a < K; ++a)
      for (int i = 0; i < D; ++i) force[D * a + i] += dA * cell.N[a] * v[i];
  }
}

template <int D, class Cell>
double measureOn(const double* X, const LoadMeasure& measure) {
  double total = 0.0;
  for (const auto& q : Cell::rule()) {
    const Cell cell(q.xi);
    const auto Xq = cell.template point<D>(X);
    total += q.weight * measure.weight(Xq.data()) * referenceJacobian<D>(cell, X);
  }
  return total;
}

}  // namespace

bool isLoadFacet(int D, int nodes) {
  if (D == 2) return nodes == 2 || nodes == 3;
  return D == 3 && (nodes == 3 || nodes == 4 || nodes == 6 || nodes == 8 || nodes == 9);
}

template <int D>
void followerPressure(int nodes, const double* x, double p, const LoadMeasure& measure, double* force,
                      double* stiffness) {
  withFacetCell<D>(nodes, [&](auto cell) {
    followerPressureOn<D, typename decltype(cell)::type>(x, p, measure, force, stiffness);
  });
}

template <int D>
void followerPressure(const double* x, double p, const LoadMeasure& measure, double* force, double* stiffness) {
  followerPressure<D>(facetNodeCount(D), x, p, measure, force, stiffness);
}

template <int D>
void facetTraction(int nodes, const double* X, const double* t, const LoadMeasure& measure, double* force) {
  withFacetCell<D>(nodes, [&](auto cell) { deadLoadOn<D, typename decltype(cell)::type>(X, t, measure, force); });
}

template <int D>
void facetTraction(const double* X, const double* t, const LoadMeasure& measure, double* force) {
  facetTraction<D>(facetNodeCount(D), X, t, measure, force);
}

template <int D>
double facetMeasure(int nodes, const double* X, const LoadMeasure& measure) {
  return withFacetCell<D>(nodes,
                          [&](auto cell) { return measureOn<D, typename decltype(cell)::type>(X, measure); });
}

template <int D>
double facetMeasure(const double* X, const LoadMeasure& measure) {
  return facetMeasure<D>(facetNodeCount(D), X, measure);
}

namespace {
// The cells' load rules: the element's own rule (ReferenceElement.hpp interface) where it integrates
// N_a w det(∂X/∂ξ) exactly on a straight-sided cell, a richer one where it does not. With w = 1 (plane strain,
// 3D) and w = 2πr (2D revolved, one degree more):
//   Quad4, Hex8     2 Gauss points per direction (MultilinearCell): degree 3 per direction, N_a w det J ≤ 3;
//   Q8, Q9          3 × 3 (the element's): N_a w det J ≤ 4 per direction;
//   Hex20, Hex27    the element's 3 × 3 × 3: N_a det J ≤ 4 per direction on a trilinear geometry;
//   Tet4, Tet10     the element's 1 and 4 points: N_a of degree 1 and 2, det J constant on a straight-sided cell;
//   Wedge6          the element's 3 × 2: N_a det J of degree 2 in (ξ, η), 3 in ζ;
//   Tri3            3 points (degree 2: N_a w), not the element's centroid (degree 1, enough for w = 1 only);
//   Tri6            the 6-point degree-4 rule (N_a w of degree 3), not the element's 3 points (degree 2);
//   Wedge15         the 6-point triangle × 3 Gauss points: N_a det J of degree 3 in (ξ, η) (the element's
//                   3-point triangle is degree 2).
template <class Shape>
struct OwnRule {
  static auto get() { return Shape::quadrature(); }
};
struct TriangleDegree2 {
  static auto get() { return triangleRule<3>(); }
};
struct WedgeDegree4By3 {
  static std::array<QuadraturePoint<3>, 18> get() {
    const auto triangle = triangleRuleDegree4();
    const auto line = gaussLegendreRule<1, 3>();
    std::array<QuadraturePoint<3>, 18> rule{};
    for (std::size_t t = 0; t < triangle.size(); ++t)
      for (std::size_t l = 0; l < line.size(); ++l)
        rule[3 * t + l] = {{triangle[t].xi[0], triangle[t].xi[1], line[l].xi[0]}, triangle[t].weight * line[l].weight};
    return rule;
  }
};

template <class Shape>
using OwnRuleCell = ShapeCell<Shape::kDimension, Shape, OwnRule<Shape>>;

/// Calls f with the CellTag of the cell of `nodes` nodes of a D-dimensional solid: every cell family of the
/// element kernels (ElementFactory.cpp), told apart by its node count within a dimension. Quad4 and Hex8 keep
/// MultilinearCell (the same arithmetic as before the other families came).
template <int D, class F>
auto withVolumeCell(int nodes, F&& f) {
  if constexpr (D == 2) {
    if (nodes == 4) return f(CellTag<MultilinearCell<2>>{});
    if (nodes == 3) return f(CellTag<ShapeCell<2, LinearTriangle, TriangleDegree2>>{});
    if (nodes == 6) return f(CellTag<Tri6Cell>{});
    if (nodes == 8) return f(CellTag<Quad8Cell>{});
    if (nodes == 9) return f(CellTag<Quad9Cell>{});
  } else {
    if (nodes == 8) return f(CellTag<MultilinearCell<3>>{});
    if (nodes == 4) return f(CellTag<OwnRuleCell<LinearTetrahedron>>{});
    if (nodes == 10) return f(CellTag<OwnRuleCell<QuadraticTetrahedron>>{});
    if (nodes == 20) return f(CellTag<OwnRuleCell<SerendipityHexahedron>>{});
    if (nodes == 27) return f(CellTag<OwnRuleCell<LagrangeHexahedron>>{});
    if (nodes == 6) return f(CellTag<OwnRuleCell<LinearWedge>>{});
    if (nodes == 15) return f(CellTag<ShapeCell<3, QuadraticWedge, WedgeDegree4By3>>{});
  }
  throw std::logic_error("DistributedLoads: no cell of " + std::to_string(nodes) + " nodes in " +
                         std::to_string(D) + "D");
}

}  // namespace

bool isLoadCell(int D, int nodes) {
  if (D == 2) return nodes == 3 || nodes == 4 || nodes == 6 || nodes == 8 || nodes == 9;
  return D == 3 && (nodes == 4 || nodes == 6 || nodes == 8 || nodes == 10 || nodes == 15 || nodes == 20 || nodes == 27);
}

template <int D>
void bodyForce(int nodes, const double* X, const double* b, const LoadMeasure& measure, double* force) {
  withVolumeCell<D>(nodes, [&](auto cell) { deadLoadOn<D, typename decltype(cell)::type>(X, b, measure, force); });
}

template <int D>
void bodyForce(const double* X, const double* b, const LoadMeasure& measure, double* force) {
  bodyForce<D>(cellNodeCount(D), X, b, measure, force);
}

template <int D>
double cellMeasure(int nodes, const double* X, const LoadMeasure& measure) {
  return withVolumeCell<D>(nodes,
                           [&](auto cell) { return measureOn<D, typename decltype(cell)::type>(X, measure); });
}

template <int D>
double cellMeasure(const double* X, const LoadMeasure& measure) {
  return cellMeasure<D>(cellNodeCount(D), X, measure);
}

template void followerPressure<2>(const double*, double, const LoadMeasure&, double*, double*);
template void followerPressure<3>(const double*, double, const LoadMeasure&, double*, double*);
template void facetTraction<2>(const double*, const double*, const LoadMeasure&, double*);
template void facetTraction<3>(const double*, const double*, const LoadMeasure&, double*);
template void bodyForce<2>(const double*, const double*, const LoadMeasure&, double*);
template void bodyForce<3>(const double*, const double*, const LoadMeasure&, double*);
template double facetMeasure<2>(const double*, const LoadMeasure&);
template double facetMeasure<3>(const double*, const LoadMeasure&);
template void followerPressure<2>(int, const double*, double, const LoadMeasure&, double*, double*);
template void followerPressure<3>(int, const double*, double, const LoadMeasure&, double*, double*);
template void facetTraction<2>(int, const double*, const double*, const LoadMeasure&, double*);
template void facetTraction<3>(int, const double*, const double*, const LoadMeasure&, double*);
template double facetMeasure<2>(int, const double*, const LoadMeasure&);
template double facetMeasure<3>(int, const double*, const LoadMeasure&);
template double cellMeasure<2>(const double*, const LoadMeasure&);
template double cellMeasure<3>(const double*, const LoadMeasure&);
template void bodyForce<2>(int, const double*, const double*, const LoadMeasure&, double*);
template void bodyForce<3>(int, const double*, const double*, const LoadMeasure&, double*);
template double cellMeasure<2>(int, const double*, const LoadMeasure&);
template double cellMeasure<3>(int, const double*, const LoadMeasure&);

}  // namespace contessa::mechanics
