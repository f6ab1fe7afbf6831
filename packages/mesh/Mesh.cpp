#include "mesh/Mesh.hpp"

#include <algorithm>
#include <stdexcept>

#include "common/Error.hpp"

namespace contessa::mesh {

int nodesPerCell(CellType type) {
  switch (type) {
    case CellType::Quad4: return 4;
    case CellType::Hex8: return 8;
  }
  throw std::logic_error("nodesPerCell: unknown cell type");
}

int cellDimension(CellType type) {
  switch (type) {
    case CellType::Quad4: return 2;
    case CellType::Hex8: return 3;
  }
  throw std::logic_error("cellDimension: unknown cell type");
}

const char* exodusCellName(CellType type) {
  switch (type) {
    case CellType::Quad4: return "QUAD4";
    case CellType::Hex8: return "HEX8";
  }
  throw std::logic_error("exodusCellName: unknown cell type");
}

namespace {

int numSides(CellType type) { return type == CellType::Quad4 ? 4 : 6; }

// Side tables from the Exodus II manual (its side k+1 is side k here). The node order matters:
// it keeps the element on the left of a 2D side and makes 3D sides counter-clockwise seen from
// outside, so normals computed from the order point outwards.
const int kQuad4Sides[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
const int kHex8Sides[6][4] = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                              {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};

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

template <class Entity>
void requireUniqueNames(const std::vector<Entity>& entities, const char* kind, const std::string& source) {
  std::vector<std::string> names;
  for (const auto& e : entities) names.push_back(e.name);
  std::sort(names.begin(), names.end());
  auto dup = std::adjacent_find(names.begin(), names.end());
  requireInput(dup == names.end(), source + ": " + kind + " name '" + (dup == names.end() ? "" : *dup) +
                                       "' is used more than once");
}

}  // namespace

std::vector<int> sideNodes(CellType type, int side) {
  if (side < 0 || side >= numSides(type))
    throw std::out_of_range(std::string("sideNodes: side ") + std::to_string(side) + " does not exist on " +
                            exodusCellName(type));
  if (type == CellType::Quad4) return {kQuad4Sides[side][0], kQuad4Sides[side][1]};
  const int* s = kHex8Sides[side];
  return {s[0], s[1], s[2], s[3]};
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

void Mesh::validate(const std::string& source) const {
  const std::string where = source + ": ";
  requireInput(dimension == 2 || dimension == 3,
               where + "mesh dimension must be 2 or 3, got " + std::to_string(dimension));
  requireInput(coordinates.size() % static_cast<size_t>(dimension) == 0,
               where + "coordinate array length " + std::to_string(coordinates.size()) +
                   " is not a multiple of the dimension " + std::to_string(dimension));
  const GlobalIndex nNodes = numNodes();
  const GlobalIndex nElements = numElements();

  // Every element id 0..numElements-1 must appear in exactly one block: the partition and the
  // results writer index global arrays by it.
  std::vector<int> blockOf(static_cast<size_t>(nElements), -1);
  for (int bi = 0; bi < static_cast<int>(blocks.size()); ++bi) {
    const auto& b = blocks[bi];
    const std::string blk = where + "element block '" + b.name + "': ";
    requireInput(cellDimension(b.cellType) == dimension,
                 blk + exodusCellName(b.cellType) + " cells in a " + std::to_string(dimension) + "D mesh");
    const size_t npe = static_cast<size_t>(nodesPerCell(b.cellType));
    requireInput(b.connectivity.size() == b.elements.size() * npe,
                 blk + "connectivity has " + std::to_string(b.connectivity.size()) + " entries, expected " +
                     std::to_string(b.elements.size() * npe));
    for (GlobalIndex e : b.elements) {
      requireInput(e >= 0 && e < nElements, blk + "element id " + std::to_string(e) + " is outside [0, " +
                                                std::to_string(nElements) + ")");
      requireInput(blockOf[e] < 0, blk + "element id " + std::to_string(e) + " appears more than once");
      blockOf[e] = bi;
    }
    for (GlobalIndex n : b.connectivity)
      requireInput(n >= 0 && n < nNodes,
                   blk + "node id " + std::to_string(n) + " is outside [0, " + std::to_string(nNodes) + ")");
  }
  for (const auto& s : nodeSets) {
    for (GlobalIndex n : s.nodes)
      requireInput(n >= 0 && n < nNodes, where + "node set '" + s.name + "': node id " + std::to_string(n) +
                                             " is outside [0, " + std::to_string(nNodes) + ")");
    requireInput(std::is_sorted(s.nodes.begin(), s.nodes.end()) &&
                     std::adjacent_find(s.nodes.begin(), s.nodes.end()) == s.nodes.end(),
                 where + "node set '" + s.name + "' is not sorted and unique");
  }
  for (const auto& s : sideSets) {
    const std::string set = where + "side set '" + s.name + "': ";
    requireInput(s.elements.size() == s.sides.size(), set + std::to_string(s.elements.size()) +
                                                          " elements but " + std::to_string(s.sides.size()) +
                                                          " sides");
    for (size_t k = 0; k < s.elements.size(); ++k) {
      const GlobalIndex e = s.elements[k];
      requireInput(e >= 0 && e < nElements, set + "element id " + std::to_string(e) + " is outside [0, " +
                                                std::to_string(nElements) + ")");
      const CellType type = blocks[blockOf[e]].cellType;
      requireInput(s.sides[k] >= 0 && s.sides[k] < numSides(type),
                   set + "side " + std::to_string(s.sides[k]) + " of element " + std::to_string(e) +
                       " does not exist on " + exodusCellName(type) + " (0-based sides 0.." +
                       std::to_string(numSides(type) - 1) + ")");
    }
  }
  requireUniqueNames(blocks, "element block", source);
  requireUniqueNames(nodeSets, "node set", source);
  requireUniqueNames(sideSets, "side set", source);
}

}  // namespace contessa::mesh
