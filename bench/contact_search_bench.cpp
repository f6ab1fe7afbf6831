// contact_search_bench: wall-clock time of the global contact search (BoundingBoxTree) for 10^4, 10^5
// and 10^6 slave nodes, in 2D against a master curve with as many segments and in 3D against a wavy
// master surface with as many quadrilaterals, and the brute-force time for the smallest size. Not a
// test; run it by hand:
//   build/bin/contact_search_bench
// It prints one line per dimension and size: build and query times, candidates per node, tree nodes
// tested per query.
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

double wave(double x) { return 0.2 * std::sin(0.3 * x); }

// The master surface and the slave nodes near it, for n slave nodes and about n facets, facet size h.
template <int Dim>
struct Scene {
  static constexpr int kFacetNodes = Dim == 2 ? 2 : 4;
  std::vector<cc::Vector<Dim>> masterNodes, slaves;
  std::vector<std::array<int, kFacetNodes>> facets;
  double h = 0;
};

// 2D: a curve of n segments along x; slave nodes at the segment midpoints, jittered off the curve.
Scene<2> curve(int n, std::mt19937& rng) {
  Scene<2> s;
  const double length = 100.0;
  s.h = length / n;
  for (int i = 0; i <= n; ++i) s.masterNodes.push_back({length - i * s.h, wave(length - i * s.h)});
  for (int i = 0; i < n; ++i) s.facets.push_back({i, i + 1});
  std::uniform_real_distribution<double> jitter(-0.25 * s.h, 0.25 * s.h);
  for (int i = 0; i < n; ++i) {
    const double x = (i + 0.5) * s.h;
    s.slaves.push_back({x, wave(x) + jitter(rng)});
  }
  return s;
}

// 3D: a k × k grid of quadrilaterals (k² ≈ n) on z = wave(x) + wave(y); slave nodes at the face centres,
// jittered in all three directions.
Scene<3> surface(int n, std::mt19937& rng) {
  Scene<3> s;
  const int k = static_cast<int>(std::lround(std::sqrt(static_cast<double>(n))));
  const double length = 100.0;
  s.h = length / k;
  for (int j = 0; j <= k; ++j)
    for (int i = 0; i <= k; ++i) {
      const double x = i * s.h, y = j * s.h;
      s.masterNodes.push_back({x, y, wave(x) + wave(y)});
    }
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      const int a = j * (k + 1) + i;
      s.facets.push_back({a, a + 1, a + k + 2, a + k + 1});
    }
  std::uniform_real_distribution<double> jitter(-0.25 * s.h, 0.25 * s.h);
  for (int j = 0; j < k; ++j)
    for (int i = 0; i < k; ++i) {
      const double x = (i + 0.5) * s.h + jitter(rng), y = (j + 0.5) * s.h + jitter(rng);
      s.slaves.push_back({x, y, wave(x) + wave(y) + jitter(rng)});
    }
  return s;
}

template <int Dim>
void measure(const Scene<Dim>& s, bool bruteForce) {
  const auto start = std::chrono::steady_clock::now();
  const auto boxes = cc::facetBoundingBoxes<Dim, Scene<Dim>::kFacetNodes>(s.masterNodes, s.facets, 0.5 * s.h);
  const cc::BoundingBoxTree<Dim> tree(boxes);
  const double build = seconds(start);
  const auto queryStart = std::chrono::steady_clock::now();
  std::size_t visited = 0;
  const cc::CandidateLists lists = tree.query(s.slaves, &visited);
  const double query = seconds(queryStart);
  const double n = static_cast<double>(s.slaves.size());
  std::printf("%4d %10zu %10zu %12.4f %12.4f %12.4f %14.2f %16.1f\n", Dim, s.slaves.size(), s.facets.size(), build,
              query, build + query, static_cast<double>(lists.items.size()) / n, static_cast<double>(visited) / n);
  if (!bruteForce) return;
  const auto bruteStart = std::chrono::steady_clock::now();
  std::size_t hits = 0;
  for (const auto& p : s.slaves)
    for (const auto& b : boxes) hits += b.contains(p) ? 1 : 0;
  std::printf("%4d %10zu %10zu %12s %12.4f %12s %14.2f %16s   (brute force O(n m))\n", Dim, s.slaves.size(),
              s.facets.size(), "-", seconds(bruteStart), "-", static_cast<double>(hits) / n, "-");
}

}  // namespace

int main() {
  std::printf("%4s %10s %10s %12s %12s %12s %14s %16s\n", "dim", "slaves", "facets", "build_s", "query_s", "total_s",
              "cand/slave", "visits/query");
  std::mt19937 rng(1);
  for (int n : {10000, 100000, 1000000}) measure(curve(n, rng), n == 10000);
  for (int n : {10000, 100000, 1000000}) measure(surface(n, rng), n == 10000);
  return 0;
}
