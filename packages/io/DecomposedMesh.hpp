#pragma once
// The Nemesis decomposition records of one rank's file of a decomposed set, from that rank's part of
// a distributed mesh (mesh/DistributedMesh.hpp): its global ids, global sizes and sharing ranks.
#include "io/ExodusWriter.hpp"
#include "mesh/DistributedMesh.hpp"

namespace contessa::io {

inline ExodusDecomposition decompositionOf(const mesh::DistributedMesh& part) {
  ExodusDecomposition d;
  d.processor = part.rank;
  d.processors = part.numRanks;
  d.globalNodes = part.part.globalNodes;
  d.globalElements = part.part.globalElements;
  d.globalNumNodes = part.numGlobalNodes;
  d.globalNumElements = part.numGlobalElements;
  d.globalBlockSizes = part.globalBlockSizes;
  d.globalNodeSetSizes = part.globalNodeSetSizes;
  d.globalSideSetSizes = part.globalSideSetSizes;
  d.sharedWith = part.part.sharedWith;
  return d;
}

}  // namespace contessa::io
