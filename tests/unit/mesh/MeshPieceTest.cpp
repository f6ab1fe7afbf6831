#include <gtest/gtest.h>

#include "mesh/Generators.hpp"
#include "mesh/MeshPiece.hpp"

using namespace contessa::mesh;

namespace {

// 2 × 1 rectangle: element 0 (left) on rank 0, element 1 (right) on rank 1; nodes 0 1 2 / 3 4 5.
Mesh twoElements() {
  RectangleSpec spec;
  spec.lx = 2;
  spec.nx = 2;
  return generateRectangle(spec);
}

}  // namespace

TEST(MeshPiece, KeepsTheRanksElementsTheirNodesAndSetsWithGlobalIds) {
  const Mesh mesh = twoElements();
  const MeshPiece right = extractPiece(mesh, {0, 1}, 1);
  EXPECT_EQ(right.globalElements, (std::vector<GlobalIndex>{1}));
  EXPECT_EQ(right.globalNodes, (std::vector<GlobalIndex>{1, 2, 4, 5}));
  ASSERT_EQ(right.mesh.blocks.size(), 1u);
  // The element's connectivity in piece numbers maps back to its global one.
  const auto& local = right.mesh.blocks[0].connectivity;
  for (std::size_t a = 0; a < 4; ++a) EXPECT_EQ(right.globalNodes[local[a]], mesh.blocks[0].connectivity[4 + a]);
  for (std::size_t n = 0; n < right.globalNodes.size(); ++n)
    for (int d = 0; d < 2; ++d)
      EXPECT_EQ(right.mesh.coordinates[2 * n + d], mesh.coordinates[2 * right.globalNodes[n] + d]);
  // The middle nodes (1 and 4) are shared with rank 0; the others are the piece's own.
  EXPECT_EQ(right.sharedWith, (std::vector<std::vector<int>>{{0}, {}, {0}, {}}));
  // Side set 'right' is wholly in this piece, 'left' not at all; node sets keep the piece's nodes.
  EXPECT_EQ(right.mesh.sideSet("right").elements.size(), 1u);
  EXPECT_TRUE(right.mesh.sideSet("left").elements.empty());
  EXPECT_EQ(right.mesh.nodeSet("bottom").nodes, (std::vector<GlobalIndex>{0, 1}));  // global 1, 2
  EXPECT_NO_THROW(right.mesh.validate("piece"));
}

TEST(MeshPiece, ARankWithoutElementsHasAnEmptyPieceWithEveryBlockAndSet) {
  const Mesh mesh = twoElements();
  const MeshPiece none = extractPiece(mesh, {0, 0}, 1);
  EXPECT_TRUE(none.globalNodes.empty());
  EXPECT_TRUE(none.globalElements.empty());
  EXPECT_EQ(none.mesh.blocks.size(), mesh.blocks.size());
  EXPECT_EQ(none.mesh.nodeSets.size(), mesh.nodeSets.size());
  EXPECT_EQ(none.mesh.sideSets.size(), mesh.sideSets.size());
}
