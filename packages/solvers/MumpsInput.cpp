#include "solvers/MumpsInput.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

namespace contessa::solvers {

bool MumpsDistributedInput::update(const model::CrsMatrix& A, MPI_Comm comm) {
  const auto graph = A.getCrsGraph();
  int newPatternHere = graph.get() != graph_.get() ? 1 : 0, newPattern = 0;
  MPI_Allreduce(&newPatternHere, &newPattern, 1, MPI_INT, MPI_MAX, comm);
  const auto local = A.getLocalMatrixHost();
  if (newPatternHere) {
    TEUCHOS_TEST_FOR_EXCEPTION(A.getGlobalNumRows() > static_cast<Tpetra::global_size_t>(std::numeric_limits<MUMPS_INT>::max()),
                               std::runtime_error, "MUMPS input: too many rows for MUMPS' 32-bit indices");
    graph_ = graph;
    n_ = static_cast<MUMPS_INT>(A.getGlobalNumRows());
    const auto& rowMap = *A.getRowMap();
    const auto& colMap = *A.getColMap();
    const auto& rowBegin = local.graph.row_map;
    const auto& entries = local.graph.entries;
    rows_.resize(entries.extent(0));
    cols_.resize(entries.extent(0));
    for (std::size_t r = 0; r + 1 < rowBegin.extent(0); ++r) {
      const auto row = static_cast<MUMPS_INT>(rowMap.getGlobalElement(static_cast<model::LO>(r)) + 1);
      for (std::size_t k = rowBegin(r); k < rowBegin(r + 1); ++k) {
        rows_[k] = row;
        cols_[k] = static_cast<MUMPS_INT>(colMap.getGlobalElement(entries(k)) + 1);
      }
    }
  }
  if (newPattern) ++generation_;
  values_.assign(local.values.data(), local.values.data() + local.values.extent(0));
  return newPattern != 0;
}

void MumpsHostInput::update(const MumpsMatrixView& local, MPI_Comm comm) {
  static_assert(sizeof(MUMPS_INT) == sizeof(int), "MUMPS_INT is sent as MPI_INT");
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  if (local.patternGeneration != generation_) {
    // MPI counts are int: a rank's part, and the whole matrix on rank 0, must fit (2^31 entries).
    int tooMany = local.numEntries > std::numeric_limits<int>::max() ? 1 : 0;
    localEntries_ = static_cast<int>(local.numEntries);
    counts_.assign(rank == 0 ? size : 0, 0);
    MPI_Gather(&localEntries_, 1, MPI_INT, counts_.data(), 1, MPI_INT, 0, comm);
    offsets_.assign(counts_.size(), 0);
    long long total = 0;
    for (std::size_t r = 0; r < counts_.size(); ++r) {
      tooMany = tooMany || total > std::numeric_limits<int>::max();
      offsets_[r] = static_cast<int>(std::min<long long>(total, std::numeric_limits<int>::max()));
      total += counts_[r];
    }
    tooMany = tooMany || total > std::numeric_limits<int>::max();
    MPI_Allreduce(MPI_IN_PLACE, &tooMany, 1, MPI_INT, MPI_MAX, comm);
    TEUCHOS_TEST_FOR_EXCEPTION(tooMany != 0, std::runtime_error,
                               "MUMPS input: too many matrix entries to gather on one rank (Reproducible)");
    rows_.resize(static_cast<std::size_t>(total));
    cols_.resize(static_cast<std::size_t>(total));
    values_.resize(static_cast<std::size_t>(total));
    MPI_Gatherv(local.rows, localEntries_, MPI_INT, rows_.data(), counts_.data(), offsets_.data(), MPI_INT, 0, comm);
    MPI_Gatherv(local.columns, localEntries_, MPI_INT, cols_.data(), counts_.data(), offsets_.data(), MPI_INT, 0, comm);
    n_ = local.order;
    generation_ = local.patternGeneration;
  }
  MPI_Gatherv(local.values, localEntries_, MPI_DOUBLE, values_.data(), counts_.data(), offsets_.data(), MPI_DOUBLE, 0,
              comm);
}

void MumpsSymmetricInput::buildPattern(const MumpsMatrixView& general) {
  const MUMPS_INT* rows = general.rows;
  const MUMPS_INT* cols = general.columns;
  const auto numEntries = static_cast<std::size_t>(general.numEntries);
  n_ = general.order;
  // Every entry by (row, column), to find each entry's transpose.
  auto key = [](MUMPS_INT i, MUMPS_INT j) { return (static_cast<std::int64_t>(i) << 32) | static_cast<std::uint32_t>(j); };
  std::vector<std::pair<std::int64_t, std::size_t>> byKey(numEntries);
  for (std::size_t k = 0; k < numEntries; ++k) byKey[k] = {key(rows[k], cols[k]), k};
  std::sort(byKey.begin(), byKey.end());
  auto find = [&](MUMPS_INT i, MUMPS_INT j) -> long {
    auto it = std::lower_bound(byKey.begin(), byKey.end(), std::make_pair(key(i, j), std::size_t{0}));
    return it != byKey.end() && it->first == key(i, j) ? static_cast<long>(it->second) : -1;
  };
  lower_.clear();
  transposeOf_.clear();
  for (std::size_t k = 0; k < numEntries; ++k) {
    if (rows[k] >= cols[k]) {
      lower_.push_back(k);
      transposeOf_.push_back(rows[k] == cols[k] ? static_cast<long>(k) : find(cols[k], rows[k]));
    } else if (find(cols[k], rows[k]) < 0) {
      // An upper entry without a lower partner: given to MUMPS as its transpose's position, with the
      // lower value taken as zero (the symmetry check then asks it to be zero).
      lower_.push_back(k);
      transposeOf_.push_back(-2);
    }
  }
  lowerRows_.resize(lower_.size());
  lowerColumns_.resize(lower_.size());
  for (std::size_t e = 0; e < lower_.size(); ++e) {
    lowerRows_[e] = std::max(rows[lower_[e]], cols[lower_[e]]);
    lowerColumns_[e] = std::min(rows[lower_[e]], cols[lower_[e]]);
  }
  lowerValues_.assign(lower_.size(), 0.0);
  generalGeneration_ = general.patternGeneration;
  patternDecoupled_.clear();  // the kept entries are chosen again
}

void MumpsSymmetricInput::keepCoupledEntries() {
  kept_.clear();
  for (std::size_t e = 0; e < lower_.size(); ++e) {
    const auto i = static_cast<std::size_t>(lowerRows_[e] - 1), j = static_cast<std::size_t>(lowerColumns_[e] - 1);
    if (i == j || (!decoupled_[i] && !decoupled_[j])) kept_.push_back(e);
  }
  rows_.resize(kept_.size());
  cols_.resize(kept_.size());
  values_.resize(kept_.size());
  for (std::size_t c = 0; c < kept_.size(); ++c) rows_[c] = lowerRows_[kept_[c]], cols_[c] = lowerColumns_[kept_[c]];
  patternDecoupled_ = decoupled_;
  ++generation_;
}

bool MumpsSymmetricInput::update(const MumpsMatrixView& general) {
  if (general.patternGeneration != generalGeneration_) buildPattern(general);
  const MUMPS_INT* rows = general.rows;
  const MUMPS_INT* cols = general.columns;
  const double* v = general.values;
  const auto numEntries = static_cast<std::size_t>(general.numEntries);
  const auto n = static_cast<std::size_t>(n_);
  std::vector<double> rowNorm(n, 0.0);
  diagonal_.assign(n, 0.0);
  std::vector<char> offDiagonal(n, 0);
  for (std::size_t k = 0; k < numEntries; ++k) {
    const auto i = static_cast<std::size_t>(rows[k] - 1);
    rowNorm[i] = std::max(rowNorm[i], std::abs(v[k]));
    if (rows[k] == cols[k]) diagonal_[i] += v[k];
    else if (v[k] != 0.0) offDiagonal[i] = 1;
  }
  decoupled_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) decoupled_[i] = !offDiagonal[i] && diagonal_[i] != 0.0;
  eliminated_.clear();
  for (std::size_t e = 0; e < lower_.size(); ++e) {
    const std::size_t k = lower_[e];
    const long t = transposeOf_[e];
    if (t == static_cast<long>(k)) {  // diagonal
      lowerValues_[e] = v[k];
      continue;
    }
    // The pair (i, j), i > j: a = a_ij, b = a_ji.
    const bool upperAlone = t == -2;
    const MUMPS_INT i = lowerRows_[e] - 1, j = lowerColumns_[e] - 1;
    const double a = upperAlone ? 0.0 : v[k];
    const double b = upperAlone ? v[k] : (t >= 0 ? v[static_cast<std::size_t>(t)] : 0.0);
    lowerValues_[e] = 0.0;
    if (decoupled_[j] && !decoupled_[i]) {
      eliminated_.push_back({i, j, a});
    } else if (decoupled_[i] && !decoupled_[j]) {
      eliminated_.push_back({j, i, b});
    } else if (!decoupled_[i] && !decoupled_[j]) {
      if (std::abs(a - b) > kSymmetryTolerance * std::max(rowNorm[static_cast<std::size_t>(i)], rowNorm[static_cast<std::size_t>(j)]))
        return false;
      lowerValues_[e] = 0.5 * (a + b);
    }
  }
  if (decoupled_ != patternDecoupled_) keepCoupledEntries();
  for (std::size_t c = 0; c < kept_.size(); ++c) values_[c] = lowerValues_[kept_[c]];
  return true;
}

void MumpsSymmetricInput::eliminateColumns(std::vector<double>& rhs) const {
  // A decoupled row's right-hand side is never changed here, so rhs[column] is still b_column.
  for (const auto& e : eliminated_)
    rhs[static_cast<std::size_t>(e.row)] -= e.value * rhs[static_cast<std::size_t>(e.column)] / diagonal_[static_cast<std::size_t>(e.column)];
}

}  // namespace contessa::solvers
