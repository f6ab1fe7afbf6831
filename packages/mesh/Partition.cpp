#include "mesh/Partition.hpp"

#include <metis.h>

#include <algorithm>
#include <stdexcept>

#include "common/Error.hpp"

namespace contessa::mesh {

namespace {

// Any fixed seed makes METIS reproducible; every rank must get the same answer without talking.
constexpr idx_t kMetisSeed = 4321;

std::vector<int> metisElementParts(const Mesh& mesh, int numParts) {
  const GlobalIndex numElements = mesh.numElements();
  // METIS wants the elements in global-id order: gather each element's nodes into its slot.
  std::vector<idx_t> eptr(static_cast<size_t>(numElements) + 1, 0);
  for (const auto& b : mesh.blocks)
    for (GlobalIndex e : b.elements) eptr[e + 1] = nodesPerCell(b.cellType);
  for (GlobalIndex e = 0; e < numElements; ++e) eptr[e + 1] += eptr[e];
  std::vector<idx_t> eind(static_cast<size_t>(eptr.back()));
  for (const auto& b : mesh.blocks) {
    const int npe = nodesPerCell(b.cellType);
    for (size_t k = 0; k < b.elements.size(); ++k)
      for (int a = 0; a < npe; ++a)
        eind[eptr[b.elements[k]] + a] = static_cast<idx_t>(b.connectivity[k * npe + a]);
  }

  idx_t ne = static_cast<idx_t>(numElements);
  idx_t nn = static_cast<idx_t>(mesh.numNodes());
  // Neighbours share a side: an edge (2 nodes, 3 when quadratic; a corner alone is 1) in 2D, a face in
  // 3D (3 or 4 corners, 6 or 8 nodes when quadratic). Quadratic cells sharing only an edge share 3
  // nodes: a mesh of quadratic cells alone asks for 4.
  bool allQuadratic = numElements > 0;
  for (const auto& b : mesh.blocks)
    if (!b.elements.empty()) allQuadratic = allQuadratic && cellOrder(b.cellType) == 2;
  idx_t ncommon = mesh.dimension == 2 ? 2 : allQuadratic ? 4 : 3;
  idx_t nparts = numParts;
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = kMetisSeed;
  options[METIS_OPTION_NUMBERING] = 0;
  idx_t objval = 0;
  std::vector<idx_t> epart(static_cast<size_t>(ne)), npart(static_cast<size_t>(nn));
  const int status = METIS_PartMeshDual(&ne, &nn, eptr.data(), eind.data(), nullptr, nullptr, &ncommon, &nparts,
                                        nullptr, options, &objval, epart.data(), npart.data());
  if (status != METIS_OK)
    throw std::runtime_error("METIS_PartMeshDual failed (status " + std::to_string(status) + ") for " +
                             std::to_string(numParts) + " parts of " + std::to_string(numElements) + " elements");
  return std::vector<int>(epart.begin(), epart.end());
}

// METIS may leave a part empty on tiny or disconnected meshes; a rank without elements would own
// no nodes and sit idle, so hand it the highest-numbered element of the largest part.
void fillEmptyParts(std::vector<int>& owner, int numParts) {
  std::vector<GlobalIndex> count(static_cast<size_t>(numParts), 0);
  for (int p : owner) ++count[p];
  for (int empty = 0; empty < numParts; ++empty) {
    if (count[empty] > 0) continue;
    const int largest = static_cast<int>(std::max_element(count.begin(), count.end()) - count.begin());
    for (size_t e = owner.size(); e-- > 0;)
      if (owner[e] == largest) {
        owner[e] = empty;
        break;
      }
    --count[largest];
    ++count[empty];
  }
}

}  // namespace

void requirePartsFit(GlobalIndex numElements, int numParts) {
  requireInput(numParts >= 1, "number of partitions must be at least 1, got " + std::to_string(numParts));
  requireInput(numParts == 1 || numParts <= numElements, "cannot split a mesh of " + std::to_string(numElements) +
                                            " elements over " + std::to_string(numParts) +
                                            " ranks: use at most one rank per element");
}

Partition partitionMesh(const Mesh& mesh, int numParts) {
  const GlobalIndex numElements = mesh.numElements();
  requirePartsFit(numElements, numParts);

  Partition partition;
  partition.numParts = numParts;
  if (numParts == 1) {
    partition.elementOwner.assign(static_cast<size_t>(numElements), 0);
  } else {
    partition.elementOwner = metisElementParts(mesh, numParts);
    fillEmptyParts(partition.elementOwner, numParts);
  }

  // Lowest rank wins so that ownership needs no tie-breaking communication; nodes outside every
  // element (rare) go to rank 0.
  partition.nodeOwner.assign(static_cast<size_t>(mesh.numNodes()), numParts);
  for (const auto& b : mesh.blocks) {
    const int npe = nodesPerCell(b.cellType);
    for (size_t k = 0; k < b.elements.size(); ++k) {
      const int rank = partition.elementOwner[b.elements[k]];
      for (int a = 0; a < npe; ++a) {
        int& owner = partition.nodeOwner[b.connectivity[k * npe + a]];
        owner = std::min(owner, rank);
      }
    }
  }
  for (int& owner : partition.nodeOwner)
    if (owner == numParts) owner = 0;
  return partition;
}

std::vector<GlobalIndex> Partition::ownedElements(int rank) const {
  std::vector<GlobalIndex> result;
  for (size_t e = 0; e < elementOwner.size(); ++e)
    if (elementOwner[e] == rank) result.push_back(static_cast<GlobalIndex>(e));
  return result;
}

std::vector<GlobalIndex> Partition::ownedNodes(int rank) const {
  std::vector<GlobalIndex> result;
  for (size_t n = 0; n < nodeOwner.size(); ++n)
    if (nodeOwner[n] == rank) result.push_back(static_cast<GlobalIndex>(n));
  return result;
}

std::vector<GlobalIndex> Partition::overlapNodes(const Mesh& mesh, int rank) const {
  std::vector<char> touched(nodeOwner.size(), 0);
  for (size_t n = 0; n < nodeOwner.size(); ++n)
    if (nodeOwner[n] == rank) touched[n] = 1;
  for (const auto& b : mesh.blocks) {
    const int npe = nodesPerCell(b.cellType);
    for (size_t k = 0; k < b.elements.size(); ++k)
      if (elementOwner[b.elements[k]] == rank)
        for (int a = 0; a < npe; ++a) touched[b.connectivity[k * npe + a]] = 1;
  }
  std::vector<GlobalIndex> result;
  for (size_t n = 0; n < touched.size(); ++n)
    if (touched[n]) result.push_back(static_cast<GlobalIndex>(n));
  return result;
}

}  // namespace contessa::mesh
