#include "solvers/MumpsOrdering.hpp"

#include <metis.h>

#include <algorithm>
#include <numeric>

namespace contessa::solvers {
namespace {

// Any fixed seed: METIS' matchings are randomised, and the same pattern must get the same order (the
// answers of a run repeat bit for bit on one rank).
constexpr idx_t kOrderingSeed = 4321;

struct Pattern {
  std::vector<MUMPS_INT> rows, columns;  // 1-based, the whole matrix, on rank 0
};

// Every rank's (row, column) pairs on rank 0, in rank order.
Pattern gatherPattern(const MumpsMatrixView& local, MPI_Comm comm) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  Pattern all;
  if (ranks == 1) {
    all.rows.assign(local.rows, local.rows + local.numEntries);
    all.columns.assign(local.columns, local.columns + local.numEntries);
    return all;
  }
  int mine = static_cast<int>(local.numEntries);
  std::vector<int> counts(rank == 0 ? ranks : 0), offsets(rank == 0 ? ranks : 0);
  MPI_Gather(&mine, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  int total = 0;
  for (int r = 0; r < static_cast<int>(counts.size()); ++r) offsets[r] = total, total += counts[r];
  all.rows.resize(total);
  all.columns.resize(total);
  MPI_Gatherv(local.rows, mine, MPI_INT, all.rows.data(), counts.data(), offsets.data(), MPI_INT, 0, comm);
  MPI_Gatherv(local.columns, mine, MPI_INT, all.columns.data(), counts.data(), offsets.data(), MPI_INT, 0, comm);
  return all;
}

// The adjacency of A + Aᵀ without the diagonal, 0-based, each neighbour once (METIS' CSR graph).
struct Graph {
  std::vector<idx_t> xadj, adjncy;
};

Graph symmetricGraph(idx_t n, const Pattern& p) {
  Graph g;
  g.xadj.assign(static_cast<std::size_t>(n) + 1, 0);
  for (std::size_t k = 0; k < p.rows.size(); ++k) {
    if (p.rows[k] == p.columns[k]) continue;
    ++g.xadj[p.rows[k]];  // row i − 1 counted at xadj[i]: the prefix sum below makes them the starts
    ++g.xadj[p.columns[k]];
  }
  std::partial_sum(g.xadj.begin(), g.xadj.end(), g.xadj.begin());
  std::vector<idx_t> next(g.xadj.begin(), g.xadj.end() - 1);
  g.adjncy.resize(static_cast<std::size_t>(g.xadj[n]));
  for (std::size_t k = 0; k < p.rows.size(); ++k) {
    const idx_t i = p.rows[k] - 1, j = p.columns[k] - 1;
    if (i == j) continue;
    g.adjncy[next[i]++] = j;
    g.adjncy[next[j]++] = i;
  }
  // Sort and drop duplicates row by row (an entry of a general matrix comes from (i, j) and (j, i)),
  // compacting in place.
  idx_t write = 0;
  for (idx_t i = 0; i < n; ++i) {
    const auto first = g.adjncy.begin() + g.xadj[i], last = g.adjncy.begin() + g.xadj[i + 1];
    std::sort(first, last);
    const auto end = std::unique(first, last);
    g.xadj[i] = write;
    write = static_cast<idx_t>(std::copy(first, end, g.adjncy.begin() + write) - g.adjncy.begin());
  }
  g.xadj[n] = write;
  g.adjncy.resize(static_cast<std::size_t>(write));
  return g;
}

}  // namespace

std::vector<MUMPS_INT> nestedDissectionOrder(const MumpsMatrixView& local, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  const Pattern pattern = gatherPattern(local, comm);
  if (rank != 0) return {};
  idx_t n = local.order;
  Graph graph = symmetricGraph(n, pattern);
  if (graph.adjncy.empty()) return {};
  idx_t options[METIS_NOPTIONS];
  METIS_SetDefaultOptions(options);
  options[METIS_OPTION_SEED] = kOrderingSeed;
  options[METIS_OPTION_NUMBERING] = 0;
  // METIS: row i of the permuted matrix is row perm[i] of A, and row i of A is row iperm[i] of the
  // permuted one; MUMPS' PERM_IN(i) is the position of variable i, that is iperm (1-based).
  std::vector<idx_t> perm(n), iperm(n);
  if (METIS_NodeND(&n, graph.xadj.data(), graph.adjncy.data(), nullptr, options, perm.data(), iperm.data()) != METIS_OK)
    return {};
  std::vector<MUMPS_INT> order(n);
  for (idx_t i = 0; i < n; ++i) order[i] = static_cast<MUMPS_INT>(iperm[i] + 1);
  return order;
}

}  // namespace contessa::solvers
