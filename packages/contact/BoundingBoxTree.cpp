#include "contact/BoundingBoxTree.hpp"

#include <algorithm>
#include <cassert>
#include <numeric>

namespace contessa::contact {

template <int Dim>
BoundingBoxTree<Dim>::BoundingBoxTree(std::vector<BoundingBox<Dim>> boxes, int leafSize)
    : leafSize_(std::max(1, leafSize)) {
  // The build moves the boxes themselves (with their centres and ids), not indices into them, so every
  // level reads memory in order; the boxes then stay in tree order, a leaf's boxes side by side.
  std::vector<Item> items(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) items[i] = {boxes[i], boxes[i].center(), static_cast<int>(i)};
  boxes.clear();
  boxes.shrink_to_fit();
  if (!items.empty()) {
    nodes_.reserve(2 * items.size() / static_cast<std::size_t>(leafSize_) + 1);
    build(items, 0, static_cast<int>(items.size()), 1);
  }
  boxes_.reserve(items.size());
  order_.reserve(items.size());
  for (const auto& item : items) {
    boxes_.push_back(item.box);
    order_.push_back(item.id);
  }
  assert(depth_ < 120 && "query stack holds 128 entries; a median-split tree has depth log2(m)");
}

// Top-down median split along the longest extent of the box centres: balanced, depth ⌈log2(m/leaf)⌉,
// and nth_element keeps each level O(m), so the build is O(m log m).
template <int Dim>
int BoundingBoxTree<Dim>::build(std::vector<Item>& items, int begin, int end, int level) {
  depth_ = std::max(depth_, level);
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  if (end - begin <= leafSize_) {
    BoundingBox<Dim> box;
    for (int k = begin; k < end; ++k) box.merge(items[static_cast<std::size_t>(k)].box);
    nodes_[static_cast<std::size_t>(index)].box = box;
    nodes_[static_cast<std::size_t>(index)].begin = begin;
    nodes_[static_cast<std::size_t>(index)].end = end;
    return index;
  }
  BoundingBox<Dim> centerBox;
  for (int k = begin; k < end; ++k) centerBox.include(items[static_cast<std::size_t>(k)].center);
  int axis = 0;
  for (int d = 1; d < Dim; ++d)
    if (centerBox.upper[d] - centerBox.lower[d] > centerBox.upper[axis] - centerBox.lower[axis]) axis = d;
  const int middle = begin + (end - begin) / 2;
  std::nth_element(items.begin() + begin, items.begin() + middle, items.begin() + end,
                   [axis](const Item& a, const Item& b) { return a.center[axis] < b.center[axis]; });
  const int left = build(items, begin, middle, level + 1);
  const int right = build(items, middle, end, level + 1);
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
      for (int k = node.begin; k < node.end; ++k)
        if (accepts(boxes_[static_cast<std::size_t>(k)])) hits.push_back(order_[static_cast<std::size_t>(k)]);
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
