#include "mesh/StructuredGrid.hpp"

#include <algorithm>
#include <utility>
#include <vector>

#include "mesh/Partition.hpp"

namespace contessa::mesh::generator {
namespace {

// Rank `rank`'s part of a structured grid under GridPartition, built in steps that each fill their own
// fields of the DistributedMesh: the nodes (with their owners and sharing ranks), the block, the sets.
// Nothing of the rest of the grid is built; the nodes scanned are those of the rank's box (its bounds).
class GridPart {
 public:
  GridPart(const GridRecipe& recipe, int rank, int numRanks)
      : recipe_(recipe),
        grid_(recipe.grid),
        dim_(grid_.dimension()),
        n_{grid_.count(0), grid_.count(1), dim_ == 2 ? 1 : grid_.count(2)},
        rank_(rank),
        partition_(n_[0], n_[1], n_[2], numRanks) {
    partition_.bounds(rank, lo_, hi_);
    nodeHi_[0] = hi_[0];
    nodeHi_[1] = hi_[1];
    nodeHi_[2] = dim_ == 2 ? 0 : hi_[2];
    for (int a = 0; a < 3; ++a) width_[a] = nodeHi_[a] - lo_[a] + 1;
    result_.rank = rank;
    result_.numRanks = numRanks;
    result_.numGlobalNodes = grid_.numNodes();
    result_.numGlobalElements = grid_.numElements();
    result_.part.mesh.dimension = dim_;
  }

  DistributedMesh build() && {
    addNodes();
    addBlock();
    addNodeSets();
    addSideSets();
    // Checked by the caller on every rank at once (validatePart, MeshDistribution.hpp): a check here
    // would fail on one rank alone, in local numbers.
    return std::move(result_);
  }

 private:
  // Node (i, j, k) of the rank's box [lo, nodeHi] within the box, in global id order.
  std::size_t boxIndex(int i, int j, int k) const {
    return (static_cast<std::size_t>(k - lo_[2]) * width_[1] + (j - lo_[1])) * width_[0] + (i - lo_[0]);
  }

  // The ranks owning the (up to 2^d) cells around grid node idx, ascending and unique.
  void ranksAround(const int idx[3], std::vector<int>& ranks) const {
    ranks.clear();
    for (int dk = dim_ == 2 ? 0 : -1; dk <= 0; ++dk)
      for (int dj = -1; dj <= 0; ++dj)
        for (int di = -1; di <= 0; ++di) {
          const int c[3] = {idx[0] + di, idx[1] + dj, idx[2] + dk};
          if (c[0] < 0 || c[0] >= n_[0] || c[1] < 0 || c[1] >= n_[1] || c[2] < 0 || c[2] >= n_[2]) continue;
          ranks.push_back(partition_.owner(c[0], c[1], c[2]));
        }
    std::sort(ranks.begin(), ranks.end());
    ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
  }

  // The box's nodes used by one of the rank's cells: their global ids, coordinates, owner (the lowest
  // rank around) and the other ranks sharing them.
  void addNodes() {
    MeshPiece& piece = result_.part;
    local_.assign(static_cast<std::size_t>(width_[0]) * width_[1] * width_[2], -1);
    std::vector<int> ranks;
    for (int k = lo_[2]; k <= nodeHi_[2]; ++k)
      for (int j = lo_[1]; j <= nodeHi_[1]; ++j)
        for (int i = lo_[0]; i <= nodeHi_[0]; ++i) {
          const int idx[3] = {i, j, k};
          ranksAround(idx, ranks);
          if (!std::binary_search(ranks.begin(), ranks.end(), rank_)) continue;
          local_[boxIndex(i, j, k)] = static_cast<GlobalIndex>(piece.globalNodes.size());
          piece.globalNodes.push_back(grid_.node(i, j, k));
          nodeIndex_.insert(nodeIndex_.end(), idx, idx + 3);
          double x[3];
          recipe_.point(i, j, k, x);
          piece.mesh.coordinates.insert(piece.mesh.coordinates.end(), x, x + dim_);
          result_.nodeOwner.push_back(ranks.front());
          std::vector<int> others;
          for (int r : ranks)
            if (r != rank_) others.push_back(r);
          piece.sharedWith.push_back(std::move(others));
        }
  }

  // The rank's cells, with their corners in StructuredGrid::cellNodes' order.
  void addBlock() {
    MeshPiece& piece = result_.part;
    ElementBlock block;
    block.name = recipe_.blockName;
    block.cellType = dim_ == 2 ? CellType::Quad4 : CellType::Hex8;
    for (int k = lo_[2]; k < hi_[2]; ++k)
      for (int j = lo_[1]; j < hi_[1]; ++j)
        for (int i = lo_[0]; i < hi_[0]; ++i) {
          if (partition_.owner(i, j, k) != rank_) continue;
          cells_.insert(cells_.end(), {i, j, k});
          block.elements.push_back(static_cast<GlobalIndex>(piece.globalElements.size()));
          piece.globalElements.push_back(grid_.element(i, j, k));
          for (int layer = 0; layer < (dim_ == 2 ? 1 : 2); ++layer)
            for (const auto& [di, dj] : {std::pair{0, 0}, std::pair{1, 0}, std::pair{1, 1}, std::pair{0, 1}})
              block.connectivity.push_back(local_[boxIndex(i + di, j + dj, k + layer)]);
        }
    piece.mesh.blocks.push_back(std::move(block));
    result_.globalBlockSizes.push_back(grid_.numElements());
  }

  // The node sets of the whole mesh (StructuredGrid::addSets) restricted to the part, in the same
  // order: each face's nodes ascending, then "all".
  void addNodeSets() {
    MeshPiece& piece = result_.part;
    for (int f = 0; f < 2 * dim_; ++f) {
      const int axis = f / 2, at = f % 2 == 1 ? grid_.count(axis) : 0;
      NodeSet set{recipe_.faceNames[f], {}};
      GlobalIndex size = 1;
      for (int a = 0; a < dim_; ++a)
        if (a != axis) size *= grid_.count(a) + 1;
      for (std::size_t k = 0; k < piece.globalNodes.size(); ++k)
        if (nodeIndex_[3 * k + axis] == at) set.nodes.push_back(static_cast<GlobalIndex>(k));
      piece.mesh.nodeSets.push_back(std::move(set));
      result_.globalNodeSetSizes.push_back(size);
    }
    NodeSet all{"all", std::vector<GlobalIndex>(piece.globalNodes.size())};
    for (std::size_t k = 0; k < all.nodes.size(); ++k) all.nodes[k] = static_cast<GlobalIndex>(k);
    piece.mesh.nodeSets.push_back(std::move(all));
    result_.globalNodeSetSizes.push_back(grid_.numNodes());
  }

  // The side sets restricted to the part: a side's position in the whole set is its cell's rank among
  // the face's cells (the axes other than the face's, lowest fastest).
  void addSideSets() {
    MeshPiece& piece = result_.part;
    for (int f = 0; f < 2 * dim_; ++f) {
      const int axis = f / 2, at = f % 2 == 1 ? n_[axis] - 1 : 0;
      SideSet set{recipe_.faceNames[f], {}, {}};
      std::vector<GlobalIndex> positions;
      GlobalIndex size = 1;
      for (int a = 0; a < dim_; ++a)
        if (a != axis) size *= n_[a];
      for (std::size_t e = 0; e < piece.globalElements.size(); ++e) {
        if (cells_[3 * e + axis] != at) continue;
        set.elements.push_back(static_cast<GlobalIndex>(e));
        set.sides.push_back(sideOfFace(axis, f % 2 == 1));
        GlobalIndex position = 0, stride = 1;
        for (int a = 0; a < dim_; ++a) {
          if (a == axis) continue;
          position += cells_[3 * e + a] * stride;
          stride *= n_[a];
        }
        positions.push_back(position);
      }
      piece.mesh.sideSets.push_back(std::move(set));
      result_.sideSetPositions.push_back(std::move(positions));
      result_.globalSideSetSizes.push_back(size);
    }
  }

  const GridRecipe& recipe_;
  const StructuredGrid& grid_;
  const int dim_;
  const int n_[3];  ///< cells per axis (1 along z in 2D)
  const int rank_;
  const GridPartition partition_;
  int lo_[3], hi_[3];              ///< the rank's cells [lo, hi) per axis
  int nodeHi_[3], width_[3];       ///< its box's nodes [lo, nodeHi] per axis (one layer in 2D), and their counts
  std::vector<GlobalIndex> local_;  ///< box node → part node (−1: not the part's)
  std::vector<int> nodeIndex_;     ///< i, j, k of each part node
  std::vector<int> cells_;         ///< i, j, k of each part cell
  DistributedMesh result_;
};

}  // namespace

Mesh GridRecipe::whole() const {
  Mesh mesh;
  grid.setCoordinates(mesh, point);
  mesh.blocks.push_back(grid.block(blockName));
  grid.addSets(mesh, faceNames);
  mesh.validate(source);
  return mesh;
}

DistributedMesh GridRecipe::part(int rank, int numRanks) const {
  requirePartsFit(grid.numElements(), numRanks);
  return GridPart(*this, rank, numRanks).build();
}

}  // namespace contessa::mesh::generator
