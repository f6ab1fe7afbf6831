// Distributed loads on the sides of the simplex and quadratic cell families (mechanics/DistributedLoads,
// isLoadFacet): 3-node edges (Tri6, Q8, Q9), 3-node faces (Tet4, Wedge6), 6-node faces (Tet10, Wedge15),
// 8-node faces (Hex20, Wedge15) and 9-node faces (Hex27). For each: the follower pressure's stiffness
// against central differences of its force on curved sides of distorted cells (2D also with the
// axisymmetric weight); the pressure on every side of a closed curved cell has no resultant; on a flat side
// the pressure's resultant is p A n and the traction's t A, with A computed independently of the kernels.
#include "MechanicsTestUtilities.hpp"
#include "mechanics/DistributedLoads.hpp"
#include "mechanics/QuadraticCells.hpp"
#include "mechanics/Simplices.hpp"
#include "mechanics/Wedges.hpp"

#include <cstdio>

namespace contessa::mechanics::test {
namespace {

using Sides = std::vector<std::vector<int>>;

// Exodus side node lists (mesh/Mesh.cpp, mesh::sideNodes): outward for positively oriented cells.
const Sides kTri3Sides{{0, 1}, {1, 2}, {2, 0}};
const Sides kTri6Sides{{0, 1, 3}, {1, 2, 4}, {2, 0, 5}};
const Sides kQuad8Sides{{0, 1, 4}, {1, 2, 5}, {2, 3, 6}, {3, 0, 7}};
const Sides kTet4Sides{{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}};
const Sides kTet10Sides{{0, 1, 3, 4, 8, 7}, {1, 2, 3, 5, 9, 8}, {0, 3, 2, 7, 9, 6}, {0, 2, 1, 6, 5, 4}};
const Sides kHex20Sides{{0, 1, 5, 4, 8, 13, 16, 12},  {1, 2, 6, 5, 9, 14, 17, 13}, {2, 3, 7, 6, 10, 15, 18, 14},
                        {0, 4, 7, 3, 12, 19, 15, 11}, {0, 3, 2, 1, 11, 10, 9, 8},  {4, 5, 6, 7, 16, 17, 18, 19}};
// Hex27: Hex20's sides, each with its centre (node 20 is the cell's centre, 21-26 those of sides 5, 6, 4, 2, 1, 3).
const Sides kHex27Sides{{0, 1, 5, 4, 8, 13, 16, 12, 25},  {1, 2, 6, 5, 9, 14, 17, 13, 24},
                        {2, 3, 7, 6, 10, 15, 18, 14, 26}, {0, 4, 7, 3, 12, 19, 15, 11, 23},
                        {0, 3, 2, 1, 11, 10, 9, 8, 21},   {4, 5, 6, 7, 16, 17, 18, 19, 22}};
const Sides kWedge15Sides{{0, 1, 4, 3, 6, 10, 12, 9}, {1, 2, 5, 4, 7, 11, 13, 10}, {0, 3, 5, 2, 9, 14, 11, 8},
                          {0, 2, 1, 8, 7, 6}, {3, 4, 5, 12, 13, 14}};

/// A cell: its parent nodes mapped by a smooth non-affine map (curved edges, mid-edge nodes off the
/// chords), D coordinates per node.
template <class Shape>
std::vector<double> curvedCell() {
  constexpr int D = Shape::kDimension;
  std::vector<double> X;
  for (const auto& xi : Shape::parentNodes()) {
    for (int i = 0; i < D; ++i) {
      double v = 1.5 * xi[i] + 0.3 * xi[(i + 1) % D];
      v += 0.12 * std::sin(1.3 * xi[(i + 1) % D] + 0.7 * xi[i]) + 0.08 * xi[i] * xi[(i + D - 1) % D];
      X.push_back(v);
    }
  }
  return X;
}

std::vector<double> pressureForce(int D, const std::vector<double>& x, double p, const LoadMeasure& m,
                                  std::vector<double>* K = nullptr) {
  const int nodes = static_cast<int>(x.size()) / D;
  std::vector<double> f(x.size());
  if (K) K->assign(x.size() * x.size(), 0.0);
  if (D == 2) followerPressure<2>(nodes, x.data(), p, m, f.data(), K ? K->data() : nullptr);
  else followerPressure<3>(nodes, x.data(), p, m, f.data(), K ? K->data() : nullptr);
  return f;
}

/// max |K − K_FD| / max |K| (central differences of the force), and K's largest asymmetry relative to it.
std::pair<double, double> stiffnessError(int D, const std::vector<double>& x, double p, const LoadMeasure& m) {
  const StiffnessCheck check = checkStiffness(
      [&](const std::vector<double>& y, std::vector<double>* K) { return pressureForce(D, y, p, m, K); }, x);
  return {check.error, check.asymmetry};
}

struct Family {
  const char* name;
  int D;
  std::vector<double> X;
  Sides sides;
};

std::vector<Family> families() {
  return {{"Tri6 (3-node edges)", 2, curvedCell<QuadraticTriangle>(), kTri6Sides},
          {"Q8 (3-node edges)", 2, curvedCell<SerendipityQuadrilateral>(), kQuad8Sides},
          {"Q9 (3-node edges)", 2, curvedCell<LagrangeQuadrilateral>(), kQuad8Sides},
          {"Tet4 (Tri3 faces)", 3, curvedCell<LinearTetrahedron>(), kTet4Sides},
          {"Tet10 (Tri6 faces)", 3, curvedCell<QuadraticTetrahedron>(), kTet10Sides},
          {"Hex20 (Quad8 faces)", 3, curvedCell<SerendipityHexahedron>(), kHex20Sides},
          {"Hex27 (Quad9 faces)", 3, curvedCell<LagrangeHexahedron>(), kHex27Sides},
          {"Wedge15 (Tri6 and Quad8 faces)", 3, curvedCell<QuadraticWedge>(), kWedge15Sides}};
}

}  // namespace

TEST(FacetLoads, EverySideOfEveryFamilyIsALoadFacet) {
  for (const auto& family : families())
    for (const auto& side : family.sides) EXPECT_TRUE(isLoadFacet(family.D, static_cast<int>(side.size())));
  EXPECT_FALSE(isLoadFacet(2, 4));
  EXPECT_FALSE(isLoadFacet(3, 2));
  EXPECT_FALSE(isLoadFacet(3, 7));
}

TEST(FacetLoads, FollowerPressureStiffnessMatchesCentralDifferencesOnCurvedSides) {
  for (const auto& family : families()) {
    const UnitMeasure measure(family.D);
    double worst = 0.0, asymmetry = 0.0;
    for (const auto& side : family.sides) {
      const auto [error, skew] = stiffnessError(family.D, sideCoordinates(family.X, side, family.D), 3.5, measure);
      EXPECT_LT(error, 1e-8) << family.name;
      EXPECT_GT(error, 0.0) << family.name;  // the differences are not a copy of K
      worst = std::max(worst, error);
      asymmetry = std::max(asymmetry, skew);
    }
    // A curved side's stiffness is not symmetric (the follower term): the test must see that.
    EXPECT_GT(asymmetry, 1e-3) << family.name;
    std::printf("[ FD       ] %-32s max|K - K_FD|/max|K| = %.1e, asymmetry %.2f\n", family.name, worst, asymmetry);
  }
}

TEST(FacetLoads, FollowerPressureStiffnessWithTheAxisymmetricWeightMatchesCentralDifferences) {
  const RevolvedMeasure revolved;
  for (const auto& family : families()) {
    if (family.D != 2) continue;
    auto X = family.X;
    for (std::size_t k = 0; k < X.size(); k += 2) X[k] += 4.0;  // r > 0
    for (const auto& side : family.sides)
      EXPECT_LT(stiffnessError(2, sideCoordinates(X, side, 2), 1.5, revolved).first, 1e-8) << family.name;
  }
}

// ∮ p n da = 0 on any closed surface: the sides of each curved cell close it, and the rules integrate the
// area vector of a curved side exactly (degree 2 on a 6-node face, ≤ 3 per direction on an 8-node face).
TEST(FacetLoads, PressureOnEverySideOfAClosedCurvedCellHasNoResultant) {
  for (const auto& family : families()) {
    const UnitMeasure measure(family.D);
    std::vector<double> total(family.D, 0.0);
    double largest = 0.0;
    for (const auto& side : family.sides) {
      const auto f = pressureForce(family.D, sideCoordinates(family.X, side, family.D), 7.0, measure);
      for (std::size_t k = 0; k < f.size(); ++k) total[k % family.D] += f[k];
      largest = std::max(largest, maxAbs(f));
    }
    EXPECT_LT(maxAbs(total), 1e-13 * largest) << family.name;
  }
}

// A flat side with straight edges in a tilted plane, nodes at the affine image of the parent nodes: the
// pressure's resultant is −p A n and the traction's t A, A = |det J| × the parent area; a uniform pressure
// loads the 6-node face's corners with nothing and the 8-node face's with −A/12 (the consistent loads).
TEST(FacetLoads, ResultantsOnFlatSidesArePressureAndTractionTimesArea) {
  const double e1[3] = {0.6, 0.8, 0.0}, e2[3] = {-0.48, 0.36, 0.8};  // orthonormal
  const double J[2][2] = {{1.3, 0.2}, {-0.1, 0.9}};                  // in-plane map, det = 1.19
  const double det = J[0][0] * J[1][1] - J[0][1] * J[1][0];
  const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
  struct Face {
    const char* name;
    std::vector<std::array<double, 2>> parent;
    double parentArea;
    int corners;
    double cornerShare;  // of the pressure's resultant, per corner
  };
  const auto tri = QuadraticTriangle::parentNodes();
  const auto quad = LagrangeQuadrilateral::parentNodes();
  const std::vector<Face> faces{
      {"Tri3", {tri[0], tri[1], tri[2]}, 0.5, 3, 1.0 / 3.0},
      {"Tri6", {tri.begin(), tri.end()}, 0.5, 3, 0.0},
      {"Quad8", {quad.begin(), quad.begin() + 8}, 4.0, 4, -1.0 / 12.0},
      {"Quad9", {quad.begin(), quad.end()}, 4.0, 4, 1.0 / 36.0}};
  const double p = 2.5, t[3] = {0.3, -1.1, 0.7};
  for (const auto& face : faces) {
    const int nodes = static_cast<int>(face.parent.size());
    std::vector<double> x;
    for (const auto& xi : face.parent) {
      const double u = J[0][0] * xi[0] + J[0][1] * xi[1], v = J[1][0] * xi[0] + J[1][1] * xi[1];
      for (int i = 0; i < 3; ++i) x.push_back(1.0 + u * e1[i] + v * e2[i]);
    }
    const double area = det * face.parentArea;
    const auto f = pressureForce(3, x, p, UnitMeasure(3));
    std::vector<double> traction(x.size());
    facetTraction<3>(nodes, x.data(), t, UnitMeasure(3), traction.data());
    for (int i = 0; i < 3; ++i) {
      double pressureTotal = 0.0, tractionTotal = 0.0;
      for (int a = 0; a < nodes; ++a) {
        pressureTotal += f[3 * a + i];
        tractionTotal += traction[3 * a + i];
      }
      EXPECT_NEAR(pressureTotal, -p * area * n[i], 1e-13) << face.name;
      EXPECT_NEAR(tractionTotal, t[i] * area, 1e-13) << face.name;
      for (int a = 0; a < face.corners; ++a) EXPECT_NEAR(f[3 * a + i], -p * area * n[i] * face.cornerShare, 1e-13);
    }
    EXPECT_NEAR(facetMeasure<3>(nodes, x.data(), UnitMeasure(3)), area, 1e-13) << face.name;
  }
  // A 3-node edge: the traction's resultant t L, its end nodes L/6 of it.
  const std::vector<double> edge{0.0, 0.0, 1.2, 1.6, 0.6, 0.8};  // L = 2, mid-edge node centred
  std::vector<double> f(6);
  facetTraction<2>(3, edge.data(), t, UnitMeasure(2), f.data());
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(f[i] + f[2 + i] + f[4 + i], 2.0 * t[i], 1e-14);
    EXPECT_NEAR(f[i], 2.0 * t[i] / 6.0, 1e-14);
  }
  EXPECT_NEAR(facetMeasure<2>(3, edge.data(), UnitMeasure(2)), 2.0, 1e-14);
}

}  // namespace contessa::mechanics::test
