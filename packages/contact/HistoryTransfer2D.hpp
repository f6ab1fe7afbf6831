#pragma once
// Friction history of a slave node that slides from one master segment to another (2D).
#include "contact/ContactHistory.hpp"
#include "contact/SegmentSelector2D.hpp"

namespace contessa::contact {

/// Re-expresses a committed history, stored on segment `from`, on segment `to`, so that the return
/// mapping of eq. (20) measures Δξ and t_T on the segment the node now projects on.
///
/// - Adjacent, consistently ordered segments (from.nodes[1] == to.nodes[0] or from.nodes[0] == to.nodes[1]):
///   the old contact point is unrolled along the surface through the shared vertex, so ā_11 Δξ² on `to`
///   is the arc length slid across the vertex (eq. 7), e.g. ξ_n → −1 − (1 − ξ_n) l_from / l_to.
/// - Other pairs: the old contact point x̄(ξ_n) is projected onto the line of `to`.
/// The covariant traction keeps its physical value: t_T1/‖ā_1‖ is invariant (eq. 14), sign by the
/// orientation of the two tangents. Status, accumulated slip are kept; segment becomes to.id.
///
/// Pass the coordinates of the COMMITTED configuration: the transferred ξ_n and t_T,n are then constants
/// during the Newton iterations of the increment, so the element's tangent stays exact.
ContactHistory<1> transferHistory2D(const ContactHistory<1>& committed, const MasterSegment2D& from,
                                    const MasterSegment2D& to);

}  // namespace contessa::contact
