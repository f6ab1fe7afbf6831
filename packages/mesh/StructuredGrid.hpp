#pragma once
// The logically structured grid every inline generator but the sphere octant is (Generators.hpp), and
// the recipe (grid, node positions, names) from which the whole mesh and any rank's part are made.
// Internal to packages/mesh.
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "mesh/DistributedMesh.hpp"
#include "mesh/GeneratorSupport.hpp"
#include "mesh/Mesh.hpp"

namespace contessa::mesh::generator {

// All generators build logically structured grids of n0 × n1 (× n2) cells: node (i, j, k) is
// (k*(n1+1) + j)*(n0+1) + i, element (i, j, k) is (k*n1 + j)*n0 + i (in 2D k = 0, which gives the
// 2D numbering j*(n0+1) + i), and a cell lists its corners in Exodus order: (i,j), (i+1,j),
// (i+1,j+1), (i,j+1) at k, then (Hex8) the same at k+1. Its Jacobians are positive whenever the map
// from (i, j, k) to (x, y, z) preserves orientation.
class StructuredGrid {
 public:
  explicit StructuredGrid(std::vector<int> counts) : n_(std::move(counts)) {
    if (n_.size() == 2) n_.push_back(0);
  }

  int dimension() const { return n_[2] == 0 ? 2 : 3; }
  int count(int axis) const { return n_[axis]; }
  GlobalIndex numNodes() const { return static_cast<GlobalIndex>(n_[0] + 1) * (n_[1] + 1) * (n_[2] + 1); }
  GlobalIndex numElements() const {
    return static_cast<GlobalIndex>(n_[0]) * n_[1] * (dimension() == 2 ? 1 : n_[2]);
  }
  GlobalIndex node(int i, int j, int k = 0) const {
    return (static_cast<GlobalIndex>(k) * (n_[1] + 1) + j) * (n_[0] + 1) + i;
  }
  GlobalIndex element(int i, int j, int k = 0) const { return (static_cast<GlobalIndex>(k) * n_[1] + j) * n_[0] + i; }

  // Calls f(i, j, k) for every node, or with `fixedAxis` ≥ 0 for those with index `fixed` on it,
  // in ascending node id.
  template <class F>
  void forNodes(F&& f, int fixedAxis = -1, int fixed = 0) const {
    int lo[3] = {0, 0, 0}, hi[3] = {n_[0], n_[1], n_[2]};
    if (fixedAxis >= 0) lo[fixedAxis] = hi[fixedAxis] = fixed;
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) f(i, j, k);
  }

  // Calls f(i, j, k) for every cell, or for those with index `fixed` on `fixedAxis`, in ascending id.
  template <class F>
  void forCells(F&& f, int fixedAxis = -1, int fixed = 0) const {
    int lo[3] = {0, 0, 0}, hi[3] = {n_[0] - 1, n_[1] - 1, dimension() == 2 ? 0 : n_[2] - 1};
    if (fixedAxis >= 0) lo[fixedAxis] = hi[fixedAxis] = fixed;
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) f(i, j, k);
  }

  // Node coordinates from point(i, j, k, x) writing dimension() values at x.
  template <class Point>
  void setCoordinates(Mesh& mesh, Point&& point) const {
    const int d = dimension();
    mesh.dimension = d;
    mesh.coordinates.resize(static_cast<size_t>(d) * numNodes());
    forNodes([&](int i, int j, int k) { point(i, j, k, &mesh.coordinates[d * static_cast<size_t>(node(i, j, k))]); });
  }

  // The corners of cell (i, j, k) in Exodus order.
  void cellNodes(int i, int j, int k, std::vector<GlobalIndex>& out) const {
    for (int layer = 0; layer < (dimension() == 2 ? 1 : 2); ++layer)
      for (GlobalIndex n : {node(i, j, k + layer), node(i + 1, j, k + layer), node(i + 1, j + 1, k + layer),
                            node(i, j + 1, k + layer)})
        out.push_back(n);
  }

  ElementBlock block(const std::string& name) const {
    ElementBlock b;
    b.name = name;
    b.cellType = dimension() == 2 ? CellType::Quad4 : CellType::Hex8;
    b.elements.reserve(static_cast<size_t>(numElements()));
    b.connectivity.reserve(static_cast<size_t>(nodesPerCell(b.cellType)) * numElements());
    forCells([&](int i, int j, int k) {
      b.elements.push_back(element(i, j, k));
      cellNodes(i, j, k, b.connectivity);
    });
    return b;
  }

  NodeSet nodeSet(const std::string& name, int axis, bool max) const {
    NodeSet s;
    s.name = name;
    forNodes([&](int i, int j, int k) { s.nodes.push_back(node(i, j, k)); }, axis, max ? n_[axis] : 0);
    return s;  // ascending by construction
  }

  SideSet sideSet(const std::string& name, int axis, bool max) const {
    SideSet s;
    s.name = name;
    const int side = sideOfFace(axis, max);
    forCells(
        [&](int i, int j, int k) {
          s.elements.push_back(element(i, j, k));
          s.sides.push_back(side);
        },
        axis, max ? n_[axis] - 1 : 0);
    return s;
  }

  NodeSet allNodes() const {
    NodeSet s;
    s.name = "all";
    s.nodes.resize(static_cast<size_t>(numNodes()));
    for (size_t k = 0; k < s.nodes.size(); ++k) s.nodes[k] = static_cast<GlobalIndex>(k);
    return s;
  }

  // Sets named after the grid faces, in the order min0, max0, min1, max1[, min2, max2], then "all".
  void addSets(Mesh& mesh, const std::vector<std::string>& names) const {
    for (int f = 0; f < 2 * dimension(); ++f) mesh.nodeSets.push_back(nodeSet(names[f], f / 2, f % 2 == 1));
    mesh.nodeSets.push_back(allNodes());
    for (int f = 0; f < 2 * dimension(); ++f) mesh.sideSets.push_back(sideSet(names[f], f / 2, f % 2 == 1));
  }

 private:
  std::vector<int> n_;
};

// What a structured generator makes, before it makes it: the grid, the position of each grid node
// (point(i, j, k, x) writes dimension() values at x), the block's and the faces' names, and the name
// its checks give the mesh. The whole mesh and any rank's part come from the same recipe.
struct GridRecipe {
  StructuredGrid grid;
  std::function<void(int, int, int, double*)> point;
  std::string blockName;
  std::vector<std::string> faceNames;  ///< min0, max0, min1, max1[, min2, max2]
  std::string source;

  /// The whole mesh, checked (Mesh::validate).
  Mesh whole() const;
  /// Rank `rank`'s part (of `numRanks`) under GridPartition, unchecked (the caller checks it on every
  /// rank at once: validatePart, MeshDistribution.hpp).
  DistributedMesh part(int rank, int numRanks) const;
};

}  // namespace contessa::mesh::generator
