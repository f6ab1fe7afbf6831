#pragma once
// Checks shared by the serial and the MPI tests of distributed meshes.
#include <gtest/gtest.h>

#include "MeshTestSupport.hpp"
#include "mesh/DistributedMesh.hpp"

namespace contessa::mesh::test {

/// Two meshes equal field by field, coordinates bit for bit (MeshTestSupport.hpp).
using test_support::expectSameMesh;

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
