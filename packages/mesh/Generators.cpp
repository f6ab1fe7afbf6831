#include "mesh/Generators.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <new>
#include <tuple>
#include <utility>
#include <sstream>
#include <vector>

#include "common/Error.hpp"
#include "mesh/MemoryEstimate.hpp"
#include "mesh/Partition.hpp"

namespace contessa::mesh {

namespace {

std::string format(double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  return out.str();
}

void requirePositive(double value, const char* parameter) {
  requireInput(std::isfinite(value) && value > 0,
               std::string(parameter) + ": expected a positive number, got " + format(value));
}

void requireFinite(double value, const char* parameter) {
  requireInput(std::isfinite(value), std::string(parameter) + ": expected a finite number, got " + format(value));
}

void requirePositiveCount(int value, const char* parameter) {
  requireInput(value > 0, std::string(parameter) + ": expected a positive integer, got " + std::to_string(value));
}

void requireBias(double value, const char* parameter) {
  requireInput(std::isfinite(value) && value > 0,
               std::string(parameter) + ": expected a value > 0, got " + format(value));
}

// Before anything is allocated: a grid of `counts` elements per direction (nodes counts+1 each, or
// `size` when given) must be indexable and its run must fit in memory (requireRunFits). Returns what
// the generator must say if an allocation fails all the same.
std::string requireFits(const MeshSize& size, const std::vector<std::pair<std::string, int>>& counts) {
  std::string what, advice;
  for (size_t k = 0; k < counts.size(); ++k) {
    what += (k ? ", " : "") + counts[k].first + " = " + std::to_string(counts[k].second);
    advice += (k == 0 ? "reduce " : k + 1 == counts.size() ? " or " : ", ") + counts[k].first;
  }
  requireRunFits(size, what, advice);
  return what + ": not enough memory for " + formatCount(size.elements) + " elements; " + advice;
}

std::string requireGridFits(const std::vector<std::pair<std::string, int>>& counts) {
  MeshSize size;
  size.nodes = 1;
  size.elements = 1;
  for (const auto& c : counts) {
    size.nodes *= c.second + 1.0;
    size.elements *= c.second;
  }
  size.dimension = static_cast<int>(counts.size());
  size.nodesPerElement = size.dimension == 2 ? 4 : 8;
  return requireFits(size, counts);
}

template <class Generate>
auto guardAllocation(const std::string& outOfMemoryMessage, Generate&& generate) {
  try {
    return generate();
  } catch (const std::bad_alloc&) {
    throw InputError(outOfMemoryMessage);
  }
}

// n+1 node positions from start to start + length (exactly, at both ends) with element sizes in a
// geometric progression whose last/first ratio is `bias`. bias = 1 reproduces start + length*i/n bit
// for bit. With L = ln(q), q = bias^(1/(n-1)), node i sits at the fraction (q^i − 1)/(q^n − 1),
// evaluated with expm1 so that q near 1 loses nothing to cancellation, and for q > 1 rewritten as
// q^(i−n)·(1 − q^−i)/(1 − q^−n) so that large biases cannot overflow.
std::vector<double> gradedPositions(double start, double length, int n, double bias, const char* parameter) {
  std::vector<double> x(static_cast<size_t>(n) + 1);
  const double L = n > 1 ? std::log(bias) / (n - 1) : 0.0;
  for (int i = 0; i < n; ++i) {
    if (L == 0) {
      x[i] = start + length * i / n;  // uniform: exactly as the ungraded generators computed it
      continue;
    }
    const double t = L < 0 ? std::expm1(i * L) / std::expm1(n * L)
                           : std::exp((i - n) * L) * (std::expm1(-i * L) / std::expm1(-n * L));
    x[i] = start + length * t;
  }
  x[n] = start + length;
  for (int i = 0; i < n; ++i)
    requireInput(x[i + 1] > x[i], std::string(parameter) + ": value " + format(bias) + " with " +
                                      std::to_string(n) + " elements makes elements too small to represent");
  return x;
}

// Local side (0-based Exodus) of a cell's face where reference coordinate ξ_axis is −1 (min) or +1
// (max): the same numbers for Quad4 edges (axes 0, 1) and Hex8 faces (axes 0, 1, 2).
int sideOfFace(int axis, bool max) {
  static const int kSides[3][2] = {{3, 1}, {0, 2}, {4, 5}};
  return kSides[axis][max ? 1 : 0];
}

// All generators build logically structured grids of n0 × n1 (× n2) cells: node (i, j, k) is
// (k*(n1+1) + j)*(n0+1) + i, element (i, j, k) is (k*n1 + j)*n0 + i (in 2D k = 0, which gives the
// 2D numbering j*(n0+1) + i), and a cell lists its corners in Exodus order: (i,j), (i+1,j),
// (i+1,j+1), (i,j+1) at k, then (Hex8) the same at k+1. Its Jacobians are positive whenever the map
// from (i, j, k) to (x, y, z) preserves orientation.
class StructuredGrid {
 public:
  explicit StructuredGrid(std::vector<int> counts) : n_(std::move(counts)) {
    if (n_.size() == 2) n_.push_back(0);
  }

  int dimension() const { return n_[2] == 0 ? 2 : 3; }
  int count(int axis) const { return n_[axis]; }
  GlobalIndex numNodes() const { return static_cast<GlobalIndex>(n_[0] + 1) * (n_[1] + 1) * (n_[2] + 1); }
  GlobalIndex numElements() const {
    return static_cast<GlobalIndex>(n_[0]) * n_[1] * (dimension() == 2 ? 1 : n_[2]);
  }
  GlobalIndex node(int i, int j, int k = 0) const {
    return (static_cast<GlobalIndex>(k) * (n_[1] + 1) + j) * (n_[0] + 1) + i;
  }
  GlobalIndex element(int i, int j, int k = 0) const { return (static_cast<GlobalIndex>(k) * n_[1] + j) * n_[0] + i; }

  // Calls f(i, j, k) for every node, or with `fixedAxis` ≥ 0 for those with index `fixed` on it,
  // in ascending node id.
  template <class F>
  void forNodes(F&& f, int fixedAxis = -1, int fixed = 0) const {
    int lo[3] = {0, 0, 0}, hi[3] = {n_[0], n_[1], n_[2]};
    if (fixedAxis >= 0) lo[fixedAxis] = hi[fixedAxis] = fixed;
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) f(i, j, k);
  }

  // Calls f(i, j, k) for every cell, or for those with index `fixed` on `fixedAxis`, in ascending id.
  template <class F>
  void forCells(F&& f, int fixedAxis = -1, int fixed = 0) const {
    int lo[3] = {0, 0, 0}, hi[3] = {n_[0] - 1, n_[1] - 1, dimension() == 2 ? 0 : n_[2] - 1};
    if (fixedAxis >= 0) lo[fixedAxis] = hi[fixedAxis] = fixed;
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) f(i, j, k);
  }

  // Node coordinates from point(i, j, k, x) writing dimension() values at x.
  template <class Point>
  void setCoordinates(Mesh& mesh, Point&& point) const {
    const int d = dimension();
    mesh.dimension = d;
    mesh.coordinates.resize(static_cast<size_t>(d) * numNodes());
    forNodes([&](int i, int j, int k) { point(i, j, k, &mesh.coordinates[d * static_cast<size_t>(node(i, j, k))]); });
  }

  // The corners of cell (i, j, k) in Exodus order.
  void cellNodes(int i, int j, int k, std::vector<GlobalIndex>& out) const {
    for (int layer = 0; layer < (dimension() == 2 ? 1 : 2); ++layer)
      for (GlobalIndex n : {node(i, j, k + layer), node(i + 1, j, k + layer), node(i + 1, j + 1, k + layer),
                            node(i, j + 1, k + layer)})
        out.push_back(n);
  }

  ElementBlock block(const std::string& name) const {
    ElementBlock b;
    b.name = name;
    b.cellType = dimension() == 2 ? CellType::Quad4 : CellType::Hex8;
    b.elements.reserve(static_cast<size_t>(numElements()));
    b.connectivity.reserve(static_cast<size_t>(nodesPerCell(b.cellType)) * numElements());
    forCells([&](int i, int j, int k) {
      b.elements.push_back(element(i, j, k));
      cellNodes(i, j, k, b.connectivity);
    });
    return b;
  }

  NodeSet nodeSet(const std::string& name, int axis, bool max) const {
    NodeSet s;
    s.name = name;
    forNodes([&](int i, int j, int k) { s.nodes.push_back(node(i, j, k)); }, axis, max ? n_[axis] : 0);
    return s;  // ascending by construction
  }

  SideSet sideSet(const std::string& name, int axis, bool max) const {
    SideSet s;
    s.name = name;
    const int side = sideOfFace(axis, max);
    forCells(
        [&](int i, int j, int k) {
          s.elements.push_back(element(i, j, k));
          s.sides.push_back(side);
        },
        axis, max ? n_[axis] - 1 : 0);
    return s;
  }

  NodeSet allNodes() const {
    NodeSet s;
    s.name = "all";
    s.nodes.resize(static_cast<size_t>(numNodes()));
    for (size_t k = 0; k < s.nodes.size(); ++k) s.nodes[k] = static_cast<GlobalIndex>(k);
    return s;
  }

  // Sets named after the grid faces, in the order min0, max0, min1, max1[, min2, max2], then "all".
  void addSets(Mesh& mesh, const std::vector<std::string>& names) const {
    for (int f = 0; f < 2 * dimension(); ++f) mesh.nodeSets.push_back(nodeSet(names[f], f / 2, f % 2 == 1));
    mesh.nodeSets.push_back(allNodes());
    for (int f = 0; f < 2 * dimension(); ++f) mesh.sideSets.push_back(sideSet(names[f], f / 2, f % 2 == 1));
  }

 private:
  std::vector<int> n_;
};

// What a structured generator makes, before it makes it: the grid, the position of each grid node
// (point(i, j, k, x) writes dimension() values at x), the block's and the faces' names, and the name
// its checks give the mesh. The whole mesh and any rank's part come from the same recipe.
struct GridRecipe {
  StructuredGrid grid;
  std::function<void(int, int, int, double*)> point;
  std::string blockName;
  std::vector<std::string> faceNames;  ///< min0, max0, min1, max1[, min2, max2]
  std::string source;

  Mesh whole() const {
    Mesh mesh;
    grid.setCoordinates(mesh, point);
    mesh.blocks.push_back(grid.block(blockName));
    grid.addSets(mesh, faceNames);
    mesh.validate(source);
    return mesh;
  }

  DistributedMesh part(int rank, int numRanks) const;
};

// Rank `rank`'s part under GridPartition: the cells of its index box, the nodes they use, each node's
// ranks found from the (up to 2^d) cells around it, whose owners every rank computes alone. Nothing of
// the rest of the grid is built; the nodes scanned are those of the rank's box (its bounds).
DistributedMesh GridRecipe::part(int rank, int numRanks) const {
  const int dim = grid.dimension();
  const int n[3] = {grid.count(0), grid.count(1), dim == 2 ? 1 : grid.count(2)};
  const GlobalIndex numElements = grid.numElements();
  requirePartsFit(numElements, numRanks);
  const GridPartition partition(n[0], n[1], n[2], numRanks);
  int lo[3], hi[3];  // cells [lo, hi) per axis
  partition.bounds(rank, lo, hi);

  DistributedMesh result;
  result.rank = rank;
  result.numRanks = numRanks;
  result.numGlobalNodes = grid.numNodes();
  result.numGlobalElements = numElements;
  MeshPiece& piece = result.part;
  piece.mesh.dimension = dim;

  // The box's nodes [lo, hi] per axis (one layer in 2D), numbered within the box, in global id order.
  const int nodeHi[3] = {hi[0], hi[1], dim == 2 ? 0 : hi[2]};
  const int width[3] = {hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, nodeHi[2] - lo[2] + 1};
  const auto boxIndex = [&](int i, int j, int k) {
    return (static_cast<std::size_t>(k - lo[2]) * width[1] + (j - lo[1])) * width[0] + (i - lo[0]);
  };
  std::vector<GlobalIndex> local(static_cast<std::size_t>(width[0]) * width[1] * width[2], -1);
  std::vector<int> ranks;
  std::vector<int> nodeIndex;  // i, j, k of each part node
  for (int k = lo[2]; k <= nodeHi[2]; ++k)
    for (int j = lo[1]; j <= nodeHi[1]; ++j)
      for (int i = lo[0]; i <= nodeHi[0]; ++i) {
        const int idx[3] = {i, j, k};
        ranks.clear();
        for (int dk = dim == 2 ? 0 : -1; dk <= 0; ++dk)
          for (int dj = -1; dj <= 0; ++dj)
            for (int di = -1; di <= 0; ++di) {
              const int c[3] = {idx[0] + di, idx[1] + dj, idx[2] + dk};
              if (c[0] < 0 || c[0] >= n[0] || c[1] < 0 || c[1] >= n[1] || c[2] < 0 || c[2] >= n[2]) continue;
              ranks.push_back(partition.owner(c[0], c[1], c[2]));
            }
        std::sort(ranks.begin(), ranks.end());
        ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
        if (!std::binary_search(ranks.begin(), ranks.end(), rank)) continue;
        local[boxIndex(i, j, k)] = static_cast<GlobalIndex>(piece.globalNodes.size());
        piece.globalNodes.push_back(grid.node(i, j, k));
        nodeIndex.insert(nodeIndex.end(), idx, idx + 3);
        double x[3];
        point(i, j, k, x);
        piece.mesh.coordinates.insert(piece.mesh.coordinates.end(), x, x + dim);
        result.nodeOwner.push_back(ranks.front());
        std::vector<int> others;
        for (int r : ranks)
          if (r != rank) others.push_back(r);
        piece.sharedWith.push_back(std::move(others));
      }

  ElementBlock block;
  block.name = blockName;
  block.cellType = dim == 2 ? CellType::Quad4 : CellType::Hex8;
  std::vector<int> cells;  // i, j, k of each part cell
  for (int k = lo[2]; k < hi[2]; ++k)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int i = lo[0]; i < hi[0]; ++i) {
        if (partition.owner(i, j, k) != rank) continue;
        cells.insert(cells.end(), {i, j, k});
        block.elements.push_back(static_cast<GlobalIndex>(piece.globalElements.size()));
        piece.globalElements.push_back(grid.element(i, j, k));
        // The corners in cellNodes' order (StructuredGrid::cellNodes).
        for (int layer = 0; layer < (dim == 2 ? 1 : 2); ++layer)
          for (const auto& [di, dj] : {std::pair{0, 0}, std::pair{1, 0}, std::pair{1, 1}, std::pair{0, 1}})
            block.connectivity.push_back(local[boxIndex(i + di, j + dj, k + layer)]);
      }
  piece.mesh.blocks.push_back(std::move(block));
  result.globalBlockSizes.push_back(numElements);

  // The sets of the whole mesh (StructuredGrid::addSets) restricted to the part, in the same order:
  // a face's nodes and cells ascending, then "all"; a side's position in the whole set is its cell's
  // rank among the face's cells (the axes other than the face's, lowest fastest).
  for (int f = 0; f < 2 * dim; ++f) {
    const int axis = f / 2, at = f % 2 == 1 ? grid.count(axis) : 0;
    NodeSet set{faceNames[f], {}};
    GlobalIndex size = 1;
    for (int a = 0; a < dim; ++a)
      if (a != axis) size *= grid.count(a) + 1;
    for (std::size_t k = 0; k < piece.globalNodes.size(); ++k)
      if (nodeIndex[3 * k + axis] == at) set.nodes.push_back(static_cast<GlobalIndex>(k));
    piece.mesh.nodeSets.push_back(std::move(set));
    result.globalNodeSetSizes.push_back(size);
  }
  NodeSet all{"all", std::vector<GlobalIndex>(piece.globalNodes.size())};
  for (std::size_t k = 0; k < all.nodes.size(); ++k) all.nodes[k] = static_cast<GlobalIndex>(k);
  piece.mesh.nodeSets.push_back(std::move(all));
  result.globalNodeSetSizes.push_back(grid.numNodes());
  for (int f = 0; f < 2 * dim; ++f) {
    const int axis = f / 2, at = f % 2 == 1 ? n[axis] - 1 : 0;
    SideSet set{faceNames[f], {}, {}};
    std::vector<GlobalIndex> positions;
    GlobalIndex size = 1;
    for (int a = 0; a < dim; ++a)
      if (a != axis) size *= n[a];
    for (std::size_t e = 0; e < piece.globalElements.size(); ++e) {
      if (cells[3 * e + axis] != at) continue;
      set.elements.push_back(static_cast<GlobalIndex>(e));
      set.sides.push_back(sideOfFace(axis, f % 2 == 1));
      GlobalIndex position = 0, stride = 1;
      for (int a = 0; a < dim; ++a) {
        if (a == axis) continue;
        position += cells[3 * e + a] * stride;
        stride *= n[a];
      }
      positions.push_back(position);
    }
    piece.mesh.sideSets.push_back(std::move(set));
    result.sideSetPositions.push_back(std::move(positions));
    result.globalSideSetSizes.push_back(size);
  }
  // Checked by the caller on every rank at once (validatePart, MeshDistribution.hpp): a check here would
  // fail on one rank alone, in local numbers.
  return result;
}

GridRecipe rectangleRecipe(const RectangleSpec& spec) {
  const std::vector<double> xs = gradedPositions(spec.x0, spec.lx, spec.nx, spec.biasX, "Bias X");
  const std::vector<double> ys = gradedPositions(spec.y0, spec.ly, spec.ny, spec.biasY, "Bias Y");
  return {StructuredGrid({spec.nx, spec.ny}),
          [xs, ys](int i, int j, int, double* x) {
            x[0] = xs[i];
            x[1] = ys[j];
          },
          spec.blockName, {"left", "right", "bottom", "top"}, "rectangle mesh"};
}

GridRecipe boxRecipe(const BoxSpec& spec) {
  const std::vector<double> xs = gradedPositions(spec.x0, spec.lx, spec.nx, spec.biasX, "Bias X");
  const std::vector<double> ys = gradedPositions(spec.y0, spec.ly, spec.ny, spec.biasY, "Bias Y");
  const std::vector<double> zs = gradedPositions(spec.z0, spec.lz, spec.nz, spec.biasZ, "Bias Z");
  return {StructuredGrid({spec.nx, spec.ny, spec.nz}),
          [xs, ys, zs](int i, int j, int k, double* x) {
            x[0] = xs[i];
            x[1] = ys[j];
            x[2] = zs[k];
          },
          spec.blockName, {"left", "right", "bottom", "top", "back", "front"}, "box mesh"};
}

// The annulus sector's radii and angles (degrees). Angles are graded in degrees, so the last one is
// exactly endAngleDeg before conversion.
struct AnnulusPositions {
  std::vector<double> radii, anglesDeg;
  explicit AnnulusPositions(const AnnulusSectorSpec& spec)
      : radii(gradedPositions(spec.innerRadius, spec.thickness, spec.elementsThroughThickness, spec.radialBias,
                              "Radial Bias")),
        anglesDeg(gradedPositions(spec.startAngleDeg, spec.endAngleDeg - spec.startAngleDeg, spec.elementsAroundArc,
                                  spec.arcBias, "Arc Bias")) {
    anglesDeg.back() = spec.endAngleDeg;  // θ0 + (θ1 − θ0) can differ from θ1 in the last bit
  }
  // (r, θ) → (x, y) has Jacobian r > 0, so the grid's counter-clockwise order carries over.
  void point(int i, int j, double* x) const {
    const double theta = anglesDeg[j] * (std::acos(-1.0) / 180.0);
    x[0] = radii[i] * std::cos(theta);
    x[1] = radii[i] * std::sin(theta);
  }
};

GridRecipe annulusSectorRecipe(const AnnulusSectorSpec& spec) {
  const AnnulusPositions annulus(spec);
  return {StructuredGrid({spec.elementsThroughThickness, spec.elementsAroundArc}),
          [annulus](int i, int j, int, double* x) { annulus.point(i, j, x); }, spec.blockName,
          {"inner", "outer", "start", "end"}, "annulus sector mesh"};
}

GridRecipe hollowCylinderSectorRecipe(const HollowCylinderSectorSpec& spec) {
  const AnnulusPositions annulus(spec.section);
  const std::vector<double> zs = gradedPositions(spec.z0, spec.length, spec.layers, spec.axialBias, "Bias Z");
  // (r, θ, z) → (x, y, z) has Jacobian r > 0: right-handed cells.
  return {StructuredGrid({spec.section.elementsThroughThickness, spec.section.elementsAroundArc, spec.layers}),
          [annulus, zs](int i, int j, int k, double* x) {
            annulus.point(i, j, x);
            x[2] = zs[k];
          },
          spec.section.blockName, {"inner", "outer", "start", "end", "back", "front"}, "hollow cylinder sector mesh"};
}

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
    MeshSize s;
    s.nodes = (n + 1.0) * (n + 1.0) * (n + 1.0) + m * (3.0 * n * n + 3.0 * n + 1.0);
    s.elements = static_cast<double>(n) * n * n + 3.0 * n * n * m;
    s.dimension = 3;
    s.nodesPerElement = 8;
    return s;
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

std::string checkRectangle(const RectangleSpec& spec) {
  requireFinite(spec.x0, "X0");
  requireFinite(spec.y0, "Y0");
  requirePositive(spec.lx, "Length X");
  requirePositive(spec.ly, "Length Y");
  requirePositiveCount(spec.nx, "Elements X");
  requirePositiveCount(spec.ny, "Elements Y");
  requireBias(spec.biasX, "Bias X");
  requireBias(spec.biasY, "Bias Y");
  return requireGridFits({{"Elements X", spec.nx}, {"Elements Y", spec.ny}});
}

void requireAnnulusSector(const AnnulusSectorSpec& spec) {
  requirePositive(spec.innerRadius, "Inner Radius");
  requirePositive(spec.thickness, "Thickness");
  requireFinite(spec.startAngleDeg, "Start Angle");
  requireFinite(spec.endAngleDeg, "End Angle");
  requireInput(spec.endAngleDeg > spec.startAngleDeg, "End Angle: expected an angle greater than Start Angle (" +
                                                          format(spec.startAngleDeg) + "), got " +
                                                          format(spec.endAngleDeg));
  requireInput(spec.endAngleDeg - spec.startAngleDeg <= 360,
               "End Angle: expected at most 360 degrees beyond Start Angle (" + format(spec.startAngleDeg) +
                   "), got " + format(spec.endAngleDeg));
  requirePositiveCount(spec.elementsThroughThickness, "Elements Through Thickness");
  requirePositiveCount(spec.elementsAroundArc, "Elements Around Arc");
  requireBias(spec.radialBias, "Radial Bias");
  requireBias(spec.arcBias, "Arc Bias");
}

std::string checkAnnulusSector(const AnnulusSectorSpec& spec) {
  requireAnnulusSector(spec);
  return requireGridFits(
      {{"Elements Through Thickness", spec.elementsThroughThickness}, {"Elements Around Arc", spec.elementsAroundArc}});
}

std::string checkBox(const BoxSpec& spec) {
  requireFinite(spec.x0, "X Origin");
  requireFinite(spec.y0, "Y Origin");
  requireFinite(spec.z0, "Z Origin");
  requirePositive(spec.lx, "Length X");
  requirePositive(spec.ly, "Length Y");
  requirePositive(spec.lz, "Length Z");
  requirePositiveCount(spec.nx, "Elements X");
  requirePositiveCount(spec.ny, "Elements Y");
  requirePositiveCount(spec.nz, "Elements Z");
  requireBias(spec.biasX, "Bias X");
  requireBias(spec.biasY, "Bias Y");
  requireBias(spec.biasZ, "Bias Z");
  return requireGridFits({{"Elements X", spec.nx}, {"Elements Y", spec.ny}, {"Elements Z", spec.nz}});
}

std::string checkHollowCylinderSector(const HollowCylinderSectorSpec& spec) {
  requireAnnulusSector(spec.section);
  requireFinite(spec.z0, "Z Origin");
  requirePositive(spec.length, "Length Z");
  requirePositiveCount(spec.layers, "Elements Z");
  requireBias(spec.axialBias, "Bias Z");
  return requireGridFits({{"Elements Through Thickness", spec.section.elementsThroughThickness},
                          {"Elements Around Arc", spec.section.elementsAroundArc},
                          {"Elements Z", spec.layers}});
}

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

Mesh generateRectangle(const RectangleSpec& spec) {
  const std::string outOfMemory = checkRectangle(spec);
  return guardAllocation(outOfMemory, [&spec] { return rectangleRecipe(spec).whole(); });
}

DistributedMesh generateRectanglePart(const RectangleSpec& spec, int rank, int numRanks) {
  const std::string outOfMemory = checkRectangle(spec);
  return guardAllocation(outOfMemory, [&] { return rectangleRecipe(spec).part(rank, numRanks); });
}

Mesh generateAnnulusSector(const AnnulusSectorSpec& spec) {
  const std::string outOfMemory = checkAnnulusSector(spec);
  return guardAllocation(outOfMemory, [&spec] { return annulusSectorRecipe(spec).whole(); });
}

DistributedMesh generateAnnulusSectorPart(const AnnulusSectorSpec& spec, int rank, int numRanks) {
  const std::string outOfMemory = checkAnnulusSector(spec);
  return guardAllocation(outOfMemory, [&] { return annulusSectorRecipe(spec).part(rank, numRanks); });
}

Mesh generateBox(const BoxSpec& spec) {
  const std::string outOfMemory = checkBox(spec);
  return guardAllocation(outOfMemory, [&spec] { return boxRecipe(spec).whole(); });
}

DistributedMesh generateBoxPart(const BoxSpec& spec, int rank, int numRanks) {
  const std::string outOfMemory = checkBox(spec);
  return guardAllocation(outOfMemory, [&] { return boxRecipe(spec).part(rank, numRanks); });
}

Mesh generateHollowCylinderSector(const HollowCylinderSectorSpec& spec) {
  const std::string outOfMemory = checkHollowCylinderSector(spec);
  return guardAllocation(outOfMemory, [&spec] { return hollowCylinderSectorRecipe(spec).whole(); });
}

DistributedMesh generateHollowCylinderSectorPart(const HollowCylinderSectorSpec& spec, int rank, int numRanks) {
  const std::string outOfMemory = checkHollowCylinderSector(spec);
  return guardAllocation(outOfMemory, [&] { return hollowCylinderSectorRecipe(spec).part(rank, numRanks); });
}

Mesh generateSphereOctant(const SphereOctantSpec& spec) {
  const std::string outOfMemory = checkSphereOctant(spec);
  return guardAllocation(outOfMemory, [&spec] { return SphereOctant(spec).build(); });
}

DistributedMesh generateSphereOctantPart(const SphereOctantSpec& spec, int rank, int numRanks) {
  const std::string outOfMemory = checkSphereOctant(spec);
  return guardAllocation(outOfMemory, [&] { return SphereOctant(spec).part(rank, numRanks); });
}

}  // namespace contessa::mesh
