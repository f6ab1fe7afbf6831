#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "mesh/CellGeometry.hpp"

using namespace contessa::mesh;

namespace {

// Exodus node order, written out here independently of the code under test.
const int kQuadCorners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
const int kHexCorners[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                               {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

int sign(CellType type, int node, int k) { return type == CellType::Quad4 ? kQuadCorners[node][k] : kHexCorners[node][k]; }

// det(∂x/∂ξ) of the isoparametric map at reference point ξ, from the shape-function derivatives
// ∂N_a/∂ξ_j = 2^-d s_aj Π_{k≠j} (1 + s_ak ξ_k): the textbook definition the corner formula must match.
double isoparametricDeterminant(CellType type, const std::vector<double>& x, const std::vector<double>& xi) {
  const int d = cellDimension(type), nodes = nodesPerCell(type);
  double J[3][3] = {};
  for (int a = 0; a < nodes; ++a)
    for (int j = 0; j < d; ++j) {
      double dN = sign(type, a, j) / std::pow(2.0, d);
      for (int k = 0; k < d; ++k)
        if (k != j) dN *= 1 + sign(type, a, k) * xi[k];
      for (int i = 0; i < d; ++i) J[i][j] += x[a * d + i] * dN;
    }
  if (d == 2) return J[0][0] * J[1][1] - J[0][1] * J[1][0];
  return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

// The reference cell scaled by `h`, each node moved by up to `noise` in every direction.
std::vector<double> distortedCell(CellType type, double h, double noise, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-noise, noise);
  const int d = cellDimension(type), nodes = nodesPerCell(type);
  std::vector<double> x(static_cast<size_t>(nodes * d));
  for (int a = 0; a < nodes; ++a)
    for (int i = 0; i < d; ++i) x[a * d + i] = h * (sign(type, a, i) + 1) / 2 + u(rng);
  return x;
}

std::vector<double> corners(CellType type, const std::vector<double>& x, bool scaled) {
  std::vector<double> j(static_cast<size_t>(nodesPerCell(type)));
  if (scaled)
    scaledCornerJacobians(type, x.data(), j.data());
  else
    cornerJacobians(type, x.data(), j.data());
  return j;
}

const std::vector<double> kUnitSquare = {0, 0, 1, 0, 1, 1, 0, 1};
const std::vector<double> kUnitCube = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};

}  // namespace

TEST(CellGeometry, ReferenceCornersFollowExodus) {
  for (int a = 0; a < 4; ++a)
    EXPECT_EQ(referenceCorner(CellType::Quad4, a), (std::vector<int>{kQuadCorners[a][0], kQuadCorners[a][1]}));
  for (int a = 0; a < 8; ++a)
    EXPECT_EQ(referenceCorner(CellType::Hex8, a),
              (std::vector<int>{kHexCorners[a][0], kHexCorners[a][1], kHexCorners[a][2]}));
  EXPECT_THROW(referenceCorner(CellType::Quad4, 4), std::out_of_range);
}

TEST(CellGeometry, CornerJacobiansAreTheIsoparametricDeterminantTimesTwoToTheD) {
  std::mt19937 rng(7);
  for (CellType type : {CellType::Quad4, CellType::Hex8}) {
    const int d = cellDimension(type);
    for (int trial = 0; trial < 20; ++trial) {
      const std::vector<double> x = distortedCell(type, 2.5, 0.6, rng);
      const auto j = corners(type, x, false);
      for (int a = 0; a < nodesPerCell(type); ++a) {
        std::vector<double> xi(static_cast<size_t>(d));
        for (int k = 0; k < d; ++k) xi[k] = sign(type, a, k);
        EXPECT_NEAR(j[a], std::pow(2.0, d) * isoparametricDeterminant(type, x, xi), 1e-12)
            << exodusCellName(type) << " trial " << trial << " corner " << a;
      }
    }
  }
}

TEST(CellGeometry, Quad4Orientation) {
  EXPECT_EQ(corners(CellType::Quad4, kUnitSquare, false), (std::vector<double>{1, 1, 1, 1}));
  // A 1000 x 0.001 rectangle: right angles, so the scaled value is 1 whatever the aspect ratio.
  const std::vector<double> sliver = {0, 0, 1000, 0, 1000, 0.001, 0, 0.001};
  for (double v : corners(CellType::Quad4, sliver, true)) EXPECT_NEAR(v, 1, 1e-12);
  // Clockwise: the same square listed the other way round.
  const std::vector<double> clockwise = {0, 0, 0, 1, 1, 1, 1, 0};
  EXPECT_EQ(corners(CellType::Quad4, clockwise, true), (std::vector<double>{-1, -1, -1, -1}));
  // Bow-tie (nodes 2 and 3 swapped): self-intersecting, both signs.
  const std::vector<double> bowTie = {0, 0, 1, 0, 0, 1, 1, 1};
  const auto b = corners(CellType::Quad4, bowTie, true);
  EXPECT_EQ(std::count_if(b.begin(), b.end(), [](double v) { return v < 0; }), 2);
  EXPECT_EQ(std::count_if(b.begin(), b.end(), [](double v) { return v > 0; }), 2);
  // Non-convex "arrow": node 2 pulled inside; negative there only.
  const std::vector<double> arrow = {0, 0, 2, 0, 0.5, 0.5, 0, 2};
  const auto a = corners(CellType::Quad4, arrow, true);
  EXPECT_LT(a[2], 0);
  EXPECT_GT(a[0], 0);
  EXPECT_GT(a[1], 0);
  EXPECT_GT(a[3], 0);
  // Zero area: all on one line; a zero-length edge gives 0, not NaN.
  for (double v : corners(CellType::Quad4, {0, 0, 1, 0, 2, 0, 3, 0}, true)) EXPECT_EQ(v, 0);
  for (double v : corners(CellType::Quad4, {0, 0, 0, 0, 1, 1, 0, 1}, true)) EXPECT_FALSE(std::isnan(v));
  // 45 degree corner: the scaled value is its sine.
  const std::vector<double> rhombus = {0, 0, 1, 0, 2, 1, 1, 1};
  EXPECT_NEAR(corners(CellType::Quad4, rhombus, true)[0], std::sin(std::acos(-1.0) / 4), 1e-14);
}

TEST(CellGeometry, Hex8Orientation) {
  EXPECT_EQ(corners(CellType::Hex8, kUnitCube, false), std::vector<double>(8, 1.0));
  // Top and bottom faces exchanged: a mirror image, left-handed at every corner.
  std::vector<double> mirrored(kUnitCube.begin() + 12, kUnitCube.end());
  mirrored.insert(mirrored.end(), kUnitCube.begin(), kUnitCube.begin() + 12);
  EXPECT_EQ(corners(CellType::Hex8, mirrored, true), std::vector<double>(8, -1.0));
  // Node 6 (1, 1, 1) pushed through the cube to (0.2, 0.2, 0.2): negative at corner 6 only.
  std::vector<double> dented = kUnitCube;
  dented[18] = dented[19] = dented[20] = 0.2;
  const auto j = corners(CellType::Hex8, dented, true);
  for (int a = 0; a < 8; ++a) {
    if (a == 6)
      EXPECT_LT(j[a], 0);
    else
      EXPECT_GT(j[a], 0) << "corner " << a;
  }
  // Flat: every node on z = 0.
  std::vector<double> flat = kUnitCube;
  for (int a = 0; a < 8; ++a) flat[3 * a + 2] = 0;
  for (double v : corners(CellType::Hex8, flat, true)) EXPECT_EQ(v, 0);
}
