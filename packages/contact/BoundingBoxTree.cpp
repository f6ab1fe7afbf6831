#include "contact/BoundingBoxTree.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

namespace contessa::contact {

namespace {

// Morton (Z-order) codes: the bits of the quantised coordinates interleaved, 31 bits per axis in 2D and
// 21 in 3D (62 and 63 bits). Sorting by them puts boxes that are close in space close in the order, and
// a run of equal leading bits is one cell of a quad- or octree: the tree's nodes are such cells, built
// without the median splits' O(m log m) partitioning.
template <int Dim>
constexpr int kMortonBits = Dim == 2 ? 31 : 21;

// Spreads the low kMortonBits<Dim> bits of v so that Dim − 1 zero bits separate them.
template <int Dim>
std::uint64_t spreadBits(std::uint64_t v) {
  if constexpr (Dim == 2) {
    v &= 0x7fffffffULL;
    v = (v | (v << 16)) & 0x0000ffff0000ffffULL;
    v = (v | (v << 8)) & 0x00ff00ff00ff00ffULL;
    v = (v | (v << 4)) & 0x0f0f0f0f0f0f0f0fULL;
    v = (v | (v << 2)) & 0x3333333333333333ULL;
    v = (v | (v << 1)) & 0x5555555555555555ULL;
  } else {
    v &= 0x1fffffULL;
    v = (v | (v << 32)) & 0x1f00000000ffffULL;
    v = (v | (v << 16)) & 0x1f0000ff0000ffULL;
    v = (v | (v << 8)) & 0x100f00f00f00f00fULL;
    v = (v | (v << 4)) & 0x10c30c30c30c30c3ULL;
    v = (v | (v << 2)) & 0x1249249249249249ULL;
  }
  return v;
}

/// Quantises points in their bounding box to Morton codes. Non-finite coordinates (an empty box's
/// centre) and flat directions map to 0: the codes only order the items, any order gives a valid tree.
template <int Dim>
class MortonEncoder {
 public:
  explicit MortonEncoder(const BoundingBox<Dim>& extent) {
    // One scale for every axis (the extent's cube): scaling each axis to its own width would make a
    // flat surface's thin direction as fine as its long ones and split it first.
    const double cells = static_cast<double>((1ULL << kMortonBits<Dim>) - 1);
    double width = 0;
    for (int d = 0; d < Dim; ++d) {
      origin_[d] = extent.lower[d];
      width = std::max(width, extent.upper[d] - extent.lower[d]);
    }
    scale_ = std::isfinite(width) && width > 0 ? cells / width : 0.0;
  }
  std::uint64_t operator()(const Vector<Dim>& point) const {
    const double cells = static_cast<double>((1ULL << kMortonBits<Dim>) - 1);
    std::uint64_t code = 0;
    for (int d = 0; d < Dim; ++d) {
      double q = (point[d] - origin_[d]) * scale_;
      q = q >= 0 ? (q <= cells ? q : cells) : 0.0;  // also maps NaN to 0
      code |= spreadBits<Dim>(static_cast<std::uint64_t>(q)) << d;
    }
    return code;
  }

 private:
  Vector<Dim> origin_{};
  double scale_ = 0;
};

/// Sorts `codes` ascending and returns the permutation applied, stable (equal codes keep their order, so
/// duplicates are ordered by index): an LSD radix sort, 8 bits per pass (the digits' counts all taken
/// in one read), passes where every code has the same digit skipped. O(m), against the comparison
/// sort's O(m log m). Code and index move together, one store stream per digit value.
std::vector<int> sortInPlace(std::vector<std::uint64_t>& codes) {
  struct Keyed {
    std::uint64_t code;
    int index;
  };
  const std::size_t n = codes.size();
  std::vector<Keyed> items(n), moved(n);
  std::array<std::array<std::size_t, 256>, 8> counts{};
  for (std::size_t i = 0; i < n; ++i) {
    items[i] = {codes[i], static_cast<int>(i)};
    for (int pass = 0; pass < 8; ++pass) ++counts[static_cast<std::size_t>(pass)][(codes[i] >> (8 * pass)) & 0xffU];
  }
  for (int pass = 0; pass < 8; ++pass) {
    auto& count = counts[static_cast<std::size_t>(pass)];
    if (std::any_of(count.begin(), count.end(), [n](std::size_t c) { return c == n; })) continue;
    std::size_t start = 0;
    for (auto& c : count) start += std::exchange(c, start);  // counts → first position of each digit
    for (const Keyed& item : items) moved[count[(item.code >> (8 * pass)) & 0xffU]++] = item;
    items.swap(moved);
  }
  std::vector<int> order(n);
  for (std::size_t i = 0; i < n; ++i) {
    codes[i] = items[i].code;
    order[i] = items[i].index;
  }
  return order;
}

/// The Morton codes of the points pointOf(0 … n − 1), sorted, and the order of the points they come from.
template <int Dim, class PointOf>
std::vector<int> mortonOrder(std::size_t n, const PointOf& pointOf, std::vector<std::uint64_t>& codes) {
  BoundingBox<Dim> extent;
  for (std::size_t i = 0; i < n; ++i) extent.include(pointOf(i));
  const MortonEncoder<Dim> encode(extent);
  codes.resize(n);
  for (std::size_t i = 0; i < n; ++i) codes[i] = encode(pointOf(i));
  return sortInPlace(codes);
}

/// Where the Morton-sorted range [begin, end) splits: at the highest bit in which its first and last
/// codes differ (the first code with that bit set), so each half is one cell of the Z-order's quad- or
/// octree, a compact region (Karras 2012, "Maximizing parallelism in the construction of BVHs"). Equal
/// codes (duplicate or coincident centres) are halved at the middle.
int mortonSplit(const std::vector<std::uint64_t>& codes, int begin, int end) {
  const std::uint64_t first = codes[static_cast<std::size_t>(begin)];
  const std::uint64_t last = codes[static_cast<std::size_t>(end - 1)];
  if (first == last) return begin + (end - begin) / 2;
  std::uint64_t bit = first ^ last;
  while ((bit & (bit - 1)) != 0) bit &= bit - 1;  // keep the highest set bit
  const auto it = std::partition_point(codes.begin() + begin, codes.begin() + end,
                                       [bit](std::uint64_t c) { return (c & bit) == 0; });
  return static_cast<int>(it - codes.begin());
}

}  // namespace

template <int Dim>
BoundingBoxTree<Dim>::BoundingBoxTree(std::vector<BoundingBox<Dim>> boxes, int leafSize)
    : leafSize_(std::max(1, leafSize)) {
  // The boxes are stored in Morton order of their centres, so a leaf's boxes are side by side and
  // every subtree is a contiguous range.
  std::vector<std::uint64_t> codes;
  order_ = mortonOrder<Dim>(boxes.size(), [&boxes](std::size_t i) { return boxes[i].center(); }, codes);
  boxes_.resize(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) boxes_[i] = boxes[static_cast<std::size_t>(order_[i])];
  boxes.clear();
  boxes.shrink_to_fit();
  if (!boxes_.empty()) {
    nodes_.reserve(2 * boxes_.size() / static_cast<std::size_t>(leafSize_) + 1);
    build(codes, 0, static_cast<int>(boxes_.size()), 1);
  }
  assert(depth_ < 120 && "query stack holds 128 entries; the depth is at most 63 + log2(m) + 1");
}

// Splits the Morton-sorted range at its highest differing bit: O(m) after the sort, depth at most the
// code's bits plus log2 of the largest group of equal codes (≤ 63 + 31), about log2(m/leaf) on a
// surface meshed evenly. Nodes are numbered depth-first, a left child right after its parent.
template <int Dim>
int BoundingBoxTree<Dim>::build(const std::vector<std::uint64_t>& codes, int begin, int end, int level) {
  depth_ = std::max(depth_, level);
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  if (end - begin <= leafSize_) {
    BoundingBox<Dim> box;
    for (int k = begin; k < end; ++k) box.merge(boxes_[static_cast<std::size_t>(k)]);
    nodes_[static_cast<std::size_t>(index)].box = box;
    nodes_[static_cast<std::size_t>(index)].begin = begin;
    nodes_[static_cast<std::size_t>(index)].end = end;
    return index;
  }
  const int middle = mortonSplit(codes, begin, end);
  const int left = build(codes, begin, middle, level + 1);
  const int right = build(codes, middle, end, level + 1);
  // An inner node's box is its children's, merged once they are built (no pass over its items).
  BoundingBox<Dim> box = nodes_[static_cast<std::size_t>(left)].box;
  box.merge(nodes_[static_cast<std::size_t>(right)].box);
  nodes_[static_cast<std::size_t>(index)].box = box;
  nodes_[static_cast<std::size_t>(index)].left = left;
  nodes_[static_cast<std::size_t>(index)].right = right;
  return index;
}

template <int Dim>
template <class Accepts>
void BoundingBoxTree<Dim>::search(const Accepts& accepts, std::vector<int>& hits, std::size_t* visitedNodes) const {
  if (nodes_.empty()) return;
  const std::size_t first = hits.size();
  std::size_t visited = 1;
  if (accepts(nodes_[0].box)) {
    // Depth-first with an explicit stack of accepted nodes; a node's children are tested before they
    // are pushed. Each level leaves at most one sibling on the stack, so depth_ + 1 entries suffice.
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
      if (node.left < 0) {
        for (int k = node.begin; k < node.end; ++k)
          if (accepts(boxes_[static_cast<std::size_t>(k)])) hits.push_back(order_[static_cast<std::size_t>(k)]);
        continue;
      }
      visited += 2;
      if (accepts(nodes_[static_cast<std::size_t>(node.right)].box)) stack[top++] = node.right;
      if (accepts(nodes_[static_cast<std::size_t>(node.left)].box)) stack[top++] = node.left;
    }
  }
  std::sort(hits.begin() + static_cast<std::ptrdiff_t>(first), hits.end());
  if (visitedNodes != nullptr) *visitedNodes += visited;
}

template <int Dim>
void BoundingBoxTree<Dim>::query(const Vector<Dim>& point, std::vector<int>& hits, std::size_t* visitedNodes) const {
  search([&](const BoundingBox<Dim>& box) { return box.contains(point); }, hits, visitedNodes);
}

template <int Dim>
void BoundingBoxTree<Dim>::queryBox(const BoundingBox<Dim>& box, std::vector<int>& hits, std::size_t* visitedNodes) const {
  search([&](const BoundingBox<Dim>& b) { return b.intersects(box); }, hits, visitedNodes);
}

template <int Dim>
CandidateLists BoundingBoxTree<Dim>::query(const std::vector<Vector<Dim>>& points, std::size_t* visitedNodes) const {
  CandidateLists lists;
  lists.offsets.reserve(points.size() + 1);
  lists.items.reserve(2 * points.size());
  for (const auto& point : points) {
    query(point, lists.items, visitedNodes);
    lists.offsets.push_back(lists.items.size());
  }
  return lists;
}

template class BoundingBoxTree<2>;
template class BoundingBoxTree<3>;

}  // namespace contessa::contact
