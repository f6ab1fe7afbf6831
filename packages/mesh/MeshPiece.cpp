#include "mesh/MeshPiece.hpp"

#include <algorithm>

#include "mesh/DistributedMesh.hpp"

namespace contessa::mesh {

MeshPiece extractPiece(const Mesh& mesh, const std::vector<int>& elementRank, int rank) {
  const int numRanks = elementRank.empty() ? 1 : *std::max_element(elementRank.begin(), elementRank.end()) + 1;
  return PartExtractor(mesh, elementRank, std::max(numRanks, rank + 1)).part(rank).part;
}

}  // namespace contessa::mesh
