#include "mesh/MeshPiece.hpp"

#include <algorithm>
#include <stdexcept>

namespace contessa::mesh {

MeshPiece extractPiece(const Mesh& mesh, const std::vector<int>& elementRank, int rank) {
  if (static_cast<GlobalIndex>(elementRank.size()) != mesh.numElements())
    throw std::logic_error("extractPiece: one rank per element expected");
  const GlobalIndex numNodes = mesh.numNodes();
  const int dim = mesh.dimension;

  // The ranks that use each node (through the elements they own): a node of this piece used by other
  // ranks too is on the border between pieces.
  std::vector<std::vector<int>> users(static_cast<std::size_t>(numNodes));
  for (const auto& block : mesh.blocks) {
    const int n = nodesPerCell(block.cellType);
    for (GlobalIndex e = 0; e < block.numElements(); ++e) {
      const int owner = elementRank[block.elements[e]];
      for (int a = 0; a < n; ++a) {
        auto& u = users[block.connectivity[e * n + a]];
        if (std::find(u.begin(), u.end(), owner) == u.end()) u.push_back(owner);
      }
    }
  }

  MeshPiece piece;
  piece.mesh.dimension = dim;
  std::vector<GlobalIndex> local(static_cast<std::size_t>(numNodes), -1);
  for (GlobalIndex node = 0; node < numNodes; ++node) {
    const auto& u = users[node];
    if (std::find(u.begin(), u.end(), rank) == u.end()) continue;
    local[node] = static_cast<GlobalIndex>(piece.globalNodes.size());
    piece.globalNodes.push_back(node);
    for (int d = 0; d < dim; ++d) piece.mesh.coordinates.push_back(mesh.coordinates[node * dim + d]);
    std::vector<int> others;
    for (int r : u)
      if (r != rank) others.push_back(r);
    std::sort(others.begin(), others.end());
    piece.sharedWith.push_back(others);
  }

  std::vector<GlobalIndex> localElement(static_cast<std::size_t>(mesh.numElements()), -1);
  for (const auto& block : mesh.blocks) {
    const int n = nodesPerCell(block.cellType);
    ElementBlock part{block.name, block.cellType, {}, {}};
    for (GlobalIndex e = 0; e < block.numElements(); ++e) {
      if (elementRank[block.elements[e]] != rank) continue;
      localElement[block.elements[e]] = static_cast<GlobalIndex>(piece.globalElements.size());
      part.elements.push_back(static_cast<GlobalIndex>(piece.globalElements.size()));
      piece.globalElements.push_back(block.elements[e]);
      for (int a = 0; a < n; ++a) part.connectivity.push_back(local[block.connectivity[e * n + a]]);
    }
    piece.mesh.blocks.push_back(std::move(part));
  }
  for (const auto& set : mesh.nodeSets) {
    NodeSet part{set.name, {}};
    for (GlobalIndex node : set.nodes)
      if (local[node] >= 0) part.nodes.push_back(local[node]);  // increasing: local ids follow global ones
    piece.mesh.nodeSets.push_back(std::move(part));
  }
  for (const auto& set : mesh.sideSets) {
    SideSet part{set.name, {}, {}};
    for (std::size_t k = 0; k < set.elements.size(); ++k)
      if (localElement[set.elements[k]] >= 0) {
        part.elements.push_back(localElement[set.elements[k]]);
        part.sides.push_back(set.sides[k]);
      }
    piece.mesh.sideSets.push_back(std::move(part));
  }
  return piece;
}

}  // namespace contessa::mesh
