// contact_graph_bench: time and size of the matrix graph's contact couplings in 3D (the model's
// ContactMechanicsModel::buildGraph reservation through contact::reserveCouplings) for 10^3, 10^4 and
// 10^5 slave nodes: a slave grid of n nodes over a master grid of quadrilaterals of the same spacing (a
// box pressed on a box, their contact faces only), the slave grid offset by a third of a facet.
// "before": every slave node against every master node (the reservation before the search, run only
// while it fits in memory; otherwise its entry count alone); "after": the search-based reservation with
// Search Reach 0 (reach = 2 x largest master facet). Both fill the per-row column lists the model builds
// (3 x 3 DOF blocks, both directions, sorted and made unique) and count their entries. Not a test; run it
// by hand:
//   build/bin/contact_graph_bench
#include "contact/CouplingReservation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

namespace cc = contessa::contact;

namespace {

constexpr int kDim = 3;

double seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

struct Surface {
  cc::ContactInterfaceSpec spec;
  std::vector<double> X;
  long long numNodes = 0;
};

// side × side slave nodes (spacing 1) over (side + 1)² master nodes.
Surface makeSurface(int side) {
  Surface s;
  s.spec.name = "bench";
  s.spec.dimension = kDim;
  s.spec.searchReach = 0.0;
  const int m = side + 1;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) s.X.insert(s.X.end(), {double(i), double(j), 0.0});
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const long long a = static_cast<long long>(j) * m + i;
      s.spec.masterFacets.insert(s.spec.masterFacets.end(), {a, a + 1, a + 1 + m, a + m});
    }
  const long long first = static_cast<long long>(m) * m;
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      s.X.insert(s.X.end(), {i + 1.0 / 3.0, j + 1.0 / 3.0, 0.001});
      s.spec.slaveNodes.push_back(first + static_cast<long long>(j) * side + i);
    }
  s.numNodes = first + static_cast<long long>(side) * side;
  return s;
}

// The column lists of the contact rows as buildGraph fills them; returns the number of entries.
std::size_t fillRows(const Surface& s, const cc::CouplingReservation& r) {
  std::vector<std::vector<int>> rows(static_cast<std::size_t>(s.numNodes) * kDim);
  for (std::size_t k = 0; k < s.spec.slaveNodes.size(); ++k)
    for (const long long* m = r.begin(k); m != r.end(k); ++m)
      for (int c = 0; c < kDim; ++c)
        for (int d = 0; d < kDim; ++d) {
          const auto sc = static_cast<int>(s.spec.slaveNodes[k] * kDim + c);
          const auto md = static_cast<int>(*m * kDim + d);
          rows[static_cast<std::size_t>(sc)].push_back(md);
          rows[static_cast<std::size_t>(md)].push_back(sc);
        }
  std::size_t entries = 0;
  for (auto& row : rows) {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    entries += row.size();
  }
  return entries;
}

}  // namespace

int main() {
  std::printf("%10s %10s | %14s %10s | %12s %10s %10s %8s\n", "slaves", "masters", "before_nnz", "before_s",
              "after_nnz", "search_s", "total_s", "ratio");
  for (int side : {32, 100, 317}) {  // ≈ 10^3, 10^4, 10^5 slave nodes
    const Surface s = makeSurface(side);
    const std::vector<char> all(s.spec.slaveNodes.size(), 1);
    const std::size_t masters = static_cast<std::size_t>(side + 1) * (side + 1);
    const std::size_t beforeEntries = 2 * kDim * kDim * s.spec.slaveNodes.size() * masters;
    double beforeSeconds = -1;
    if (beforeEntries <= 50'000'000) {  // ~0.2 GB of column indices before sorting
      const auto start = std::chrono::steady_clock::now();
      auto automatic = s.spec;  // automatic reach with no size limit: the whole surface
      automatic.searchReach = -1.0;
      const auto wholeReservation = cc::reserveCouplings(automatic, s.X, all, static_cast<std::size_t>(-1));
      const std::size_t entries = fillRows(s, wholeReservation);
      beforeSeconds = seconds(start);
      if (entries != beforeEntries) std::printf("(before: %zu entries counted)\n", entries);
    }
    auto start = std::chrono::steady_clock::now();
    const auto r = cc::reserveCouplings(s.spec, s.X, all);
    const double searchSeconds = seconds(start);
    const std::size_t afterEntries = fillRows(s, r);
    const double totalSeconds = seconds(start);
    char before[32];
    if (beforeSeconds >= 0)
      std::snprintf(before, sizeof before, "%10.3f", beforeSeconds);
    else
      std::snprintf(before, sizeof before, "%10s", "(no mem)");
    std::printf("%10zu %10zu | %14zu %s | %12zu %10.3f %10.3f %8.1f\n", s.spec.slaveNodes.size(), masters,
                beforeEntries, before, afterEntries, searchSeconds, totalSeconds,
                double(beforeEntries) / double(afterEntries));
  }
  return 0;
}
