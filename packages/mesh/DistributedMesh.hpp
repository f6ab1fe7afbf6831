#pragma once
// One rank's part of a mesh that no rank holds whole: the elements the rank assembles, every node they
// use, the node and side sets restricted to them, and what the rank must know about its halo (which
// rank owns each of its nodes, which other ranks hold each of them). Ownership follows
// mesh::Partition's rules exactly (a node belongs to the lowest rank among its elements'; a node of no
// element to rank 0), so a model built on the parts assembles the same system as on the replicated
// mesh with the same element owners.
//
// Parts come from three sources: extracted from a replicated mesh (PartExtractor: the reference, and
// rank 0's distribution of a file it read, MeshDistribution.hpp), generated directly by the structured
// generators (Generators.hpp, generate*Part), or read from a pre-split file set.
#include <cstddef>
#include <string>
#include <vector>

#include <mpi.h>

#include "mesh/MeshPiece.hpp"

namespace contessa::mesh {

struct DistributedMesh {
  int rank = 0, numRanks = 1;
  /// The ranks the parts are spread over (rank and numRanks are this rank's place in it): what every
  /// collective step on the parts (gathering, checking, contact surfaces) talks over. A part made alone
  /// (PartExtractor, a test's whole mesh) is on MPI_COMM_SELF until its maker says otherwise.
  MPI_Comm comm = MPI_COMM_SELF;
  /// The local mesh (numbered from 0: nodes in increasing global id, elements block by block), the
  /// global id of every local node and element, and for every local node the other ranks whose parts
  /// hold it (empty inside the part). Every block of the whole mesh is there, maybe empty; node sets
  /// keep the part's nodes (owned and halo), side sets the sides of the part's elements.
  MeshPiece part;
  std::vector<int> nodeOwner;  ///< owner rank of each local node: min(rank, sharedWith) (Partition's rule)
  /// Position of each local side-set entry in the whole mesh's side set (side set by side set), so that
  /// gathered surfaces come out in the replicated order and contact's answers do not change.
  std::vector<std::vector<GlobalIndex>> sideSetPositions;
  /// Sizes of the whole mesh: nodes, elements, and per block, node set and side set (in part order).
  GlobalIndex numGlobalNodes = 0, numGlobalElements = 0;
  std::vector<GlobalIndex> globalBlockSizes, globalNodeSetSizes, globalSideSetSizes;

  const Mesh& local() const { return part.mesh; }
  GlobalIndex numLocalNodes() const { return static_cast<GlobalIndex>(part.globalNodes.size()); }
  /// Global ids of the nodes this rank owns (ascending), and of its halo (used, owned elsewhere).
  std::vector<GlobalIndex> ownedNodes() const;
  std::vector<GlobalIndex> haloNodes() const;
  /// Local number of a global node, −1 when the part does not hold it (binary search).
  GlobalIndex localNode(GlobalIndex globalNode) const;
  /// Bytes held by the part's containers (capacity not counted): the memory figure per rank.
  std::size_t bytes() const;
};

/// The deterministic element partition every rank computes alone for generated meshes: contiguous
/// ranges of global element ids, rank r holding [begin(r), begin(r+1)) with begin(r) = ⌊r·E/P⌋. Since
/// the owner grows with the element id, a node's owner is the owner of its lowest-numbered element.
struct ElementRanges {
  GlobalIndex numElements = 0;
  int numRanks = 1;
  GlobalIndex begin(int rank) const;
  int owner(GlobalIndex element) const;
  /// The owner of every element (for the replicated reference path).
  std::vector<int> owners() const;
};

/// The partition of a structured grid of n0 × n1 × n2 cells (n2 = 1 in 2D; cell id i + n0 (j + n1 k)) that
/// every rank computes alone for the structured generators: index boxes, p0 × p1 × p2 = P of them, with
/// the fewest cut cell faces (ties: the first found, p0 smallest), box b along axis a holding the cells
/// [⌊b·n_a/p_a⌋, ⌊(b+1)·n_a/p_a⌋); rank = b0 + p0 (b1 + p1 b2). Compact subdomains: a rank's interface
/// shrinks as (N/P)^((d−1)/d), where slabs of ids would cut whole cross-sections. When no boxes fit
/// (P has a prime factor larger than the grid along every axis that could take it), contiguous id
/// ranges (ElementRanges).
class GridPartition {
 public:
  GridPartition(int n0, int n1, int n2, int numRanks);
  int owner(int i, int j, int k) const;
  /// The index box [lo, hi) per axis that holds every cell of `rank` (exactly its cells with boxes).
  void bounds(int rank, int lo[3], int hi[3]) const;
  /// The owner of every cell, by cell id (for tests and the replicated reference).
  std::vector<int> owners() const;
  bool boxes() const { return boxes_; }
  const int* parts() const { return parts_; }

 private:
  int n_[3];
  int parts_[3] = {1, 1, 1};
  bool boxes_ = false;
  ElementRanges ranges_;
  static int split(int count, int parts, int index) {
    return static_cast<int>(static_cast<long long>(index) * count / parts);
  }
  int boxAlong(int axis, int index) const;
};

/// Rank r's part of a replicated mesh under element owners `elementOwner` (one per global element, the
/// same on every rank): node users computed once (O(mesh)), then one part per call (O(mesh)).
class PartExtractor {
 public:
  PartExtractor(const Mesh& mesh, std::vector<int> elementOwner, int numRanks);
  DistributedMesh part(int rank) const;

 private:
  const Mesh& mesh_;
  std::vector<int> elementOwner_;
  int numRanks_;
  // Ranks using each node, CSR: users_[userStart_[n] .. userStart_[n+1]) sorted, unique.
  std::vector<GlobalIndex> userStart_;
  std::vector<int> users_;
};

/// Bytes of a mesh's containers (coordinates, connectivity, sets; names not counted).
std::size_t meshBytes(const Mesh& mesh);

}  // namespace contessa::mesh
