#pragma once
// Inline mesh generators for decks ("Problem/Mesh/Type" = "Rectangle" or "Annulus Sector").
// Before allocating, each generator estimates the memory of a run on its mesh and refuses one that
// will not fit, naming its element-count parameters (requireRunFits). Their meshes pass
// Mesh::validate.
#include <string>

#include "mesh/Mesh.hpp"

namespace contessa::mesh {

/// Structured nx × ny Quad4 mesh of [x0, x0+lx] × [y0, y0+ly].
/// Node sets and side sets: "left" (x = x0), "right", "bottom" (y = y0), "top"; node sets also
/// "all". Node id = j*(nx+1) + i; element id = j*nx + i; counter-clockwise connectivity.
///
/// Grading: biasX (biasY) is the ratio of the LAST element's size to the FIRST one's along x (y):
/// sizes form a geometric progression h, h·q, …, h·q^(n−1) with q = bias^(1/(n−1)) summing to the
/// length. 1 = uniform (identical coordinates to the ungraded generator), > 1 = elements grow with
/// x (y), < 1 = they shrink. Must be finite and > 0 ("Bias X", "Bias Y"); ignored when n = 1. The
/// last node is exactly at x0 + lx (y0 + ly).
struct RectangleSpec {
  double x0 = 0, y0 = 0, lx = 1, ly = 1;
  int nx = 1, ny = 1;
  std::string blockName = "block_1";
  double biasX = 1, biasY = 1;
};
Mesh generateRectangle(const RectangleSpec& spec);

/// Annulus sector (ring segment) centred at the origin: radii [ri, ri+t], angles [θ0, θ1] (degrees,
/// counter-clockwise from +x). nr elements through the thickness, nt around the arc.
/// Node sets and side sets: "inner" (r = ri), "outer" (r = ri + t), "start" (θ = θ0), "end" (θ = θ1);
/// node sets also "all". Node id = j*(nr+1) + i (i radial, j angular); counter-clockwise elements.
///
/// Grading, same meaning as RectangleSpec::biasX: radialBias is the ratio of the outermost to the
/// innermost element's radial size (inner → outer radius), arcBias the ratio of the last to the first
/// element's angular size (start → end angle). Must be finite and > 0 ("Radial Bias", "Arc Bias");
/// 1 = uniform. The last nodes are exactly at r = ri + t and θ = θ1.
struct AnnulusSectorSpec {
  double innerRadius = 100, thickness = 20;
  double startAngleDeg = 0, endAngleDeg = 90;
  int elementsThroughThickness = 13, elementsAroundArc = 101;
  std::string blockName = "block_1";
  double radialBias = 1, arcBias = 1;
};
Mesh generateAnnulusSector(const AnnulusSectorSpec& spec);

}  // namespace contessa::mesh
