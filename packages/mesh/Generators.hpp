#pragma once
// Inline mesh generators (deck "Problem/Mesh/Type", registered in MeshFactory.cpp): Rectangle and
// Annulus Sector (Quad4), Box, Hollow Cylinder Sector and Sphere Octant (Hex8). Before allocating, each
// generator estimates the memory of a run on its mesh and refuses one that will not fit, naming its
// element-count parameters (requireRunFits). Their meshes pass Mesh::validate: positive Jacobians at
// every corner, side sets on the boundary with outward normals (Exodus side order). Errors are
// InputErrors whose message starts with the deck parameter's name ("Elements X: ...").
// One file per family: CartesianGenerators.cpp (Rectangle, Box), AnnulusGenerators.cpp (Annulus Sector,
// Hollow Cylinder Sector), SphereOctantGenerator.cpp; what they share in StructuredGrid.hpp (the grid,
// and a rank's part of it) and GeneratorSupport.hpp (parameter checks, memory check, graded positions).
#include <string>

#include "mesh/DistributedMesh.hpp"
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

/// Structured nx × ny × nz Hex8 mesh of [x0, x0+lx] × [y0, y0+ly] × [z0, z0+lz]: the Rectangle with a
/// third direction, graded the same way in each (biasX, biasY, biasZ as RectangleSpec::biasX).
/// Node sets and side sets: "left" (x = x0), "right", "bottom" (y = y0), "top", "back" (z = z0),
/// "front"; node sets also "all". Node id = (k*(ny+1) + j)*(nx+1) + i; element id = (k*ny + j)*nx + i;
/// each hexahedron lists its z = z_k face counter-clockwise seen from +z, then its z = z_(k+1) face.
struct BoxSpec {
  double x0 = 0, y0 = 0, z0 = 0, lx = 1, ly = 1, lz = 1;
  int nx = 1, ny = 1, nz = 1;
  std::string blockName = "block_1";
  double biasX = 1, biasY = 1, biasZ = 1;
};
Mesh generateBox(const BoxSpec& spec);

/// The annulus sector extruded along z over [z0, z0 + length] in `layers` layers of Hex8 (graded by
/// axialBias, as RectangleSpec::biasX). Layer k = 0 of nodes is the 2D annulus sector of `section`:
/// the same node ids (j*(nr+1) + i) and bit-identical x, y; node (i, j, k) is k*(nr+1)*(nt+1) +
/// j*(nr+1) + i and element (i, j, k) is k*nr*nt + j*nr + i, so element ids of the first layer are
/// the 2D ones. One layer with u_z = 0 everywhere reproduces a plane-strain run of the 2D sector.
/// Node sets and side sets: "inner", "outer", "start", "end" (as the annulus sector), "back"
/// (z = z0) and "front" (z = z0 + length); node sets also "all".
struct HollowCylinderSectorSpec {
  AnnulusSectorSpec section;
  double z0 = 0, length = 10;
  int layers = 1;
  double axialBias = 1;
};
Mesh generateHollowCylinderSector(const HollowCylinderSectorSpec& spec);

/// One eighth of a ball of radius R about `center`, on hexahedra without degenerate elements (an
/// O-grid, as a cube-sphere): an inner cube [0, f·R]³ (f = innerCubeFraction < 1/√3) meshed n × n × n,
/// and over each of its three outer faces a shell of n × n × m hexahedra reaching the sphere along
/// rays through the centre. Along a cube edge the nodes are equiangular as seen from the centre
/// (cube coordinate f·R·tan(π/4·t), t ∈ [0, 1]), so the three surface patches meet smoothly.
///
/// The octant is the one around the pole `poleDirection` ("-z", "+z", "-x", "+x", "-y", "+y"): with
/// "-z", x ≥ xc, y ≥ yc, z ≤ zc, the pole (xc, yc, zc − R) at the bottom, a body for Hertz contact on a
/// plane below. The patch around the pole spans the two other axes; poleBias grades its elements
/// along both of them (size far from the pole / size at the pole: > 1 refines near the pole), and
/// radialBias the shell layers (outermost / innermost thickness: < 1 refines towards the surface).
///
/// Side sets and node sets: "surface" (the curved part of the sphere), "equator" (the flat face
/// through the centre, normal to the pole), "symmetry_<a>" for each of the two other axes a ("x", "y"
/// or "z": the plane a = center_a); node sets also "pole" (the node on the pole) and "all".
/// Nodes: the cube's (k*(n+1) + j)*(n+1) + i first, then the shell layers outwards. Elements: the
/// cube's (as the box), then the shells.
struct SphereOctantSpec {
  double radius = 50;
  double center[3] = {0, 0, 0};
  std::string poleDirection = "-z";
  int elementsAlongEdge = 4, elementsThroughShell = 4;
  double innerCubeFraction = 0.5;
  double poleBias = 1, radialBias = 1;
  std::string blockName = "block_1";
};
Mesh generateSphereOctant(const SphereOctantSpec& spec);

/// Rank `rank`'s part (of `numRanks`) of the mesh the generator of the same name makes, built alone
/// without communication and without the rest of the mesh: the rank's elements (the structured grids:
/// its index box of GridPartition; the sphere octant, not one grid: its range of ElementRanges), their
/// nodes (bit-identical coordinates), the sets restricted to them, and each node's owner and sharing
/// ranks from the owners of the cells around it. Equal, field by field, to PartExtractor(whole mesh,
/// those owners).part(rank). The same parameter errors as the
/// whole-mesh generator, plus requirePartsFit (at most one rank per element); the part's mesh check is
/// the caller's, on every rank at once (validatePart, MeshDistribution.hpp). The sphere octant (not
/// one structured grid) finds the ranks of its part's nodes and the sets' global order in one pass
/// over every element's corners, computed and dropped one at a time: memory of the part plus its
/// surfaces, time of the whole mesh's connectivity.
DistributedMesh generateRectanglePart(const RectangleSpec& spec, int rank, int numRanks);
DistributedMesh generateAnnulusSectorPart(const AnnulusSectorSpec& spec, int rank, int numRanks);
DistributedMesh generateBoxPart(const BoxSpec& spec, int rank, int numRanks);
DistributedMesh generateHollowCylinderSectorPart(const HollowCylinderSectorSpec& spec, int rank, int numRanks);
DistributedMesh generateSphereOctantPart(const SphereOctantSpec& spec, int rank, int numRanks);

}  // namespace contessa::mesh
