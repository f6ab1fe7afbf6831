// Global contact search: the bounding-box tree must return exactly the brute-force candidate sets.
#include "contact/BoundingBoxTree.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <vector>

namespace cc = contessa::contact;
using cc::Vector;

namespace {

template <int Dim>
std::vector<int> bruteForce(const std::vector<cc::BoundingBox<Dim>>& boxes, const Vector<Dim>& point) {
  std::vector<int> hits;
  for (std::size_t b = 0; b < boxes.size(); ++b)
    if (boxes[b].contains(point)) hits.push_back(static_cast<int>(b));
  return hits;
}

template <int Dim>
void expectSameAsBruteForce(const std::vector<cc::BoundingBox<Dim>>& boxes, const std::vector<Vector<Dim>>& points) {
  const cc::BoundingBoxTree<Dim> tree(boxes);
  const cc::CandidateLists lists = tree.query(points);
  ASSERT_EQ(lists.numPoints(), points.size());
  std::size_t nonEmpty = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::vector<int> fromTree(lists.begin(i), lists.end(i));
    ASSERT_EQ(fromTree, bruteForce(boxes, points[i])) << "point " << i;
    nonEmpty += fromTree.empty() ? 0 : 1;
  }
  // The test is only meaningful if many points have candidates and many have none.
  EXPECT_GT(nonEmpty, points.size() / 10);
  EXPECT_LT(nonEmpty, points.size());
}

// `count` random facets of N nodes in the unit square or cube (`facetNodes(unit, offset)` draws one facet's
// nodes from uniform numbers in [0, 1] and in [-spread, spread]), boxed with `padding` and queried at 3000
// random points: the tree gives the brute-force candidates.
template <int Dim, int N, class FacetNodes>
void expectRandomFacetsGiveBruteForce(unsigned seed, int count, double spread, double padding,
                                      const FacetNodes& facetNodes) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unitDistribution(0.0, 1.0);
  std::uniform_real_distribution<double> offsetDistribution(-spread, spread);
  const auto unit = [&] { return unitDistribution(rng); };
  const auto offset = [&] { return offsetDistribution(rng); };
  std::vector<Vector<Dim>> nodes;
  std::vector<std::array<int, N>> facets;
  for (int f = 0; f < count; ++f) {
    const std::array<Vector<Dim>, N> x = facetNodes(unit, offset);
    std::array<int, N> ids;
    for (int k = 0; k < N; ++k) {
      ids[k] = N * f + k;
      nodes.push_back(x[k]);
    }
    facets.push_back(ids);
  }
  const auto boxes = cc::facetBoundingBoxes<Dim, N>(nodes, facets, padding);
  std::vector<Vector<Dim>> points(3000);
  for (auto& point : points)
    for (auto& c : point) c = unit();
  expectSameAsBruteForce<Dim>(boxes, points);
}

}  // namespace

TEST(BoundingBoxTree, RandomSegments2DGiveTheBruteForceCandidates) {
  // 500 short segments: a random node and another within 0.05 of it in x and y.
  expectRandomFacetsGiveBruteForce<2, 2>(42, 500, 0.05, 0.01, [](const auto& unit, const auto& offset) {
    const Vector<2> a{unit(), unit()};
    return std::array<Vector<2>, 2>{a, Vector<2>{a[0] + offset(), a[1] + offset()}};
  });
}

TEST(BoundingBoxTree, RandomQuadFaces3DGiveTheBruteForceCandidates) {
  // 400 small faces: four nodes within 0.08 of a random centre in each direction.
  expectRandomFacetsGiveBruteForce<3, 4>(7, 400, 0.08, 0.02, [](const auto& unit, const auto& offset) {
    const Vector<3> c{unit(), unit(), unit()};
    std::array<Vector<3>, 4> x;
    for (auto& node : x) node = {c[0] + offset(), c[1] + offset(), c[2] + offset()};
    return x;
  });
}

TEST(BoundingBoxTree, BoxBoundaryIsClosedAndEmptyTreeHasNoCandidates) {
  std::vector<cc::BoundingBox<2>> boxes(1);
  boxes[0].include({0.0, 0.0});
  boxes[0].include({1.0, 1.0});
  const cc::BoundingBoxTree<2> tree(boxes);
  std::vector<int> hits;
  tree.query({1.0, 0.5}, hits);
  EXPECT_EQ(hits, std::vector<int>{0});
  hits.clear();
  tree.query({1.0 + 1e-12, 0.5}, hits);
  EXPECT_TRUE(hits.empty());

  const cc::BoundingBoxTree<2> empty(std::vector<cc::BoundingBox<2>>{});
  const auto lists = empty.query(std::vector<Vector<2>>{{0.0, 0.0}, {1.0, 1.0}});
  EXPECT_EQ(lists.numPoints(), 2u);
  EXPECT_TRUE(lists.items.empty());
}

// 10^5 slave nodes against a master curve of 10^5 segments. The cost is checked by counting the tree
// nodes a query tests (deterministic), not by timing: O(log m) per query instead of the m of brute force.
// Wall-clock figures come from the contact_search_bench executable.
TEST(BoundingBoxTree, ScalesAsNLogNOnA100kNodeSurface) {
  constexpr int kSegments = 100000;
  constexpr double kLength = 100.0;
  const double h = kLength / kSegments;
  std::vector<Vector<2>> masterNodes;
  for (int i = 0; i <= kSegments; ++i) {
    const double x = kLength - i * h;  // counter-clockwise top of a body: right to left
    masterNodes.push_back({x, 0.2 * std::sin(0.3 * x)});
  }
  std::vector<std::array<int, 2>> segments;
  for (int i = 0; i < kSegments; ++i) segments.push_back({i, i + 1});
  const auto boxes = cc::facetBoundingBoxes<2, 2>(masterNodes, segments, 0.5 * h);

  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.25 * h, 0.25 * h);
  std::vector<Vector<2>> slaves;
  for (int i = 0; i < kSegments; ++i) {
    const double x = (i + 0.5) * h;
    slaves.push_back({x, 0.2 * std::sin(0.3 * x) + jitter(rng)});
  }

  const cc::BoundingBoxTree<2> tree(boxes);
  // Nearly balanced: ⌈log2(10^5 / 4)⌉ + 1 = 16 for median splits; the Morton splits follow the quadtree's
  // cells, which the curve fills unevenly.
  EXPECT_LE(tree.depth(), 19);
  std::size_t visited = 0;
  const cc::CandidateLists lists = tree.query(slaves, &visited);
  const double log2m = std::log2(static_cast<double>(kSegments));
  EXPECT_LT(static_cast<double>(visited) / kSegments, 6.0 * log2m);  // brute force would test 10^5
  std::size_t total = 0;
  for (std::size_t i = 0; i < lists.numPoints(); ++i) {
    ASSERT_GE(lists.count(i), 1u) << "slave " << i << " lost its segment";
    EXPECT_LE(lists.count(i), 6u);
    total += lists.count(i);
  }
  EXPECT_LT(total, 4u * kSegments);
  // Spot-check against brute force.
  for (std::size_t i = 0; i < slaves.size(); i += 997) {
    const std::vector<int> fromTree(lists.begin(i), lists.end(i));
    EXPECT_EQ(fromTree, bruteForce<2>(boxes, slaves[i])) << "slave " << i;
  }
}

// Box queries (the swept boxes of the tunnelling check) return exactly the boxes that intersect.
TEST(BoundingBoxTree, BoxQueryMatchesBruteForce) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 100.0), size(0.0, 3.0);
  std::vector<cc::BoundingBox<2>> boxes(2000);
  for (auto& b : boxes) {
    const Vector<2> p{u(rng), u(rng)};
    b.include(p);
    b.include({p[0] + size(rng), p[1] + size(rng)});
  }
  const cc::BoundingBoxTree<2> tree(boxes);
  std::size_t total = 0;
  for (int q = 0; q < 500; ++q) {
    cc::BoundingBox<2> query;
    const Vector<2> p{u(rng), u(rng)};
    query.include(p);
    query.include({p[0] + 2 * size(rng), p[1] + 2 * size(rng)});
    std::vector<int> hits, expected;
    tree.queryBox(query, hits);
    for (std::size_t b = 0; b < boxes.size(); ++b)
      if (boxes[b].intersects(query)) expected.push_back(static_cast<int>(b));
    ASSERT_EQ(hits, expected) << "query " << q;
    total += hits.size();
  }
  EXPECT_GT(total, 500u);  // the queries do find boxes
}

// The Morton-ordered build must not change any answer: point and box queries against brute force on
// structured surfaces (where many centres share coordinates and boxes touch exactly), flat and
// degenerate boxes, duplicated boxes, and points on box faces.
namespace {

template <int Dim>
void expectBoxQueriesMatchBruteForce(const std::vector<cc::BoundingBox<Dim>>& boxes,
                                     const std::vector<cc::BoundingBox<Dim>>& queries) {
  const cc::BoundingBoxTree<Dim> tree(boxes);
  std::size_t total = 0;
  for (std::size_t q = 0; q < queries.size(); ++q) {
    std::vector<int> hits, expected;
    tree.queryBox(queries[q], hits);
    for (std::size_t b = 0; b < boxes.size(); ++b)
      if (boxes[b].intersects(queries[q])) expected.push_back(static_cast<int>(b));
    ASSERT_EQ(hits, expected) << "box query " << q;
    total += hits.size();
  }
  EXPECT_GT(total, queries.size());
}

// A k × k grid of unit quadrilaterals on z = 0 (flat boxes: zero height before the enlargement), each
// face listed twice (duplicates: equal centres, equal Morton codes).
std::vector<cc::BoundingBox<3>> gridFaceBoxes(int k, double enlarge) {
  std::vector<cc::BoundingBox<3>> boxes;
  for (int copy = 0; copy < 2; ++copy)
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < k; ++i) {
        cc::BoundingBox<3> b;
        b.include({double(i), double(j), 0.0});
        b.include({double(i + 1), double(j + 1), 0.0});
        b.enlarge(enlarge);
        boxes.push_back(b);
      }
  return boxes;
}

}  // namespace

TEST(BoundingBoxTree, StructuredFlatGrid3DWithDuplicatesGivesTheBruteForceCandidates) {
  for (double enlarge : {0.0, 0.25}) {
    const auto boxes = gridFaceBoxes(23, enlarge);  // 23 is not a power of two: cells straddle Morton cells
    std::vector<Vector<3>> points;
    // Grid vertices and edge midpoints (on the faces of up to 4 boxes, each twice), centres, and points
    // just above and below the plane.
    for (int j = 0; j <= 46; ++j)
      for (int i = 0; i <= 46; ++i)
        for (double z : {0.0, 0.1, -0.3, 1e-13}) points.push_back({0.5 * i, 0.5 * j, z});
    for (int p = 0; p < 40; ++p) points.push_back({-0.5 + 0.01 * p, 3.0, 0.0});  // off the grid's edge
    expectSameAsBruteForce<3>(boxes, points);
  }
}

TEST(BoundingBoxTree, StructuredCurve2DWithFlatAndPointBoxesGivesTheBruteForceCandidates) {
  // Horizontal and vertical segments (flat boxes, no enlargement), zero-length segments (point boxes)
  // and repeated segments: a staircase.
  std::vector<Vector<2>> nodes;
  std::vector<std::array<int, 2>> segments;
  for (int s = 0; s < 300; ++s) {
    nodes.push_back({double(s / 2 + s % 2), double(s / 2)});
    if (s > 0) segments.push_back({s - 1, s});
    if (s % 7 == 0) segments.push_back({s, s});                  // point box
    if (s % 5 == 0 && s > 0) segments.push_back({s - 1, s});    // duplicate
  }
  const auto boxes = cc::facetBoundingBoxes<2, 2>(nodes, segments, 0.0);
  std::vector<Vector<2>> points;  // a half-unit lattice around the staircase: on and off its boxes
  for (const auto& node : nodes)
    for (int j = -2; j <= 2; ++j)
      for (int i = -2; i <= 2; ++i) points.push_back({node[0] + 0.5 * i, node[1] + 0.5 * j});
  expectSameAsBruteForce<2>(boxes, points);
}

TEST(BoundingBoxTree, AllBoxesEqualOrEmptyGiveTheBruteForceCandidates) {
  // Every centre equal (one Morton code for all): the build halves by index; with empty boxes (no
  // points, non-finite centres) mixed in, they match nothing.
  std::vector<cc::BoundingBox<3>> boxes(500);
  for (std::size_t b = 0; b < boxes.size(); ++b) {
    if (b % 3 == 0) continue;  // empty
    boxes[b].include({0.0, 0.0, 0.0});
    boxes[b].include({1.0, 1.0, 1.0});
  }
  const cc::BoundingBoxTree<3> tree(boxes);
  EXPECT_LE(tree.depth(), 10);  // ⌈log2(500 / 4)⌉ + 1 = 8: equal codes are halved, not chained
  std::vector<Vector<3>> points{{0.5, 0.5, 0.5}, {1.0, 1.0, 1.0}, {0.0, 0.5, 1.0}, {1.5, 0.5, 0.5}};
  for (const auto& p : points) {
    std::vector<int> hits;
    tree.query(p, hits);
    EXPECT_EQ(hits, bruteForce<3>(boxes, p));
  }
  std::vector<int> hits;
  tree.query({0.5, 0.5, 0.5}, hits);
  EXPECT_EQ(hits.size(), 333u);
}

TEST(BoundingBoxTree, WidelySpreadAndClusteredBoxesGiveTheBruteForceCandidates) {
  // Clusters 10^6 apart holding boxes 10^-6 wide: most boxes share their leading Morton bits, so the
  // tree is deep; it must stay within the query stack and exact.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<cc::BoundingBox<3>> boxes;
  std::vector<Vector<3>> points;
  for (const double scale : {1e6, 1.0, 1e-6}) {
    for (int b = 0; b < 600; ++b) {
      const Vector<3> c{scale * unit(rng), scale * unit(rng), scale * unit(rng)};
      cc::BoundingBox<3> box;
      box.include(c);
      box.include({c[0] + 0.05 * scale * unit(rng), c[1] + 0.05 * scale * unit(rng), c[2]});  // flat in z
      box.enlarge(0.02 * scale);
      boxes.push_back(box);
    }
    for (int p = 0; p < 2000; ++p) points.push_back({scale * unit(rng), scale * unit(rng), scale * unit(rng)});
    for (std::size_t b = boxes.size() - 600; b < boxes.size(); b += 2) points.push_back(boxes[b].center());
  }
  expectSameAsBruteForce<3>(boxes, points);
  EXPECT_LT(cc::BoundingBoxTree<3>(boxes).depth(), 120);
}

TEST(BoundingBoxTree, BoxQueryMatchesBruteForce3DOnAGrid) {
  const auto boxes = gridFaceBoxes(17, 0.1);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 18.0), size(0.0, 2.0), z(-0.3, 0.3);
  std::vector<cc::BoundingBox<3>> queries(400);
  for (auto& q : queries) {
    const Vector<3> p{u(rng), u(rng), z(rng)};
    q.include(p);
    q.include({p[0] + size(rng), p[1] + size(rng), p[2] + 0.1 * size(rng)});
  }
  expectBoxQueriesMatchBruteForce<3>(boxes, queries);
}
