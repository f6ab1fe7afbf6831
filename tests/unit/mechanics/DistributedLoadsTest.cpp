// Distributed loads (mechanics/DistributedLoads): the follower pressure's load stiffness against central
// differences of its force on every side of distorted 2D and 3D elements (also with the axisymmetric
// weight 2πr, whose gradient enters the stiffness), and the resultants of pressure, traction and body
// force against p·A·n, t·A and b·V computed independently of the kernels.
#include "MechanicsTestUtilities.hpp"
#include "mechanics/DistributedLoads.hpp"

namespace contessa::mechanics::test {
namespace {

// Exodus side node lists (mesh/Mesh.cpp): outward normals for counter-clockwise (positively oriented) cells.
const std::vector<std::vector<int>> kQuadSides = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
const std::vector<std::vector<int>> kHexSides = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                                 {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};

std::vector<double> pressureForce(int D, const std::vector<double>& x, double p, const LoadMeasure& m,
                                  std::vector<double>* K = nullptr) {
  std::vector<double> f(x.size());
  if (K) K->assign(x.size() * x.size(), 0.0);
  if (D == 2) followerPressure<2>(x.data(), p, m, f.data(), K ? K->data() : nullptr);
  else followerPressure<3>(x.data(), p, m, f.data(), K ? K->data() : nullptr);
  return f;
}

// The largest difference between K and central differences of f over the largest entry of K.
double stiffnessError(int D, const std::vector<double>& x, double p, const LoadMeasure& m) {
  return checkStiffness([&](const std::vector<double>& y, std::vector<double>* K) { return pressureForce(D, y, p, m, K); },
                        x).error;
}

TEST(FollowerPressure, StiffnessMatchesCentralDifferencesOnEverySideIn2D) {
  const UnitMeasure plane(2);
  for (const auto& X : distortedQuads()) {
    const auto x = quadDeformation(X, {{0.3, 0.2}, {-0.1, -0.2}}, 0.2, 1.0);  // a deformed configuration
    std::vector<double> current(X.size());
    for (std::size_t k = 0; k < X.size(); ++k) current[k] = X[k] + x[k];
    for (const auto& side : kQuadSides) {
      const double error = stiffnessError(2, sideCoordinates(current, side, 2), 3.5, plane);
      EXPECT_LT(error, 1e-8);
      EXPECT_GT(error, 0.0);  // the differences are not a copy of K
    }
  }
}

TEST(FollowerPressure, StiffnessMatchesCentralDifferencesOnEverySideIn3D) {
  const UnitMeasure space(3);
  for (const auto& X : distortedBricks()) {
    const auto u = brickDeformation(X, 1.0);
    std::vector<double> current(X.size());
    for (std::size_t k = 0; k < X.size(); ++k) current[k] = X[k] + u[k];
    for (const auto& side : kHexSides) {
      const auto x = sideCoordinates(current, side, 3);
      std::vector<double> K;
      pressureForce(3, x, 2.0, space, &K);
      // A warped face's stiffness is not symmetric (the follower term): the test must see that.
      double asymmetry = 0.0;
      for (int a = 0; a < 12; ++a)
        for (int b = 0; b < 12; ++b) asymmetry = std::max(asymmetry, std::abs(K[12 * a + b] - K[12 * b + a]));
      EXPECT_GT(asymmetry, 1e-3 * maxAbs(K));
      EXPECT_LT(stiffnessError(3, x, 2.0, space), 1e-8);
    }
  }
}

TEST(FollowerPressure, StiffnessWithTheAxisymmetricWeightMatchesCentralDifferences) {
  // The weight 2πr at the current point moves with the nodes: its gradient is part of the stiffness.
  const RevolvedMeasure revolved;
  for (const auto& X : distortedQuads())
    for (const auto& side : kQuadSides) {
      auto x = sideCoordinates(X, side, 2);
      x[0] += 3.0;  // r > 0
      x[2] += 3.0;
      EXPECT_LT(stiffnessError(2, x, 1.5, revolved), 1e-8);
    }
}

TEST(FollowerPressure, PressureOnEverySideOfAClosedCellHasNoResultant) {
  // ∮ p n da = 0 on any closed surface: the outward sides of a distorted (3D: warped) cell.
  for (int D : {2, 3}) {
    const UnitMeasure measure(D);
    const auto& cells = D == 2 ? distortedQuads() : distortedBricks();
    for (const auto& X : cells) {
      std::vector<double> total(D, 0.0);
      double largest = 0.0;
      for (const auto& side : D == 2 ? kQuadSides : kHexSides) {
        const auto f = pressureForce(D, sideCoordinates(X, side, D), 7.0, measure);
        for (std::size_t k = 0; k < f.size(); ++k) total[k % D] += f[k];
        largest = std::max(largest, maxAbs(f));
      }
      EXPECT_LT(maxAbs(total), 1e-13 * largest) << D << "D";
    }
  }
}

TEST(FollowerPressure, ResultantOnAFlatFaceIsPressureTimesAreaIntoTheBody) {
  // A planar quadrilateral (not a parallelogram) in a tilted plane: area ½|d1 × d2| with the diagonals
  // d1 = x2 − x0, d2 = x3 − x1, whose direction is the right-hand normal of the node order.
  const double e1[3] = {0.6, 0.8, 0.0}, e2[3] = {-0.48, 0.36, 0.8};
  const double uv[4][2] = {{0, 0}, {2.0, 0.1}, {1.7, 1.6}, {-0.2, 1.1}};
  std::vector<double> x(12);
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 3; ++i) x[3 * a + i] = 1.0 + uv[a][0] * e1[i] + uv[a][1] * e2[i];
  const double d1[3] = {x[6] - x[0], x[7] - x[1], x[8] - x[2]}, d2[3] = {x[9] - x[3], x[10] - x[4], x[11] - x[5]};
  const double c[3] = {d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
  const double p = 2.5;
  const auto f = pressureForce(3, x, p, UnitMeasure(3));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f[i] + f[3 + i] + f[6 + i] + f[9 + i], -p * 0.5 * c[i], 1e-13);
  EXPECT_NEAR(facetMeasure<3>(x.data(), UnitMeasure(3)), 0.5 * std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), 1e-13);
}

TEST(DeadLoads, TractionResultantIsTractionTimesReferenceArea) {
  const double t2[2] = {0.3, -1.2};
  const std::vector<double> edge = {0.5, 0.2, 3.5, 4.2};  // length 5
  std::vector<double> f2(4);
  facetTraction<2>(edge.data(), t2, UnitMeasure(2), f2.data());
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(f2[i], 2.5 * t2[i], 1e-14);  // half to each node
    EXPECT_NEAR(f2[2 + i], 2.5 * t2[i], 1e-14);
  }
  // A flat, non-rectangular face in the z = 1 plane: area by the shoelace formula.
  const std::vector<double> face = {0, 0, 1, 2, 0.3, 1, 2.4, 1.8, 1, -0.2, 1.5, 1};
  double area = 0.0;
  for (int a = 0; a < 4; ++a) {
    const int b = (a + 1) % 4;
    area += 0.5 * (face[3 * a] * face[3 * b + 1] - face[3 * b] * face[3 * a + 1]);
  }
  const double t3[3] = {1.0, -2.0, 0.5};
  std::vector<double> f3(12);
  facetTraction<3>(face.data(), t3, UnitMeasure(3), f3.data());
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(f3[i] + f3[3 + i] + f3[6 + i] + f3[9 + i], area * t3[i], 1e-13);
}

TEST(DeadLoads, BodyForceResultantIsForceDensityTimesReferenceVolume) {
  const UnitMeasure plane(2), space(3);
  const double b2[2] = {0.0, -9.81};
  for (const auto& X : distortedQuads()) {
    double area = 0.0;  // shoelace: exact for a bilinear quadrilateral
    for (int a = 0; a < 4; ++a) {
      const int c = (a + 1) % 4;
      area += 0.5 * (X[2 * a] * X[2 * c + 1] - X[2 * c] * X[2 * a + 1]);
    }
    std::vector<double> f(8);
    bodyForce<2>(X.data(), b2, plane, f.data());
    EXPECT_NEAR(f[1] + f[3] + f[5] + f[7], area * b2[1], 1e-12);
    EXPECT_NEAR(f[0] + f[2] + f[4] + f[6], 0.0, 1e-14);
    EXPECT_NEAR(cellMeasure<2>(X.data(), plane), area, 1e-13);
  }
  // A parallelepiped X = c + A ξ over [−1, 1]³: volume 8 det A.
  const double A[3][3] = {{1.0, 0.2, 0.1}, {0.1, 0.7, -0.2}, {0.05, 0.1, 0.5}};
  const double detA = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                      A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  const double corner[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  std::vector<double> X(24);
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) X[3 * a + i] = 2.0 + A[i][0] * corner[a][0] + A[i][1] * corner[a][1] + A[i][2] * corner[a][2];
  const double b3[3] = {1.0, 0.0, -3.0};
  std::vector<double> f(24);
  bodyForce<3>(X.data(), b3, space, f.data());
  double total[3] = {0, 0, 0};
  for (int k = 0; k < 24; ++k) total[k % 3] += f[k];
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(total[i], 8.0 * detA * b3[i], 1e-12);
}

TEST(DeadLoads, RevolvedMeasureGivesTheFullCircumference) {
  // A ring of rectangular section [2, 3] × [0, 1] revolved about y: volume π (3² − 2²) · 1; its outer
  // face r = 3, y ∈ [0, 1], has area 2π · 3 · 1.
  const std::vector<double> X = {2, 0, 3, 0, 3, 1, 2, 1};
  const RevolvedMeasure revolved;
  EXPECT_NEAR(cellMeasure<2>(X.data(), revolved), M_PI * 5.0, 1e-12);
  const std::vector<double> outer = {3, 0, 3, 1};
  EXPECT_NEAR(facetMeasure<2>(outer.data(), revolved), 2 * M_PI * 3.0, 1e-12);
}

}  // namespace
}  // namespace contessa::mechanics::test
