// The Cartesian grids: Rectangle (Quad4) and Box (Hex8), graded along each axis.
#include "mesh/Generators.hpp"

#include <string>
#include <utility>
#include <vector>

#include "mesh/GeneratorSupport.hpp"
#include "mesh/StructuredGrid.hpp"

namespace contessa::mesh {
namespace {

using namespace generator;

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

// One axis of a structured grid's spec, with the deck parameters its checks name.
struct GridAxis {
  double origin, length;
  int count;
  double bias;
  const char* originName;
  const char* lengthName;
  const char* countName;
  const char* biasName;
};

// The grid's checks in the deck's order (every origin, every length, every count, every bias, so the
// first failing parameter is named), then whether the grid fits.
std::string checkGrid(const std::vector<GridAxis>& axes) {
  for (const GridAxis& a : axes) requireFinite(a.origin, a.originName);
  for (const GridAxis& a : axes) requirePositive(a.length, a.lengthName);
  std::vector<std::pair<std::string, int>> counts;
  for (const GridAxis& a : axes) {
    requirePositiveCount(a.count, a.countName);
    counts.emplace_back(a.countName, a.count);
  }
  for (const GridAxis& a : axes) requireBias(a.bias, a.biasName);
  return requireGridFits(counts);
}

std::string checkRectangle(const RectangleSpec& spec) {
  return checkGrid({{spec.x0, spec.lx, spec.nx, spec.biasX, "X0", "Length X", "Elements X", "Bias X"},
                    {spec.y0, spec.ly, spec.ny, spec.biasY, "Y0", "Length Y", "Elements Y", "Bias Y"}});
}

std::string checkBox(const BoxSpec& spec) {
  return checkGrid({{spec.x0, spec.lx, spec.nx, spec.biasX, "X Origin", "Length X", "Elements X", "Bias X"},
                    {spec.y0, spec.ly, spec.ny, spec.biasY, "Y Origin", "Length Y", "Elements Y", "Bias Y"},
                    {spec.z0, spec.lz, spec.nz, spec.biasZ, "Z Origin", "Length Z", "Elements Z", "Bias Z"}});
}

}  // namespace

Mesh generateRectangle(const RectangleSpec& spec) {
  return guardAllocation(checkRectangle(spec), [&] { return rectangleRecipe(spec).whole(); });
}

DistributedMesh generateRectanglePart(const RectangleSpec& spec, int rank, int numRanks) {
  return guardAllocation(checkRectangle(spec), [&] { return rectangleRecipe(spec).part(rank, numRanks); });
}

Mesh generateBox(const BoxSpec& spec) {
  return guardAllocation(checkBox(spec), [&] { return boxRecipe(spec).whole(); });
}

DistributedMesh generateBoxPart(const BoxSpec& spec, int rank, int numRanks) {
  return guardAllocation(checkBox(spec), [&] { return boxRecipe(spec).part(rank, numRanks); });
}

}  // namespace contessa::mesh
