#pragma once
// Inline mesh generators for decks ("Problem/Mesh/Type" = "Rectangle" or "Annulus Sector").
#include <string>

#include "mesh/Mesh.hpp"

namespace contessa::mesh {

/// Structured nx × ny Quad4 mesh of [x0, x0+lx] × [y0, y0+ly].
/// Node sets and side sets: "left" (x = x0), "right", "bottom" (y = y0), "top"; node sets also
/// "all". Node id = j*(nx+1) + i; element id = j*nx + i; counter-clockwise connectivity.
struct RectangleSpec {
  double x0 = 0, y0 = 0, lx = 1, ly = 1;
  int nx = 1, ny = 1;
  std::string blockName = "block_1";
};
Mesh generateRectangle(const RectangleSpec& spec);

/// Annulus sector (ring segment) centred at the origin: radii [ri, ri+t], angles [θ0, θ1] (degrees,
/// counter-clockwise from +x). nr elements through the thickness, nt around the arc.
/// Node sets and side sets: "inner" (r = ri), "outer" (r = ri + t), "start" (θ = θ0), "end" (θ = θ1);
/// node sets also "all". Node id = j*(nr+1) + i (i radial, j angular); counter-clockwise elements.
struct AnnulusSectorSpec {
  double innerRadius = 100, thickness = 20;
  double startAngleDeg = 0, endAngleDeg = 90;
  int elementsThroughThickness = 13, elementsAroundArc = 101;
  std::string blockName = "block_1";
};
Mesh generateAnnulusSector(const AnnulusSectorSpec& spec);

}  // namespace contessa::mesh
