#pragma once
// What defines a contact interface, in mesh terms: its slave nodes with their tributary areas, its master
// facets (mesh nodes, or a rigid surface), the contact law's parameters. Built by ContactSurface from the
// deck's side sets; read by the contact interface (ContactInterface.hpp) and the graph reservation. A light
// header: no contact algorithm, no Trilinos.
#include <cstddef>
#include <string>
#include <vector>

#include "contact/ContactLawParameters.hpp"

namespace contessa::contact {

using GlobalIndex = long long;

/// A rigid master surface: facets over points that move rigidly by λ · motion. Each facet lists
/// nodesPerFacet point indices (2D: a segment, 2; 3D: a quadrilateral, 4), ordered so the facet's normal
/// (MasterFacet.hpp: the right of the direction of traversal in 2D, the right-hand rule in 3D) points out
/// of the rigid body, towards the slave.
struct RigidSurface {
  std::vector<double> points;  ///< reference positions, spaceDim values per point
  std::vector<int> facets;     ///< point indices (0-based), nodesPerFacet per facet
  std::vector<double> motion;  ///< displacement of every point at load factor 1, spaceDim values
};

/// A slave node on the axis (r = 0) of a revolved 3-node edge (ContactSurface::axisNodes): ∫ H 2πr ds weighs
/// it by 0, so it carries no contact force and its own ε_N g_N or multiplier is no pressure. Its output is
/// recovered from the edge's two other nodes (contact::valueOnAxis). Indices into slaveNodes; reference radii.
struct AxisNode {
  std::size_t node = 0, mid = 0, far = 0;  ///< the node on the axis, the edge's mid node, its other corner
  double rMid = 0, rFar = 0;               ///< 0 < rMid < rFar
};

/// Everything that defines an interface, in mesh terms (built by ContactSurface from side sets).
struct ContactInterfaceSpec {
  std::string name;
  int dimension = 2;                      ///< space dimension: 2 (node-to-segment) or 3 (node-to-face)
  std::vector<GlobalIndex> slaveNodes;    ///< mesh nodes, sorted
  std::vector<double> slaveAreas;         ///< tributary length (2D, unit thickness) or area (3D) of each slave node
  std::vector<double> slaveFacetLengths;  ///< mean size of the slave facets at each node (slip tolerance's L_k)
  /// Deformable master: mesh nodes, nodesPerFacet() per facet, oriented so the master body's outward
  /// normal is the facet's normal.
  std::vector<GlobalIndex> masterFacets;
  bool rigidMaster = false;
  RigidSurface rigidSurface;  ///< when rigidMaster
  ContactLawParameters law;
  /// Distance a slave node may move relative to the master beyond one master facet size before it needs a
  /// matrix coupling that was not reserved (the graph is then rebuilt around the current configuration);
  /// < 0: automatic (deck: Search Reach; CouplingReservation.hpp).
  double searchReach = -1.0;
  /// Two Pass: this spec is the interface's second pass, slave and master swapped, with its own history;
  /// its force acts on the first pass's master body. `name` is the deck's name in both passes.
  bool secondPass = false;
  /// Discretization = Mortar: the slave nodes' weighted gaps over the slave segments (MortarInterface.hpp)
  /// instead of one node-to-segment element per slave node.
  bool mortar = false;
  /// The slave side's facets as mesh node tuples, nodesPerFacet() per facet, oriented so their normal is
  /// the slave body's outward normal (the mortar integrates over them).
  std::vector<GlobalIndex> slaveFacets;
  /// Each slave facet's reference length (2D) or area (3D): the mortar's measure (MortarSegment, MortarFacetPair).
  std::vector<double> slaveFacetMeasures;
  /// Axisymmetric 3-node slave edges: the slave nodes on the axis, whose output is their edge's (AxisNode).
  std::vector<AxisNode> slaveAxisNodes;

  /// The interface in messages: its name, "(second pass)" added for the second pass.
  std::string label() const { return secondPass ? name + " (second pass)" : name; }

  /// Nodes per facet of a deformable master's side set and of the slave side set (MasterFacet.hpp: 2, 3 in 2D;
  /// 3, 4, 6, 8, 9 in 3D), set from their side sets (ContactSurface::nodesPerFacet); 0: the linear facet of
  /// the dimension (a rigid master's segments and quadrilaterals).
  int masterFacetNodes = 0;
  int slaveFacetNodes = 0;

  /// Nodes per master facet: the interface's facet type (makeContactInterface).
  int nodesPerFacet() const { return masterFacetNodes > 0 ? masterFacetNodes : linearFacetNodes(); }
  /// Nodes per facet of slaveFacets.
  int slaveNodesPerFacet() const { return slaveFacetNodes > 0 ? slaveFacetNodes : linearFacetNodes(); }
  int linearFacetNodes() const { return dimension == 2 ? 2 : 4; }
  std::size_t numMasterFacets() const {
    return (rigidMaster ? rigidSurface.facets.size() : masterFacets.size()) / static_cast<std::size_t>(nodesPerFacet());
  }
};

}  // namespace contessa::contact
