// The Cartesian grids: Rectangle (Quad4) and Box (Hex8), graded along each axis.
#include "mesh/Generators.hpp"

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
