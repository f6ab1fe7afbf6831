#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "MeshTestSupport.hpp"
#include "common/Error.hpp"
#include "mesh/Generators.hpp"
#include "mesh/Mesh.hpp"

using namespace contessa;
using namespace contessa::mesh;
using test_support::messageOf;

TEST(CellTypes, NodesDimensionAndNames) {
  EXPECT_EQ(nodesPerCell(CellType::Quad4), 4);
  EXPECT_EQ(nodesPerCell(CellType::Hex8), 8);
  EXPECT_EQ(cellDimension(CellType::Quad4), 2);
  EXPECT_EQ(cellDimension(CellType::Hex8), 3);
  EXPECT_STREQ(exodusCellName(CellType::Quad4), "QUAD4");
  EXPECT_STREQ(exodusCellName(CellType::Hex8), "HEX8");
}

TEST(CellTypes, QuadSidesFollowExodus) {
  EXPECT_EQ(sideNodes(CellType::Quad4, 0), (std::vector<int>{0, 1}));
  EXPECT_EQ(sideNodes(CellType::Quad4, 1), (std::vector<int>{1, 2}));
  EXPECT_EQ(sideNodes(CellType::Quad4, 2), (std::vector<int>{2, 3}));
  EXPECT_EQ(sideNodes(CellType::Quad4, 3), (std::vector<int>{3, 0}));
  EXPECT_THROW(sideNodes(CellType::Quad4, 4), std::out_of_range);
  EXPECT_THROW(sideNodes(CellType::Quad4, -1), std::out_of_range);
}

TEST(CellTypes, HexSidesFollowExodusAndPointOutwards) {
  EXPECT_EQ(sideNodes(CellType::Hex8, 0), (std::vector<int>{0, 1, 5, 4}));
  EXPECT_EQ(sideNodes(CellType::Hex8, 3), (std::vector<int>{0, 4, 7, 3}));
  EXPECT_EQ(sideNodes(CellType::Hex8, 4), (std::vector<int>{0, 3, 2, 1}));
  EXPECT_EQ(sideNodes(CellType::Hex8, 5), (std::vector<int>{4, 5, 6, 7}));
  EXPECT_THROW(sideNodes(CellType::Hex8, 6), std::out_of_range);
  // Unit cube in Exodus order: the normal from the first three side nodes points away from the centre.
  const double x[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  for (int side = 0; side < 6; ++side) {
    const auto n = sideNodes(CellType::Hex8, side);
    double a[3], b[3], c[3] = {0, 0, 0};
    for (int d = 0; d < 3; ++d) {
      a[d] = x[n[1]][d] - x[n[0]][d];
      b[d] = x[n[2]][d] - x[n[0]][d];
      for (int k = 0; k < 4; ++k) c[d] += x[n[k]][d] / 4 - 0.125;  // side centre minus cube centre
    }
    const double normal[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    EXPECT_GT(normal[0] * c[0] + normal[1] * c[1] + normal[2] * c[2], 0) << "side " << side;
  }
}

TEST(MeshLookup, FindsSetsAndBlocksByName) {
  const Mesh mesh = generateRectangle({});
  EXPECT_TRUE(mesh.hasNodeSet("top"));
  EXPECT_FALSE(mesh.hasNodeSet("topp"));
  EXPECT_TRUE(mesh.hasSideSet("left"));
  EXPECT_FALSE(mesh.hasSideSet("all"));
  EXPECT_TRUE(mesh.hasBlock("block_1"));
  EXPECT_EQ(mesh.nodeSet("top").name, "top");
  EXPECT_EQ(mesh.sideSet("bottom").elements.size(), 1u);
  EXPECT_EQ(mesh.block("block_1").numElements(), 1);
}

TEST(MeshLookup, MissingNamesListTheKnownOnes) {
  const Mesh mesh = generateRectangle({});
  EXPECT_EQ(messageOf([&] { mesh.nodeSet("topp"); }),
            "node set 'topp' does not exist in the mesh (known: all, bottom, left, right, top)");
  EXPECT_EQ(messageOf([&] { mesh.sideSet("all"); }),
            "side set 'all' does not exist in the mesh (known: bottom, left, right, top)");
  EXPECT_EQ(messageOf([&] { mesh.block("steel"); }),
            "element block 'steel' does not exist in the mesh (known: block_1)");
}

TEST(MeshLocate, ContiguousAndScatteredBlocks) {
  Mesh mesh;
  mesh.dimension = 2;
  mesh.coordinates = {0, 0, 1, 0, 1, 1, 0, 1, 2, 0, 2, 1};
  ElementBlock a{"a", CellType::Quad4, {2, 0}, {0, 1, 2, 3, 0, 1, 2, 3}};
  ElementBlock b{"b", CellType::Quad4, {1}, {1, 4, 5, 2}};
  mesh.blocks = {a, b};
  EXPECT_NO_THROW(mesh.validate("test"));
  EXPECT_EQ(mesh.numElements(), 3);
  EXPECT_EQ(mesh.numNodes(), 6);
  EXPECT_EQ(mesh.locate(2).block, 0);
  EXPECT_EQ(mesh.locate(2).local, 0);
  EXPECT_EQ(mesh.locate(0).block, 0);
  EXPECT_EQ(mesh.locate(0).local, 1);
  EXPECT_EQ(mesh.locate(1).block, 1);
  EXPECT_EQ(mesh.locate(1).local, 0);
  EXPECT_THROW(mesh.locate(3), std::out_of_range);
}

TEST(MeshValidate, RejectsInconsistentMeshesNamingTheSource) {
  const Mesh good = generateRectangle({0, 0, 1, 1, 2, 2, "block_1"});
  EXPECT_NO_THROW(good.validate("deck.yaml"));

  Mesh badNode = good;
  badNode.blocks[0].connectivity[5] = 9;
  EXPECT_EQ(messageOf([&] { badNode.validate("deck.yaml"); }),
            "deck.yaml: element 2 of block 'block_1' refers to node 10, but the mesh has 9 nodes");

  Mesh badSize = good;
  badSize.blocks[0].connectivity.pop_back();
  EXPECT_NE(messageOf([&] { badSize.validate("deck.yaml"); }).find("deck.yaml:"), std::string::npos);

  Mesh duplicate = good;
  duplicate.blocks[0].elements[1] = 0;
  EXPECT_NE(messageOf([&] { duplicate.validate("m.exo"); }).find("appears more than once"), std::string::npos);

  Mesh badSide = good;
  badSide.sideSets[0].sides[0] = 4;
  EXPECT_EQ(messageOf([&] { badSide.validate("m.exo"); }),
            "m.exo: side set 'left' refers to side 5 of element 1, but a QUAD4 has sides 1 to 4");

  Mesh badSideElement = good;
  badSideElement.sideSets[1].elements[0] = 4;
  EXPECT_EQ(messageOf([&] { badSideElement.validate("m.exo"); }),
            "m.exo: side set 'right' refers to element 5, but the mesh has 4 elements");

  Mesh unsorted = good;
  std::swap(unsorted.nodeSets[0].nodes[0], unsorted.nodeSets[0].nodes[1]);
  EXPECT_NE(messageOf([&] { unsorted.validate("m.exo"); }).find("not sorted"), std::string::npos);

  Mesh twice = good;
  twice.nodeSets[1].name = twice.nodeSets[0].name;
  EXPECT_NE(messageOf([&] { twice.validate("m.exo"); }).find("used more than once"), std::string::npos);

  Mesh wrongDimension = good;
  wrongDimension.blocks[0].cellType = CellType::Hex8;
  EXPECT_THROW(wrongDimension.validate("m.exo"), InputError);
}
