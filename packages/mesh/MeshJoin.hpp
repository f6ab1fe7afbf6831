#pragma once
// The whole mesh put back together from its parts (DistributedMesh.hpp) through their global ids, as
// SEACAS epu joins a decomposed Exodus set: node g at global id g, each block's elements in increasing
// global element id (as every reader and generator numbers them), node sets the union of the parts'
// (sorted), side sets at the parts' sideSetPositions when they carry them, otherwise in (global
// element, side) order. One part at a time, so a part can be freed once added. Serial: used on one
// rank to join a pre-split file set (joinDecomposedExodus), and by gatherMeshOnRoot on rank 0.
#include <string>
#include <utility>
#include <vector>

#include "mesh/DistributedMesh.hpp"
#include "mesh/Mesh.hpp"

namespace contessa::mesh {

/// What the parts of one mesh agree on: the dimension and the names of its blocks, node sets and side
/// sets, in order (a part's blocks and sets are matched to the whole mesh's by position).
std::string meshListing(const Mesh& mesh);

class MeshJoiner {
 public:
  /// Adds a part. The first fixes the dimension and the blocks and sets; every other must list the same
  /// (meshListing) and give a block's elements the same cell type: InputError naming `source` (its
  /// file) otherwise. An empty block's cell type is not looked at (files write any for it).
  void add(const DistributedMesh& part, const std::string& source);

  /// The whole mesh. InputError starting with `source` when a node id below the largest is in no part.
  /// Not validated (Mesh::validate: every element id once, sides on the boundary) : the caller does.
  Mesh finish(const std::string& source);

 private:
  Mesh whole_;
  bool started_ = false;
  std::vector<char> blockTyped_, nodeSeen_;
  // Per block: (global element, global nodes) of every part's elements.
  std::vector<std::vector<std::pair<GlobalIndex, std::vector<GlobalIndex>>>> blockElements_;
  // Per side set: (order key, global element, side); the key is the entry's position in the whole set
  // when the parts give it, otherwise −1 (then (element, side) orders the set).
  struct SideEntry {
    GlobalIndex key, element;
    int side;
  };
  std::vector<std::vector<SideEntry>> sides_;
};

}  // namespace contessa::mesh
