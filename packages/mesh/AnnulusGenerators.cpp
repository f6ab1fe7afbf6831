// The polar grids: Annulus Sector (Quad4) and its extrusion along z, Hollow Cylinder Sector (Hex8).
#include "mesh/Generators.hpp"

#include <cmath>
#include <vector>

#include "mesh/GeneratorSupport.hpp"
#include "mesh/StructuredGrid.hpp"

namespace contessa::mesh {
namespace {

using namespace generator;

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

}  // namespace

Mesh generateAnnulusSector(const AnnulusSectorSpec& spec) {
  return guardAllocation(checkAnnulusSector(spec), [&] { return annulusSectorRecipe(spec).whole(); });
}

DistributedMesh generateAnnulusSectorPart(const AnnulusSectorSpec& spec, int rank, int numRanks) {
  return guardAllocation(checkAnnulusSector(spec), [&] { return annulusSectorRecipe(spec).part(rank, numRanks); });
}

Mesh generateHollowCylinderSector(const HollowCylinderSectorSpec& spec) {
  return guardAllocation(checkHollowCylinderSector(spec), [&] { return hollowCylinderSectorRecipe(spec).whole(); });
}

DistributedMesh generateHollowCylinderSectorPart(const HollowCylinderSectorSpec& spec, int rank, int numRanks) {
  return guardAllocation(checkHollowCylinderSector(spec),
                         [&] { return hollowCylinderSectorRecipe(spec).part(rank, numRanks); });
}

}  // namespace contessa::mesh
