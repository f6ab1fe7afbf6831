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
#include "mesh/MeshMerge.hpp"

using namespace contessa;
using namespace contessa::mesh;
using test_support::messageOf;

namespace {

using Parts = std::vector<std::pair<std::string, Mesh>>;

double x(const Mesh& m, GlobalIndex n) { return m.coordinates[2 * n]; }
double y(const Mesh& m, GlobalIndex n) { return m.coordinates[2 * n + 1]; }

Mesh rectangle(double x0, double y0, double lx, double ly, int nx, int ny) {
  RectangleSpec spec = test_support::rectangleSpec(nx, ny, lx, ly, x0, y0);
  return generateRectangle(spec);
}

// Global node ids of every side in a side set, via the element's block and connectivity.
std::vector<std::vector<GlobalIndex>> sideNodeIds(const Mesh& m, const std::string& set) {
  std::vector<std::vector<GlobalIndex>> out;
  const auto& s = m.sideSet(set);
  for (size_t k = 0; k < s.elements.size(); ++k) {
    const auto loc = m.locate(s.elements[k]);
    const auto& b = m.blocks[loc.block];
    const size_t npe = static_cast<size_t>(nodesPerCell(b.cellType));
    std::vector<GlobalIndex> nodes;
    for (int a : sideNodes(b.cellType, s.sides[k])) nodes.push_back(b.connectivity[npe * loc.local + a]);
    out.push_back(nodes);
  }
  return out;
}

// A single Hex8 unit cube: a valid 3D mesh.
Mesh unitCube() {
  Mesh m;
  m.dimension = 3;
  m.coordinates = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
  ElementBlock b;
  b.name = "cube";
  b.cellType = CellType::Hex8;
  b.elements = {0};
  b.connectivity = {0, 1, 2, 3, 4, 5, 6, 7};
  m.blocks.push_back(b);
  m.nodeSets.push_back({"top", {4, 5, 6, 7}});
  m.sideSets.push_back({"top", {0}, {5}});
  return m;
}

}  // namespace

TEST(MeshMerge, TwoRectanglesCountsNamesAndOffsets) {
  // Lower body [0,2]×[0,1] (4×2), upper body [0.5,2.5]×[1,1.5] (3×1): touching along y = 1.
  const Mesh lower = rectangle(0, 0, 2, 1, 4, 2);
  const Mesh upper = translateMesh(rectangle(0, 0, 2, 0.5, 3, 1), {0.5, 1});
  const Mesh m = mergeMeshes({{"lower", lower}, {"upper", upper}});
  EXPECT_NO_THROW(m.validate("test"));
  EXPECT_EQ(m.dimension, 2);
  EXPECT_EQ(m.numNodes(), 15 + 8);  // coincident nodes on y = 1 are kept apart
  EXPECT_EQ(m.numElements(), 8 + 3);

  // One block per part: blocks are named after the parts; element ids sequential.
  ASSERT_EQ(m.blocks.size(), 2u);
  EXPECT_EQ(m.blocks[0].name, "lower");
  EXPECT_EQ(m.blocks[1].name, "upper");
  EXPECT_EQ(m.blocks[0].elements, (std::vector<GlobalIndex>{0, 1, 2, 3, 4, 5, 6, 7}));
  EXPECT_EQ(m.blocks[1].elements, (std::vector<GlobalIndex>{8, 9, 10}));
  EXPECT_EQ(m.blocks[0].connectivity, lower.blocks[0].connectivity);
  for (size_t k = 0; k < upper.blocks[0].connectivity.size(); ++k)
    EXPECT_EQ(m.blocks[1].connectivity[k], upper.blocks[0].connectivity[k] + 15);
  for (GlobalIndex n = 0; n < 15; ++n) {
    EXPECT_EQ(x(m, n), x(lower, n));
    EXPECT_EQ(y(m, n), y(lower, n));
  }
  for (GlobalIndex n = 0; n < 8; ++n) {
    EXPECT_EQ(x(m, 15 + n), x(upper, n));
    EXPECT_EQ(y(m, 15 + n), y(upper, n));
  }

  // Sets renamed "<part>_<name>", in part order.
  std::vector<std::string> nodeSetNames, sideSetNames;
  for (const auto& s : m.nodeSets) nodeSetNames.push_back(s.name);
  for (const auto& s : m.sideSets) sideSetNames.push_back(s.name);
  EXPECT_EQ(nodeSetNames, (std::vector<std::string>{"lower_left", "lower_right", "lower_bottom", "lower_top",
                                                    "lower_all", "upper_left", "upper_right", "upper_bottom",
                                                    "upper_top", "upper_all"}));
  EXPECT_EQ(sideSetNames, (std::vector<std::string>{"lower_left", "lower_right", "lower_bottom", "lower_top",
                                                    "upper_left", "upper_right", "upper_bottom", "upper_top"}));
  EXPECT_EQ(m.nodeSet("lower_top").nodes, (std::vector<GlobalIndex>{10, 11, 12, 13, 14}));
  EXPECT_EQ(m.nodeSet("upper_bottom").nodes, (std::vector<GlobalIndex>{15, 16, 17, 18}));
  EXPECT_EQ(m.nodeSet("upper_all").nodes.size(), 8u);
  EXPECT_EQ(m.nodeSet("upper_all").nodes.front(), 15);
  EXPECT_EQ(m.nodeSet("upper_all").nodes.back(), 22);
  for (GlobalIndex n : m.nodeSet("upper_bottom").nodes) EXPECT_DOUBLE_EQ(y(m, n), 1);
  for (GlobalIndex n : m.nodeSet("upper_top").nodes) EXPECT_DOUBLE_EQ(y(m, n), 1.5);

  // Side sets point at the right (offset) elements: check the coordinates of the sides' nodes.
  EXPECT_EQ(m.sideSet("upper_bottom").elements, (std::vector<GlobalIndex>{8, 9, 10}));
  EXPECT_EQ(m.sideSet("upper_bottom").sides, (std::vector<int>{0, 0, 0}));
  EXPECT_EQ(m.sideSet("lower_top").elements, (std::vector<GlobalIndex>{4, 5, 6, 7}));
  EXPECT_EQ(m.sideSet("upper_right").elements, (std::vector<GlobalIndex>{10}));
  for (const auto& side : sideNodeIds(m, "upper_bottom"))
    for (GlobalIndex n : side) {
      EXPECT_GE(n, 15);
      EXPECT_DOUBLE_EQ(y(m, n), 1);
      EXPECT_GE(x(m, n), 0.5);
      EXPECT_LE(x(m, n), 2.5);
    }
  for (const auto& side : sideNodeIds(m, "lower_top"))
    for (GlobalIndex n : side) {
      EXPECT_LT(n, 15);
      EXPECT_DOUBLE_EQ(y(m, n), 1);
    }
  for (const auto& side : sideNodeIds(m, "upper_right"))
    for (GlobalIndex n : side) EXPECT_DOUBLE_EQ(x(m, n), 2.5);
  for (const auto& side : sideNodeIds(m, "upper_top"))
    for (GlobalIndex n : side) EXPECT_DOUBLE_EQ(y(m, n), 1.5);
  // Outward order survives: the bottom side of the upper body runs in +x (element on its left).
  for (const auto& side : sideNodeIds(m, "upper_bottom")) EXPECT_LT(x(m, side[0]), x(m, side[1]));
}

TEST(MeshMerge, MultiBlockPartsPrefixBlockNamesAndRenumberElements) {
  // Part "two" holds two blocks listed out of id order: "upper_row" (ids 4..7) before "lower_row"
  // (ids 0..3). The merge numbers elements sequentially over blocks in order, and side sets follow.
  Mesh two = rectangle(0, 0, 4, 2, 4, 2);
  const ElementBlock whole = two.blocks[0];
  ElementBlock lowerRow, upperRow;
  lowerRow.name = "lower_row";
  upperRow.name = "upper_row";
  lowerRow.elements.assign(whole.elements.begin(), whole.elements.begin() + 4);
  lowerRow.connectivity.assign(whole.connectivity.begin(), whole.connectivity.begin() + 16);
  upperRow.elements.assign(whole.elements.begin() + 4, whole.elements.end());
  upperRow.connectivity.assign(whole.connectivity.begin() + 16, whole.connectivity.end());
  two.blocks = {upperRow, lowerRow};
  two.validate("test part");

  const Mesh one = rectangle(-3, 0, 1, 1, 1, 1);
  const Mesh m = mergeMeshes({{"one", one}, {"two", two}});
  ASSERT_EQ(m.blocks.size(), 3u);
  EXPECT_EQ(m.blocks[0].name, "one");  // single block: just the part name
  EXPECT_EQ(m.blocks[1].name, "two_upper_row");
  EXPECT_EQ(m.blocks[2].name, "two_lower_row");
  EXPECT_TRUE(m.hasBlock("two_lower_row"));
  EXPECT_FALSE(m.hasBlock("two"));
  EXPECT_EQ(m.blocks[0].elements, (std::vector<GlobalIndex>{0}));
  EXPECT_EQ(m.blocks[1].elements, (std::vector<GlobalIndex>{1, 2, 3, 4}));
  EXPECT_EQ(m.blocks[2].elements, (std::vector<GlobalIndex>{5, 6, 7, 8}));
  EXPECT_NO_THROW(m.validate("test"));

  // "bottom" was elements 0..3 of the part (the lower row), now the block listed second.
  EXPECT_EQ(m.sideSet("two_bottom").elements, (std::vector<GlobalIndex>{5, 6, 7, 8}));
  EXPECT_EQ(m.sideSet("two_top").elements, (std::vector<GlobalIndex>{1, 2, 3, 4}));
  EXPECT_EQ(m.sideSet("two_left").elements, (std::vector<GlobalIndex>{5, 1}));
  for (const auto& side : sideNodeIds(m, "two_bottom"))
    for (GlobalIndex n : side) EXPECT_DOUBLE_EQ(y(m, n), 0);
  for (const auto& side : sideNodeIds(m, "two_top"))
    for (GlobalIndex n : side) EXPECT_DOUBLE_EQ(y(m, n), 2);
  for (const auto& side : sideNodeIds(m, "two_left"))
    for (GlobalIndex n : side) EXPECT_DOUBLE_EQ(x(m, n), 0);
  for (const auto& side : sideNodeIds(m, "one_left"))
    for (GlobalIndex n : side) EXPECT_DOUBLE_EQ(x(m, n), -3);
}

TEST(MeshMerge, SinglePartOnlyRenames) {
  const Mesh part = rectangle(0, 0, 1, 1, 2, 2);
  const Mesh m = mergeMeshes({{"plate", part}});
  EXPECT_EQ(m.coordinates, part.coordinates);
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].name, "plate");
  EXPECT_EQ(m.blocks[0].elements, part.blocks[0].elements);
  EXPECT_EQ(m.blocks[0].connectivity, part.blocks[0].connectivity);
  EXPECT_EQ(m.nodeSet("plate_top").nodes, part.nodeSet("top").nodes);
  EXPECT_EQ(m.sideSet("plate_right").elements, part.sideSet("right").elements);
  EXPECT_FALSE(m.hasNodeSet("top"));
}

TEST(MeshMerge, ThreeDimensionalParts) {
  const Mesh m = mergeMeshes({{"a", unitCube()}, {"b", translateMesh(unitCube(), {0, 0, 1})}});
  EXPECT_EQ(m.dimension, 3);
  EXPECT_EQ(m.numNodes(), 16);
  EXPECT_EQ(m.numElements(), 2);
  EXPECT_EQ(m.block("b").connectivity, (std::vector<GlobalIndex>{8, 9, 10, 11, 12, 13, 14, 15}));
  EXPECT_EQ(m.nodeSet("b_top").nodes, (std::vector<GlobalIndex>{12, 13, 14, 15}));
  EXPECT_EQ(m.sideSet("b_top").elements, (std::vector<GlobalIndex>{1}));
  for (GlobalIndex n : m.nodeSet("b_top").nodes) EXPECT_DOUBLE_EQ(m.coordinates[3 * n + 2], 2);
}

TEST(MeshMerge, RejectsBadParts) {
  const Mesh plate = rectangle(0, 0, 1, 1, 1, 1);
  EXPECT_EQ(messageOf([&] { mergeMeshes({{"plate", plate}, {"cube", unitCube()}}); }),
            "mesh merge: mesh part 'cube' is 3D but mesh part 'plate' is 2D");
  EXPECT_EQ(messageOf([&] { mergeMeshes({{"a", plate}, {"b", plate}, {"a", plate}}); }),
            "mesh merge: mesh part name 'a' is used more than once");
  EXPECT_EQ(messageOf([&] { mergeMeshes({{"a", plate}, {"", plate}}); }),
            "mesh merge: mesh part 2 has an empty name");
  EXPECT_EQ(messageOf([&] { mergeMeshes({}); }), "mesh merge: expected at least one mesh part, got none");

  Mesh broken = plate;
  broken.blocks[0].connectivity[2] = 99;
  const std::string message = messageOf([&] { mergeMeshes({{"a", plate}, {"broken", broken}}); });
  EXPECT_NE(message.find("mesh part 'broken'"), std::string::npos) << message;

  // Prefixed names can still collide; the merged mesh's validation reports it.
  Mesh ab = plate, a = plate;
  ab.nodeSets[0].name = "c";
  a.nodeSets[0].name = "b_c";
  EXPECT_EQ(messageOf([&] { mergeMeshes({{"a_b", ab}, {"a", a}}); }),
            "merged mesh: node set name 'a_b_c' is used more than once");
}

TEST(MeshTranslate, MovesEveryNodeAndNothingElse) {
  const Mesh part = rectangle(0, 0, 2, 1, 2, 1);
  const Mesh moved = translateMesh(part, {1.5, -2});
  ASSERT_EQ(moved.coordinates.size(), part.coordinates.size());
  for (GlobalIndex n = 0; n < part.numNodes(); ++n) {
    EXPECT_DOUBLE_EQ(x(moved, n), x(part, n) + 1.5);
    EXPECT_DOUBLE_EQ(y(moved, n), y(part, n) - 2);
  }
  EXPECT_EQ(moved.blocks[0].connectivity, part.blocks[0].connectivity);
  EXPECT_EQ(moved.nodeSet("top").nodes, part.nodeSet("top").nodes);
  EXPECT_EQ(moved.sideSet("top").elements, part.sideSet("top").elements);

  const Mesh cube = translateMesh(unitCube(), {1, 2, 3});
  EXPECT_DOUBLE_EQ(cube.coordinates[3 * 6 + 0], 2);
  EXPECT_DOUBLE_EQ(cube.coordinates[3 * 6 + 1], 3);
  EXPECT_DOUBLE_EQ(cube.coordinates[3 * 6 + 2], 4);
}

TEST(MeshTranslate, RejectsWrongOffsets) {
  const Mesh part = rectangle(0, 0, 1, 1, 1, 1);
  EXPECT_EQ(messageOf([&] { translateMesh(part, {1, 2, 3}); }),
            "mesh translation: expected an offset with 2 components (the mesh dimension), got 3");
  EXPECT_THROW(translateMesh(part, {}), InputError);
  EXPECT_EQ(messageOf([&] { translateMesh(part, {0, std::nan("")}); }),
            "mesh translation: offset component 2 must be finite, got nan");
}
