// nestedDissectionOrder: METIS' nested dissection as MUMPS' PERM_IN. On a grid Laplacian (5-point
// stencil, the graph of a 2D mesh) it is a permutation, the same on 1 and 2 ranks (each rank giving its
// own rows), the same at every call, and it needs less fill than the natural (row by row) order; a matrix
// without off-diagonal entries gets none (MUMPS then orders with AMD).
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <set>
#include <vector>

#include "solvers/MumpsOrdering.hpp"

namespace contessa::solvers {
namespace {

// This rank's rows of the k x k grid Laplacian's pattern (rows split evenly, in order), 1-based.
struct GridRows {
  std::vector<MUMPS_INT> rows, cols;
  std::vector<double> values;
  MumpsMatrixView view(MUMPS_INT n) {
    return {n, static_cast<MUMPS_INT8>(rows.size()), rows.data(), cols.data(), values.data(), 1};
  }
};

GridRows gridRows(int k, int rank, int ranks) {
  GridRows g;
  const int n = k * k;
  for (int r = rank * n / ranks; r < (rank + 1) * n / ranks; ++r) {
    const int x = r % k, y = r / k;
    auto add = [&](int c) { g.rows.push_back(r + 1), g.cols.push_back(c + 1), g.values.push_back(r == c ? 4.0 : -1.0); };
    add(r);
    if (x > 0) add(r - 1);
    if (x + 1 < k) add(r + 1);
    if (y > 0) add(r - k);
    if (y + 1 < k) add(r + k);
  }
  return g;
}

// Entries of the Cholesky factor of the grid's pattern eliminated in `position` order (symbolic
// elimination: each eliminated vertex's later neighbours become a clique).
long factorEntries(int k, const std::vector<MUMPS_INT>& position) {
  const int n = k * k;
  std::vector<std::set<int>> later(n);
  for (int r = 0; r < n; ++r) {
    const int x = r % k, y = r / k;
    for (int c : {x > 0 ? r - 1 : -1, x + 1 < k ? r + 1 : -1, y > 0 ? r - k : -1, y + 1 < k ? r + k : -1})
      if (c >= 0) later[position[r] < position[c] ? r : c].insert(position[r] < position[c] ? c : r);
  }
  std::vector<int> byPosition(n);
  for (int r = 0; r < n; ++r) byPosition[position[r] - 1] = r;
  long entries = n;
  for (int v : byPosition) {
    entries += static_cast<long>(later[v].size());
    if (later[v].empty()) continue;
    int next = *std::min_element(later[v].begin(), later[v].end(), [&](int a, int b) { return position[a] < position[b]; });
    for (int w : later[v])
      if (w != next) later[next].insert(w);
  }
  return entries;
}

TEST(MumpsOrdering, NestedDissectionOfAGridIsAPermutationWithLessFillThanTheNaturalOrder) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  const int k = 30, n = k * k;
  GridRows mine = gridRows(k, rank, ranks);
  const std::vector<MUMPS_INT> order = nestedDissectionOrder(mine.view(n), MPI_COMM_WORLD);
  if (rank != 0) {
    EXPECT_TRUE(order.empty());
    return;
  }
  ASSERT_EQ(order.size(), static_cast<std::size_t>(n));
  std::vector<MUMPS_INT> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (int i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i + 1) << "not a permutation of 1..n";
  // The same pattern given by one rank alone: the same order (METIS' seed is fixed).
  GridRows whole = gridRows(k, 0, 1);
  EXPECT_EQ(nestedDissectionOrder(whole.view(n), MPI_COMM_SELF), order);
  std::vector<MUMPS_INT> natural(n);
  for (int i = 0; i < n; ++i) natural[i] = i + 1;
  // The natural order fills the band of width k (27 029 entries of the factor); nested dissection, whose
  // fill grows as n log n instead of n^1.5, gives 11 873: ask for half.
  EXPECT_LT(factorEntries(k, order), 0.5 * factorEntries(k, natural));
}

TEST(MumpsOrdering, ADiagonalMatrixGetsNoOrder) {
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::vector<MUMPS_INT> rows = {1, 2, 3}, cols = {1, 2, 3};
  std::vector<double> values = {1.0, 2.0, 3.0};
  MumpsMatrixView diagonal{3, 3, rows.data(), cols.data(), values.data(), 1};
  if (rank == 0) {
    EXPECT_TRUE(nestedDissectionOrder(diagonal, MPI_COMM_SELF).empty());
  }
}

}  // namespace
}  // namespace contessa::solvers
