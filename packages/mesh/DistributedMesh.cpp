#include "mesh/DistributedMesh.hpp"

#include <algorithm>
#include <stdexcept>

#include "common/Error.hpp"

namespace contessa::mesh {

std::vector<GlobalIndex> DistributedMesh::ownedNodes() const {
  std::vector<GlobalIndex> result;
  for (std::size_t n = 0; n < nodeOwner.size(); ++n)
    if (nodeOwner[n] == rank) result.push_back(part.globalNodes[n]);
  return result;
}

std::vector<GlobalIndex> DistributedMesh::haloNodes() const {
  std::vector<GlobalIndex> result;
  for (std::size_t n = 0; n < nodeOwner.size(); ++n)
    if (nodeOwner[n] != rank) result.push_back(part.globalNodes[n]);
  return result;
}

GlobalIndex DistributedMesh::localNode(GlobalIndex globalNode) const {
  const auto& g = part.globalNodes;
  const auto it = std::lower_bound(g.begin(), g.end(), globalNode);
  return it != g.end() && *it == globalNode ? static_cast<GlobalIndex>(it - g.begin()) : -1;
}

namespace {

template <class T>
std::size_t vectorBytes(const std::vector<T>& v) {
  return v.size() * sizeof(T);
}

}  // namespace

std::size_t meshBytes(const Mesh& mesh) {
  std::size_t bytes = vectorBytes(mesh.coordinates);
  for (const auto& b : mesh.blocks) bytes += vectorBytes(b.elements) + vectorBytes(b.connectivity);
  for (const auto& s : mesh.nodeSets) bytes += vectorBytes(s.nodes);
  for (const auto& s : mesh.sideSets) bytes += vectorBytes(s.elements) + vectorBytes(s.sides);
  return bytes;
}

std::size_t DistributedMesh::bytes() const {
  std::size_t total = meshBytes(part.mesh) + vectorBytes(part.globalNodes) + vectorBytes(part.globalElements) +
                      vectorBytes(nodeOwner) + part.sharedWith.size() * sizeof(std::vector<int>);
  for (const auto& s : part.sharedWith) total += vectorBytes(s);
  for (const auto& p : sideSetPositions) total += vectorBytes(p);
  return total;
}

GlobalIndex ElementRanges::begin(int rank) const {
  // r·E < 2^62: E is below 2^31 (kMaxIndex, MemoryEstimate.hpp) for any mesh the size checks pass.
  return static_cast<GlobalIndex>(rank) * numElements / numRanks;
}

int ElementRanges::owner(GlobalIndex element) const {
  // The largest r with begin(r) ≤ element: start from the estimate and correct it.
  int r = static_cast<int>(element * numRanks / std::max<GlobalIndex>(numElements, 1));
  r = std::min(std::max(r, 0), numRanks - 1);
  while (r > 0 && begin(r) > element) --r;
  while (r + 1 < numRanks && begin(r + 1) <= element) ++r;
  return r;
}

std::vector<int> ElementRanges::owners() const {
  std::vector<int> result(static_cast<std::size_t>(numElements));
  for (int r = 0; r < numRanks; ++r)
    std::fill(result.begin() + begin(r), result.begin() + begin(r + 1), r);
  return result;
}

PartExtractor::PartExtractor(const Mesh& mesh, std::vector<int> elementOwner, int numRanks)
    : mesh_(mesh), elementOwner_(std::move(elementOwner)), numRanks_(numRanks) {
  if (static_cast<GlobalIndex>(elementOwner_.size()) != mesh.numElements())
    throw std::logic_error("PartExtractor: one owner per element expected");
  const GlobalIndex numNodes = mesh.numNodes();
  // Element-node incidences per node, then each node's ranks sorted and made unique in place.
  userStart_.assign(static_cast<std::size_t>(numNodes) + 1, 0);
  for (const auto& b : mesh.blocks)
    for (GlobalIndex node : b.connectivity) ++userStart_[node + 1];
  for (GlobalIndex n = 0; n < numNodes; ++n) userStart_[n + 1] += userStart_[n];
  users_.resize(static_cast<std::size_t>(userStart_.back()));
  std::vector<GlobalIndex> fill(userStart_.begin(), userStart_.end() - 1);
  for (const auto& b : mesh.blocks) {
    const int npe = nodesPerCell(b.cellType);
    for (std::size_t k = 0; k < b.elements.size(); ++k)
      for (int a = 0; a < npe; ++a) users_[fill[b.connectivity[k * npe + a]]++] = elementOwner_[b.elements[k]];
  }
  GlobalIndex out = 0;
  for (GlobalIndex n = 0; n < numNodes; ++n) {
    auto first = users_.begin() + userStart_[n], last = users_.begin() + userStart_[n + 1];
    std::sort(first, last);
    last = std::unique(first, last);
    userStart_[n] = out;
    out = std::copy(first, last, users_.begin() + out) - users_.begin();
  }
  userStart_[numNodes] = out;
  users_.resize(static_cast<std::size_t>(out));
  users_.shrink_to_fit();
}

DistributedMesh PartExtractor::part(int rank) const {
  const Mesh& mesh = mesh_;
  const GlobalIndex numNodes = mesh.numNodes();
  const int dim = mesh.dimension;
  DistributedMesh result;
  result.rank = rank;
  result.numRanks = numRanks_;
  result.numGlobalNodes = numNodes;
  result.numGlobalElements = mesh.numElements();
  MeshPiece& piece = result.part;
  piece.mesh.dimension = dim;

  std::vector<GlobalIndex> local(static_cast<std::size_t>(numNodes), -1);
  for (GlobalIndex node = 0; node < numNodes; ++node) {
    const auto first = users_.begin() + userStart_[node], last = users_.begin() + userStart_[node + 1];
    // A node of no element belongs to rank 0 (Partition's rule), and so is in rank 0's part.
    const bool used = first == last ? rank == 0 : std::binary_search(first, last, rank);
    if (!used) continue;
    local[node] = static_cast<GlobalIndex>(piece.globalNodes.size());
    piece.globalNodes.push_back(node);
    for (int d = 0; d < dim; ++d) piece.mesh.coordinates.push_back(mesh.coordinates[node * dim + d]);
    std::vector<int> others;
    for (auto u = first; u != last; ++u)
      if (*u != rank) others.push_back(*u);
    piece.sharedWith.push_back(std::move(others));
    result.nodeOwner.push_back(first == last ? 0 : *first);  // users sorted: the lowest rank
  }

  std::vector<GlobalIndex> localElement(static_cast<std::size_t>(mesh.numElements()), -1);
  for (const auto& block : mesh.blocks) {
    const int n = nodesPerCell(block.cellType);
    ElementBlock part{block.name, block.cellType, {}, {}};
    for (GlobalIndex e = 0; e < block.numElements(); ++e) {
      if (elementOwner_[block.elements[e]] != rank) continue;
      localElement[block.elements[e]] = static_cast<GlobalIndex>(piece.globalElements.size());
      part.elements.push_back(static_cast<GlobalIndex>(piece.globalElements.size()));
      piece.globalElements.push_back(block.elements[e]);
      for (int a = 0; a < n; ++a) part.connectivity.push_back(local[block.connectivity[e * n + a]]);
    }
    piece.mesh.blocks.push_back(std::move(part));
    result.globalBlockSizes.push_back(block.numElements());
  }
  for (const auto& set : mesh.nodeSets) {
    NodeSet part{set.name, {}};
    for (GlobalIndex node : set.nodes)
      if (local[node] >= 0) part.nodes.push_back(local[node]);  // increasing: local ids follow global ones
    piece.mesh.nodeSets.push_back(std::move(part));
    result.globalNodeSetSizes.push_back(static_cast<GlobalIndex>(set.nodes.size()));
  }
  for (const auto& set : mesh.sideSets) {
    SideSet part{set.name, {}, {}};
    std::vector<GlobalIndex> positions;
    for (std::size_t k = 0; k < set.elements.size(); ++k)
      if (localElement[set.elements[k]] >= 0) {
        part.elements.push_back(localElement[set.elements[k]]);
        part.sides.push_back(set.sides[k]);
        positions.push_back(static_cast<GlobalIndex>(k));
      }
    piece.mesh.sideSets.push_back(std::move(part));
    result.sideSetPositions.push_back(std::move(positions));
    result.globalSideSetSizes.push_back(static_cast<GlobalIndex>(set.elements.size()));
  }
  return result;
}

}  // namespace contessa::mesh
