#pragma once
// Checks shared by the serial and the MPI tests of distributed meshes.
#include <gtest/gtest.h>

#include "mesh/DistributedMesh.hpp"

namespace contessa::mesh::test {

/// Two meshes equal field by field (coordinates bit for bit).
inline void expectSameMesh(const Mesh& x, const Mesh& y) {
  EXPECT_EQ(x.dimension, y.dimension);
  EXPECT_EQ(x.coordinates, y.coordinates);
  ASSERT_EQ(x.blocks.size(), y.blocks.size());
  for (std::size_t k = 0; k < x.blocks.size(); ++k) {
    EXPECT_EQ(x.blocks[k].name, y.blocks[k].name);
    EXPECT_EQ(x.blocks[k].cellType, y.blocks[k].cellType);
    EXPECT_EQ(x.blocks[k].elements, y.blocks[k].elements) << x.blocks[k].name;
    EXPECT_EQ(x.blocks[k].connectivity, y.blocks[k].connectivity) << x.blocks[k].name;
  }
  ASSERT_EQ(x.nodeSets.size(), y.nodeSets.size());
  for (std::size_t k = 0; k < x.nodeSets.size(); ++k) {
    EXPECT_EQ(x.nodeSets[k].name, y.nodeSets[k].name);
    EXPECT_EQ(x.nodeSets[k].nodes, y.nodeSets[k].nodes) << x.nodeSets[k].name;
  }
  ASSERT_EQ(x.sideSets.size(), y.sideSets.size());
  for (std::size_t k = 0; k < x.sideSets.size(); ++k) {
    EXPECT_EQ(x.sideSets[k].name, y.sideSets[k].name);
    EXPECT_EQ(x.sideSets[k].elements, y.sideSets[k].elements) << x.sideSets[k].name;
    EXPECT_EQ(x.sideSets[k].sides, y.sideSets[k].sides) << x.sideSets[k].name;
  }
}

/// Two parts equal field by field (coordinates bit for bit).
inline void expectSameParts(const DistributedMesh& a, const DistributedMesh& b) {
  EXPECT_EQ(a.rank, b.rank);
  EXPECT_EQ(a.numRanks, b.numRanks);
  EXPECT_EQ(a.numGlobalNodes, b.numGlobalNodes);
  EXPECT_EQ(a.numGlobalElements, b.numGlobalElements);
  EXPECT_EQ(a.globalBlockSizes, b.globalBlockSizes);
  EXPECT_EQ(a.globalNodeSetSizes, b.globalNodeSetSizes);
  EXPECT_EQ(a.globalSideSetSizes, b.globalSideSetSizes);
  EXPECT_EQ(a.part.globalNodes, b.part.globalNodes);
  EXPECT_EQ(a.part.globalElements, b.part.globalElements);
  EXPECT_EQ(a.part.sharedWith, b.part.sharedWith);
  EXPECT_EQ(a.nodeOwner, b.nodeOwner);
  EXPECT_EQ(a.sideSetPositions, b.sideSetPositions);
  expectSameMesh(a.local(), b.local());
}

}  // namespace contessa::mesh::test
