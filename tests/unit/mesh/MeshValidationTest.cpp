// Mesh::validate on meshes broken the way real files are: one test per defect, the message asserted
// in full (it is what the user reads).
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <string>

#include "MeshTestSupport.hpp"
#include "common/Error.hpp"
#include "mesh/Generators.hpp"
#include "mesh/Mesh.hpp"
#include "mesh/MeshMerge.hpp"

using namespace contessa;
using namespace contessa::mesh;
using test_support::messageOf;

namespace {

// 2 x 2 unit squares: node (i, j) = 3j + i, element (i, j) = 2j + i, counter-clockwise.
Mesh square() {
  RectangleSpec spec;
  spec.lx = spec.ly = 2;
  spec.nx = spec.ny = 2;
  return generateRectangle(spec);
}

Mesh oneQuad(std::vector<double> coordinates) {
  Mesh m;
  m.dimension = 2;
  m.coordinates = std::move(coordinates);
  m.blocks.push_back({"plate", CellType::Quad4, {0}, {0, 1, 2, 3}});
  return m;
}

// Two unit cubes side by side along x: node (i, j, k) = 6k + 3j + i.
Mesh twoCubes() {
  Mesh m;
  m.dimension = 3;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) m.coordinates.insert(m.coordinates.end(), {double(i), double(j), double(k)});
  auto node = [](int i, int j, int k) -> GlobalIndex { return 6 * k + 3 * j + i; };
  ElementBlock b{"cubes", CellType::Hex8, {0, 1}, {}};
  for (int i = 0; i < 2; ++i)
    for (GlobalIndex n : {node(i, 0, 0), node(i + 1, 0, 0), node(i + 1, 1, 0), node(i, 1, 0), node(i, 0, 1),
                          node(i + 1, 0, 1), node(i + 1, 1, 1), node(i, 1, 1)})
      b.connectivity.push_back(n);
  m.blocks.push_back(b);
  return m;
}

void reverseElement(Mesh& m, size_t element) {
  auto first = m.blocks[0].connectivity.begin() + 4 * element;
  std::reverse(first, first + 4);
}

}  // namespace

TEST(MeshValidation, GoodMeshesPass) {
  EXPECT_NO_THROW(square().validate("m.exo"));
  EXPECT_NO_THROW(generateAnnulusSector({}).validate("m.exo"));
  Mesh cubes = twoCubes();
  cubes.sideSets.push_back({"x_max", {1}, {1}});
  EXPECT_NO_THROW(cubes.validate("m.exo"));
}

TEST(MeshValidation, NonFiniteCoordinate) {
  Mesh m = square();
  m.coordinates[2 * 4 + 1] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(messageOf([&] { m.validate("m.exo"); }), "m.exo: node 5 has a non-finite coordinate (y = inf)");
  m.coordinates[2 * 4 + 1] = 1;
  m.coordinates[2 * 8] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(messageOf([&] { m.validate("m.exo"); }), "m.exo: node 9 has a non-finite coordinate (x = nan)");
}

TEST(MeshValidation, ConnectivityOutOfRangeAndRepeatedNodes) {
  Mesh m = square();
  m.blocks[0].connectivity[4 * 3 + 2] = -1;
  EXPECT_EQ(messageOf([&] { m.validate("m.exo"); }),
            "m.exo: element 4 of block 'block_1' refers to node 0, but the mesh has 9 nodes");
  m = square();
  m.blocks[0].connectivity[1] = m.blocks[0].connectivity[0];
  EXPECT_EQ(messageOf([&] { m.validate("m.exo"); }),
            "m.exo: element 1 of block 'block_1' lists node 1 twice (a collapsed element): give it 4 distinct nodes");
}

TEST(MeshValidation, ClockwiseElementsAreInverted) {
  Mesh m = square();
  reverseElement(m, 2);
  EXPECT_EQ(messageOf([&] { m.validate("tube.exo"); }),
            "tube.exo: element 3 of block 'block_1' is inverted (clockwise node order): list its nodes "
            "counter-clockwise");
  // A mirrored mesh: every element clockwise; the count tells it from a single bad element.
  for (size_t e : {0, 1, 3}) reverseElement(m, e);
  EXPECT_EQ(messageOf([&] { m.validate("tube.exo"); }),
            "tube.exo: element 1 of block 'block_1' is inverted (clockwise node order): list its nodes "
            "counter-clockwise (4 elements fail this check)");
}

TEST(MeshValidation, TangledAndDegenerateElements) {
  // Bow-tie: the last two nodes of element 1 swapped (nodes 1, 2, 4, 5 → 1, 2, 4 ... listed 1 2 4 5).
  Mesh m = square();
  std::swap(m.blocks[0].connectivity[2], m.blocks[0].connectivity[3]);
  EXPECT_EQ(messageOf([&] { m.validate("m.exo"); }),
            "m.exo: element 1 of block 'block_1' is tangled (its Jacobian is negative at node 4): a "
            "self-intersecting or non-convex quadrilateral; check its node order and coordinates");
  EXPECT_EQ(messageOf([&] { oneQuad({0, 0, 1, 0, 2, 0, 3, 0}).validate("m.exo"); }),
            "m.exo: element 1 of block 'plate' is degenerate (zero area): its nodes lie on one line");
  // Node 2 on the straight line from node 1 to node 3: a triangle with a node in the middle of a side.
  EXPECT_EQ(messageOf([&] { oneQuad({0, 0, 1, 0, 2, 0, 0, 2}).validate("m.exo"); }),
            "m.exo: element 1 of block 'plate' is degenerate at node 2 (zero Jacobian: the two edges there are "
            "in line): move the node or split the element");
}

TEST(MeshValidation, InvertedHexahedron) {
  Mesh m = twoCubes();
  auto& c = m.blocks[0].connectivity;
  std::swap_ranges(c.begin() + 8, c.begin() + 12, c.begin() + 12);  // element 2: top and bottom exchanged
  EXPECT_EQ(messageOf([&] { m.validate("m.exo"); }),
            "m.exo: element 2 of block 'cubes' is inverted (left-handed node order): list the bottom face "
            "counter-clockwise seen from the top face, then the top face in the same order");
}

TEST(MeshValidation, NodeSetOutOfRange) {
  Mesh m = square();
  m.nodeSets[0].nodes.back() = 20;
  EXPECT_EQ(messageOf([&] { m.validate("m.exo"); }), "m.exo: node set 'left' refers to node 21, but the mesh has 9 nodes");
}

TEST(MeshValidation, InteriorSideSetsAreRefused) {
  Mesh m = square();
  m.sideSets.push_back({"middle", {3, 0}, {2, 1}});  // element 4's top is on the boundary; element 1's right is not
  EXPECT_EQ(messageOf([&] { m.validate("m.exo"); }),
            "m.exo: side set 'middle' holds side 2 of element 1, which element 2 shares: an interior side, not "
            "on the boundary of the mesh");
  // 3D: the face x = 1 between the two cubes.
  Mesh cubes = twoCubes();
  cubes.sideSets.push_back({"between", {0}, {1}});
  EXPECT_EQ(messageOf([&] { cubes.validate("m.exo"); }),
            "m.exo: side set 'between' holds side 2 of element 1, which element 2 shares: an interior side, not "
            "on the boundary of the mesh");
}

TEST(MeshValidation, TouchingBodiesKeepTheirBoundaries) {
  // Two parts meeting at x = 2 with coincident but distinct nodes: separate bodies, so the right side
  // of the first and the left side of the second are both on the boundary (contact surfaces).
  const Mesh merged = mergeMeshes({{"a", square()}, {"b", translateMesh(square(), {2, 0})}});
  EXPECT_NO_THROW(merged.validate("m.exo"));
  EXPECT_TRUE(merged.hasSideSet("a_right"));
  EXPECT_TRUE(merged.hasSideSet("b_left"));
}
