// The body force on every cell family (mechanics::bodyForce with a node count): its resultant Σ_a f_a against
// b ∫ w dV and its first moment Σ_a f_a X_a against b ∫ X w dV, with w = 1 (plane strain, 3D) and w = 2πr (the
// 2D cells revolved). The references are computed here, not by the kernels: the cell's geometry is a map φ(ξ)
// of its corners by the linear cell of its family (bilinear, trilinear, affine, the wedge's L_a (1 ± ζ)/2), the
// nodes of the quadratic cells sit on it, and the integrals of det ∇φ, φ det ∇φ and their products with 2πr are
// taken over the parent cell with a rule exact for them (5 Gauss points per direction, collapsed onto the
// triangle and the tetrahedron), which none of the kernels uses. On such a straight-sided but distorted cell
// every kernel's rule is exact (DistributedLoads.cpp lists why), so both identities hold to round-off, and so
// does every nodal force against b ∫ N_a w dV (which the identities alone would not catch: a rule exact for
// det J and X det J but not for N_a det J passes them).
// The curved quadratic quadrilaterals and hexahedra (mid-edge nodes moved off the straight edges) are checked
// against their own isoparametric map under the 5-point rule: Q8/Q9's 3 × 3 points are exact for det J (degree
// 3 per direction) times N_a, so the resultant and the first moment hold; Hex20/Hex27's 3 × 3 × 3 points are
// exact for det J (degree 5) only, so the resultant holds.
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "MechanicsTestUtilities.hpp"
#include "mechanics/DistributedLoads.hpp"
#include "mechanics/Hex8.hpp"
#include "mechanics/Quad4.hpp"
#include "mechanics/QuadraticCells.hpp"
#include "mechanics/Simplices.hpp"
#include "mechanics/Wedges.hpp"

namespace contessa::mechanics::test {
namespace {

enum class Parent { Cube, Simplex, Wedge };

/// 5-point Gauss–Legendre on [−1, 1] (exact to degree 9).
std::vector<QuadraturePoint<1>> gauss5() {
  const double a = std::sqrt(5.0 - 2.0 * std::sqrt(10.0 / 7.0)) / 3.0, b = std::sqrt(5.0 + 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
  const double wa = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0, wb = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
  return {{{-b}, wb}, {{-a}, wa}, {{0.0}, 128.0 / 225.0}, {{a}, wa}, {{b}, wb}};
}

/// The reference rule of a parent cell (D = 2 or 3), none of the kernels' rules: 5 Gauss points per direction
/// on the cube; on the triangle and the tetrahedron the cube's points collapsed onto them (ξ = u, η = v (1 − u),
/// ζ = w (1 − u)(1 − v) from [0, 1]^D, weight × (1 − u)^(D−1) (1 − v)^(D−2)): exact to degree 7 at least, far
/// above the integrands' 4; the wedge's: the collapsed triangle times 5 points in ζ.
std::vector<std::pair<std::array<double, 3>, double>> referenceRule(Parent parent, int D) {
  std::vector<std::pair<std::array<double, 3>, double>> rule;
  const auto line = gauss5();
  if (parent == Parent::Cube) {
    for (const auto& p : line)
      for (const auto& q : line) {
        if (D == 2) rule.push_back({{p.xi[0], q.xi[0], 0.0}, p.weight * q.weight});
        else
          for (const auto& s : line) rule.push_back({{p.xi[0], q.xi[0], s.xi[0]}, p.weight * q.weight * s.weight});
      }
    return rule;
  }
  // The triangle (of a 2D simplex or a wedge's cross-section) from (u, v) ∈ [0, 1]², its third direction ζ (the
  // wedge's, Gauss) or t (the tetrahedron's, collapsed again).
  for (const auto& p : line)
    for (const auto& q : line) {
      const double u = 0.5 * (1 + p.xi[0]), v = 0.5 * (1 + q.xi[0]);
      const double weight = 0.25 * p.weight * q.weight * (1 - u);
      if (parent == Parent::Simplex && D == 2) {
        rule.push_back({{u, v * (1 - u), 0.0}, weight});
        continue;
      }
      for (const auto& s : line) {
        if (parent == Parent::Wedge) {
          rule.push_back({{u, v * (1 - u), s.xi[0]}, weight * s.weight});
        } else {
          const double t = 0.5 * (1 + s.xi[0]);
          rule.push_back({{u, v * (1 - u), t * (1 - u) * (1 - v)}, weight * 0.5 * s.weight * (1 - u) * (1 - v)});
        }
      }
    }
  return rule;
}

/// A cell under test: its node count, parent, and the map from parent coordinates to the Shape's N_a and
/// ∂N_a/∂ξ (for the geometry: the linear cell of the family; for the curved checks: the cell itself).
struct Family {
  std::string name;
  int D, nodes;
  Parent parent;
  std::vector<std::array<double, 3>> parentNodes;
  void (*values)(const double*, double*);
  void (*gradients)(const double*, double*);
  int cornerCount;
  void (*cornerValues)(const double*, double*);
  void (*cornerGradients)(const double*, double*);
};

template <class Shape, class Corners>
Family family(const std::string& name, Parent parent) {
  Family f{name, Shape::kDimension, Shape::kNodes, parent, {}, &Shape::shapeValues, &Shape::shapeGradients,
           Corners::kNodes, &Corners::shapeValues, &Corners::shapeGradients};
  for (const auto& x : Shape::parentNodes()) {
    std::array<double, 3> p{};
    for (int i = 0; i < Shape::kDimension; ++i) p[i] = x[i];
    f.parentNodes.push_back(p);
  }
  return f;
}

/// TrilinearHexahedron with the shape values it does not offer (its kernel needs only gradients).
struct TrilinearShape : TrilinearHexahedron {
  static void shapeValues(const double* xi, double* N) {
    const auto nodes = parentNodes();
    for (int a = 0; a < kNodes; ++a)
      N[a] = 0.125 * (1 + nodes[a][0] * xi[0]) * (1 + nodes[a][1] * xi[1]) * (1 + nodes[a][2] * xi[2]);
  }
};

std::vector<Family> families() {
  return {family<BilinearQuadrilateral, BilinearQuadrilateral>("Quad4", Parent::Cube),
          family<SerendipityQuadrilateral, BilinearQuadrilateral>("Q8", Parent::Cube),
          family<LagrangeQuadrilateral, BilinearQuadrilateral>("Q9", Parent::Cube),
          family<LinearTriangle, LinearTriangle>("Tri3", Parent::Simplex),
          family<QuadraticTriangle, LinearTriangle>("Tri6", Parent::Simplex),
          family<TrilinearShape, TrilinearShape>("Hex8", Parent::Cube),
          family<SerendipityHexahedron, TrilinearShape>("Hex20", Parent::Cube),
          family<LagrangeHexahedron, TrilinearShape>("Hex27", Parent::Cube),
          family<LinearTetrahedron, LinearTetrahedron>("Tet4", Parent::Simplex),
          family<QuadraticTetrahedron, LinearTetrahedron>("Tet10", Parent::Simplex),
          family<LinearWedge, LinearWedge>("Wedge6", Parent::Wedge),
          family<QuadraticWedge, LinearWedge>("Wedge15", Parent::Wedge)};
}

/// Distorted corners of the linear cell (positively oriented, off every affine map for the cube and the
/// wedge; the simplices are affine by construction), shifted away from the axis so that r = x > 0.
std::vector<double> distortedCorners(const Family& f) {
  const int D = f.D;
  std::vector<double> C(static_cast<std::size_t>(f.cornerCount * D));
  const double skew[3][3] = {{1.1, 0.25, 0.1}, {-0.15, 0.9, 0.2}, {0.05, -0.1, 0.8}};
  for (int c = 0; c < f.cornerCount; ++c) {
    std::vector<double> xi(3, 0.0);
    for (int i = 0; i < D; ++i) xi[i] = f.parentNodes[c][i];  // the linear cell's nodes come first
    for (int i = 0; i < D; ++i) {
      double v = i == 0 ? 3.0 : 1.0;
      for (int j = 0; j < D; ++j) v += skew[i][j] * xi[j];
      // A non-affine wobble of each corner (none for a simplex: any map of its corners is affine).
      v += 0.13 * std::sin(1.7 * c + 0.9 * i) * (f.parent == Parent::Simplex ? 0.0 : 1.0);
      C[D * c + i] = v;
    }
  }
  return C;
}

/// The point and det ∂X/∂ξ at ξ of the cell with `n` nodes at X under the shape (values, gradients).
void mapAt(int D, int n, const double* X, void (*values)(const double*, double*),
           void (*gradients)(const double*, double*), const double* xi, double* x, double* detJ) {
  std::vector<double> N(n), dN(static_cast<std::size_t>(n * D));
  values(xi, N.data());
  gradients(xi, dN.data());
  double J[3][3] = {};
  for (int i = 0; i < D; ++i) x[i] = 0.0;
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < D; ++i) {
      x[i] += N[a] * X[D * a + i];
      for (int m = 0; m < D; ++m) J[i][m] += dN[D * a + m] * X[D * a + i];
    }
  *detJ = D == 2 ? J[0][0] * J[1][1] - J[0][1] * J[1][0]
                 : J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                       J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

/// The reference integrals over a cell whose geometry is the map of `n` points G by (values, gradients):
/// ∫ w dV, ∫ X_i w dV (i < D) and ∫ N_a w dV for the family's own N_a (nodal), by the reference rule.
struct Reference {
  double volume = 0.0;
  std::vector<double> moment, nodal;
};
Reference referenceIntegrals(const Family& f, int n, const double* G, void (*values)(const double*, double*),
                             void (*gradients)(const double*, double*), bool revolved) {
  Reference out{0.0, std::vector<double>(f.D, 0.0), std::vector<double>(f.nodes, 0.0)};
  std::vector<double> N(f.nodes);
  for (const auto& [xi, weight] : referenceRule(f.parent, f.D)) {
    double x[3], detJ;
    mapAt(f.D, n, G, values, gradients, xi.data(), x, &detJ);
    const double dV = weight * detJ * (revolved ? 2.0 * M_PI * x[0] : 1.0);
    out.volume += dV;
    for (int i = 0; i < f.D; ++i) out.moment[i] += x[i] * dV;
    f.values(xi.data(), N.data());
    for (int a = 0; a < f.nodes; ++a) out.nodal[a] += N[a] * dV;
  }
  return out;
}

/// The nodes of the cell on the map of its distorted corners.
std::vector<double> nodesOnTheMap(const Family& f, const std::vector<double>& C) {
  std::vector<double> X;
  for (const auto& xi : f.parentNodes) {
    double x[3], detJ;
    mapAt(f.D, f.cornerCount, C.data(), f.cornerValues, f.cornerGradients, xi.data(), x, &detJ);
    for (int i = 0; i < f.D; ++i) X.push_back(x[i]);
  }
  return X;
}

struct Moments {
  std::vector<double> resultant;  ///< Σ_a f_a (D)
  std::vector<double> moment;     ///< Σ_a f_a,i X_a,j at D·i + j
};

Moments kernelMoments(const Family& f, const std::vector<double>& X, const double* b, const LoadMeasure& m) {
  std::vector<double> force(X.size());
  if (f.D == 2) bodyForce<2>(f.nodes, X.data(), b, m, force.data());
  else bodyForce<3>(f.nodes, X.data(), b, m, force.data());
  Moments out{std::vector<double>(f.D, 0.0), std::vector<double>(f.D * f.D, 0.0)};
  for (int a = 0; a < f.nodes; ++a)
    for (int i = 0; i < f.D; ++i) {
      out.resultant[i] += force[f.D * a + i];
      for (int j = 0; j < f.D; ++j) out.moment[f.D * i + j] += force[f.D * a + i] * X[f.D * a + j];
    }
  return out;
}

/// Checks Σ f_a = b V, (when `moment`) Σ f_a,i X_a,j = b_i ∫ X_j w dV and (when `nodal`) every f_a = b ∫ N_a w dV
/// against the reference.
void expectIdentities(const Family& f, const std::vector<double>& X, const LoadMeasure& m, const Reference& reference,
                      bool moment, bool nodal, const std::string& what) {
  const double b[3] = {0.7, -9.81, 2.5};
  const Moments k = kernelMoments(f, X, b, m);
  const double V = reference.volume, scale = std::abs(V) * 10.0;
  const double measure = f.D == 2 ? cellMeasure<2>(f.nodes, X.data(), m) : cellMeasure<3>(f.nodes, X.data(), m);
  EXPECT_NEAR(measure, V, 1e-13 * std::abs(V)) << f.name << " " << what;
  for (int i = 0; i < f.D; ++i) {
    EXPECT_NEAR(k.resultant[i], b[i] * V, 1e-13 * scale) << f.name << " " << what << " resultant " << i;
    if (!moment) continue;
    for (int j = 0; j < f.D; ++j)
      EXPECT_NEAR(k.moment[f.D * i + j], b[i] * reference.moment[j], 1e-13 * scale * 5.0)
          << f.name << " " << what << " moment " << i << j;
  }
  if (!nodal) return;
  std::vector<double> force(X.size());
  if (f.D == 2) bodyForce<2>(f.nodes, X.data(), b, m, force.data());
  else bodyForce<3>(f.nodes, X.data(), b, m, force.data());
  for (int a = 0; a < f.nodes; ++a)
    for (int i = 0; i < f.D; ++i)
      EXPECT_NEAR(force[f.D * a + i], b[i] * reference.nodal[a], 1e-13 * scale) << f.name << " " << what << " node " << a;
}

TEST(BodyForceFamilies, EveryCellTypeOfTheElementKernelsIsALoadCell) {
  for (const auto& f : families()) EXPECT_TRUE(isLoadCell(f.D, f.nodes)) << f.name;
  EXPECT_FALSE(isLoadCell(2, 10));
  EXPECT_FALSE(isLoadCell(3, 9));
}

TEST(BodyForceFamilies, ResultantAndFirstMomentAreExactOnADistortedStraightSidedCell) {
  const UnitMeasure plane(2), space(3);
  for (const auto& f : families()) {
    const auto C = distortedCorners(f);
    const auto X = nodesOnTheMap(f, C);
    const auto reference = referenceIntegrals(f, f.cornerCount, C.data(), f.cornerValues, f.cornerGradients, false);
    ASSERT_GT(reference.volume, 0.1) << f.name;  // positively oriented, not degenerate
    expectIdentities(f, X, f.D == 2 ? static_cast<const LoadMeasure&>(plane) : space, reference, true, true, "w = 1");
  }
}

TEST(BodyForceFamilies, RevolvedResultantAndFirstMomentAreExactOnEvery2DCell) {
  const RevolvedMeasure revolved;
  for (const auto& f : families()) {
    if (f.D != 2) continue;
    const auto C = distortedCorners(f);
    const auto X = nodesOnTheMap(f, C);
    const auto reference = referenceIntegrals(f, f.cornerCount, C.data(), f.cornerValues, f.cornerGradients, true);
    expectIdentities(f, X, revolved, reference, true, true, "w = 2 pi r");
  }
}

TEST(BodyForceFamilies, CurvedQuadraticCellsKeepTheirResultantAndIn2DTheirFirstMoment) {
  const UnitMeasure plane(2), space(3);
  const RevolvedMeasure revolved;
  for (const auto& f : families()) {
    if (f.parent != Parent::Cube || f.nodes == f.cornerCount) continue;
    auto X = nodesOnTheMap(f, distortedCorners(f));
    // Bow every node past the corners off the straight cell (by up to a tenth of the cell's size).
    for (int a = f.cornerCount; a < f.nodes; ++a)
      for (int i = 0; i < f.D; ++i) X[f.D * a + i] += 0.1 * std::cos(2.3 * a + 1.1 * i);
    const auto reference = referenceIntegrals(f, f.nodes, X.data(), f.values, f.gradients, false);
    expectIdentities(f, X, f.D == 2 ? static_cast<const LoadMeasure&>(plane) : space, reference, f.D == 2, f.D == 2,
                     "curved");
    if (f.D == 2)  // det J 2πr of degree 5 per direction: the resultant stays exact
      expectIdentities(f, X, revolved, referenceIntegrals(f, f.nodes, X.data(), f.values, f.gradients, true), false,
                       false, "curved, w = 2 pi r");
  }
}

TEST(BodyForceFamilies, TheOverloadWithoutANodeCountIsTheQuad4AndHex8Kernel) {
  const UnitMeasure plane(2), space(3);
  const double b[3] = {0.3, -1.0, 0.2};
  for (const auto& f : families()) {
    if (f.nodes != cellNodeCount(f.D) || f.parent != Parent::Cube) continue;
    const auto X = nodesOnTheMap(f, distortedCorners(f));
    std::vector<double> a(X.size()), c(X.size());
    if (f.D == 2) {
      bodyForce<2>(X.data(), b, plane, a.data());
      bodyForce<2>(f.nodes, X.data(), b, plane, c.data());
    } else {
      bodyForce<3>(X.data(), b, space, a.data());
      bodyForce<3>(f.nodes, X.data(), b, space, c.data());
    }
    EXPECT_EQ(a, c) << f.name;
  }
}

}  // namespace
}  // namespace contessa::mechanics::test
