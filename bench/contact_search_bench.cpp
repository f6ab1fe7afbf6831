// contact_search_bench: wall-clock time of the global contact search (BoundingBoxTree) for 10^4, 10^5
// and 10^6 slave nodes against a master curve with as many segments, and the brute-force time for the
// smallest size. Not a test; run it by hand:
//   build/bin/contact_search_bench
// It prints one line per size: build and query times, candidates per node, tree nodes tested per query.
#include "contact/BoundingBoxTree.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

namespace cc = contessa::contact;

namespace {

double seconds(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main() {
  std::printf("%10s %10s %12s %12s %12s %14s %16s\n", "slaves", "segments", "build_s", "query_s", "total_s",
              "cand/slave", "visits/query");
  for (int n : {10000, 100000, 1000000}) {
    const double length = 100.0;
    const double h = length / n;
    std::vector<cc::Vector<2>> masterNodes;
    masterNodes.reserve(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i <= n; ++i) {
      const double x = length - i * h;
      masterNodes.push_back({x, 0.2 * std::sin(0.3 * x)});
    }
    std::vector<std::array<int, 2>> segments;
    segments.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) segments.push_back({i, i + 1});
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> jitter(-0.25 * h, 0.25 * h);
    std::vector<cc::Vector<2>> slaves;
    slaves.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      const double x = (i + 0.5) * h;
      slaves.push_back({x, 0.2 * std::sin(0.3 * x) + jitter(rng)});
    }

    const auto start = std::chrono::steady_clock::now();
    const auto boxes = cc::facetBoundingBoxes<2, 2>(masterNodes, segments, 0.5 * h);
    const cc::BoundingBoxTree<2> tree(boxes);
    const double build = seconds(start);
    const auto queryStart = std::chrono::steady_clock::now();
    std::size_t visited = 0;
    const cc::CandidateLists lists = tree.query(slaves, &visited);
    const double query = seconds(queryStart);
    std::printf("%10d %10d %12.4f %12.4f %12.4f %14.2f %16.1f\n", n, n, build, query, build + query,
                static_cast<double>(lists.items.size()) / n, static_cast<double>(visited) / n);

    if (n == 10000) {
      const auto bruteStart = std::chrono::steady_clock::now();
      std::size_t hits = 0;
      for (const auto& p : slaves)
        for (const auto& b : boxes) hits += b.contains(p) ? 1 : 0;
      std::printf("%10d %10d %12s %12.4f %12s %14.2f %16s   (brute force O(n m))\n", n, n, "-", seconds(bruteStart),
                  "-", static_cast<double>(hits) / n, "-");
    }
  }
  return 0;
}
