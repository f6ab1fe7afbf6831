// Global contact search: the bounding-box tree must return exactly the brute-force candidate sets.
#include "contact/BoundingBoxTree.hpp"

#include <gtest/gtest.h>

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

}  // namespace

TEST(BoundingBoxTree, RandomSegments2DGiveTheBruteForceCandidates) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> offset(-0.05, 0.05);
  std::vector<Vector<2>> nodes;
  std::vector<std::array<int, 2>> segments;
  for (int s = 0; s < 500; ++s) {
    const Vector<2> a{unit(rng), unit(rng)};
    nodes.push_back(a);
    nodes.push_back({a[0] + offset(rng), a[1] + offset(rng)});
    segments.push_back({2 * s, 2 * s + 1});
  }
  const auto boxes = cc::facetBoundingBoxes<2, 2>(nodes, segments, 0.01);
  std::vector<Vector<2>> points;
  for (int p = 0; p < 3000; ++p) points.push_back({unit(rng), unit(rng)});
  expectSameAsBruteForce<2>(boxes, points);
}

TEST(BoundingBoxTree, RandomQuadFaces3DGiveTheBruteForceCandidates) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_real_distribution<double> offset(-0.08, 0.08);
  std::vector<Vector<3>> nodes;
  std::vector<std::array<int, 4>> faces;
  for (int f = 0; f < 400; ++f) {
    const Vector<3> c{unit(rng), unit(rng), unit(rng)};
    for (int k = 0; k < 4; ++k) nodes.push_back({c[0] + offset(rng), c[1] + offset(rng), c[2] + offset(rng)});
    faces.push_back({4 * f, 4 * f + 1, 4 * f + 2, 4 * f + 3});
  }
  const auto boxes = cc::facetBoundingBoxes<3, 4>(nodes, faces, 0.02);
  std::vector<Vector<3>> points;
  for (int p = 0; p < 3000; ++p) points.push_back({unit(rng), unit(rng), unit(rng)});
  expectSameAsBruteForce<3>(boxes, points);
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
  EXPECT_LE(tree.depth(), 16);  // balanced: ⌈log2(10^5 / 4)⌉ + 1 = 16
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
