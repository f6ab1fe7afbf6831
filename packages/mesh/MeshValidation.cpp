// Mesh::validate: every mesh, read or generated, is checked here before anything runs, so that a
// bad mesh is one line naming the file and the entity instead of a solver that silently fails
// (a NaN coordinate or a clockwise element otherwise ends as "maximum number of steps reached").
// Every check is one pass over the mesh (the side-set check sorts the side-set sides): O(n log n).
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "common/Error.hpp"
#include "mesh/CellGeometry.hpp"
#include "mesh/Mesh.hpp"
#include "mesh/ShapeFunctions.hpp"

namespace contessa::mesh {

namespace {

// A corner whose scaled Jacobian (the sine of the corner angle in 2D) is below this counts as
// zero: the element is degenerate there. Round-off in coordinates alone stays orders below it.
constexpr double kDegenerateCorner = 1e-10;

constexpr int kMaxDimension = 3;

// A mid-edge node may sit off the middle of its edge by at most this fraction of the edge's length.
// Along a straight edge the quadratic map's Jacobian vanishes at a corner when its mid-edge node sits
// at the quarter point (the quarter-point element of fracture mechanics, Barsoum 1976), so a shift of
// a quarter or more is never a usable element; across the edge, a quarter is the sagitta of a
// circular arc of 106°, far more curvature than any mesh of a curved face has on one edge. What is
// beyond it is a node order read wrongly (Gmsh's and Exodus's orders differ) or a node misplaced.
constexpr double kMidEdgeTolerance = 0.25;

// Entities are numbered from 1 in messages, as in the Exodus file (and in ParaView's ids).
std::string number(GlobalIndex zeroBased) { return std::to_string(zeroBased + 1); }

// One rank's part of a distributed mesh is checked in its local numbering; its messages name the
// whole mesh's numbers (global ids), which the user's files and ParaView show.
struct Numbering {
  const std::vector<GlobalIndex>* nodes = nullptr;
  const std::vector<GlobalIndex>* elements = nullptr;
  GlobalIndex* badShapes = nullptr;  ///< set: the count of badly shaped elements goes here, not into the message
  std::string node(GlobalIndex n) const {
    return number(nodes && n >= 0 && n < static_cast<GlobalIndex>(nodes->size()) ? (*nodes)[n] : n);
  }
  std::string element(GlobalIndex e) const {
    return number(elements && e >= 0 && e < static_cast<GlobalIndex>(elements->size()) ? (*elements)[e] : e);
  }
};

std::string format(double value) {
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

class Validator {
 public:
  Validator(const Mesh& mesh, const std::string& source, Numbering numbering = {})
      : mesh_(mesh), where_(source + ": "), numbering_(numbering) {}

  void run() {
    structure();
    coordinates();
    elements();
    nodeSets();
    sideSets();
    uniqueNames(mesh_.blocks, "element block");
    uniqueNames(mesh_.nodeSets, "node set");
    uniqueNames(mesh_.sideSets, "side set");
  }

 private:
  void fail(const std::string& message) const { throw InputError(where_ + message); }

  std::string elementName(GlobalIndex e, int block) const {
    return "element " + numbering_.element(e) + " of block '" + mesh_.blocks[block].name + "'";
  }

  // Sizes and ids: what the other checks index by.
  void structure() {
    const int dim = mesh_.dimension;
    if (dim != 2 && dim != 3) fail("mesh dimension must be 2 or 3, got " + std::to_string(dim));
    if (mesh_.coordinates.size() % static_cast<size_t>(dim) != 0)
      fail("coordinate array length " + std::to_string(mesh_.coordinates.size()) +
           " is not a multiple of the dimension " + std::to_string(dim));
    numNodes_ = mesh_.numNodes();
    numElements_ = mesh_.numElements();
    // Every element id 0..numElements-1 must appear in exactly one block: the partition and the
    // results writer index global arrays by it.
    blockOf_.assign(static_cast<size_t>(numElements_), -1);
    localOf_.assign(static_cast<size_t>(numElements_), -1);
    for (int bi = 0; bi < static_cast<int>(mesh_.blocks.size()); ++bi) {
      const auto& b = mesh_.blocks[bi];
      const std::string blk = "element block '" + b.name + "': ";
      if (cellDimension(b.cellType) != dim)
        fail(blk + exodusCellName(b.cellType) + " cells in a " + std::to_string(dim) + "D mesh");
      const size_t npe = static_cast<size_t>(nodesPerCell(b.cellType));
      if (b.connectivity.size() != b.elements.size() * npe)
        fail(blk + "connectivity has " + std::to_string(b.connectivity.size()) + " entries, expected " +
             std::to_string(b.elements.size() * npe));
      for (size_t k = 0; k < b.elements.size(); ++k) {
        const GlobalIndex e = b.elements[k];
        if (e < 0 || e >= numElements_)
          fail(blk + "element id " + std::to_string(e) + " is outside [0, " + std::to_string(numElements_) + ")");
        if (blockOf_[e] >= 0) fail(blk + "element id " + std::to_string(e) + " appears more than once");
        blockOf_[e] = bi;
        localOf_[e] = static_cast<GlobalIndex>(k);
      }
    }
  }

  void coordinates() const {
    const int dim = mesh_.dimension;
    const char* axis[3] = {"x", "y", "z"};
    for (size_t k = 0; k < mesh_.coordinates.size(); ++k)
      if (!std::isfinite(mesh_.coordinates[k]))
        fail("node " + numbering_.node(static_cast<GlobalIndex>(k / dim)) + " has a non-finite coordinate (" +
             axis[k % dim] + " = " + format(mesh_.coordinates[k]) + ")");
  }

  // Connectivity in range, no repeated node, positive corner Jacobians. The first bad element is
  // named; for the Jacobian, the count of all bad elements tells a wholly mirrored mesh from one
  // bad element.
  void elements() const {
    const int dim = mesh_.dimension;
    std::string firstBadShape;
    GlobalIndex badShapes = 0;
    for (int bi = 0; bi < static_cast<int>(mesh_.blocks.size()); ++bi) {
      const auto& b = mesh_.blocks[bi];
      const int npe = nodesPerCell(b.cellType);
      double x[kMaxNodesPerCell * kMaxDimension];
      double jacobian[kMaxShapeCheckPoints];
      for (size_t k = 0; k < b.elements.size(); ++k) {
        const GlobalIndex* nodes = &b.connectivity[k * npe];
        for (int a = 0; a < npe; ++a) {
          if (nodes[a] < 0 || nodes[a] >= numNodes_)
            fail(elementName(b.elements[k], bi) + " refers to node " + numbering_.node(nodes[a]) + ", but the mesh has " +
                 std::to_string(numNodes_) + " nodes");
          for (int c = 0; c < a; ++c)
            if (nodes[c] == nodes[a])
              fail(elementName(b.elements[k], bi) + " lists node " + numbering_.node(nodes[a]) +
                   " twice (a collapsed element): give it " + std::to_string(npe) + " distinct nodes");
          for (int i = 0; i < dim; ++i) x[a * dim + i] = mesh_.coordinates[nodes[a] * dim + i];
        }
        std::string problem = midEdgeProblem(b.cellType, nodes, x);
        if (problem.empty()) problem = shapeProblem(b.cellType, nodes, x, jacobian);
        if (problem.empty()) continue;
        if (badShapes++ == 0) firstBadShape = elementName(b.elements[k], bi) + " " + problem;
      }
    }
    if (badShapes > 0 && numbering_.badShapes != nullptr) {
      *numbering_.badShapes = badShapes;  // the caller counts over every part
      fail(firstBadShape);
    }
    if (badShapes == 1) fail(firstBadShape);
    if (badShapes > 1) fail(firstBadShape + " (" + std::to_string(badShapes) + " elements fail this check)");
  }

  // "" when every mid-edge node lies within kMidEdgeTolerance of its edge's length from the middle of
  // the edge between its corners; otherwise the first that does not.
  std::string midEdgeProblem(CellType type, const GlobalIndex* nodes, const double* x) const {
    const int d = mesh_.dimension;
    for (const MidEdgeNode& e : midEdgeNodes(type)) {
      double edge2 = 0, offset2 = 0;
      for (int i = 0; i < d; ++i) {
        const double a = x[e.first * d + i], b = x[e.second * d + i], m = x[e.middle * d + i];
        edge2 += (b - a) * (b - a);
        offset2 += (m - (a + b) / 2) * (m - (a + b) / 2);
      }
      if (offset2 <= kMidEdgeTolerance * kMidEdgeTolerance * edge2) continue;
      const double percent = edge2 > 0 ? std::round(100 * std::sqrt(offset2 / edge2)) : 100;
      return "has its mid-edge node " + numbering_.node(nodes[e.middle]) + " off the middle of the edge from node " +
             numbering_.node(nodes[e.first]) + " to node " + numbering_.node(nodes[e.second]) + " by " +
             format(percent) + " % of the edge's length (at most 25 % is accepted): check the mid-edge node order (" +
             exodusCellName(type) + " in Exodus order) and the node's coordinates";
    }
    return "";
  }

  // "" when the Jacobian is positive at every check point (Quad4, Hex8: the corners; every other type:
  // every node and integration point); otherwise what is wrong and what to do.
  std::string shapeProblem(CellType type, const GlobalIndex* nodes, const double* x, double* jacobian) const {
    const bool box = type == CellType::Quad4 || type == CellType::Hex8;
    int points = nodesPerCell(type);
    if (box) scaledCornerJacobians(type, x, jacobian);
    else points = shapeCheckJacobians(type, x, jacobian);
    int negative = 0, zero = 0, firstNegative = -1, firstZero = -1;
    for (int a = 0; a < points; ++a) {
      if (jacobian[a] < -kDegenerateCorner) {
        if (negative++ == 0) firstNegative = a;
      } else if (jacobian[a] <= kDegenerateCorner) {
        if (zero++ == 0) firstZero = a;
      }
    }
    if (negative == 0 && zero == 0) return "";
    const bool twoD = cellDimension(type) == 2;
    const std::string shape = shapeName(type);
    if (negative + zero == points && negative > 0) return "is inverted (" + inversionAdvice(type);
    if (negative == 0 && zero == points)
      return std::string("is degenerate (zero ") + (twoD ? "area" : "volume") +
             "): its nodes lie on one " + (twoD ? "line" : "plane");
    const auto at = [&](int point) {
      return point < nodesPerCell(type) ? "node " + numbering_.node(nodes[point])
                                        : "integration point " + std::to_string(point - nodesPerCell(type) + 1);
    };
    if (negative > 0)
      return "is tangled (its Jacobian is negative at " + at(firstNegative) + "): a self-intersecting or non-convex " +
             shape + "; check its node order and coordinates";
    if (box)
      return "is degenerate at node " + numbering_.node(nodes[firstZero]) + " (zero Jacobian: " +
             (twoD ? "the two edges there are in line" : "the three edges there lie in one plane") +
             "): move the node or split the element";
    return "is degenerate at " + at(firstZero) + " (zero Jacobian): a flattened " + shape +
           "; move the node or split the element";
  }

  static std::string shapeName(CellType type) {
    switch (numCorners(type)) {
      case 3: return "triangle";
      case 4: return cellDimension(type) == 2 ? "quadrilateral" : "tetrahedron";
      case 6: return "wedge";
      default: return "hexahedron";
    }
  }

  // How to list the nodes of a cell the right way round.
  static std::string inversionAdvice(CellType type) {
    if (cellDimension(type) == 2) return "clockwise node order): list its nodes counter-clockwise";
    if (numCorners(type) == 4)
      return "left-handed node order): list nodes 1, 2, 3 counter-clockwise seen from node 4";
    return std::string("left-handed node order): list the bottom face counter-clockwise seen from ") +
           "the top face, then the top face in the same order";
  }

  void nodeSets() const {
    for (const auto& s : mesh_.nodeSets) {
      for (GlobalIndex n : s.nodes)
        if (n < 0 || n >= numNodes_)
          fail("node set '" + s.name + "' refers to node " + numbering_.node(n) + ", but the mesh has " +
               std::to_string(numNodes_) + " nodes");
      if (!std::is_sorted(s.nodes.begin(), s.nodes.end()) ||
          std::adjacent_find(s.nodes.begin(), s.nodes.end()) != s.nodes.end())
        fail("node set '" + s.name + "' is not sorted and unique");
    }
  }

  // A side is identified by its corner nodes, sorted: two elements share a side when they share its
  // corners (a triangular and a quadrilateral face never do: −1 pads the 2 or 3 corners).
  using SideKey = std::array<GlobalIndex, 4>;

  SideKey sideKey(int block, GlobalIndex local, int side) const {
    const auto& b = mesh_.blocks[block];
    const GlobalIndex* nodes = &b.connectivity[local * nodesPerCell(b.cellType)];
    SideKey key;
    key.fill(-1);
    const auto sideLocal = sideNodes(b.cellType, side);
    const int corners = numSideCorners(b.cellType, side);
    for (int i = 0; i < corners; ++i) key[i] = nodes[sideLocal[i]];
    std::sort(key.begin(), key.begin() + corners);
    return key;
  }

  void sideSets() const {
    struct Entry {
      SideKey key;
      GlobalIndex element;
      GlobalIndex neighbour;  // another element with the same side, or −1
      int set, position;
    };
    std::vector<Entry> entries;
    for (int si = 0; si < static_cast<int>(mesh_.sideSets.size()); ++si) {
      const auto& s = mesh_.sideSets[si];
      const std::string set = "side set '" + s.name + "' ";
      if (s.elements.size() != s.sides.size())
        fail(set + "has " + std::to_string(s.elements.size()) + " elements but " + std::to_string(s.sides.size()) +
             " sides");
      for (size_t k = 0; k < s.elements.size(); ++k) {
        const GlobalIndex e = s.elements[k];
        if (e < 0 || e >= numElements_)
          fail(set + "refers to element " + numbering_.element(e) + ", but the mesh has " + std::to_string(numElements_) +
               " elements");
        const CellType type = mesh_.blocks[blockOf_[e]].cellType;
        if (s.sides[k] < 0 || s.sides[k] >= numSides(type))
          fail(set + "refers to side " + std::to_string(s.sides[k] + 1) + " of element " + numbering_.element(e) + ", but a " +
               exodusCellName(type) + " has sides 1 to " + std::to_string(numSides(type)));
        entries.push_back({sideKey(blockOf_[e], localOf_[e], s.sides[k]), e, -1, si, static_cast<int>(k)});
      }
    }
    if (entries.empty()) return;

    // Every element side whose nodes all lie on side-set sides is looked up among the side-set
    // sides: one pass over the elements, a binary search only for sides on a side set.
    std::vector<char> onSideSet(static_cast<size_t>(numNodes_), 0);
    for (const auto& entry : entries)
      for (GlobalIndex n : entry.key)
        if (n >= 0) onSideSet[n] = 1;
    std::vector<Entry*> byKey;
    for (auto& entry : entries) byKey.push_back(&entry);
    auto keyLess = [](const Entry* a, const Entry* b) { return a->key < b->key; };
    std::sort(byKey.begin(), byKey.end(), keyLess);
    for (int bi = 0; bi < static_cast<int>(mesh_.blocks.size()); ++bi) {
      const auto& b = mesh_.blocks[bi];
      const int npe = nodesPerCell(b.cellType);
      std::vector<std::vector<int>> sides;
      for (int side = 0; side < numSides(b.cellType); ++side) {
        auto corners = sideNodes(b.cellType, side);
        corners.resize(static_cast<size_t>(numSideCorners(b.cellType, side)));
        sides.push_back(corners);
      }
      for (size_t k = 0; k < b.elements.size(); ++k) {
        const GlobalIndex* nodes = &b.connectivity[k * npe];
        for (int side = 0; side < static_cast<int>(sides.size()); ++side) {
          bool candidate = true;
          for (int a : sides[side]) candidate = candidate && onSideSet[nodes[a]];
          if (!candidate) continue;
          Entry probe{sideKey(bi, static_cast<GlobalIndex>(k), side), 0, 0, 0, 0};
          auto range = std::equal_range(byKey.begin(), byKey.end(), &probe, keyLess);
          for (auto it = range.first; it != range.second; ++it)
            if ((*it)->element != b.elements[k]) (*it)->neighbour = b.elements[k];
        }
      }
    }
    for (const auto& entry : entries)  // in set order: the first interior side of the first set
      if (entry.neighbour >= 0)
        fail("side set '" + mesh_.sideSets[entry.set].name + "' holds side " +
             std::to_string(mesh_.sideSets[entry.set].sides[entry.position] + 1) + " of element " +
             numbering_.element(entry.element) + ", which element " + numbering_.element(entry.neighbour) +
             " shares: an interior side, not on the boundary of the mesh");
  }

  template <class Entity>
  void uniqueNames(const std::vector<Entity>& entities, const char* kind) const {
    std::vector<std::string> names;
    for (const auto& e : entities) names.push_back(e.name);
    std::sort(names.begin(), names.end());
    auto dup = std::adjacent_find(names.begin(), names.end());
    if (dup != names.end()) fail(std::string(kind) + " name '" + *dup + "' is used more than once");
  }

  const Mesh& mesh_;
  const std::string where_;
  const Numbering numbering_;
  GlobalIndex numNodes_ = 0, numElements_ = 0;
  std::vector<int> blockOf_;
  std::vector<GlobalIndex> localOf_;
};

}  // namespace

void Mesh::validate(const std::string& source) const { Validator(*this, source).run(); }

void Mesh::validate(const std::string& source, const std::vector<GlobalIndex>& globalNodes,
                    const std::vector<GlobalIndex>& globalElements, GlobalIndex& badShapes) const {
  badShapes = 0;
  Validator(*this, source, Numbering{&globalNodes, &globalElements, &badShapes}).run();
}

}  // namespace contessa::mesh
