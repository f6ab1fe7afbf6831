#include "solvers/MumpsInput.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
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
  values_ = const_cast<double*>(local.values.data());
  numValues_ = local.values.extent(0);
  return newPattern != 0;
}

bool MumpsUnchangedMatrix::matches(const MumpsMatrixView& local, MPI_Comm comm) const {
  const auto count = static_cast<std::size_t>(local.numEntries);
  int sameHere = generation_ >= 0 && local.patternGeneration == generation_ && count == values_.size() &&
                 (count == 0 || std::memcmp(local.values, values_.data(), count * sizeof(double)) == 0);
  int size = 1;
  MPI_Comm_size(comm, &size);
  if (size == 1) return sameHere != 0;
  int same = 0;
  MPI_Allreduce(&sameHere, &same, 1, MPI_INT, MPI_MIN, comm);
  return same != 0;
}

void MumpsUnchangedMatrix::remember(const MumpsMatrixView& local) {
  generation_ = local.patternGeneration;
  values_.assign(local.values, local.values + local.numEntries);
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

namespace {

// The general entries grouped by row, each row's by ascending column (ties in input order), as
// compressed rows: a counting sort by column, then a stable one by row, O(entries + order). Finding an
// entry's transpose is then a binary search within one row (about 81 entries on a Hex8 mesh), where a
// global sort and binary searches over all the entries cost 8 % of the 1.1·10^4-unknown punch's run
// (bench/README.md, "Issue 23, sixth round").
struct RowsByColumn {
  std::vector<std::size_t> begin;  ///< per 0-based row, its first position; begin[n] the end
  std::vector<MUMPS_INT> columns;  ///< per position, the column (1-based)
  std::vector<std::size_t> entry;  ///< per position, the general entry

  RowsByColumn(const MUMPS_INT* rows, const MUMPS_INT* cols, std::size_t numEntries, std::size_t n)
      : begin(n + 1, 0), columns(numEntries), entry(numEntries) {
    std::vector<std::size_t> byColumn(numEntries), start(n + 1, 0);
    for (std::size_t k = 0; k < numEntries; ++k) ++start[static_cast<std::size_t>(cols[k])];
    for (std::size_t c = 1; c <= n; ++c) start[c] += start[c - 1];  // 1-based columns: start[c - 1] is column c's
    for (std::size_t k = 0; k < numEntries; ++k) byColumn[start[static_cast<std::size_t>(cols[k]) - 1]++] = k;
    for (std::size_t k = 0; k < numEntries; ++k) ++begin[static_cast<std::size_t>(rows[k])];
    for (std::size_t r = 1; r <= n; ++r) begin[r] += begin[r - 1];
    std::vector<std::size_t> next(begin.begin(), begin.end() - 1);
    for (const std::size_t k : byColumn) {
      const std::size_t at = next[static_cast<std::size_t>(rows[k]) - 1]++;
      columns[at] = cols[k];
      entry[at] = k;
    }
  }

  /// The first general entry at (i, j), 1-based, or −1.
  long find(MUMPS_INT i, MUMPS_INT j) const {
    const auto first = columns.begin() + static_cast<long>(begin[static_cast<std::size_t>(i) - 1]);
    const auto last = columns.begin() + static_cast<long>(begin[static_cast<std::size_t>(i)]);
    const auto it = std::lower_bound(first, last, j);
    return it != last && *it == j ? static_cast<long>(entry[static_cast<std::size_t>(it - columns.begin())]) : -1;
  }
};

}  // namespace

void MumpsSymmetricInput::buildPattern(const MumpsMatrixView& general) {
  const MUMPS_INT* rows = general.rows;
  const MUMPS_INT* cols = general.columns;
  const auto numEntries = static_cast<std::size_t>(general.numEntries);
  n_ = general.order;
  const RowsByColumn byRow(rows, cols, numEntries, static_cast<std::size_t>(n_));
  auto find = [&byRow](MUMPS_INT i, MUMPS_INT j) { return byRow.find(i, j); };
  entryA_.clear();
  entryB_.clear();
  lowerRows_.clear();
  lowerColumns_.clear();
  const std::size_t lowerEstimate = numEntries / 2 + static_cast<std::size_t>(n_);  // the lower half and the diagonal
  for (auto* v : {&entryA_, &entryB_}) v->reserve(lowerEstimate);
  for (auto* v : {&lowerRows_, &lowerColumns_}) v->reserve(lowerEstimate);
  for (std::size_t k = 0; k < numEntries; ++k) {
    const auto entry = static_cast<long>(k);
    if (rows[k] >= cols[k]) {
      entryA_.push_back(entry);
      entryB_.push_back(rows[k] == cols[k] ? entry : find(cols[k], rows[k]));
    } else if (find(cols[k], rows[k]) < 0) {
      // An upper entry without a lower partner: given to MUMPS at its transpose's position, with the
      // lower value taken as zero (the symmetry check then asks it to be zero).
      entryA_.push_back(-1);
      entryB_.push_back(entry);
    } else {
      continue;
    }
    lowerRows_.push_back(std::max(rows[k], cols[k]));
    lowerColumns_.push_back(std::min(rows[k], cols[k]));
  }
  runs_.clear();
  diagonalPositions_.clear();
  for (std::size_t k = 0; k < numEntries;) {
    RowRun run{static_cast<std::size_t>(rows[k] - 1), k, k, diagonalPositions_.size(), 0};
    for (; k < numEntries && rows[k] == rows[run.begin]; ++k)
      if (cols[k] == rows[k]) diagonalPositions_.push_back(k);
    run.end = k;
    run.diagonalEnd = diagonalPositions_.size();
    runs_.push_back(run);
  }
  generalGeneration_ = general.patternGeneration;
  patternDecoupled_.clear();  // the roles are chosen again
}

void MumpsSymmetricInput::planEntries() {
  const auto n = static_cast<std::size_t>(n_);
  std::vector<MUMPS_INT> mumpsRow(n, 0);  // 1-based MUMPS numbering of the coupled rows
  coupledRows_.clear();
  for (std::size_t i = 0; i < n; ++i)
    if (!decoupled_[i]) {
      coupledRows_.push_back(static_cast<MUMPS_INT>(i));
      mumpsRow[i] = static_cast<MUMPS_INT>(coupledRows_.size());
    }
  coupledOrder_ = static_cast<MUMPS_INT>(coupledRows_.size());
  diagonalEntries_.clear();
  pairEntries_.clear();
  eliminatedSources_.clear();
  rows_.clear();
  cols_.clear();
  eliminated_.clear();
  for (std::size_t e = 0; e < lowerRows_.size(); ++e) {
    const auto i = static_cast<MUMPS_INT>(lowerRows_[e] - 1), j = static_cast<MUMPS_INT>(lowerColumns_[e] - 1);
    const bool iDecoupled = decoupled_[static_cast<std::size_t>(i)], jDecoupled = decoupled_[static_cast<std::size_t>(j)];
    if (iDecoupled && jDecoupled) continue;  // a decoupled row's diagonal, or zero after the elimination
    if (iDecoupled || jDecoupled) {
      // a_ij with j decoupled (the lower entry), or a_ji with i decoupled (its transpose).
      eliminatedSources_.push_back({jDecoupled ? entryA_[e] : entryB_[e]});
      eliminated_.push_back(jDecoupled ? EliminatedEntry{i, j, 0.0} : EliminatedEntry{j, i, 0.0});
      continue;
    }
    if (i == j) diagonalEntries_.push_back({entryA_[e], rows_.size()});
    else pairEntries_.push_back({entryA_[e], entryB_[e], i, j, rows_.size()});
    rows_.push_back(mumpsRow[static_cast<std::size_t>(i)]);
    cols_.push_back(mumpsRow[static_cast<std::size_t>(j)]);
  }
  values_.resize(rows_.size());
  patternDecoupled_ = decoupled_;
  ++generation_;
}

void MumpsSymmetricInput::measureRows(const MumpsMatrixView& general) {
  const double* v = general.values;
  const auto n = static_cast<std::size_t>(n_);
  rowNorm_.assign(n, 0.0);
  diagonal_.assign(n, 0.0);
  offDiagonal_.assign(n, 0);
  // Per run of one row's entries (buildPattern), in four independent lanes: one maximum and one count
  // of non-zero values carried from entry to entry was a chain of dependent operations, with a
  // comparison of each entry's column with its row (bench/README.md, issue 23 seventh round). The maximum does not depend on the order; a row's diagonal entries are
  // summed in their order as before, so every value is the one of the entry-by-entry loop.
  for (const RowRun& run : runs_) {
    double m0 = 0.0, m1 = 0.0, m2 = 0.0, m3 = 0.0;
    std::size_t nz0 = 0, nz1 = 0, nz2 = 0, nz3 = 0;
    std::size_t k = run.begin;
    for (; k + 4 <= run.end; k += 4) {
      m0 = std::max(m0, std::abs(v[k]));
      m1 = std::max(m1, std::abs(v[k + 1]));
      m2 = std::max(m2, std::abs(v[k + 2]));
      m3 = std::max(m3, std::abs(v[k + 3]));
      nz0 += v[k] != 0.0;
      nz1 += v[k + 1] != 0.0;
      nz2 += v[k + 2] != 0.0;
      nz3 += v[k + 3] != 0.0;
    }
    for (; k < run.end; ++k) {
      m0 = std::max(m0, std::abs(v[k]));
      nz0 += v[k] != 0.0;
    }
    double diagonal = 0.0;
    std::size_t diagonalNonZero = 0;
    for (std::size_t d = run.diagonalBegin; d < run.diagonalEnd; ++d) {
      diagonal += v[diagonalPositions_[d]];
      diagonalNonZero += v[diagonalPositions_[d]] != 0.0;
    }
    const std::size_t i = run.row;
    rowNorm_[i] = std::max(rowNorm_[i], std::max(std::max(m0, m1), std::max(m2, m3)));
    diagonal_[i] += diagonal;
    offDiagonal_[i] |= static_cast<char>(nz0 + nz1 + nz2 + nz3 > diagonalNonZero);
  }
  decoupled_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) decoupled_[i] = !offDiagonal_[i] && diagonal_[i] != 0.0;
}

bool MumpsSymmetricInput::update(const MumpsMatrixView& general) {
  if (general.patternGeneration != generalGeneration_) buildPattern(general);
  measureRows(general);
  if (decoupled_ != patternDecoupled_) planEntries();
  const double* v = general.values;
  const auto valueAt = [v](long entry) { return entry >= 0 ? v[entry] : 0.0; };
  for (const auto& d : diagonalEntries_) values_[d.slot] = v[d.entry];
  for (const auto& p : pairEntries_) {
    const double a = valueAt(p.a), b = valueAt(p.b);
    if (std::abs(a - b) > kSymmetryTolerance * std::max(rowNorm_[static_cast<std::size_t>(p.i)], rowNorm_[static_cast<std::size_t>(p.j)]))
      return false;
    values_[p.slot] = 0.5 * (a + b);
  }
  for (std::size_t k = 0; k < eliminated_.size(); ++k) eliminated_[k].value = valueAt(eliminatedSources_[k].entry);
  return true;
}

void MumpsSymmetricInput::reduce(const std::vector<double>& rhs, std::vector<double>& reduced) const {
  std::vector<double> b = rhs;
  // A decoupled row's right-hand side is never changed here, so b[column] is still b_column. A zero
  // b_column (a prescribed value already met: every Newton iterate after the first) moves nothing.
  for (const auto& e : eliminated_) {
    const double bColumn = b[static_cast<std::size_t>(e.column)];
    if (bColumn != 0.0) b[static_cast<std::size_t>(e.row)] -= e.value * bColumn / diagonal_[static_cast<std::size_t>(e.column)];
  }
  reduced.resize(coupledRows_.size());
  for (std::size_t r = 0; r < coupledRows_.size(); ++r) reduced[r] = b[static_cast<std::size_t>(coupledRows_[r])];
}

void MumpsSymmetricInput::expand(const std::vector<double>& reduced, std::vector<double>& rhs) const {
  for (std::size_t i = 0; i < rhs.size(); ++i)
    if (decoupled_[i]) rhs[i] /= diagonal_[i];
  for (std::size_t r = 0; r < coupledRows_.size(); ++r) rhs[static_cast<std::size_t>(coupledRows_[r])] = reduced[r];
}

std::vector<double> MumpsSymmetricInput::expandNullVector(const std::vector<double>& reduced) const {
  std::vector<double> whole(static_cast<std::size_t>(n_), 0.0);
  for (std::size_t r = 0; r < coupledRows_.size() && r < reduced.size(); ++r)
    whole[static_cast<std::size_t>(coupledRows_[r])] = reduced[r];
  return whole;
}

}  // namespace contessa::solvers
