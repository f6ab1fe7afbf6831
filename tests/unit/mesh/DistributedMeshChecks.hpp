#pragma once
// Checks shared by the serial and the MPI tests of distributed meshes.
#include <gtest/gtest.h>

#include "MeshTestSupport.hpp"
#include "mesh/DistributedMesh.hpp"

namespace contessa::mesh::test {

/// Two meshes equal field by field, coordinates bit for bit (MeshTestSupport.hpp).
using test_support::expectSameMesh;

/// EXPECT_EQ on each of the members `fields` of a and b (a failure names the member by its place in the list).
template <class T, class... Fields>
void expectSameMembers(const T& a, const T& b, Fields T::*... fields) {
  int place = 0;
  const auto check = [&](auto field) { EXPECT_EQ(a.*field, b.*field) << "member " << place++ << " of the list"; };
  (check(fields), ...);
}

/// Two parts equal field by field (coordinates bit for bit).
inline void expectSameParts(const DistributedMesh& a, const DistributedMesh& b) {
  using D = DistributedMesh;
  expectSameMembers(a, b, &D::rank, &D::numRanks, &D::numGlobalNodes, &D::numGlobalElements, &D::globalBlockSizes,
                    &D::globalNodeSetSizes, &D::globalSideSetSizes, &D::nodeOwner, &D::sideSetPositions);
  expectSameMembers(a.part, b.part, &MeshPiece::globalNodes, &MeshPiece::globalElements, &MeshPiece::sharedWith);
  expectSameMesh(a.local(), b.local());
}

}  // namespace contessa::mesh::test
