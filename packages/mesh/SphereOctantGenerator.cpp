// The Sphere Octant (Hex8): an O-grid of a cube and three shells, not one structured grid.
#include "mesh/Generators.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "mesh/GeneratorSupport.hpp"
#include "mesh/Partition.hpp"
#include "mesh/StructuredGrid.hpp"

namespace contessa::mesh {
namespace {

using namespace generator;

// The sphere octant in local coordinates (u, v, w) ≥ 0 about the centre, w towards the pole, then
// placed by a rotation (never a reflection, so right-handed cells stay right-handed).
class SphereOctant {
 public:
  explicit SphereOctant(const SphereOctantSpec& spec)
      : spec_(spec), n_(spec.elementsAlongEdge), m_(spec.elementsThroughShell), cube_({n_, n_, n_}) {
    const double a = spec.innerCubeFraction * spec.radius;
    // Equiangular cube coordinates a·tan(π/4·t); the pole patch's axes u, v graded towards the pole.
    const double quarterPi = std::atan(1.0);
    auto cubeCoordinates = [&](double bias, const char* parameter) {
      std::vector<double> t = gradedPositions(0, 1, n_, bias, parameter);
      for (double& c : t) c = a * std::tan(quarterPi * c);
      t.back() = a;  // tan(π/4) is 1 - 1e-16 in floating point
      return t;
    };
    axis_[0] = axis_[1] = cubeCoordinates(spec.poleBias, "Pole Bias");
    axis_[2] = cubeCoordinates(1.0, "Pole Bias");
    layers_ = gradedPositions(0, 1, m_, spec.radialBias, "Radial Bias");
    placeAxes();
    // Shell nodes sit on rays through the cube's outer-boundary nodes: number those.
    boundaryIndex_.assign(static_cast<size_t>(cube_.numNodes()), -1);
    cube_.forNodes([&](int i, int j, int k) {
      if (i == n_ || j == n_ || k == n_) {
        boundaryIndex_[cube_.node(i, j, k)] = boundaryCount_++;
        boundaryNode_.push_back(cube_.node(i, j, k));
      }
    });
  }

  // The cube's (n+1)³ nodes and n³ elements, and per shell layer the 3n² + 3n + 1 nodes of the
  // cube's outer boundary and 3n² elements.
  static MeshSize size(int n, int m) {
    return MeshSize((n + 1.0) * (n + 1.0) * (n + 1.0) + m * (3.0 * n * n + 3.0 * n + 1.0),
                    static_cast<double>(n) * n * n + 3.0 * n * n * m, 3);
  }

  GlobalIndex numNodes() const { return cube_.numNodes() + m_ * boundaryCount_; }
  GlobalIndex numElements() const { return cube_.numElements() + 3 * static_cast<GlobalIndex>(n_) * n_ * m_; }

  // The whole octant, element by element and node by node through the same functions a part uses.
  Mesh build() const {
    Mesh mesh;
    mesh.dimension = 3;
    mesh.coordinates.resize(3 * static_cast<size_t>(numNodes()));
    for (GlobalIndex node = 0; node < numNodes(); ++node) nodePoint(node, &mesh.coordinates[3 * static_cast<size_t>(node)]);

    ElementBlock block;
    block.name = spec_.blockName;
    block.cellType = CellType::Hex8;
    std::vector<SideSet> sets = emptySideSets();
    std::vector<std::pair<int, int>> faces;
    for (GlobalIndex e = 0; e < numElements(); ++e) {
      block.elements.push_back(e);
      elementNodes(e, block.connectivity);
      faces.clear();
      elementFaces(e, faces);
      for (const auto& [set, side] : faces) {
        sets[set].elements.push_back(e);
        sets[set].sides.push_back(side);
      }
    }
    mesh.blocks.push_back(std::move(block));
    for (const SideSet& s : sets) {
      mesh.sideSets.push_back(s);
      mesh.nodeSets.push_back(nodesOf(mesh, s));
    }
    mesh.nodeSets.push_back({"pole", {poleNode()}});
    NodeSet all{"all", std::vector<GlobalIndex>(static_cast<size_t>(mesh.numNodes()))};
    for (size_t k = 0; k < all.nodes.size(); ++k) all.nodes[k] = static_cast<GlobalIndex>(k);
    mesh.nodeSets.push_back(std::move(all));
    mesh.validate("sphere octant mesh");
    return mesh;
  }

  // Rank `rank`'s part under ElementRanges, without the rest of the mesh: the part's elements and
  // nodes, then one pass over every element's corners and faces, computed and dropped one element at
  // a time, for the ranks holding each part node and the sets' global order and sizes. Memory: the
  // part plus the sets' nodes (surfaces); time: the whole mesh's connectivity, once.
  DistributedMesh part(int rank, int numRanks) const {
    const GlobalIndex numCells = numElements();
    requirePartsFit(numCells, numRanks);
    const ElementRanges ranges{numCells, numRanks};
    const GlobalIndex first = ranges.begin(rank), last = ranges.begin(rank + 1);
    DistributedMesh result;
    result.rank = rank;
    result.numRanks = numRanks;
    result.numGlobalNodes = numNodes();
    result.numGlobalElements = numCells;
    MeshPiece& piece = result.part;
    piece.mesh.dimension = 3;

    std::vector<GlobalIndex> corners;  // of the part's elements, in order
    for (GlobalIndex e = first; e < last; ++e) elementNodes(e, corners);
    piece.globalNodes = corners;
    std::sort(piece.globalNodes.begin(), piece.globalNodes.end());
    piece.globalNodes.erase(std::unique(piece.globalNodes.begin(), piece.globalNodes.end()), piece.globalNodes.end());
    auto localOf = [&](GlobalIndex node) -> GlobalIndex {
      const auto it = std::lower_bound(piece.globalNodes.begin(), piece.globalNodes.end(), node);
      return it != piece.globalNodes.end() && *it == node ? it - piece.globalNodes.begin() : -1;
    };

    std::vector<std::vector<int>> users(piece.globalNodes.size());
    std::vector<SideSet> sets = emptySideSets();
    std::vector<std::vector<GlobalIndex>> positions(sets.size()), setNodes(sets.size());
    std::vector<GlobalIndex> counts(sets.size(), 0), cell;
    std::vector<std::pair<int, int>> faces;
    int owner = 0;
    for (GlobalIndex e = 0; e < numCells; ++e) {
      while (ranges.begin(owner + 1) <= e) ++owner;  // owners grow with e: users come out sorted
      cell.clear();
      elementNodes(e, cell);
      for (GlobalIndex node : cell) {
        const GlobalIndex local = localOf(node);
        if (local >= 0 && (users[local].empty() || users[local].back() != owner)) users[local].push_back(owner);
      }
      faces.clear();
      elementFaces(e, faces);
      for (const auto& [set, side] : faces) {
        if (e >= first && e < last) {
          sets[set].elements.push_back(e - first);
          sets[set].sides.push_back(side);
          positions[set].push_back(counts[set]);
        }
        ++counts[set];
        for (int a : sideNodes(CellType::Hex8, side)) setNodes[set].push_back(cell[a]);
      }
    }
    for (std::size_t k = 0; k < piece.globalNodes.size(); ++k) {
      double x[3];
      nodePoint(piece.globalNodes[k], x);
      piece.mesh.coordinates.insert(piece.mesh.coordinates.end(), x, x + 3);
      result.nodeOwner.push_back(users[k].front());
      std::vector<int> others;
      for (int r : users[k])
        if (r != rank) others.push_back(r);
      piece.sharedWith.push_back(std::move(others));
    }

    ElementBlock block;
    block.name = spec_.blockName;
    block.cellType = CellType::Hex8;
    for (GlobalIndex e = first; e < last; ++e) {
      block.elements.push_back(e - first);
      piece.globalElements.push_back(e);
    }
    for (GlobalIndex node : corners) block.connectivity.push_back(localOf(node));
    piece.mesh.blocks.push_back(std::move(block));
    result.globalBlockSizes.push_back(numCells);

    // The sets in build()'s order: a node set per side set (its faces' nodes), "pole", "all".
    auto addNodeSet = [&](const std::string& name, std::vector<GlobalIndex> nodes) {
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
      NodeSet set{name, {}};
      for (GlobalIndex node : nodes)
        if (localOf(node) >= 0) set.nodes.push_back(localOf(node));
      piece.mesh.nodeSets.push_back(std::move(set));
      result.globalNodeSetSizes.push_back(static_cast<GlobalIndex>(nodes.size()));
    };
    for (std::size_t s = 0; s < sets.size(); ++s) {
      addNodeSet(sets[s].name, std::move(setNodes[s]));
      result.globalSideSetSizes.push_back(counts[s]);
    }
    addNodeSet("pole", {poleNode()});
    NodeSet all{"all", std::vector<GlobalIndex>(piece.globalNodes.size())};
    for (std::size_t k = 0; k < all.nodes.size(); ++k) all.nodes[k] = static_cast<GlobalIndex>(k);
    piece.mesh.nodeSets.push_back(std::move(all));
    result.globalNodeSetSizes.push_back(numNodes());
    piece.mesh.sideSets = std::move(sets);
    result.sideSetPositions = std::move(positions);
    // Checked by the caller on every rank at once (validatePart, MeshDistribution.hpp).
    return result;
  }

 private:
  // Element e's corners in Exodus order. The cube's cells first (numbered as the box), then the
  // shells over the cube faces u = a, v = a, w = a, each spanning two cube axes (p, q) with p × q = the
  // face's outward normal, so (p, q, outwards) is right-handed: the face's quad at layer l, then at
  // l + 1, is an Exodus-ordered Hex8 with reference axes (p, q, radial). Shell element ids run over
  // (normal, b, a, l), l fastest.
  void elementNodes(GlobalIndex e, std::vector<GlobalIndex>& out) const {
    if (e < cube_.numElements()) {
      cube_.cellNodes(static_cast<int>(e % n_), static_cast<int>(e / n_ % n_), static_cast<int>(e / n_ / n_), out);
      return;
    }
    int normal, a, b, l;
    shellCell(e, normal, a, b, l);
    const int p = (normal + 1) % 3, q = (normal + 2) % 3;
    for (int layer = l; layer <= l + 1; ++layer)
      for (auto [da, db] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
        int index[3];
        index[normal] = n_;
        index[p] = a + da;
        index[q] = b + db;
        out.push_back(shellNode(layer, cube_.node(index[0], index[1], index[2])));
      }
  }

  // The side sets element e has a face in, as (set, side): set 0 "surface", 1 "equator", 2 and 3 the
  // symmetry planes of the local axes u and v. The cube's faces at u = 0, v = 0, w = 0 are symmetry
  // and equator; a shell's faces on the planes p = 0, q = 0 too, and its outermost layer the sphere.
  void elementFaces(GlobalIndex e, std::vector<std::pair<int, int>>& out) const {
    auto plane = [](int axis) { return axis == 2 ? 1 : 2 + axis; };
    if (e < cube_.numElements()) {
      const int index[3] = {static_cast<int>(e % n_), static_cast<int>(e / n_ % n_), static_cast<int>(e / n_ / n_)};
      for (int axis = 0; axis < 3; ++axis)
        if (index[axis] == 0) out.emplace_back(plane(axis), sideOfFace(axis, false));
      return;
    }
    int normal, a, b, l;
    shellCell(e, normal, a, b, l);
    const int p = (normal + 1) % 3, q = (normal + 2) % 3;
    if (a == 0) out.emplace_back(plane(p), sideOfFace(0, false));
    if (b == 0) out.emplace_back(plane(q), sideOfFace(1, false));
    if (l == m_ - 1) out.emplace_back(0, sideOfFace(2, true));
  }

  void shellCell(GlobalIndex e, int& normal, int& a, int& b, int& l) const {
    GlobalIndex s = e - cube_.numElements();
    l = static_cast<int>(s % m_);
    s /= m_;
    a = static_cast<int>(s % n_);
    s /= n_;
    b = static_cast<int>(s % n_);
    normal = static_cast<int>(s / n_);
  }

  // A cube node sits at its axis coordinates; shell layer l's node on the ray from the centre through
  // cube boundary node P at (1 − ρ_l)·P + ρ_l·R·P/|P|.
  void nodePoint(GlobalIndex node, double* x) const {
    GlobalIndex cubeNode = node;
    int layer = 0;
    if (node >= cube_.numNodes()) {
      const GlobalIndex s = node - cube_.numNodes();
      layer = static_cast<int>(s / boundaryCount_) + 1;
      cubeNode = boundaryNode_[static_cast<size_t>(s % boundaryCount_)];
    }
    const GlobalIndex row = n_ + 1;
    const double local[3] = {axis_[0][cubeNode % row], axis_[1][cubeNode / row % row], axis_[2][cubeNode / row / row]};
    if (layer == 0) {
      place(local, x);
      return;
    }
    const double norm = std::sqrt(local[0] * local[0] + local[1] * local[1] + local[2] * local[2]);
    const double scale = (1 - layers_[layer]) + layers_[layer] * spec_.radius / norm;
    const double p[3] = {scale * local[0], scale * local[1], scale * local[2]};
    place(p, x);
  }

  GlobalIndex poleNode() const { return shellNode(m_, cube_.node(0, 0, n_)); }

  std::vector<SideSet> emptySideSets() const {
    return {{"surface", {}, {}},
            {"equator", {}, {}},
            {"symmetry_" + std::string(1, "xyz"[globalAxis_[0]]), {}, {}},
            {"symmetry_" + std::string(1, "xyz"[globalAxis_[1]]), {}, {}}};
  }

  // Layer 0 of the shell is the cube's boundary itself.
  GlobalIndex shellNode(int layer, GlobalIndex cubeNode) const {
    if (layer == 0) return cubeNode;
    return cube_.numNodes() + static_cast<GlobalIndex>(layer - 1) * boundaryCount_ + boundaryIndex_[cubeNode];
  }

  // Local axes (u, v, w) → global: w along the pole direction; u, v along the other two axes in the
  // order that makes the map a rotation (cyclic order for a + pole, swapped for a − pole).
  void placeAxes() {
    const std::string& d = spec_.poleDirection;
    const int pole = d[1] - 'x';
    const bool negative = d[0] == '-';
    const int next = (pole + 1) % 3, last = (pole + 2) % 3;
    globalAxis_[0] = negative ? last : next;
    globalAxis_[1] = negative ? next : last;
    globalAxis_[2] = pole;
    sign_[0] = sign_[1] = 1;
    sign_[2] = negative ? -1 : 1;
  }

  void place(const double local[3], double* x) const {
    for (int a = 0; a < 3; ++a) x[globalAxis_[a]] = spec_.center[globalAxis_[a]] + sign_[a] * local[a];
  }

  static NodeSet nodesOf(const Mesh& mesh, const SideSet& set) {
    NodeSet s{set.name, {}};
    const ElementBlock& block = mesh.blocks[0];
    for (size_t k = 0; k < set.elements.size(); ++k)
      for (int a : sideNodes(CellType::Hex8, set.sides[k]))
        s.nodes.push_back(block.connectivity[8 * static_cast<size_t>(set.elements[k]) + a]);
    std::sort(s.nodes.begin(), s.nodes.end());
    s.nodes.erase(std::unique(s.nodes.begin(), s.nodes.end()), s.nodes.end());
    return s;
  }

  const SphereOctantSpec& spec_;
  int n_, m_;
  StructuredGrid cube_;
  std::vector<double> axis_[3], layers_;
  int globalAxis_[3] = {0, 1, 2}, sign_[3] = {1, 1, 1};
  std::vector<GlobalIndex> boundaryIndex_, boundaryNode_;  // cube node → boundary index, and back
  GlobalIndex boundaryCount_ = 0;
};

std::string checkSphereOctant(const SphereOctantSpec& spec) {
  requirePositive(spec.radius, "Radius");
  requireFinite(spec.center[0], "X Center");
  requireFinite(spec.center[1], "Y Center");
  requireFinite(spec.center[2], "Z Center");
  const std::string& d = spec.poleDirection;
  requireInput(d.size() == 2 && (d[0] == '-' || d[0] == '+') && d[1] >= 'x' && d[1] <= 'z',
               "Pole Direction: expected one of -x, +x, -y, +y, -z, +z, got '" + d + "'");
  requirePositiveCount(spec.elementsAlongEdge, "Elements Along Edge");
  requirePositiveCount(spec.elementsThroughShell, "Elements Through Shell");
  // The shell's rays must leave the cube before the sphere: its corner f·R·√3 lies inside R.
  requireInput(std::isfinite(spec.innerCubeFraction) && spec.innerCubeFraction > 0 &&
                   spec.innerCubeFraction * std::sqrt(3.0) < 1,
               "Inner Cube Fraction: expected a value in (0, 0.57735) (the inner cube's corner inside the sphere: "
               "fraction < 1/sqrt(3)), got " + format(spec.innerCubeFraction));
  requireBias(spec.poleBias, "Pole Bias");
  requireBias(spec.radialBias, "Radial Bias");
  return requireFits(SphereOctant::size(spec.elementsAlongEdge, spec.elementsThroughShell),
                     {{"Elements Along Edge", spec.elementsAlongEdge}, {"Elements Through Shell", spec.elementsThroughShell}});
}

}  // namespace

Mesh generateSphereOctant(const SphereOctantSpec& spec) {
  return guardAllocation(checkSphereOctant(spec), [&] { return SphereOctant(spec).build(); });
}

DistributedMesh generateSphereOctantPart(const SphereOctantSpec& spec, int rank, int numRanks) {
  return guardAllocation(checkSphereOctant(spec), [&] { return SphereOctant(spec).part(rank, numRanks); });
}

}  // namespace contessa::mesh
