#include "model/StiffnessScatter.hpp"

#include <algorithm>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <string>

namespace contessa::model {

using Teuchos::RCP;
using Teuchos::rcp;

namespace {

constexpr LO kNone = -1;

// Index of `col` in the sorted `cols[begin, end)`, or -1.
long findColumn(const std::vector<LO>& cols, std::size_t begin, std::size_t end, LO col) {
  const auto first = cols.begin() + static_cast<std::ptrdiff_t>(begin);
  const auto last = cols.begin() + static_cast<std::ptrdiff_t>(end);
  const auto it = std::lower_bound(first, last, col);
  return it != last && *it == col ? static_cast<long>(it - cols.begin()) : -1L;
}

// The CSR arrays of a fill-complete graph (local indices, sorted within each row).
void copyLocalGraph(const CrsGraph& graph, std::vector<std::size_t>& begin, std::vector<LO>& cols) {
  TEUCHOS_TEST_FOR_EXCEPTION(!graph.isFillComplete() || !graph.isSorted(), std::logic_error,
                             "StiffnessScatter: the graph must be fill complete with sorted rows");
  const auto local = graph.getLocalGraphHost();
  begin.assign(local.row_map.data(), local.row_map.data() + local.row_map.extent(0));
  cols.assign(local.entries.data(), local.entries.data() + local.entries.extent(0));
}

}  // namespace

StiffnessScatter::StiffnessScatter(const RCP<const CrsGraph>& ownedGraph, const RCP<const Map>& overlapMap,
                                   const OverlapCouplings& overlapRows)
    : ownedGraph_(ownedGraph), overlapMap_(overlapMap) {
  const auto& rowMap = *ownedGraph_->getRowMap();
  const auto& colMap = *ownedGraph_->getColMap();
  const LO numOverlap = static_cast<LO>(overlapMap_->getNodeNumElements());
  ownedRow_.assign(numOverlap, kNone);
  ownedCol_.assign(numOverlap, kNone);
  ghostRow_.assign(numOverlap, kNone);
  std::vector<GO> ghostIds;
  for (LO r = 0; r < numOverlap; ++r) {
    const GO g = overlapMap_->getGlobalElement(r);
    ownedRow_[r] = rowMap.getLocalElement(g);
    const LO c = colMap.getLocalElement(g);
    ownedCol_[r] = c == Teuchos::OrdinalTraits<LO>::invalid() ? kNone : c;
    if (ownedRow_[r] == Teuchos::OrdinalTraits<LO>::invalid()) {
      ownedRow_[r] = kNone;
      if (overlapRows.rowSize(r) > 0) {
        ghostRow_[r] = static_cast<LO>(ghostIds.size());
        ghostIds.push_back(g);
      }
    }
  }
  copyLocalGraph(*ownedGraph_, rowBegin_, columns_);
  values_.assign(columns_.size(), 0.0);

  const auto comm = rowMap.getComm();
  distributed_ = comm->getSize() > 1;
  if (distributed_) {
    // The rows shared with their owners: a matrix over them alone, exported (ADD) with a plan built once.
    const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
    auto ghostMap = rcp(new Map(invalid, Teuchos::ArrayView<const GO>(ghostIds), 0, comm));
    std::vector<std::size_t> counts;
    for (LO r = 0; r < numOverlap; ++r)
      if (ghostRow_[r] != kNone) counts.push_back(overlapRows.rowSize(r));
    auto ghostGraph = rcp(new CrsGraph(ghostMap, overlapMap_, Teuchos::ArrayView<const std::size_t>(counts)));
    for (LO r = 0; r < numOverlap; ++r)
      if (ghostRow_[r] != kNone)
        ghostGraph->insertLocalIndices(ghostRow_[r], Teuchos::ArrayView<const LO>(overlapRows.row(r), overlapRows.rowSize(r)));
    ghostGraph->fillComplete(ownedGraph_->getDomainMap(), ownedGraph_->getRangeMap());
    copyLocalGraph(*ghostGraph, ghostRowBegin_, ghostColumns_);
    ghostMatrix_ = rcp(new CrsMatrix(ghostGraph));
    ghostMatrix_->fillComplete(ownedGraph_->getDomainMap(), ownedGraph_->getRangeMap());
    ghostExporter_ = rcp(new Export(ghostMap, ownedGraph_->getRowMap()));
  }
}

int StiffnessScatter::position(LO row, LO col) const {
  const auto missing = [&] {
    return std::logic_error("StiffnessScatter: the matrix graph has no entry (" +
                            std::to_string(overlapMap_->getGlobalElement(row)) + ", " +
                            std::to_string(overlapMap_->getGlobalElement(col)) + ")");
  };
  if (ownedRow_[row] != kNone) {
    const LO r = ownedRow_[row], c = ownedCol_[col];
    const long k = c == kNone ? -1 : findColumn(columns_, rowBegin_[r], rowBegin_[r + 1], c);
    if (k < 0) throw missing();
    return static_cast<int>(k);
  }
  const LO r = ghostRow_[row];
  // The ghost matrix's column map is the overlap map: its local columns are overlapped DOFs.
  const long k = r == kNone ? -1 : findColumn(ghostColumns_, ghostRowBegin_[r], ghostRowBegin_[r + 1], col);
  if (k < 0) throw missing();
  return static_cast<int>(-1 - k);
}

void StiffnessScatter::addElement(const int* dofs, int n) {
  elementsByFirstDof_.emplace(dofs[0], elementSize_.size());
  elementDofBegin_.push_back(elementDofs_.size());
  elementPositionBegin_.push_back(elementPositions_.size());
  elementSize_.push_back(n);
  elementDofs_.insert(elementDofs_.end(), dofs, dofs + n);
  // The element's columns in increasing local column: each owned row then finds all of them in one
  // forward pass over its sorted columns instead of a binary search per entry (this is most of the set-up
  // of a scatter). Ghost rows, and a column the row lacks, go through position() (which names it).
  columnOrder_.resize(static_cast<std::size_t>(n));
  std::iota(columnOrder_.begin(), columnOrder_.end(), 0);
  std::sort(columnOrder_.begin(), columnOrder_.end(), [&](int a, int b) { return ownedCol_[dofs[a]] < ownedCol_[dofs[b]]; });
  const std::size_t base = elementPositions_.size();
  elementPositions_.resize(base + static_cast<std::size_t>(n) * n);
  for (int i = 0; i < n; ++i) {
    int* out = elementPositions_.data() + base + static_cast<std::size_t>(i) * n;
    const LO r = ownedRow_[dofs[i]];
    if (r == kNone) {
      for (int j = 0; j < n; ++j) out[j] = position(dofs[i], dofs[j]);
      continue;
    }
    std::size_t k = rowBegin_[r];
    const std::size_t end = rowBegin_[r + 1];
    for (int j : columnOrder_) {
      const LO c = ownedCol_[dofs[j]];
      while (k < end && columns_[k] < c) ++k;
      out[j] = k < end && columns_[k] == c ? static_cast<int>(k) : position(dofs[i], dofs[j]);
    }
  }
}

void StiffnessScatter::beginPass() {
  std::fill(values_.begin(), values_.end(), 0.0);
  if (!ghostMatrix_.is_null()) {
    auto v = ghostMatrix_->getLocalMatrixHost().values;
    ghostValues_ = v.data();
    std::fill(ghostValues_, ghostValues_ + v.extent(0), 0.0);
  }
  cursor_ = 0;
}

void StiffnessScatter::add(const int* positions, int count, const double* values) {
  for (int k = 0; k < count; ++k) {
    const int p = positions[k];
    if (p >= 0)
      values_[p] += values[k];
    else
      ghostValues_[-1 - p] += values[k];
  }
}

void StiffnessScatter::addElementStiffness(const int* dofs, int n, const double* ke) {
  const auto matches = [&](std::size_t e) {
    return elementSize_[e] == n && std::memcmp(&elementDofs_[elementDofBegin_[e]], dofs, n * sizeof(int)) == 0;
  };
  std::size_t e = cursor_;
  if (e >= elementSize_.size() || !matches(e)) {
    // Not the next element (the one expected failed and was skipped): find it by its DOFs.
    e = elementSize_.size();
    const auto [first, last] = elementsByFirstDof_.equal_range(dofs[0]);
    for (auto it = first; it != last; ++it)
      if (matches(it->second)) e = it->second;
  }
  if (e < elementSize_.size()) {
    add(&elementPositions_[elementPositionBegin_[e]], n * n, ke);
    cursor_ = e + 1;
    return;
  }
  scratch_.resize(static_cast<std::size_t>(n) * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) scratch_[i * n + j] = position(dofs[i], dofs[j]);
  add(scratch_.data(), n * n, ke);
}

void StiffnessScatter::addStiffness(const LO* dofs, int n, const double* k) {
  auto& block = blocks_[dofs[0]];
  if (block.dofs.size() != static_cast<std::size_t>(n) || !std::equal(block.dofs.begin(), block.dofs.end(), dofs)) {
    block.dofs.assign(dofs, dofs + n);
    block.positions.resize(static_cast<std::size_t>(n) * n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) block.positions[i * n + j] = position(dofs[i], dofs[j]);
  }
  add(block.positions.data(), n * n, k);
}

void StiffnessScatter::copyTo(CrsMatrix& W, const std::vector<LO>& identityRows) const {
  TEUCHOS_TEST_FOR_EXCEPTION(W.getCrsGraph().get() != ownedGraph_.get(), std::logic_error,
                             "StiffnessScatter: the Jacobian does not have the model's graph");
  if (!W.isFillComplete()) W.fillComplete(ownedGraph_->getDomainMap(), ownedGraph_->getRangeMap());
  {
    auto v = W.getLocalMatrixHost().values;
    TEUCHOS_TEST_FOR_EXCEPTION(v.extent(0) != values_.size(), std::logic_error, "StiffnessScatter: value count");
    std::copy(values_.begin(), values_.end(), v.data());
  }
  if (distributed_) W.doExport(*ghostMatrix_, *ghostExporter_, Tpetra::ADD);
  auto v = W.getLocalMatrixHost().values;
  const auto& rowMap = *ownedGraph_->getRowMap();
  const auto& colMap = *ownedGraph_->getColMap();
  for (const LO r : identityRows) {
    const LO diagonal = colMap.getLocalElement(rowMap.getGlobalElement(r));
    for (std::size_t k = rowBegin_[r]; k < rowBegin_[r + 1]; ++k) v(k) = columns_[k] == diagonal ? 1.0 : 0.0;
  }
}

}  // namespace contessa::model
