#pragma once
// Mortar (segment-to-segment) contact of one interface, penalty or augmented Lagrangian (theory-contact §13.4); 2D frictionless or Coulomb, 3D
// frictionless or Coulomb on linear and quadratic faces (theory-contact.md §13, eq. M21 on quadratic ones): each slave node k carries the weighted gap g̃_k = ∫ N_k g dΓ_0 over
// its slave facets (2D, MortarSegment.hpp: segmented along the averaged nodal normals; 3D,
// MortarFacetPair.hpp: the facets projected on the slave facet's plane and clipped; the gap along the
// master's normal in both), the pressure p_k = ε_N ⟨−g̃_k⟩ / A_k (A_k its reference tributary length or
// area, as the node-to-facet force uses) and the contact energy Σ_k ε_N ⟨−g̃_k⟩² / (2 A_k), whose gradient is the residual and whose
// Hessian, with the exact second derivatives of g̃_k, the tangent. With friction, the weighted slip
// increment Δũ_k (eq. M9; in 3D a 2-vector in the node's tangent basis, eq. M9′, MortarSlipBasis.hpp) goes
// through node-to-segment's return mapping (CoulombReturnMapping<kDim − 1>) and adds t_Tα ∇Δũ_kα and its
// linearisation (eq. M11–M12, M11′–M12′). Behind the same ContactInterfaceBase as node-to-segment:
// the owner of slave node k assembles node k's term (its weighted gap's whole support: the slave nodes
// within two segments in 2D, of its facets in 3D, and the master nodes under its facets), and Contact Beta counts events on the
// slave nodes' weighted gaps and stick/slip states.
#include <memory>
#include <vector>

#include "contact/ContactInterface.hpp"

namespace contessa::contact {

/// The mortar interface of spec (spec.mortar; 2D segments of 2 nodes, or 3 on a side: MortarQuadraticSegment.hpp; 3D triangles (3- or 6-node) and quadrilaterals (4, 8
/// or 9 nodes), frictionless or Coulomb on each).
std::unique_ptr<ContactInterfaceBase> makeMortarInterface(ContactInterfaceSpec spec, std::vector<char> evaluatesSlave);

/// The spec whose reservation (CouplingReservation) holds every master node a mortar slave node's term can
/// couple: the master facets within reach of the node plus one slave segment length (the search-based rule
/// always; the whole master surface would make each slave node's block dense in all its nodes).
ContactInterfaceSpec mortarReservationSpec(const ContactInterfaceSpec& spec);

/// The slave nodes (indices into spec.slaveNodes) a mortar slave node k's term couples, k first: in 2D
/// those within two slave segments (its segments' nodes, and theirs through the averaged nodal normals), in
/// 3D those of its slave facets.
std::vector<std::size_t> mortarSlaveNeighbours(const ContactInterfaceSpec& spec, std::size_t k);

}  // namespace contessa::contact
