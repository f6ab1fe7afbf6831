#include "model/DofLayout.hpp"

#include <algorithm>

namespace contessa::model {

using Teuchos::rcp;

DofLayout::DofLayout(const Teuchos::RCP<const Comm>& comm, const mesh::DistributedMesh& part,
                     const std::vector<mesh::GlobalIndex>& replicatedNodes)
    : comm_(comm), dim_(part.local().dimension) {
  const auto owned = part.ownedNodes();
  auto overlap = part.part.globalNodes;
  overlap.insert(overlap.end(), replicatedNodes.begin(), replicatedNodes.end());
  std::sort(overlap.begin(), overlap.end());
  overlap.erase(std::unique(overlap.begin(), overlap.end()), overlap.end());
  std::vector<GO> ownedDofs, overlapDofs;
  for (GO n : owned)
    for (int c = 0; c < dim_; ++c) ownedDofs.push_back(n * dim_ + c);
  for (GO n : overlap)
    for (int c = 0; c < dim_; ++c) overlapDofs.push_back(n * dim_ + c);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  ownedMap_ = rcp(new Map(invalid, Teuchos::ArrayView<const GO>(ownedDofs), 0, comm_));
  overlapMap_ = rcp(new Map(invalid, Teuchos::ArrayView<const GO>(overlapDofs), 0, comm_));
  // The part's elements in its order (block by block), which the element loop and the output follow.
  const auto& elements = part.part.globalElements;
  std::vector<GO> elementIds(elements.begin(), elements.end());
  elementMap_ = rcp(new Map(invalid, Teuchos::ArrayView<const GO>(elementIds), 0, comm_));
  nodeMap_ = rcp(new Map(invalid, Teuchos::ArrayView<const GO>(std::vector<GO>(owned.begin(), owned.end())), 0, comm_));
  exporter_ = rcp(new Export(overlapMap_, ownedMap_));
  importer_ = rcp(new Import(ownedMap_, overlapMap_));
}

void DofLayout::buildGraph(std::vector<std::vector<LO>>& rows) {
  const LO numOverlap = numOverlapDofs();
  std::size_t maxPerRow = 1;
  for (auto& r : rows) {
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
    maxPerRow = std::max(maxPerRow, r.size());
  }
  auto overlapGraph = rcp(new CrsGraph(overlapMap_, overlapMap_, maxPerRow));
  for (LO i = 0; i < numOverlap; ++i)
    if (!rows[i].empty()) overlapGraph->insertLocalIndices(i, Teuchos::ArrayView<const LO>(rows[i]));
  overlapGraph->fillComplete(ownedMap_, ownedMap_);
  // Rows shared between ranks receive entries from each: the sum of the contributions bounds a row.
  Vector overlapCounts(overlapMap_), ownedCounts(ownedMap_);
  {
    auto c = overlapCounts.getDataNonConst(0);
    for (LO i = 0; i < numOverlap; ++i) c[i] = static_cast<double>(rows[i].size());
  }
  ownedCounts.doExport(overlapCounts, *exporter_, Tpetra::ADD);
  std::vector<std::size_t> perRow;
  for (double c : ownedCounts.getData(0)) perRow.push_back(std::max<std::size_t>(1, static_cast<std::size_t>(c)));
  auto ownedGraph = rcp(new CrsGraph(ownedMap_, Teuchos::ArrayView<const std::size_t>(perRow)));
  ownedGraph->doExport(*overlapGraph, *exporter_, Tpetra::INSERT);
  ownedGraph->fillComplete(ownedMap_, ownedMap_);
  ownedGraph_ = ownedGraph;
}

}  // namespace contessa::model
