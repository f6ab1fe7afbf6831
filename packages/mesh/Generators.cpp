#include "mesh/Generators.hpp"

#include <cmath>
#include <new>
#include <sstream>
#include <vector>

#include "common/Error.hpp"
#include "mesh/MemoryEstimate.hpp"

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

// Before anything is allocated: an n0 × n1 grid's counts must be indexable and its run must fit in
// memory (requireRunFits). Returns what the
// generator must say if an allocation fails all the same.
std::string requireGridFits(int n0, int n1, const std::string& name0, const std::string& name1) {
  MeshSize size;
  size.nodes = (n0 + 1.0) * (n1 + 1.0);
  size.elements = static_cast<double>(n0) * n1;
  size.dimension = 2;
  size.nodesPerElement = 4;
  const std::string what = name0 + " = " + std::to_string(n0) + ", " + name1 + " = " + std::to_string(n1);
  const std::string advice = "reduce " + name0 + " or " + name1;
  requireRunFits(size, what, advice);
  return what + ": not enough memory for " + formatCount(size.elements) + " elements; " + advice;
}

template <class Generate>
Mesh guardAllocation(const std::string& outOfMemoryMessage, Generate&& generate) {
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

// Both generators build the same logically structured n0 × n1 grid: node (i, j) is j*(n0+1) + i,
// element (i, j) is j*n0 + i, and its corners (i,j), (i+1,j), (i+1,j+1), (i,j+1) are
// counter-clockwise whenever the map from (i, j) to (x, y) preserves orientation.
class StructuredGrid {
 public:
  StructuredGrid(int n0, int n1) : n0_(n0), n1_(n1) {}

  GlobalIndex node(int i, int j) const { return static_cast<GlobalIndex>(j) * (n0_ + 1) + i; }
  GlobalIndex element(int i, int j) const { return static_cast<GlobalIndex>(j) * n0_ + i; }

  ElementBlock block(const std::string& name) const {
    ElementBlock b;
    b.name = name;
    b.cellType = CellType::Quad4;
    b.elements.reserve(static_cast<size_t>(n0_) * n1_);
    b.connectivity.reserve(4 * static_cast<size_t>(n0_) * n1_);
    for (int j = 0; j < n1_; ++j)
      for (int i = 0; i < n0_; ++i) {
        b.elements.push_back(element(i, j));
        for (GlobalIndex n : {node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)})
          b.connectivity.push_back(n);
      }
    return b;
  }

  // Grid edges: i = 0 (side 3), i = n0 (side 1), j = 0 (side 0), j = n1 (side 2).
  enum Edge { kMin0, kMax0, kMin1, kMax1 };

  NodeSet nodeSet(const std::string& name, Edge edge) const {
    NodeSet s;
    s.name = name;
    if (edge == kMin0 || edge == kMax0) {
      const int i = edge == kMin0 ? 0 : n0_;
      for (int j = 0; j <= n1_; ++j) s.nodes.push_back(node(i, j));
    } else {
      const int j = edge == kMin1 ? 0 : n1_;
      for (int i = 0; i <= n0_; ++i) s.nodes.push_back(node(i, j));
    }
    return s;  // ascending by construction
  }

  SideSet sideSet(const std::string& name, Edge edge) const {
    SideSet s;
    s.name = name;
    auto add = [&s](GlobalIndex e, int side) {
      s.elements.push_back(e);
      s.sides.push_back(side);
    };
    switch (edge) {
      case kMin0: for (int j = 0; j < n1_; ++j) add(element(0, j), 3); break;
      case kMax0: for (int j = 0; j < n1_; ++j) add(element(n0_ - 1, j), 1); break;
      case kMin1: for (int i = 0; i < n0_; ++i) add(element(i, 0), 0); break;
      case kMax1: for (int i = 0; i < n0_; ++i) add(element(i, n1_ - 1), 2); break;
    }
    return s;
  }

  NodeSet allNodes() const {
    NodeSet s;
    s.name = "all";
    s.nodes.resize(static_cast<size_t>(n0_ + 1) * (n1_ + 1));
    for (size_t k = 0; k < s.nodes.size(); ++k) s.nodes[k] = static_cast<GlobalIndex>(k);
    return s;
  }

  // Sets named after the grid edges, in the order min0, max0, min1, max1, then "all".
  void addSets(Mesh& mesh, const std::string names[4]) const {
    const Edge edges[4] = {kMin0, kMax0, kMin1, kMax1};
    for (int k = 0; k < 4; ++k) mesh.nodeSets.push_back(nodeSet(names[k], edges[k]));
    mesh.nodeSets.push_back(allNodes());
    for (int k = 0; k < 4; ++k) mesh.sideSets.push_back(sideSet(names[k], edges[k]));
  }

 private:
  int n0_, n1_;
};

// The allocating part of the generators, once their specs are checked and known to fit.
Mesh buildRectangle(const RectangleSpec& spec) {
  // Positions are computed per node (not by summing steps), and the last one is set to x0 + lx.
  const std::vector<double> xs = gradedPositions(spec.x0, spec.lx, spec.nx, spec.biasX, "Bias X");
  const std::vector<double> ys = gradedPositions(spec.y0, spec.ly, spec.ny, spec.biasY, "Bias Y");
  const StructuredGrid grid(spec.nx, spec.ny);
  Mesh mesh;
  mesh.dimension = 2;
  mesh.coordinates.resize(2 * static_cast<size_t>(spec.nx + 1) * (spec.ny + 1));
  for (int j = 0; j <= spec.ny; ++j)
    for (int i = 0; i <= spec.nx; ++i) {
      const size_t n = static_cast<size_t>(grid.node(i, j));
      mesh.coordinates[2 * n] = xs[i];
      mesh.coordinates[2 * n + 1] = ys[j];
    }
  mesh.blocks.push_back(grid.block(spec.blockName));
  const std::string names[4] = {"left", "right", "bottom", "top"};
  grid.addSets(mesh, names);
  mesh.validate("rectangle mesh");
  return mesh;
}

Mesh buildAnnulusSector(const AnnulusSectorSpec& spec) {
  const int nr = spec.elementsThroughThickness;
  const int nt = spec.elementsAroundArc;
  // Angles are graded in degrees, so the last one is exactly endAngleDeg before conversion.
  const std::vector<double> radii =
      gradedPositions(spec.innerRadius, spec.thickness, nr, spec.radialBias, "Radial Bias");
  std::vector<double> anglesDeg = gradedPositions(spec.startAngleDeg, spec.endAngleDeg - spec.startAngleDeg, nt,
                                                  spec.arcBias, "Arc Bias");
  anglesDeg.back() = spec.endAngleDeg;  // θ0 + (θ1 − θ0) can differ from θ1 in the last bit
  const StructuredGrid grid(nr, nt);
  const double degToRad = std::acos(-1.0) / 180.0;
  Mesh mesh;
  mesh.dimension = 2;
  mesh.coordinates.resize(2 * static_cast<size_t>(nr + 1) * (nt + 1));
  for (int j = 0; j <= nt; ++j) {
    const double theta = anglesDeg[j] * degToRad;
    const double c = std::cos(theta), s = std::sin(theta);
    for (int i = 0; i <= nr; ++i) {
      const double r = radii[i];
      const size_t n = static_cast<size_t>(grid.node(i, j));
      mesh.coordinates[2 * n] = r * c;
      mesh.coordinates[2 * n + 1] = r * s;
    }
  }
  // (r, θ) → (x, y) has Jacobian r > 0, so the grid's counter-clockwise order carries over.
  mesh.blocks.push_back(grid.block(spec.blockName));
  const std::string names[4] = {"inner", "outer", "start", "end"};
  grid.addSets(mesh, names);
  mesh.validate("annulus sector mesh");
  return mesh;
}

}  // namespace

Mesh generateRectangle(const RectangleSpec& spec) {
  requireFinite(spec.x0, "X0");
  requireFinite(spec.y0, "Y0");
  requirePositive(spec.lx, "Length X");
  requirePositive(spec.ly, "Length Y");
  requirePositiveCount(spec.nx, "Elements X");
  requirePositiveCount(spec.ny, "Elements Y");
  requireBias(spec.biasX, "Bias X");
  requireBias(spec.biasY, "Bias Y");
  const std::string outOfMemory = requireGridFits(spec.nx, spec.ny, "Elements X", "Elements Y");
  return guardAllocation(outOfMemory, [&spec] { return buildRectangle(spec); });
}

Mesh generateAnnulusSector(const AnnulusSectorSpec& spec) {
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
  const std::string outOfMemory = requireGridFits(spec.elementsThroughThickness, spec.elementsAroundArc,
                                                  "Elements Through Thickness", "Elements Around Arc");
  return guardAllocation(outOfMemory, [&spec] { return buildAnnulusSector(spec); });
}

}  // namespace contessa::mesh
