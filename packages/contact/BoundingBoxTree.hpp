#pragma once
// Global contact search: an axis-aligned bounding-box tree over the master facets. Each master facet's
// box is enlarged by a search distance; a slave node's candidates are the facets whose enlarged box
// contains it. Building sorts the boxes by the Morton (Z-order) code of their centres (a radix sort,
// O(m)) and splits the sorted range recursively at the codes' highest differing bit (a linear BVH);
// a query is O(log m + k), so n slave nodes against m facets cost O((n + m) log m) instead of the
// brute-force O(n·m). The tree only filters: a box is a candidate exactly when it contains the point,
// whatever the tree's shape. The local choice among the candidates is FacetSelector's job.
#include "contact/SmallMatrix.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace contessa::contact {

/// Closed axis-aligned box in Dim = 2 or 3 dimensions. Default-constructed boxes are empty.
template <int Dim>
struct BoundingBox {
  Vector<Dim> lower = filled(std::numeric_limits<double>::infinity());
  Vector<Dim> upper = filled(-std::numeric_limits<double>::infinity());

  void include(const Vector<Dim>& point) {
    for (int d = 0; d < Dim; ++d) {
      lower[d] = point[d] < lower[d] ? point[d] : lower[d];
      upper[d] = point[d] > upper[d] ? point[d] : upper[d];
    }
  }
  void merge(const BoundingBox& box) {
    include(box.lower);
    include(box.upper);
  }
  /// Grows the box by `distance` on every side (the search distance).
  void enlarge(double distance) {
    for (int d = 0; d < Dim; ++d) {
      lower[d] -= distance;
      upper[d] += distance;
    }
  }
  // Both tests evaluate every comparison (& and |, not && and ||): one unpredictable branch instead of
  // up to 2·Dim, as the search tests about log2(m) boxes per query that pass or fail at random.
  bool contains(const Vector<Dim>& point) const {
    bool outside = false;
    for (int d = 0; d < Dim; ++d) outside |= (point[d] < lower[d]) | (point[d] > upper[d]);
    return !outside;
  }
  /// The two closed boxes share at least one point.
  bool intersects(const BoundingBox& box) const {
    bool apart = false;
    for (int d = 0; d < Dim; ++d) apart |= (box.upper[d] < lower[d]) | (box.lower[d] > upper[d]);
    return !apart;
  }
  Vector<Dim> center() const { return scaled(0.5, add(lower, upper)); }

 private:
  static Vector<Dim> filled(double value) {
    Vector<Dim> v{};
    v.fill(value);
    return v;
  }
};

/// Candidates of many query points in compressed rows: those of point i are
/// items[offsets[i]] … items[offsets[i + 1] − 1], in ascending order.
struct CandidateLists {
  std::vector<std::size_t> offsets{0};
  std::vector<int> items;

  std::size_t numPoints() const { return offsets.size() - 1; }
  std::size_t count(std::size_t point) const { return offsets[point + 1] - offsets[point]; }
  const int* begin(std::size_t point) const { return items.data() + offsets[point]; }
  const int* end(std::size_t point) const { return items.data() + offsets[point + 1]; }
};

template <int Dim>
class BoundingBoxTree {
 public:
  /// Builds the tree over `boxes` (facet i has box i, already enlarged by the search distance).
  explicit BoundingBoxTree(std::vector<BoundingBox<Dim>> boxes, int leafSize = 4);

  /// Appends the indices of the boxes containing `point` to `hits`, sorted ascending.
  /// `visitedNodes`, when given, is incremented by the number of tree nodes tested.
  void query(const Vector<Dim>& point, std::vector<int>& hits, std::size_t* visitedNodes = nullptr) const;

  /// Candidates of every point.
  CandidateLists query(const std::vector<Vector<Dim>>& points, std::size_t* visitedNodes = nullptr) const;

  /// Appends the indices of the boxes that intersect `box` to `hits`, sorted ascending (swept boxes of
  /// the tunnelling check: a node's path against the facets' motion).
  void queryBox(const BoundingBox<Dim>& box, std::vector<int>& hits, std::size_t* visitedNodes = nullptr) const;

  std::size_t numBoxes() const { return boxes_.size(); }
  std::size_t numTreeNodes() const { return nodes_.size(); }
  int depth() const { return depth_; }

 private:
  struct Node {
    BoundingBox<Dim> box;
    int left = -1;  ///< child indices, −1 for a leaf
    int right = -1;
    int begin = 0;  ///< leaf: boxes_[begin, end), whose indices are order_[begin, end)
    int end = 0;
  };

  /// Builds the subtree over boxes_[begin, end), whose sorted Morton codes are codes[begin, end).
  int build(const std::vector<std::uint64_t>& codes, int begin, int end, int level);
  /// Depth-first search for the boxes a predicate accepts (on tree nodes and on items alike).
  template <class Accepts>
  void search(const Accepts& accepts, std::vector<int>& hits, std::size_t* visitedNodes) const;

  std::vector<BoundingBox<Dim>> boxes_;  ///< in tree order: a leaf holds boxes_[begin, end)
  std::vector<int> order_;               ///< the constructor's index of each box of boxes_
  std::vector<Node> nodes_;
  int leafSize_;
  int depth_ = 0;
};

extern template class BoundingBoxTree<2>;
extern template class BoundingBoxTree<3>;

/// Bounding boxes of master facets (2-node segments, 4-node faces), each enlarged by `searchDistance`.
template <int Dim, int NodesPerFacet>
std::vector<BoundingBox<Dim>> facetBoundingBoxes(const std::vector<Vector<Dim>>& nodeCoordinates,
                                                 const std::vector<std::array<int, NodesPerFacet>>& facets,
                                                 double searchDistance) {
  std::vector<BoundingBox<Dim>> boxes(facets.size());
  for (std::size_t f = 0; f < facets.size(); ++f) {
    for (int node : facets[f]) boxes[f].include(nodeCoordinates[static_cast<std::size_t>(node)]);
    boxes[f].enlarge(searchDistance);
  }
  return boxes;
}

}  // namespace contessa::contact
