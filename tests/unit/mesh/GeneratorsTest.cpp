#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "MeshTestSupport.hpp"
#include "common/Error.hpp"
#include "mesh/Generators.hpp"

using namespace contessa;
using namespace contessa::mesh;
using test_support::messageOf;

namespace {

const double kPi = std::acos(-1.0);

double x(const Mesh& m, GlobalIndex n) { return m.coordinates[2 * n]; }
double y(const Mesh& m, GlobalIndex n) { return m.coordinates[2 * n + 1]; }
double radius(const Mesh& m, GlobalIndex n) { return std::hypot(x(m, n), y(m, n)); }
double angleDeg(const Mesh& m, GlobalIndex n) { return std::atan2(y(m, n), x(m, n)) * 180 / kPi; }

// Shoelace area: positive for counter-clockwise connectivity.
double signedArea(const Mesh& m, const ElementBlock& b, size_t element) {
  double area = 0;
  for (int a = 0; a < 4; ++a) {
    const GlobalIndex p = b.connectivity[4 * element + a], q = b.connectivity[4 * element + (a + 1) % 4];
    area += x(m, p) * y(m, q) - x(m, q) * y(m, p);
  }
  return area / 2;
}

bool sortedUnique(const std::vector<GlobalIndex>& v) {
  return std::is_sorted(v.begin(), v.end()) && std::adjacent_find(v.begin(), v.end()) == v.end();
}

// Every side listed in the set must have both nodes in the node set of the same name.
void expectSidesOnNodeSet(const Mesh& m, const std::string& name) {
  const auto& sides = m.sideSet(name);
  const auto& nodes = m.nodeSet(name).nodes;
  ASSERT_EQ(sides.elements.size(), sides.sides.size());
  for (size_t k = 0; k < sides.elements.size(); ++k) {
    const auto loc = m.locate(sides.elements[k]);
    const auto& block = m.blocks[loc.block];
    for (int a : sideNodes(block.cellType, sides.sides[k])) {
      const GlobalIndex node = block.connectivity[4 * loc.local + a];
      EXPECT_TRUE(std::binary_search(nodes.begin(), nodes.end(), node))
          << name << ": element " << sides.elements[k] << " side " << sides.sides[k] << " node " << node;
    }
  }
}

}  // namespace

TEST(RectangleGenerator, CountsCoordinatesAndNumbering) {
  RectangleSpec spec = test_support::rectangleSpec(4, 3, 4, 3, -1, 2);
  spec.blockName = "plate";
  const Mesh m = generateRectangle(spec);
  EXPECT_EQ(m.dimension, 2);
  EXPECT_EQ(m.numNodes(), 20);
  EXPECT_EQ(m.numElements(), 12);
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].name, "plate");
  EXPECT_EQ(m.blocks[0].cellType, CellType::Quad4);
  // Corners: node j*(nx+1) + i.
  EXPECT_DOUBLE_EQ(x(m, 0), -1);
  EXPECT_DOUBLE_EQ(y(m, 0), 2);
  EXPECT_DOUBLE_EQ(x(m, 4), 3);
  EXPECT_DOUBLE_EQ(y(m, 4), 2);
  EXPECT_DOUBLE_EQ(x(m, 19), 3);
  EXPECT_DOUBLE_EQ(y(m, 19), 5);
  EXPECT_DOUBLE_EQ(x(m, 7), 1);  // i = 2, j = 1
  EXPECT_DOUBLE_EQ(y(m, 7), 3);
  // Element j*nx + i = 5 is (1, 1): nodes 6, 7, 12, 11.
  EXPECT_EQ(m.blocks[0].elements[5], 5);
  EXPECT_EQ(std::vector<GlobalIndex>(m.blocks[0].connectivity.begin() + 20, m.blocks[0].connectivity.begin() + 24),
            (std::vector<GlobalIndex>{6, 7, 12, 11}));
  for (size_t e = 0; e < 12; ++e) EXPECT_NEAR(signedArea(m, m.blocks[0], e), 1.0, 1e-12);
}

TEST(RectangleGenerator, NodeAndSideSets) {
  RectangleSpec spec = test_support::rectangleSpec(4, 2, 2, 1);
  const Mesh m = generateRectangle(spec);
  EXPECT_EQ(m.nodeSet("left").nodes, (std::vector<GlobalIndex>{0, 5, 10}));
  EXPECT_EQ(m.nodeSet("right").nodes, (std::vector<GlobalIndex>{4, 9, 14}));
  EXPECT_EQ(m.nodeSet("bottom").nodes, (std::vector<GlobalIndex>{0, 1, 2, 3, 4}));
  EXPECT_EQ(m.nodeSet("top").nodes, (std::vector<GlobalIndex>{10, 11, 12, 13, 14}));
  EXPECT_EQ(m.nodeSet("all").nodes.size(), 15u);
  for (const auto& s : m.nodeSets) EXPECT_TRUE(sortedUnique(s.nodes)) << s.name;
  for (GlobalIndex n : m.nodeSet("right").nodes) EXPECT_DOUBLE_EQ(x(m, n), 2);
  for (GlobalIndex n : m.nodeSet("top").nodes) EXPECT_DOUBLE_EQ(y(m, n), 1);

  EXPECT_EQ(m.sideSet("bottom").elements, (std::vector<GlobalIndex>{0, 1, 2, 3}));
  EXPECT_EQ(m.sideSet("bottom").sides, (std::vector<int>{0, 0, 0, 0}));
  EXPECT_EQ(m.sideSet("right").elements, (std::vector<GlobalIndex>{3, 7}));
  EXPECT_EQ(m.sideSet("right").sides, (std::vector<int>{1, 1}));
  EXPECT_EQ(m.sideSet("top").elements, (std::vector<GlobalIndex>{4, 5, 6, 7}));
  EXPECT_EQ(m.sideSet("top").sides, (std::vector<int>{2, 2, 2, 2}));
  EXPECT_EQ(m.sideSet("left").elements, (std::vector<GlobalIndex>{0, 4}));
  EXPECT_EQ(m.sideSet("left").sides, (std::vector<int>{3, 3}));
  for (const char* name : {"left", "right", "bottom", "top"}) expectSidesOnNodeSet(m, name);
}

TEST(RectangleGenerator, RejectsBadSpecs) {
  RectangleSpec spec;
  spec.nx = 0;
  EXPECT_EQ(messageOf([&] { generateRectangle(spec); }), "Elements X: expected a positive integer, got 0");
  spec = {};
  spec.ny = -3;
  EXPECT_THROW(generateRectangle(spec), InputError);
  spec = {};
  spec.lx = 0;
  EXPECT_EQ(messageOf([&] { generateRectangle(spec); }), "Length X: expected a positive number, got 0");
  spec = {};
  spec.ly = -1;
  EXPECT_THROW(generateRectangle(spec), InputError);
  spec = {};
  spec.x0 = std::nan("");
  EXPECT_THROW(generateRectangle(spec), InputError);
}

TEST(AnnulusSectorGenerator, CountsRadiiAndAngles) {
  AnnulusSectorSpec spec = test_support::annulusSpec(4, 9, 100, 20, 30, 120);
  const Mesh m = generateAnnulusSector(spec);
  EXPECT_EQ(m.numNodes(), 5 * 10);
  EXPECT_EQ(m.numElements(), 4 * 9);
  // Node j*(nr+1) + i: i radial, j angular.
  for (int j = 0; j <= 9; ++j)
    for (int i = 0; i <= 4; ++i) {
      const GlobalIndex n = j * 5 + i;
      EXPECT_NEAR(radius(m, n), 100 + 5.0 * i, 1e-10) << n;
      EXPECT_NEAR(angleDeg(m, n), 30 + 10.0 * j, 1e-10) << n;
    }
  EXPECT_NEAR(x(m, 0), 100 * std::cos(kPi / 6), 1e-12);
  EXPECT_NEAR(y(m, 0), 50, 1e-12);
  EXPECT_NEAR(x(m, 49), 120 * std::cos(2 * kPi / 3), 1e-12);  // outer end corner
  EXPECT_NEAR(y(m, 49), 120 * std::sin(2 * kPi / 3), 1e-12);
  // Element j*nr + i = 6 is (2, 1): nodes 7, 8, 13, 12.
  EXPECT_EQ(std::vector<GlobalIndex>(m.blocks[0].connectivity.begin() + 24, m.blocks[0].connectivity.begin() + 28),
            (std::vector<GlobalIndex>{7, 8, 13, 12}));
  for (size_t e = 0; e < 36; ++e) EXPECT_GT(signedArea(m, m.blocks[0], e), 0) << e;
}

TEST(AnnulusSectorGenerator, DefaultSpecMatchesTheDocumentedRing) {
  const Mesh m = generateAnnulusSector({});
  EXPECT_EQ(m.numNodes(), 14 * 102);
  EXPECT_EQ(m.numElements(), 13 * 101);
  EXPECT_EQ(m.blocks[0].name, "block_1");
  EXPECT_NEAR(x(m, 13), 120, 1e-12);
  EXPECT_NEAR(y(m, 13), 0, 1e-12);
  EXPECT_NEAR(x(m, 101 * 14), 0, 1e-12);
  EXPECT_NEAR(y(m, 101 * 14), 100, 1e-12);
  double total = 0;
  for (size_t e = 0; e < static_cast<size_t>(m.numElements()); ++e) {
    const double a = signedArea(m, m.blocks[0], e);
    EXPECT_GT(a, 0);
    total += a;
  }
  // Chords cut a little off the quarter ring π(120² − 100²)/4.
  EXPECT_NEAR(total, kPi * (120 * 120 - 100 * 100) / 4, 0.5);
}

TEST(AnnulusSectorGenerator, NodeAndSideSets) {
  AnnulusSectorSpec spec = test_support::annulusSpec(3, 6, 10, 2, -45, 45);
  const Mesh m = generateAnnulusSector(spec);
  ASSERT_EQ(m.nodeSet("inner").nodes.size(), 7u);
  ASSERT_EQ(m.nodeSet("outer").nodes.size(), 7u);
  ASSERT_EQ(m.nodeSet("start").nodes.size(), 4u);
  ASSERT_EQ(m.nodeSet("end").nodes.size(), 4u);
  EXPECT_EQ(m.nodeSet("all").nodes.size(), 28u);
  for (const auto& s : m.nodeSets) EXPECT_TRUE(sortedUnique(s.nodes)) << s.name;
  for (GlobalIndex n : m.nodeSet("inner").nodes) EXPECT_NEAR(radius(m, n), 10, 1e-12);
  for (GlobalIndex n : m.nodeSet("outer").nodes) EXPECT_NEAR(radius(m, n), 12, 1e-12);
  for (GlobalIndex n : m.nodeSet("start").nodes) EXPECT_NEAR(angleDeg(m, n), -45, 1e-10);
  for (GlobalIndex n : m.nodeSet("end").nodes) EXPECT_NEAR(angleDeg(m, n), 45, 1e-10);
  EXPECT_EQ(m.nodeSet("start").nodes, (std::vector<GlobalIndex>{0, 1, 2, 3}));
  EXPECT_EQ(m.nodeSet("end").nodes, (std::vector<GlobalIndex>{24, 25, 26, 27}));

  EXPECT_EQ(m.sideSet("inner").elements, (std::vector<GlobalIndex>{0, 3, 6, 9, 12, 15}));
  EXPECT_EQ(m.sideSet("inner").sides, std::vector<int>(6, 3));
  EXPECT_EQ(m.sideSet("outer").elements, (std::vector<GlobalIndex>{2, 5, 8, 11, 14, 17}));
  EXPECT_EQ(m.sideSet("outer").sides, std::vector<int>(6, 1));
  EXPECT_EQ(m.sideSet("start").elements, (std::vector<GlobalIndex>{0, 1, 2}));
  EXPECT_EQ(m.sideSet("start").sides, std::vector<int>(3, 0));
  EXPECT_EQ(m.sideSet("end").elements, (std::vector<GlobalIndex>{15, 16, 17}));
  EXPECT_EQ(m.sideSet("end").sides, std::vector<int>(3, 2));
  for (const char* name : {"inner", "outer", "start", "end"}) expectSidesOnNodeSet(m, name);
}

TEST(AnnulusSectorGenerator, FullRingIsAllowed) {
  AnnulusSectorSpec spec = test_support::annulusSpec(2, 12, 100, 20, 0, 360);
  const Mesh m = generateAnnulusSector(spec);
  EXPECT_EQ(m.numElements(), 24);
  for (size_t e = 0; e < 24; ++e) EXPECT_GT(signedArea(m, m.blocks[0], e), 0);
}

TEST(AnnulusSectorGenerator, RejectsBadSpecs) {
  AnnulusSectorSpec spec;
  spec.elementsThroughThickness = 0;
  EXPECT_EQ(messageOf([&] { generateAnnulusSector(spec); }),
            "Elements Through Thickness: expected a positive integer, got 0");
  spec = {};
  spec.elementsAroundArc = -2;
  EXPECT_EQ(messageOf([&] { generateAnnulusSector(spec); }), "Elements Around Arc: expected a positive integer, got -2");
  spec = {};
  spec.innerRadius = 0;
  EXPECT_EQ(messageOf([&] { generateAnnulusSector(spec); }), "Inner Radius: expected a positive number, got 0");
  spec = {};
  spec.thickness = -1;
  EXPECT_THROW(generateAnnulusSector(spec), InputError);
  spec = {};
  spec.startAngleDeg = 90;
  spec.endAngleDeg = 90;
  EXPECT_EQ(messageOf([&] { generateAnnulusSector(spec); }),
            "End Angle: expected an angle greater than Start Angle (90), got 90");
  spec = {};
  spec.startAngleDeg = 10;
  spec.endAngleDeg = 380.5;
  EXPECT_EQ(messageOf([&] { generateAnnulusSector(spec); }),
            "End Angle: expected at most 360 degrees beyond Start Angle (10), got 380.5");
}

// ---- graded (biased) generators ----

namespace {

// Differences of consecutive values: element sizes from node positions.
std::vector<double> steps(const std::vector<double>& positions) {
  std::vector<double> h;
  for (size_t k = 1; k < positions.size(); ++k) h.push_back(positions[k] - positions[k - 1]);
  return h;
}

void expectGeometric(const std::vector<double>& h, double bias, double length, const std::string& what) {
  ASSERT_GE(h.size(), 2u) << what;
  EXPECT_NEAR(h.back() / h.front(), bias, 1e-12 * bias) << what;
  const double q = h[1] / h[0];
  for (size_t k = 1; k < h.size(); ++k) {
    EXPECT_GT(h[k], 0) << what << " element " << k;
    EXPECT_NEAR(h[k] / h[k - 1], q, 1e-10 * q) << what << " element " << k;
  }
  double sum = 0;
  for (double v : h) sum += v;
  EXPECT_NEAR(sum, length, 1e-12 * length) << what;
}

}  // namespace

TEST(RectangleGenerator, GradedSizesFollowTheBias) {
  for (const auto& [bx, by] : {std::pair{5.0, 0.2}, std::pair{0.01, 40.0}, std::pair{1 + 1e-9, 1 - 1e-9}}) {
    RectangleSpec spec = test_support::rectangleSpec(10, 7, 3, 2, 0, 0);
    spec.biasX = bx;
    spec.biasY = by;
    const Mesh m = generateRectangle(spec);
    std::vector<double> xs, ys;
    for (int i = 0; i <= spec.nx; ++i) xs.push_back(x(m, i));                    // bottom row, j = 0
    for (int j = 0; j <= spec.ny; ++j) ys.push_back(y(m, j * (spec.nx + 1)));  // left column, i = 0
    expectGeometric(steps(xs), bx, spec.lx, "x, bias " + std::to_string(bx));
    expectGeometric(steps(ys), by, spec.ly, "y, bias " + std::to_string(by));
    // Every row and column sees the same grading.
    for (int j = 0; j <= spec.ny; ++j)
      for (int i = 0; i <= spec.nx; ++i) {
        EXPECT_EQ(x(m, j * (spec.nx + 1) + i), xs[i]);
        EXPECT_EQ(y(m, j * (spec.nx + 1) + i), ys[j]);
      }
    double area = 0;
    for (size_t e = 0; e < static_cast<size_t>(m.numElements()); ++e) {
      const double a = signedArea(m, m.blocks[0], e);
      EXPECT_GT(a, 0) << e;
      area += a;
    }
    EXPECT_NEAR(area, spec.lx * spec.ly, 1e-12);
    for (const char* name : {"left", "right", "bottom", "top"}) expectSidesOnNodeSet(m, name);
  }
}

TEST(RectangleGenerator, GradedEndpointsAreExact) {
  RectangleSpec spec = test_support::rectangleSpec(9, 13, 0.3, 1.1, -0.1, 0.7);
  spec.biasX = 7;
  spec.biasY = 1.0 / 3;
  const Mesh m = generateRectangle(spec);
  EXPECT_EQ(x(m, 0), spec.x0);
  EXPECT_EQ(y(m, 0), spec.y0);
  for (GlobalIndex n : m.nodeSet("right").nodes) EXPECT_EQ(x(m, n), spec.x0 + spec.lx);
  for (GlobalIndex n : m.nodeSet("top").nodes) EXPECT_EQ(y(m, n), spec.y0 + spec.ly);
  for (GlobalIndex n : m.nodeSet("left").nodes) EXPECT_EQ(x(m, n), spec.x0);
  for (GlobalIndex n : m.nodeSet("bottom").nodes) EXPECT_EQ(y(m, n), spec.y0);
}

TEST(RectangleGenerator, UnitBiasIsTheUniformMesh) {
  RectangleSpec spec = test_support::rectangleSpec(7, 3, 2.5, 0.7);
  const Mesh uniform = generateRectangle(spec);
  spec.biasX = 1;
  spec.biasY = 1;
  EXPECT_EQ(generateRectangle(spec).coordinates, uniform.coordinates);
  for (int i = 0; i <= 7; ++i) EXPECT_NEAR(x(uniform, i), 2.5 * i / 7, 1e-15);
}

TEST(RectangleGenerator, BiasIsIgnoredForASingleElement) {
  RectangleSpec spec;
  spec.lx = 2;
  spec.nx = 1;
  spec.biasX = 9;
  const Mesh m = generateRectangle(spec);
  EXPECT_EQ(x(m, 0), 0);
  EXPECT_EQ(x(m, 1), 2);
}

TEST(RectangleGenerator, RejectsBadBias) {
  RectangleSpec spec;
  spec.biasX = 0;
  EXPECT_EQ(messageOf([&] { generateRectangle(spec); }), "Bias X: expected a value > 0, got 0");
  spec = {};
  spec.biasY = -2;
  EXPECT_EQ(messageOf([&] { generateRectangle(spec); }), "Bias Y: expected a value > 0, got -2");
  spec = {};
  spec.biasX = std::nan("");
  EXPECT_THROW(generateRectangle(spec), InputError);
  spec = {};
  spec.biasY = HUGE_VAL;
  EXPECT_THROW(generateRectangle(spec), InputError);
  // So strong a grading that the first element vanishes next to x0 = 1.
  spec = {};
  spec.x0 = 1;
  spec.nx = 2;
  spec.biasX = 1e300;
  EXPECT_EQ(messageOf([&] { generateRectangle(spec); }),
            "Bias X: value 1e+300 with 2 elements makes elements too small to represent");
}

TEST(AnnulusSectorGenerator, GradedSizesFollowTheBias) {
  AnnulusSectorSpec spec = test_support::annulusSpec(8, 30, 100, 20, 0, 90);
  spec.radialBias = 0.1;  // fine at the outer surface
  spec.arcBias = 6;       // fine near the start angle
  const Mesh m = generateAnnulusSector(spec);
  const int nr = spec.elementsThroughThickness, nt = spec.elementsAroundArc;
  std::vector<double> radii, angles;
  for (int i = 0; i <= nr; ++i) radii.push_back(x(m, i));  // θ = 0: y = 0, x = r exactly
  for (int j = 0; j <= nt; ++j) angles.push_back(angleDeg(m, j * (nr + 1)));
  expectGeometric(steps(radii), spec.radialBias, spec.thickness, "radial");
  // atan2 recovers the angles to ~1e-14 degrees, the arc sizes to ~1e-13 relative.
  const auto h = steps(angles);
  EXPECT_NEAR(h.back() / h.front(), spec.arcBias, 1e-12 * spec.arcBias);
  double sum = 0;
  for (double v : h) sum += v;
  EXPECT_NEAR(sum, 90, 1e-12);
  // Exact ends: inner and outer radius, start and end angle.
  EXPECT_EQ(x(m, 0), 100);
  EXPECT_EQ(y(m, 0), 0);
  EXPECT_EQ(x(m, nr), 120);
  const double degToRad = std::acos(-1.0) / 180.0;
  const GlobalIndex outerEnd = static_cast<GlobalIndex>(nt) * (nr + 1) + nr;
  EXPECT_EQ(x(m, outerEnd), 120 * std::cos(90 * degToRad));
  EXPECT_EQ(y(m, outerEnd), 120 * std::sin(90 * degToRad));
  for (GlobalIndex n : m.nodeSet("outer").nodes) EXPECT_NEAR(radius(m, n), 120, 1e-12);
  for (GlobalIndex n : m.nodeSet("inner").nodes) EXPECT_NEAR(radius(m, n), 100, 1e-12);
  for (size_t e = 0; e < static_cast<size_t>(m.numElements()); ++e) EXPECT_GT(signedArea(m, m.blocks[0], e), 0) << e;
  for (const char* name : {"inner", "outer", "start", "end"}) expectSidesOnNodeSet(m, name);
}

TEST(AnnulusSectorGenerator, GradedEndAngleIsExact) {
  // −50.6 + (87.8 − (−50.6)) is not 87.8 in floating point (and moves the node); the last angle must
  // still be exactly 87.8 degrees.
  AnnulusSectorSpec spec = test_support::annulusSpec(2, 5, 100, 20, -50.6, 87.8);
  spec.arcBias = 0.5;
  const Mesh m = generateAnnulusSector(spec);
  const double theta = 87.8 * (std::acos(-1.0) / 180.0);
  const GlobalIndex innerEnd = 5 * 3;
  EXPECT_EQ(x(m, innerEnd), 100 * std::cos(theta));
  EXPECT_EQ(y(m, innerEnd), 100 * std::sin(theta));
}

TEST(AnnulusSectorGenerator, RejectsBadBias) {
  AnnulusSectorSpec spec;
  spec.radialBias = 0;
  EXPECT_EQ(messageOf([&] { generateAnnulusSector(spec); }), "Radial Bias: expected a value > 0, got 0");
  spec = {};
  spec.arcBias = -0.5;
  EXPECT_EQ(messageOf([&] { generateAnnulusSector(spec); }), "Arc Bias: expected a value > 0, got -0.5");
  spec = {};
  spec.arcBias = std::nan("");
  EXPECT_THROW(generateAnnulusSector(spec), InputError);
}
