#include <gtest/gtest.h>

#include <algorithm>

#include "common/Error.hpp"
#include "mesh/Generators.hpp"
#include "mesh/Partition.hpp"

using namespace contessa;
using namespace contessa::mesh;

namespace {

Mesh square(int n) {
  RectangleSpec spec;
  spec.nx = n;
  spec.ny = n;
  return generateRectangle(spec);
}

}  // namespace

TEST(Partition, OnePartGivesEverythingToRankZero) {
  const Mesh mesh = square(3);
  const Partition p = partitionMesh(mesh, 1);
  EXPECT_EQ(p.numParts, 1);
  EXPECT_EQ(p.elementOwner, std::vector<int>(9, 0));
  EXPECT_EQ(p.nodeOwner, std::vector<int>(16, 0));
  EXPECT_EQ(p.ownedElements(0).size(), 9u);
  EXPECT_EQ(p.ownedNodes(0).size(), 16u);
  EXPECT_EQ(p.overlapNodes(mesh, 0), p.ownedNodes(0));
  EXPECT_TRUE(p.ownedElements(1).empty());
}

TEST(Partition, TwoPartsOfATenByTenSquare) {
  const Mesh mesh = square(10);
  const Partition p = partitionMesh(mesh, 2);
  ASSERT_EQ(p.elementOwner.size(), 100u);
  ASSERT_EQ(p.nodeOwner.size(), 121u);
  for (int owner : p.elementOwner) EXPECT_TRUE(owner == 0 || owner == 1);

  const auto e0 = p.ownedElements(0), e1 = p.ownedElements(1);
  EXPECT_EQ(e0.size() + e1.size(), 100u);
  EXPECT_NEAR(static_cast<double>(e0.size()), 50.0, 5.0);  // balanced within 10%
  EXPECT_TRUE(std::is_sorted(e0.begin(), e0.end()));

  // A node belongs to the lowest rank among the elements around it.
  std::vector<int> lowest(121, 2);
  const auto& block = mesh.blocks[0];
  for (size_t k = 0; k < block.elements.size(); ++k)
    for (int a = 0; a < 4; ++a) {
      int& l = lowest[block.connectivity[4 * k + a]];
      l = std::min(l, p.elementOwner[block.elements[k]]);
    }
  EXPECT_EQ(p.nodeOwner, lowest);

  const auto n0 = p.ownedNodes(0), n1 = p.ownedNodes(1);
  EXPECT_EQ(n0.size() + n1.size(), 121u);
  for (int rank = 0; rank < 2; ++rank) {
    const auto owned = p.ownedNodes(rank);
    const auto overlap = p.overlapNodes(mesh, rank);
    EXPECT_TRUE(std::is_sorted(overlap.begin(), overlap.end()));
    EXPECT_TRUE(std::includes(overlap.begin(), overlap.end(), owned.begin(), owned.end()));
    // Rank 1 needs the interface nodes that rank 0 owns; rank 0 owns all of its own.
    if (rank == 0) {
      EXPECT_EQ(overlap, owned);
    } else {
      EXPECT_GT(overlap.size(), owned.size());
    }
    for (GlobalIndex e : p.ownedElements(rank))
      for (int a = 0; a < 4; ++a)
        EXPECT_TRUE(std::binary_search(overlap.begin(), overlap.end(), block.connectivity[4 * e + a]));
  }
}

TEST(Partition, IsDeterministic) {
  const Mesh mesh = square(10);
  for (int parts : {2, 3, 4}) {
    const Partition a = partitionMesh(mesh, parts);
    const Partition b = partitionMesh(mesh, parts);
    EXPECT_EQ(a.elementOwner, b.elementOwner) << parts;
    EXPECT_EQ(a.nodeOwner, b.nodeOwner) << parts;
    for (int rank = 0; rank < parts; ++rank) EXPECT_FALSE(a.ownedElements(rank).empty()) << parts;
  }
}

TEST(Partition, AsManyPartsAsElements) {
  const Mesh mesh = square(2);
  const Partition p = partitionMesh(mesh, 4);
  std::vector<int> owners = p.elementOwner;
  std::sort(owners.begin(), owners.end());
  EXPECT_EQ(owners, (std::vector<int>{0, 1, 2, 3}));
}

TEST(Partition, NodesOutsideElementsGoToRankZero) {
  Mesh mesh = square(4);
  mesh.coordinates.insert(mesh.coordinates.end(), {5.0, 5.0});  // stray node 25
  const Partition p = partitionMesh(mesh, 2);
  ASSERT_EQ(p.nodeOwner.size(), 26u);
  EXPECT_EQ(p.nodeOwner[25], 0);
}

TEST(Partition, RejectsMorePartsThanElements) {
  const Mesh mesh = square(2);
  EXPECT_THROW(partitionMesh(mesh, 5), InputError);
  EXPECT_THROW(partitionMesh(mesh, 0), InputError);
}
