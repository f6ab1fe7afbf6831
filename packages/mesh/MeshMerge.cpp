#include "mesh/MeshMerge.hpp"

#include <cmath>
#include <set>
#include <sstream>

#include "common/Error.hpp"
#include "mesh/MemoryEstimate.hpp"

namespace contessa::mesh {

Mesh mergeMeshes(const std::vector<std::pair<std::string, Mesh>>& parts) {
  requireInput(!parts.empty(), "mesh merge: expected at least one mesh part, got none");
  std::set<std::string> seen;
  for (size_t p = 0; p < parts.size(); ++p) {
    const std::string& name = parts[p].first;
    requireInput(!name.empty(), "mesh merge: mesh part " + std::to_string(p + 1) + " has an empty name");
    requireInput(seen.insert(name).second, "mesh merge: mesh part name '" + name + "' is used more than once");
    parts[p].second.validate("mesh part '" + name + "'");
    requireInput(parts[p].second.dimension == parts[0].second.dimension,
                 "mesh merge: mesh part '" + name + "' is " + std::to_string(parts[p].second.dimension) +
                     "D but mesh part '" + parts[0].first + "' is " + std::to_string(parts[0].second.dimension) +
                     "D");
  }

  // Each part passed its own check; the merged copy and the run on it need the sum.
  MeshSize total(0, 0, parts[0].second.dimension);
  for (const auto& part : parts) {
    total.nodes += static_cast<double>(part.second.numNodes());
    total.elements += static_cast<double>(part.second.numElements());
  }
  requireRunFits(total, "mesh merge: the " + std::to_string(parts.size()) + " mesh parts together",
                 "use fewer elements in the parts");

  Mesh merged;
  merged.dimension = parts[0].second.dimension;
  GlobalIndex nodeOffset = 0, nextElement = 0;
  for (const auto& [partName, part] : parts) {
    const auto prefixed = [&partName](const std::string& name) { return partName + "_" + name; };
    merged.coordinates.insert(merged.coordinates.end(), part.coordinates.begin(), part.coordinates.end());

    // Part element id → merged element id, sequential over the part's blocks in order.
    std::vector<GlobalIndex> newId(static_cast<size_t>(part.numElements()), -1);
    for (const auto& b : part.blocks) {
      ElementBlock nb;
      nb.name = part.blocks.size() == 1 ? partName : prefixed(b.name);
      nb.cellType = b.cellType;
      nb.elements.reserve(b.elements.size());
      for (GlobalIndex e : b.elements) {
        newId[static_cast<size_t>(e)] = nextElement;
        nb.elements.push_back(nextElement++);
      }
      nb.connectivity.reserve(b.connectivity.size());
      for (GlobalIndex n : b.connectivity) nb.connectivity.push_back(n + nodeOffset);
      merged.blocks.push_back(std::move(nb));
    }
    for (const auto& s : part.nodeSets) {
      NodeSet ns;
      ns.name = prefixed(s.name);
      ns.nodes.reserve(s.nodes.size());
      for (GlobalIndex n : s.nodes) ns.nodes.push_back(n + nodeOffset);  // an offset keeps them sorted
      merged.nodeSets.push_back(std::move(ns));
    }
    for (const auto& s : part.sideSets) {
      SideSet ss;
      ss.name = prefixed(s.name);
      ss.sides = s.sides;
      ss.elements.reserve(s.elements.size());
      for (GlobalIndex e : s.elements) ss.elements.push_back(newId[static_cast<size_t>(e)]);
      merged.sideSets.push_back(std::move(ss));
    }
    nodeOffset += part.numNodes();
  }
  merged.validate("merged mesh");
  return merged;
}

Mesh translateMesh(Mesh mesh, const std::vector<double>& offset) {
  requireInput(offset.size() == static_cast<size_t>(mesh.dimension),
               "mesh translation: expected an offset with " + std::to_string(mesh.dimension) +
                   " components (the mesh dimension), got " + std::to_string(offset.size()));
  for (size_t d = 0; d < offset.size(); ++d) {
    std::ostringstream value;
    value.precision(12);
    value << offset[d];
    requireInput(std::isfinite(offset[d]), "mesh translation: offset component " + std::to_string(d + 1) +
                                               " must be finite, got " + value.str());
  }
  const size_t dim = offset.size();
  if (dim == 0) return mesh;  // dimension 0: no coordinates to move
  for (size_t k = 0; k < mesh.coordinates.size(); ++k) mesh.coordinates[k] += offset[k % dim];
  return mesh;
}

}  // namespace contessa::mesh
