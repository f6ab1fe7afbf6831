#pragma once
// One rank's piece of a mesh, for output that each rank writes on its own (the spatially decomposed
// Exodus set name.exo.N.r that ParaView opens as one data set and SEACAS `epu` joins): the elements a
// rank owns, the nodes they use, and the node and side sets restricted to them, numbered from 0 in
// the piece, with the global ids of each node and element kept beside.
#include <vector>

#include "mesh/Mesh.hpp"

namespace contessa::mesh {

struct MeshPiece {
  Mesh mesh;                             ///< local numbering; every block of the whole mesh, maybe empty
  std::vector<GlobalIndex> globalNodes;     ///< global id of each piece node (increasing)
  std::vector<GlobalIndex> globalElements;  ///< global id of each piece element (piece element order)
  /// Nodes shared with other pieces: for each piece node, the other ranks whose pieces hold it (sorted;
  /// empty for a node inside the piece).
  std::vector<std::vector<int>> sharedWith;
};

/// The piece of `mesh` made of the elements with elementRank[e] == rank (elementRank: the owner of
/// every global element, the same on every rank). Blocks keep their order and names (empty when the
/// rank owns none of their elements), node sets keep the piece's nodes, side sets the piece's sides.
/// A node of no element is in rank 0's piece (it owns it, as in mesh::Partition). The piece of
/// PartExtractor (DistributedMesh.hpp), which a distributed mesh holds.
MeshPiece extractPiece(const Mesh& mesh, const std::vector<int>& elementRank, int rank);

}  // namespace contessa::mesh
