#pragma once
// The geometry an interface needs of a mesh side set, built once in the reference configuration: the
// slave nodes with their tributary areas and facet sizes, and the master facets as oriented node tuples.
// Also the checks of a rigid master surface given in the deck.
#include <string>
#include <vector>

#include "contact/ContactInterface.hpp"
#include "contact/MasterFacet.hpp"
#include "mesh/Mesh.hpp"
#include "mesh/MeshDistribution.hpp"

namespace contessa::contact {

struct ContactSurface {
  int nodesPerFacet = 2;  ///< the facet type (MasterFacet.hpp): 2, 3 (2D); 3, 4, 6, 8, 9 (3D)
  std::vector<GlobalIndex> nodes;      ///< the side set's nodes, sorted
  /// Tributary area A_k of each node, summed over its facets (tributaryAreas: 2D: half of each adjacent side's
  /// length, per unit thickness; revolved: ∫ H_k 2π r ds; 3D bilinear faces: ∫ H_k dA, 2×2 Gauss; quadratic
  /// facets: see tributaryAreas): a traction times A_k is the nodal force.
  std::vector<double> areas;
  /// L_k, the mean size of the facets at each node (2D: side length; 3D: √(face area)), the length the
  /// slip tolerance refers to (ContactLawParameters).
  std::vector<double> facetLengths;
  /// The sides as node tuples in mesh::sideNodes order, nodesPerFacet per side: the Exodus side orderings
  /// make the facet's normal (MasterFacet.hpp) the outward normal of the body.
  std::vector<GlobalIndex> facets;
  /// A revolved surface of 3-node edges: its nodes on the axis, each with the edge it recovers its output
  /// from (AxisNode, valueOnAxis); empty otherwise.
  std::vector<AxisNode> axisNodes;

  /// Throws InputError starting with `where` for a side set that is not a surface of the mesh's dimension.
  static ContactSurface fromSideSet(const mesh::Mesh& mesh, const mesh::SideSet& set, const std::string& where);
  /// The same from the side set's facets alone (mesh::surfaceOfSideSet of a replicated mesh, or
  /// mesh::gatherSurface from the ranks' parts of a distributed one): identical, bit for bit. `revolved`:
  /// a 2D surface of an axisymmetric body (r = x): its areas are those of the full circumference.
  static ContactSurface fromSurface(const mesh::ReplicatedSurface& facets, const std::string& where,
                                   bool revolved = false);
};

/// The tributary area of each node of a slave facet (a traction times it is the nodal force) and the facet's
/// area, in the facet's node order: for a straight segment l/2 each (revolved about the y axis: ∫ H_i 2π r ds);
/// the consistent ∫ H_i dA where it is positive at every node (Tri3, Quad4 faces, Line3 edges, Quad9 faces:
/// a uniform gap then loads the body as a uniform pressure does); the consistent areas of the linear
/// sub-facets where it is not (Tri6 and Quad8 faces, whose corners ∫ H_i dA leaves with zero or negative
/// weight; MasterFacet.hpp, docs/theory-contact.md).
template <class Facet>
std::array<double, Facet::kNodes> tributaryAreas(const std::array<typename Facet::Point, Facet::kNodes>& x,
                                                 bool revolved, double& area);

/// The value at the axis (r = 0) of a nodal field of a revolved 3-node edge (contact pressure, gap), from its
/// values at the edge's mid node and other corner: the field a + b r² through them. A smooth axisymmetric
/// field is even in r (∂/∂r = 0 on the axis), and the consistent weights ∫ H 2πr ds leave the node on the axis
/// with no information of its own (its row of the projection ∫ H_i H_j 2πr ds p_j = ∫ H_i t 2πr ds, with its
/// right-hand side 0, would only copy the far corner's value, H_0 H_1 integrating to 0 on a straight edge).
/// Exact for a + b r²; p₀ √(1 − r²/a²) (Hertz) to p₀ r_mid² r_far² / (8 a⁴). On a straight edge, (4 f_mid − f_far)/3.
double valueOnAxis(const AxisNode& axis, double atMid, double atFar);

/// Checks a rigid master surface of the given dimension (one-line InputError naming `where`/Points,
/// Facets or Motion): spaceDim coordinates per point, facets of 2 (2D) or 4 (3D) indices in range, no
/// degenerate facet (coincident points; a quad with a vanishing or folded area Jacobian), motion of
/// spaceDim values.
void validateRigidSurface(const RigidSurface& surface, int dimension, const std::string& where);

/// Checks that each facet of a rigid master surface faces the slave body (its normal, MasterFacet.hpp,
/// points out of the rigid body, towards the slave) in the reference configuration: one-line InputError
/// naming `where`/Facets and the facet when a facet has slave faces behind it turned the same way as it
/// (normals within 60°, gap ≤ 0: the slave body lies on the facet's outer side, as it does when the facet's
/// points are listed clockwise) and none in front of it turned towards it. Only slave faces whose centre
/// projects inside the facet and lies within a facet size of it count; a facet with none is not judged.
/// Without this check such a facet simply never touched the slave: a run to the end with zero force.
void checkRigidSurfaceFacesSlave(const RigidSurface& surface, const mesh::ReplicatedSurface& slave,
                                 const std::string& where);

}  // namespace contessa::contact
