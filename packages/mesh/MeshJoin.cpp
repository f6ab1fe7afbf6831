#include "mesh/MeshJoin.hpp"

#include <algorithm>
#include <tuple>

#include "common/Error.hpp"

namespace contessa::mesh {

std::string meshListing(const Mesh& mesh) {
  std::string s = std::to_string(mesh.dimension);
  for (const auto& b : mesh.blocks) s += "\nblock " + b.name;
  for (const auto& n : mesh.nodeSets) s += "\nnode set " + n.name;
  for (const auto& x : mesh.sideSets) s += "\nside set " + x.name;
  return s;
}

void MeshJoiner::add(const DistributedMesh& part, const std::string& source) {
  const Mesh& local = part.local();
  const std::vector<GlobalIndex>& nodes = part.part.globalNodes;
  const std::vector<GlobalIndex>& elements = part.part.globalElements;
  if (!started_) {
    started_ = true;
    whole_.dimension = local.dimension;
    for (const auto& b : local.blocks) whole_.blocks.push_back({b.name, b.cellType, {}, {}});
    for (const auto& n : local.nodeSets) whole_.nodeSets.push_back({n.name, {}});
    for (const auto& s : local.sideSets) whole_.sideSets.push_back({s.name, {}, {}});
    blockTyped_.assign(local.blocks.size(), 0);
    blockElements_.resize(local.blocks.size());
    sides_.resize(local.sideSets.size());
  }
  requireInput(meshListing(local) == meshListing(whole_),
               source + ": its dimension, element blocks, node sets or side sets differ from those of the first "
                        "part (the parts of a mesh list the same)");

  const auto dim = static_cast<std::size_t>(whole_.dimension);
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    requireInput(nodes[k] >= 0, source + ": global node id " + std::to_string(nodes[k] + 1) + " out of range");
    const auto g = static_cast<std::size_t>(nodes[k]);
    if (g >= nodeSeen_.size()) {
      nodeSeen_.resize(g + 1, 0);
      whole_.coordinates.resize((g + 1) * dim, 0.0);
    }
    nodeSeen_[g] = 1;  // a border node is in several parts, at the same place
    std::copy(local.coordinates.begin() + static_cast<std::ptrdiff_t>(k * dim),
              local.coordinates.begin() + static_cast<std::ptrdiff_t>((k + 1) * dim),
              whole_.coordinates.begin() + static_cast<std::ptrdiff_t>(g * dim));
  }
  for (std::size_t b = 0; b < local.blocks.size(); ++b) {
    const ElementBlock& block = local.blocks[b];
    if (block.elements.empty()) continue;
    if (!blockTyped_[b]) whole_.blocks[b].cellType = block.cellType;
    blockTyped_[b] = 1;
    requireInput(block.cellType == whole_.blocks[b].cellType,
                 source + ": block '" + block.name + "' holds " + exodusCellName(block.cellType) + " elements, " +
                     exodusCellName(whole_.blocks[b].cellType) + " in another part");
    const auto perElement = static_cast<std::size_t>(nodesPerCell(block.cellType));
    for (std::size_t k = 0; k < block.elements.size(); ++k) {
      std::vector<GlobalIndex> global(perElement);
      for (std::size_t a = 0; a < perElement; ++a) global[a] = nodes[block.connectivity[k * perElement + a]];
      blockElements_[b].emplace_back(elements[block.elements[k]], std::move(global));
    }
  }
  for (std::size_t n = 0; n < local.nodeSets.size(); ++n)
    for (GlobalIndex node : local.nodeSets[n].nodes) whole_.nodeSets[n].nodes.push_back(nodes[node]);
  const bool positioned = part.sideSetPositions.size() == local.sideSets.size();
  for (std::size_t s = 0; s < local.sideSets.size(); ++s)
    for (std::size_t k = 0; k < local.sideSets[s].elements.size(); ++k)
      sides_[s].push_back({positioned ? part.sideSetPositions[s][k] : -1, elements[local.sideSets[s].elements[k]],
                           local.sideSets[s].sides[k]});
}

Mesh MeshJoiner::finish(const std::string& source) {
  for (std::size_t g = 0; g < nodeSeen_.size(); ++g)
    requireInput(nodeSeen_[g], source + ": global node id " + std::to_string(g + 1) + " is in none of the parts");
  for (std::size_t b = 0; b < whole_.blocks.size(); ++b) {
    auto& elements = blockElements_[b];
    std::sort(elements.begin(), elements.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (auto& [element, nodes] : elements) {
      whole_.blocks[b].elements.push_back(element);
      whole_.blocks[b].connectivity.insert(whole_.blocks[b].connectivity.end(), nodes.begin(), nodes.end());
    }
    elements.clear();
  }
  for (auto& n : whole_.nodeSets) {
    std::sort(n.nodes.begin(), n.nodes.end());
    n.nodes.erase(std::unique(n.nodes.begin(), n.nodes.end()), n.nodes.end());
  }
  for (std::size_t s = 0; s < whole_.sideSets.size(); ++s) {
    auto& entries = sides_[s];
    std::sort(entries.begin(), entries.end(), [](const SideEntry& x, const SideEntry& y) {
      return std::tie(x.key, x.element, x.side) < std::tie(y.key, y.element, y.side);
    });
    for (const SideEntry& e : entries) {
      whole_.sideSets[s].elements.push_back(e.element);
      whole_.sideSets[s].sides.push_back(e.side);
    }
    entries.clear();
  }
  return std::move(whole_);
}

}  // namespace contessa::mesh
