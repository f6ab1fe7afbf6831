#pragma once
// Friction history of a slave node that slides from one master facet to another.
#include "contact/ContactHistory.hpp"
#include "contact/MasterFacet.hpp"

namespace contessa::contact {

/// Re-expresses a committed history, stored on facet `from`, on facet `to`, so that the return mapping of
/// eq. (20) measures Δξ and t_T on the facet the node now projects on. The physical tangential traction
/// t_T = t_Tα ā^α (eq. 14) is carried over (its magnitude is kept); status and accumulated slip are kept;
/// `segment` becomes to.id.
///
/// Straight segments (Line2Facet):
/// - adjacent, consistently ordered segments (from.nodes[1] == to.nodes[0] or from.nodes[0] == to.nodes[1]):
///   the old contact point is unrolled along the surface through the shared vertex, so ā_11 Δξ² on `to`
///   is the arc length slid across the vertex (eq. 7), e.g. ξ_n → −1 − (1 − ξ_n) l_from / l_to;
/// - other pairs: the old contact point x̄(ξ_n) is projected onto the line of `to`; the traction's sign
///   follows the orientation of the two tangents.
/// Faces (any other facet):
/// - neighbours sharing an edge (two nodes): the old contact point and its traction are unfolded about the
///   shared edge into the surface of `to` (the distance from the edge and the position along it are kept,
///   the point lands on the far side of the edge, outside `to`), then projected onto `to`;
/// - other pairs (a shared corner, or none): x̄(ξ_n) is projected onto `to`, and the traction onto its
///   tangent plane, with its magnitude kept.
///
/// Pass the coordinates of the COMMITTED configuration: the transferred ξ_n and t_T,n are then constants
/// during the Newton iterations of the increment, so the element's tangent stays exact.
template <class Facet>
ContactHistory<Facet::kSurfaceDim> transferHistory(const ContactHistory<Facet::kSurfaceDim>& committed,
                                                   const MasterFacetNodes<Facet>& from,
                                                   const MasterFacetNodes<Facet>& to);

template <>
ContactHistory<1> transferHistory<Line2Facet>(const ContactHistory<1>& committed, const MasterFacetNodes<Line2Facet>& from,
                                              const MasterFacetNodes<Line2Facet>& to);

template <>
ContactHistory<1> transferHistory<Line3Facet>(const ContactHistory<1>& committed, const MasterFacetNodes<Line3Facet>& from,
                                              const MasterFacetNodes<Line3Facet>& to);
extern template ContactHistory<2> transferHistory<Tri3Facet>(const ContactHistory<2>&, const MasterFacetNodes<Tri3Facet>&,
                                                             const MasterFacetNodes<Tri3Facet>&);
extern template ContactHistory<2> transferHistory<Tri6Facet>(const ContactHistory<2>&, const MasterFacetNodes<Tri6Facet>&,
                                                             const MasterFacetNodes<Tri6Facet>&);
extern template ContactHistory<2> transferHistory<Quad8Facet>(const ContactHistory<2>&, const MasterFacetNodes<Quad8Facet>&,
                                                             const MasterFacetNodes<Quad8Facet>&);
extern template ContactHistory<2> transferHistory<Quad9Facet>(const ContactHistory<2>&, const MasterFacetNodes<Quad9Facet>&,
                                                             const MasterFacetNodes<Quad9Facet>&);
extern template ContactHistory<2> transferHistory<Quad4Facet>(const ContactHistory<2>&, const MasterFacetNodes<Quad4Facet>&,
                                                              const MasterFacetNodes<Quad4Facet>&);

}  // namespace contessa::contact
