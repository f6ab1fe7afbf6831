#include "mesh/MeshConversion.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace contessa::mesh {

namespace {

// Kuhn's 6 tetrahedra of the cube: for each order of the axes, the path from corner (0,0,0) to (1,1,1)
// stepping along them; corners as Exodus Hex8 numbers (bit 0: x, bit 1: y, bit 2: z → local node).
constexpr int kHexCornerOfBits[8] = {0, 1, 3, 2, 4, 5, 7, 6};

std::vector<std::vector<int>> kuhnTetrahedra() {
  std::vector<std::vector<int>> tets;
  int axes[3] = {0, 1, 2};
  do {
    int bits = 0;
    std::vector<int> tet{kHexCornerOfBits[0]};
    for (int axis : axes) {
      bits |= 1 << axis;
      tet.push_back(kHexCornerOfBits[bits]);
    }
    // The path's edges (e_a, e_a + e_b, e_a + e_b + e_c) have determinant sign(axes): an odd order of
    // the axes is listed with two nodes swapped to keep the tetrahedron right-handed.
    const bool odd = (axes[0] > axes[1]) + (axes[0] > axes[2]) + (axes[1] > axes[2]) == 1 ||
                     (axes[0] > axes[1]) + (axes[0] > axes[2]) + (axes[1] > axes[2]) == 3;
    if (odd) std::swap(tet[1], tet[2]);
    tets.push_back(tet);
  } while (std::next_permutation(axes, axes + 3));
  return tets;
}

// The simplices of one cell (local corner numbers) and their type.
struct Split {
  CellType type;
  std::vector<std::vector<int>> pieces;
};

Split splitOf(CellType type) {
  if (type == CellType::Quad4) return {CellType::Tri3, {{0, 1, 2}, {0, 2, 3}}};
  if (type == CellType::Hex8) return {CellType::Tet4, kuhnTetrahedra()};
  throw std::logic_error(std::string("splitIntoSimplices: ") + exodusCellName(type) + " is not a Quad4 or Hex8");
}

// Which side of the cell, if any, holds all the corners `corners` (cell-local numbers): −1 if none.
int parentSide(CellType type, const std::vector<int>& corners) {
  for (int s = 0; s < numSides(type); ++s) {
    const auto side = sideNodes(type, s);
    if (std::all_of(corners.begin(), corners.end(),
                    [&](int c) { return std::find(side.begin(), side.end(), c) != side.end(); }))
      return s;
  }
  return -1;
}

}  // namespace

Mesh splitIntoSimplices(const Mesh& mesh) {
  Mesh out;
  out.dimension = mesh.dimension;
  out.coordinates = mesh.coordinates;
  out.nodeSets = mesh.nodeSets;
  // (cell, cell side) → the (simplex, simplex side) pairs on it.
  std::map<std::pair<GlobalIndex, int>, std::vector<std::pair<GlobalIndex, int>>> onSide;
  for (const ElementBlock& b : mesh.blocks) {
    const Split split = splitOf(b.cellType);
    const int nn = nodesPerCell(b.cellType), pieces = static_cast<int>(split.pieces.size());
    ElementBlock nb{b.name, split.type, {}, {}};
    for (std::size_t k = 0; k < b.elements.size(); ++k) {
      for (int p = 0; p < pieces; ++p) {
        const GlobalIndex child = b.elements[k] * pieces + p;
        nb.elements.push_back(child);
        for (int c : split.pieces[p]) nb.connectivity.push_back(b.connectivity[nn * k + c]);
        for (int s = 0; s < numSides(split.type); ++s) {
          std::vector<int> corners;
          for (int a : sideNodes(split.type, s)) corners.push_back(split.pieces[p][a]);
          const int parent = parentSide(b.cellType, corners);
          if (parent >= 0) onSide[{b.elements[k], parent}].push_back({child, s});
        }
      }
    }
    out.blocks.push_back(std::move(nb));
  }
  for (const SideSet& set : mesh.sideSets) {
    SideSet ns{set.name, {}, {}};
    for (std::size_t k = 0; k < set.elements.size(); ++k)
      for (const auto& [child, side] : onSide[{set.elements[k], set.sides[k]}]) {
        ns.elements.push_back(child);
        ns.sides.push_back(side);
      }
    out.sideSets.push_back(std::move(ns));
  }
  return out;
}

namespace {

CellType quadraticOf(CellType type, bool complete) {
  switch (type) {
    case CellType::Tri3: return CellType::Tri6;
    case CellType::Quad4: return complete ? CellType::Quad9 : CellType::Quad8;
    case CellType::Tet4: return CellType::Tet10;
    case CellType::Hex8: return complete ? CellType::Hex27 : CellType::Hex20;
    case CellType::Wedge6: return CellType::Wedge15;
    default: break;
  }
  throw std::logic_error(std::string("withMidEdgeNodes: ") + exodusCellName(type) + " is not a linear cell");
}

// The corners (cell-local) each non-corner node of `type` is made from: its edge's two, its face's
// four (Quad9's and Hex27's face nodes: the side that lists it last), or all the corners (a centre).
std::vector<std::vector<int>> parentCorners(CellType type) {
  std::vector<std::vector<int>> parents(static_cast<std::size_t>(nodesPerCell(type)));
  for (const MidEdgeNode& e : midEdgeNodes(type)) parents[e.middle] = {e.first, e.second};
  if (type == CellType::Hex27)
    for (int s = 0; s < numSides(type); ++s) {
      const auto side = sideNodes(type, s);
      parents[side[8]] = {side[0], side[1], side[2], side[3]};
    }
  for (auto& p : parents)
    if (p.empty()) p = {0, 1, 2, 3, 4, 5, 6, 7};  // the centre of a Quad9 (4 corners) or Hex27 (8)
  if (type == CellType::Quad9) parents[8] = {0, 1, 2, 3};
  return parents;
}

}  // namespace

Mesh withMidEdgeNodes(const Mesh& mesh, bool complete) {
  Mesh out;
  out.dimension = mesh.dimension;
  out.coordinates = mesh.coordinates;
  out.sideSets = mesh.sideSets;
  const int d = mesh.dimension;
  std::map<std::vector<GlobalIndex>, GlobalIndex> made;  // sorted parent corners → new node
  std::vector<std::vector<GlobalIndex>> madeFrom;          // new node − old count → its corners
  const GlobalIndex oldNodes = mesh.numNodes();
  for (const ElementBlock& b : mesh.blocks) {
    const CellType type = quadraticOf(b.cellType, complete);
    const int corners = nodesPerCell(b.cellType), nn = nodesPerCell(type);
    const auto parents = parentCorners(type);
    ElementBlock nb{b.name, type, b.elements, {}};
    for (std::size_t k = 0; k < b.elements.size(); ++k) {
      const GlobalIndex* cell = &b.connectivity[corners * k];
      nb.connectivity.insert(nb.connectivity.end(), cell, cell + corners);
      for (int a = corners; a < nn; ++a) {
        std::vector<GlobalIndex> key;
        for (int c : parents[a]) key.push_back(cell[c]);
        std::sort(key.begin(), key.end());
        auto [it, inserted] = made.emplace(key, oldNodes + static_cast<GlobalIndex>(madeFrom.size()));
        if (inserted) {
          madeFrom.push_back(key);
          for (int i = 0; i < d; ++i) {
            double sum = 0;
            for (GlobalIndex n : key) sum += mesh.coordinates[d * n + i];
            out.coordinates.push_back(sum / static_cast<double>(key.size()));
          }
        }
        nb.connectivity.push_back(it->second);
      }
    }
    out.blocks.push_back(std::move(nb));
  }
  for (const NodeSet& set : mesh.nodeSets) {
    NodeSet ns = set;
    for (std::size_t k = 0; k < madeFrom.size(); ++k)
      if (std::all_of(madeFrom[k].begin(), madeFrom[k].end(),
                      [&](GlobalIndex n) { return std::binary_search(set.nodes.begin(), set.nodes.end(), n); }))
        ns.nodes.push_back(oldNodes + static_cast<GlobalIndex>(k));  // ascending: new nodes follow the old
    out.nodeSets.push_back(std::move(ns));
  }
  return out;
}

}  // namespace contessa::mesh
