#include "mesh/Mesh.hpp"

#include <algorithm>
#include <stdexcept>

#include "common/Error.hpp"

namespace contessa::mesh {

namespace {

// Error messages list the known names sorted, so they read the same whatever the file order.
template <class Entity>
std::string knownNames(const std::vector<Entity>& entities) {
  std::vector<std::string> names;
  for (const auto& e : entities) names.push_back(e.name);
  std::sort(names.begin(), names.end());
  if (names.empty()) return "none";
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  return list;
}

template <class Entity>
const Entity* findByName(const std::vector<Entity>& entities, const std::string& name) {
  for (const auto& e : entities)
    if (e.name == name) return &e;
  return nullptr;
}

template <class Entity>
const Entity& lookup(const std::vector<Entity>& entities, const std::string& name, const char* kind) {
  if (const Entity* e = findByName(entities, name)) return *e;
  throw InputError(std::string(kind) + " '" + name + "' does not exist in the mesh (known: " +
                   knownNames(entities) + ")");
}

}  // namespace

namespace {

// One cell topology in Exodus II order (SEACAS "Exodus element types"; Exodus side k+1 is side k here).
// Side nodes: the corners in an order that keeps the element on the left of a 2D side and makes a 3D
// side counter-clockwise seen from outside (normals from the order point outwards), then the mid-edge
// nodes of the side's edges in that order, then a face centre (Hex27).
struct Topology {
  CellType type;
  const char* name;
  int dimension, nodes, corners, order;
  std::vector<std::vector<int>> sides;
  std::vector<int> sideCorners;
  std::vector<MidEdgeNode> midEdges;
};

std::vector<Topology> makeTopologies() {
  const std::vector<std::vector<int>> triSides{{0, 1}, {1, 2}, {2, 0}};
  const std::vector<std::vector<int>> tri6Sides{{0, 1, 3}, {1, 2, 4}, {2, 0, 5}};
  const std::vector<std::vector<int>> quadSides{{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  const std::vector<std::vector<int>> quad8Sides{{0, 1, 4}, {1, 2, 5}, {2, 3, 6}, {3, 0, 7}};
  const std::vector<std::vector<int>> tetSides{{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}};
  const std::vector<std::vector<int>> tet10Sides{
      {0, 1, 3, 4, 8, 7}, {1, 2, 3, 5, 9, 8}, {0, 3, 2, 7, 9, 6}, {0, 2, 1, 6, 5, 4}};
  const std::vector<std::vector<int>> hexSides{{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                               {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  const std::vector<std::vector<int>> hex20Sides{{0, 1, 5, 4, 8, 13, 16, 12},  {1, 2, 6, 5, 9, 14, 17, 13},
                                                 {2, 3, 7, 6, 10, 15, 18, 14}, {0, 4, 7, 3, 12, 19, 15, 11},
                                                 {0, 3, 2, 1, 11, 10, 9, 8},   {4, 5, 6, 7, 16, 17, 18, 19}};
  // Hex27: node 20 is the centre, 21-26 the centres of sides 5, 6, 4, 2, 1, 3.
  std::vector<std::vector<int>> hex27Sides = hex20Sides;
  const int hex27FaceCentre[6] = {25, 24, 26, 23, 21, 22};
  for (int f = 0; f < 6; ++f) hex27Sides[f].push_back(hex27FaceCentre[f]);
  const std::vector<std::vector<int>> wedgeSides{{0, 1, 4, 3}, {1, 2, 5, 4}, {0, 3, 5, 2}, {0, 2, 1}, {3, 4, 5}};
  const std::vector<std::vector<int>> wedge15Sides{{0, 1, 4, 3, 6, 10, 12, 9}, {1, 2, 5, 4, 7, 11, 13, 10},
                                                   {0, 3, 5, 2, 9, 14, 11, 8},  {0, 2, 1, 8, 7, 6},
                                                   {3, 4, 5, 12, 13, 14}};
  const std::vector<MidEdgeNode> triEdges{{0, 1, 3}, {1, 2, 4}, {2, 0, 5}};
  const std::vector<MidEdgeNode> quadEdges{{0, 1, 4}, {1, 2, 5}, {2, 3, 6}, {3, 0, 7}};
  const std::vector<MidEdgeNode> tetEdges{{0, 1, 4}, {1, 2, 5}, {2, 0, 6}, {0, 3, 7}, {1, 3, 8}, {2, 3, 9}};
  const std::vector<MidEdgeNode> hexEdges{{0, 1, 8},  {1, 2, 9},  {2, 3, 10}, {3, 0, 11}, {0, 4, 12}, {1, 5, 13},
                                          {2, 6, 14}, {3, 7, 15}, {4, 5, 16}, {5, 6, 17}, {6, 7, 18}, {7, 4, 19}};
  const std::vector<MidEdgeNode> wedgeEdges{{0, 1, 6},  {1, 2, 7},  {2, 0, 8},  {0, 3, 9}, {1, 4, 10},
                                            {2, 5, 11}, {3, 4, 12}, {4, 5, 13}, {5, 3, 14}};
  return {
      {CellType::Quad4, "QUAD4", 2, 4, 4, 1, quadSides, {}, {}},
      {CellType::Hex8, "HEX8", 3, 8, 8, 1, hexSides, {}, {}},
      {CellType::Tri3, "TRI3", 2, 3, 3, 1, triSides, {}, {}},
      {CellType::Tri6, "TRI6", 2, 6, 3, 2, tri6Sides, {}, triEdges},
      {CellType::Quad8, "QUAD8", 2, 8, 4, 2, quad8Sides, {}, quadEdges},
      {CellType::Quad9, "QUAD9", 2, 9, 4, 2, quad8Sides, {}, quadEdges},
      {CellType::Tet4, "TETRA4", 3, 4, 4, 1, tetSides, {}, {}},
      {CellType::Tet10, "TETRA10", 3, 10, 4, 2, tet10Sides, {}, tetEdges},
      {CellType::Hex20, "HEX20", 3, 20, 8, 2, hex20Sides, {}, hexEdges},
      {CellType::Hex27, "HEX27", 3, 27, 8, 2, hex27Sides, {}, hexEdges},
      {CellType::Wedge6, "WEDGE6", 3, 6, 6, 1, wedgeSides, {}, {}},
      {CellType::Wedge15, "WEDGE15", 3, 15, 6, 2, wedge15Sides, {}, wedgeEdges},
  };
}

const Topology& topology(CellType type) {
  static const std::vector<Topology> all = [] {
    std::vector<Topology> t = makeTopologies();
    // A side's corners: 2 for an edge; a face has as many corners as mid-edge nodes (quadratic) or
    // all its nodes (linear).
    for (auto& top : t)
      for (const auto& side : top.sides) {
        const int n = static_cast<int>(side.size());
        top.sideCorners.push_back(top.dimension == 2 ? 2 : top.order == 1 ? n : n / 2);
      }
    return t;
  }();
  const auto index = static_cast<std::size_t>(type);
  if (index >= all.size() || all[index].type != type) throw std::logic_error("topology: unknown cell type");
  return all[index];
}

}  // namespace

int nodesPerCell(CellType type) { return topology(type).nodes; }
int cellDimension(CellType type) { return topology(type).dimension; }
const char* exodusCellName(CellType type) { return topology(type).name; }
int numCorners(CellType type) { return topology(type).corners; }
int cellOrder(CellType type) { return topology(type).order; }
int numSides(CellType type) { return static_cast<int>(topology(type).sides.size()); }
const std::vector<MidEdgeNode>& midEdgeNodes(CellType type) { return topology(type).midEdges; }

bool cellTypeOf(int dimension, int numNodes, CellType& type) {
  for (int t = 0; t <= static_cast<int>(CellType::Wedge15); ++t) {
    const Topology& top = topology(static_cast<CellType>(t));
    if (top.dimension == dimension && top.nodes == numNodes) {
      type = top.type;
      return true;
    }
  }
  return false;
}

std::vector<int> sideNodes(CellType type, int side) {
  if (side < 0 || side >= numSides(type))
    throw std::out_of_range(std::string("sideNodes: side ") + std::to_string(side) + " does not exist on " +
                            exodusCellName(type));
  return topology(type).sides[side];
}

int numSideCorners(CellType type, int side) {
  if (side < 0 || side >= numSides(type))
    throw std::out_of_range(std::string("numSideCorners: side ") + std::to_string(side) + " does not exist on " +
                            exodusCellName(type));
  return topology(type).sideCorners[side];
}

GlobalIndex Mesh::numNodes() const {
  return dimension > 0 ? static_cast<GlobalIndex>(coordinates.size()) / dimension : 0;
}

GlobalIndex Mesh::numElements() const {
  GlobalIndex n = 0;
  for (const auto& b : blocks) n += b.numElements();
  return n;
}

const ElementBlock& Mesh::block(const std::string& name) const { return lookup(blocks, name, "element block"); }
const NodeSet& Mesh::nodeSet(const std::string& name) const { return lookup(nodeSets, name, "node set"); }
const SideSet& Mesh::sideSet(const std::string& name) const { return lookup(sideSets, name, "side set"); }
bool Mesh::hasBlock(const std::string& name) const { return findByName(blocks, name) != nullptr; }
bool Mesh::hasNodeSet(const std::string& name) const { return findByName(nodeSets, name) != nullptr; }
bool Mesh::hasSideSet(const std::string& name) const { return findByName(sideSets, name) != nullptr; }

Mesh::ElementLocation Mesh::locate(GlobalIndex element) const {
  // Blocks almost always hold a contiguous id range (generators, Exodus files), which gives an
  // O(blocks) answer; anything else falls back to a search.
  for (int b = 0; b < static_cast<int>(blocks.size()); ++b) {
    const auto& ids = blocks[b].elements;
    if (ids.empty() || element < ids.front()) continue;
    const GlobalIndex offset = element - ids.front();
    if (offset < static_cast<GlobalIndex>(ids.size()) && ids[offset] == element) return {b, offset};
  }
  for (int b = 0; b < static_cast<int>(blocks.size()); ++b) {
    const auto& ids = blocks[b].elements;
    auto it = std::find(ids.begin(), ids.end(), element);
    if (it != ids.end()) return {b, static_cast<GlobalIndex>(it - ids.begin())};
  }
  throw std::out_of_range("Mesh::locate: element " + std::to_string(element) + " is in no block");
}

}  // namespace contessa::mesh
