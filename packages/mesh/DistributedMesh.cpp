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

GridPartition::GridPartition(int n0, int n1, int n2, int numRanks)
    : n_{n0, n1, n2}, ranges_{static_cast<GlobalIndex>(n0) * n1 * n2, numRanks} {
  // Every factorisation p0 p1 p2 = P with p_a <= n_a; the cut faces of p_a boxes along a are
  // (p_a − 1) times the cross-section across a.
  double best = -1;
  for (int p0 = 1; p0 <= numRanks; ++p0) {
    if (numRanks % p0 != 0 || p0 > n0) continue;
    for (int p1 = 1; p1 <= numRanks / p0; ++p1) {
      if ((numRanks / p0) % p1 != 0 || p1 > n1) continue;
      const int p2 = numRanks / p0 / p1;
      if (p2 > n2) continue;
      const double cut = (p0 - 1.0) * n1 * n2 + (p1 - 1.0) * n0 * n2 + (p2 - 1.0) * n0 * n1;
      if (best < 0 || cut < best) {
        best = cut;
        parts_[0] = p0, parts_[1] = p1, parts_[2] = p2;
      }
    }
  }
  boxes_ = best >= 0;
}

int GridPartition::boxAlong(int axis, int index) const {
  // The largest b with split(b) <= index: start from the estimate and correct it.
  const int p = parts_[axis], n = n_[axis];
  int b = static_cast<int>(static_cast<long long>(index) * p / n);
  b = std::min(std::max(b, 0), p - 1);
  while (b > 0 && split(n, p, b) > index) --b;
  while (b + 1 < p && split(n, p, b + 1) <= index) ++b;
  return b;
}

int GridPartition::owner(int i, int j, int k) const {
  if (!boxes_) return ranges_.owner((static_cast<GlobalIndex>(k) * n_[1] + j) * n_[0] + i);
  return boxAlong(0, i) + parts_[0] * (boxAlong(1, j) + parts_[1] * boxAlong(2, k));
}

void GridPartition::bounds(int rank, int lo[3], int hi[3]) const {
  if (boxes_) {
    const int b[3] = {rank % parts_[0], rank / parts_[0] % parts_[1], rank / (parts_[0] * parts_[1])};
    for (int a = 0; a < 3; ++a) {
      lo[a] = split(n_[a], parts_[a], b[a]);
      hi[a] = split(n_[a], parts_[a], b[a] + 1);
    }
    return;
  }
  // Ids [first, last): along the slowest axis from the first cell's index to the last's; a faster axis
  // whole unless every slower one is a single index.
  const GlobalIndex first = ranges_.begin(rank), last = ranges_.begin(rank + 1) - 1;
  const int f[3] = {static_cast<int>(first % n_[0]), static_cast<int>(first / n_[0] % n_[1]),
                    static_cast<int>(first / (static_cast<GlobalIndex>(n_[0]) * n_[1]))};
  const int l[3] = {static_cast<int>(last % n_[0]), static_cast<int>(last / n_[0] % n_[1]),
                    static_cast<int>(last / (static_cast<GlobalIndex>(n_[0]) * n_[1]))};
  bool single = true;  // every slower axis holds one index
  for (int a = 2; a >= 0; --a) {
    if (single) {
      lo[a] = f[a];
      hi[a] = l[a] + 1;
      single = f[a] == l[a];
    } else {
      lo[a] = 0;
      hi[a] = n_[a];
    }
  }
}

std::vector<int> GridPartition::owners() const {
  std::vector<int> result;
  result.reserve(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2]);
  for (int k = 0; k < n_[2]; ++k)
    for (int j = 0; j < n_[1]; ++j)
      for (int i = 0; i < n_[0]; ++i) result.push_back(owner(i, j, k));
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
