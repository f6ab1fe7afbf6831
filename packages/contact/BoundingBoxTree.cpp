#include "contact/BoundingBoxTree.hpp"

#include <algorithm>
#include <cassert>
#include <numeric>

namespace contessa::contact {

template <int Dim>
BoundingBoxTree<Dim>::BoundingBoxTree(std::vector<BoundingBox<Dim>> boxes, int leafSize)
    : boxes_(std::move(boxes)), leafSize_(std::max(1, leafSize)) {
  centers_.reserve(boxes_.size());
  for (const auto& box : boxes_) centers_.push_back(box.center());
  order_.resize(boxes_.size());
  std::iota(order_.begin(), order_.end(), 0);
  if (!boxes_.empty()) {
    nodes_.reserve(2 * boxes_.size() / static_cast<std::size_t>(leafSize_) + 1);
    build(0, static_cast<int>(boxes_.size()), 1);
  }
  assert(depth_ < 120 && "query stack holds 128 entries; a median-split tree has depth log2(m)");
}

// Top-down median split along the longest extent of the box centres: balanced, depth ⌈log2(m/leaf)⌉,
// and nth_element keeps each level O(m), so the build is O(m log m).
template <int Dim>
int BoundingBoxTree<Dim>::build(int begin, int end, int level) {
  depth_ = std::max(depth_, level);
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  BoundingBox<Dim> box;
  BoundingBox<Dim> centerBox;
  for (int k = begin; k < end; ++k) {
    box.merge(boxes_[static_cast<std::size_t>(order_[static_cast<std::size_t>(k)])]);
    centerBox.include(centers_[static_cast<std::size_t>(order_[static_cast<std::size_t>(k)])]);
  }
  nodes_[static_cast<std::size_t>(index)].box = box;
  if (end - begin <= leafSize_) {
    nodes_[static_cast<std::size_t>(index)].begin = begin;
    nodes_[static_cast<std::size_t>(index)].end = end;
    return index;
  }
  int axis = 0;
  for (int d = 1; d < Dim; ++d)
    if (centerBox.upper[d] - centerBox.lower[d] > centerBox.upper[axis] - centerBox.lower[axis]) axis = d;
  const int middle = begin + (end - begin) / 2;
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end, [&](int a, int b) {
    return centers_[static_cast<std::size_t>(a)][axis] < centers_[static_cast<std::size_t>(b)][axis];
  });
  const int left = build(begin, middle, level + 1);
  const int right = build(middle, end, level + 1);
  nodes_[static_cast<std::size_t>(index)].left = left;
  nodes_[static_cast<std::size_t>(index)].right = right;
  return index;
}

template <int Dim>
template <class Accepts>
void BoundingBoxTree<Dim>::search(const Accepts& accepts, std::vector<int>& hits, std::size_t* visitedNodes) const {
  if (nodes_.empty()) return;
  const std::size_t first = hits.size();
  // Depth-first with an explicit stack; the tree is balanced, so depth_ + 1 entries suffice.
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  std::size_t visited = 0;
  while (top > 0) {
    const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
    ++visited;
    if (!accepts(node.box)) continue;
    if (node.left < 0) {
      for (int k = node.begin; k < node.end; ++k) {
        const int item = order_[static_cast<std::size_t>(k)];
        if (accepts(boxes_[static_cast<std::size_t>(item)])) hits.push_back(item);
      }
    } else {
      stack[top++] = node.right;
      stack[top++] = node.left;
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
