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

}  // namespace

int numSides(CellType type) {
  switch (type) {
    case CellType::Quad4: return 4;
    case CellType::Hex8: return 6;
  }
  throw std::logic_error("numSides: unknown cell type");
}

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

}  // namespace contessa::mesh
