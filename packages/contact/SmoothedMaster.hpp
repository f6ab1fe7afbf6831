#pragma once
// `Master Smoothing = Hermite` (docs/user-guide.md, docs/theory-contact.md §16): the 2D master
// side set's segments as C¹ Hermite segments (HermiteLine4Facet, SmoothedMasterFacet.hpp), and what the
// contact interface needs of such a facet beyond its traits: the friction history carried from one segment
// to the next, and the tunnelling check.
#include <vector>

#include "contact/HistoryTransfer.hpp"
#include "contact/InterfaceSpec.hpp"
#include "contact/SmoothedMasterFacet.hpp"
#include "contact/SweptCrossing.hpp"

namespace contessa::contact {

/// The master facets [x_p, x_a, x_b, x_n] of the 2-node segments `segments` (node pairs, the master body on
/// the left of a → b, as the side set gives them): x_p the other end of the segment ending at a, x_n of the
/// one starting at b. Where there is none (a free end of the surface) or more than one (a junction), the
/// end node itself stands in (x_p = x_a: the end tangent is then half the chord, the curve stays C¹ inside).
std::vector<GlobalIndex> hermiteMasterFacets(const std::vector<GlobalIndex>& segments);

/// A slave node moving from one smoothed segment to another: its contact point is carried along the curve.
/// Neighbours share their end and their end tangent dx̄/dξ (C¹), so ξ_n → ξ_n ∓ 2 and t_T1 = t·ā_1 is kept;
/// other pairs: x̄(ξ_n) projected on `to`, t_T1 scaled by ‖ā_1‖ at the two points, signed by their
/// orientation (as Line3Facet).
template <>
ContactHistory<1> transferHistory<HermiteLine4Facet>(const ContactHistory<1>& committed,
                                                     const MasterFacetNodes<HermiteLine4Facet>& from,
                                                     const MasterFacetNodes<HermiteLine4Facet>& to);

/// The tunnelling check on a smoothed segment: on its chord x_a – x_b (which lies within the sagitta
/// h²κ/8 of the curve: a node that went through the curve by more than that went through the chord).
template <>
SweptCrossing sweptCrossing<HermiteLine4Facet>(const HermiteLine4Facet::Point& slave0,
                                               const HermiteLine4Facet::Point& slave1,
                                               const std::array<HermiteLine4Facet::Point, 4>& facet0,
                                               const std::array<HermiteLine4Facet::Point, 4>& facet1,
                                               double insideTolerance);

}  // namespace contessa::contact
