#include "model/DofLayout.hpp"

#include <algorithm>
#include <functional>
#include <numeric>

#include <Tpetra_Details_makeColMap.hpp>

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

OverlapCouplings OverlapCouplings::gather(LO numRows, const std::vector<int>& elementDofs,
                                          const std::vector<std::size_t>& elementBegin,
                                          const std::vector<std::vector<LO>>& extraRows) {
  // The elements of each row, in compressed rows: count, prefix sum, fill.
  const std::size_t numElements = elementBegin.empty() ? 0 : elementBegin.size() - 1;
  std::vector<std::size_t> incidenceBegin(static_cast<std::size_t>(numRows) + 1, 0);
  for (int d : elementDofs) ++incidenceBegin[d + 1];
  std::partial_sum(incidenceBegin.begin(), incidenceBegin.end(), incidenceBegin.begin());
  std::vector<std::size_t> elementsOfRow(incidenceBegin.back());
  {
    std::vector<std::size_t> next(incidenceBegin.begin(), incidenceBegin.end() - 1);
    for (std::size_t e = 0; e < numElements; ++e)
      for (std::size_t k = elementBegin[e]; k < elementBegin[e + 1]; ++k) elementsOfRow[next[elementDofs[k]]++] = e;
  }
  // Row r's columns, each once: a column is taken when its mark is not yet this visit's stamp. Two
  // visits, the first counting (the exact size of every row), the second filling.
  std::vector<std::size_t> mark(static_cast<std::size_t>(numRows), static_cast<std::size_t>(-1));
  const auto visit = [&](LO r, std::size_t stamp, auto&& take) {
    const auto takeOnce = [&](LO c) {
      if (mark[c] != stamp) {
        mark[c] = stamp;
        take(c);
      }
    };
    for (std::size_t k = incidenceBegin[r]; k < incidenceBegin[r + 1]; ++k) {
      const std::size_t e = elementsOfRow[k];
      for (std::size_t j = elementBegin[e]; j < elementBegin[e + 1]; ++j) takeOnce(elementDofs[j]);
    }
    for (LO c : extraRows[r]) takeOnce(c);
  };
  OverlapCouplings g;
  g.rowBegin.assign(static_cast<std::size_t>(numRows) + 1, 0);
  for (LO r = 0; r < numRows; ++r) {
    std::size_t count = 0;
    visit(r, static_cast<std::size_t>(r), [&](LO) { ++count; });
    g.rowBegin[r + 1] = g.rowBegin[r] + count;
  }
  g.columns.resize(g.rowBegin.back());
  for (LO r = 0; r < numRows; ++r) {
    LO* out = g.columns.data() + g.rowBegin[r];
    visit(r, static_cast<std::size_t>(numRows) + r, [&](LO c) { *out++ = c; });
    std::sort(g.columns.data() + g.rowBegin[r], out);
  }
  return g;
}

Teuchos::RCP<const CrsGraph> DofLayout::receiveSharedRows(const OverlapCouplings& rows) const {
  if (comm_->getSize() == 1) return Teuchos::null;
  std::vector<GO> sharedIds;
  std::vector<LO> sharedRows;
  std::vector<std::size_t> counts;
  for (LO r = 0; r < rows.numRows(); ++r) {
    const GO g = overlapMap_->getGlobalElement(r);
    if (rows.rowSize(r) == 0 || ownedMap_->isNodeGlobalElement(g)) continue;
    sharedIds.push_back(g);
    sharedRows.push_back(r);
    counts.push_back(rows.rowSize(r));
  }
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  auto sharedMap = rcp(new Map(invalid, Teuchos::ArrayView<const GO>(sharedIds), 0, comm_));
  auto shared = rcp(new CrsGraph(sharedMap, overlapMap_, Teuchos::ArrayView<const std::size_t>(counts)));
  for (std::size_t k = 0; k < sharedRows.size(); ++k)
    shared->insertLocalIndices(static_cast<LO>(k), Teuchos::ArrayView<const LO>(rows.row(sharedRows[k]), counts[k]));
  shared->fillComplete(ownedMap_, ownedMap_);
  // An owned row receives at most the sum of its senders' lengths.
  const Export toOwners(sharedMap, ownedMap_);
  Vector sent(sharedMap), bound(ownedMap_);
  {
    auto c = sent.getDataNonConst(0);
    for (std::size_t k = 0; k < counts.size(); ++k) c[k] = static_cast<double>(counts[k]);
  }
  bound.doExport(sent, toOwners, Tpetra::ADD);
  std::vector<std::size_t> perRow;
  for (double c : bound.getData(0)) perRow.push_back(static_cast<std::size_t>(c));
  auto received = rcp(new CrsGraph(ownedMap_, Teuchos::ArrayView<const std::size_t>(perRow)));
  received->doExport(*shared, toOwners, Tpetra::INSERT);
  return received;
}

void DofLayout::buildGraph(const OverlapCouplings& rows) {
  const auto received = receiveSharedRows(rows);
  const LO numOverlap = numOverlapDofs();
  const LO numOwned = static_cast<LO>(ownedMap_->getNodeNumElements());
  const LO none = Teuchos::OrdinalTraits<LO>::invalid();
  // The overlapped row of each owned row, and the columns the owned rows use (their global indices).
  std::vector<LO> overlapRowOf(numOwned, none);
  for (LO r = 0; r < numOverlap; ++r) {
    const LO o = ownedMap_->getLocalElement(overlapMap_->getGlobalElement(r));
    if (o != none) overlapRowOf[o] = r;
  }
  std::vector<char> used(numOverlap, 0);
  std::vector<GO> columnIds;
  for (LO o = 0; o < numOwned; ++o)
    if (overlapRowOf[o] != none)
      for (std::size_t k = rows.rowBegin[overlapRowOf[o]]; k < rows.rowBegin[overlapRowOf[o] + 1]; ++k) used[rows.columns[k]] = 1;
  for (LO c = 0; c < numOverlap; ++c)
    if (used[c]) columnIds.push_back(overlapMap_->getGlobalElement(c));
  CrsGraph::global_inds_host_view_type fromOthers;
  if (!received.is_null())
    for (LO o = 0; o < numOwned; ++o) {
      received->getGlobalRowView(ownedMap_->getGlobalElement(o), fromOthers);
      columnIds.insert(columnIds.end(), fromOthers.data(), fromOthers.data() + fromOthers.extent(0));
    }
  // The column map by Tpetra's own rule (the owned columns in the domain map's order, then the others
  // grouped by owning rank), as fillComplete would make it.
  Teuchos::RCP<const Map> colMap;
  Kokkos::View<GO*, Node::memory_space> ids("column ids", columnIds.size());
  std::copy(columnIds.begin(), columnIds.end(), ids.data());
  Tpetra::Details::makeColMap<LO, GO, Node>(colMap, ownedMap_, ids);
  // The rows in local columns, sorted: each overlapped column's local column once, then per row.
  std::vector<LO> localColumn(numOverlap, none);
  for (LO c = 0; c < numOverlap; ++c)
    if (used[c]) localColumn[c] = colMap->getLocalElement(overlapMap_->getGlobalElement(c));
  using LocalGraph = CrsGraph::local_graph_device_type;
  LocalGraph::row_map_type::non_const_type rowPointers("row pointers", static_cast<std::size_t>(numOwned) + 1);
  std::vector<LO> columns;
  columns.reserve(rows.columns.size());
  for (LO o = 0; o < numOwned; ++o) {
    const std::size_t begin = columns.size();
    if (overlapRowOf[o] != none)
      for (std::size_t k = rows.rowBegin[overlapRowOf[o]]; k < rows.rowBegin[overlapRowOf[o] + 1]; ++k)
        columns.push_back(localColumn[rows.columns[k]]);
    if (!received.is_null()) {
      received->getGlobalRowView(ownedMap_->getGlobalElement(o), fromOthers);
      for (std::size_t k = 0; k < fromOthers.extent(0); ++k) columns.push_back(colMap->getLocalElement(fromOthers(k)));
    }
    // Strictly increasing already where the local columns keep the global order and no other rank
    // added to the row; otherwise sorted, and a column both gave kept once.
    const auto first = columns.begin() + static_cast<std::ptrdiff_t>(begin);
    if (std::adjacent_find(first, columns.end(), std::greater_equal<LO>()) != columns.end()) {
      std::sort(first, columns.end());
      columns.erase(std::unique(first, columns.end()), columns.end());
    }
    rowPointers(o + 1) = columns.size();
  }
  LocalGraph::entries_type::non_const_type columnIndices("column indices", columns.size());
  std::copy(columns.begin(), columns.end(), columnIndices.data());
  auto graph = rcp(new CrsGraph(ownedMap_, colMap, rowPointers, columnIndices));
  graph->expertStaticFillComplete(ownedMap_, ownedMap_);
  ownedGraph_ = graph;
}

}  // namespace contessa::model
