#pragma once
// Local search for one slave node among candidate master segments (2D node-to-segment): which segment
// (or corner vertex) the node is in contact with, after the global search (BoundingBoxTree) has produced
// the candidates.
#include "contact/Projection.hpp"

#include <vector>

namespace contessa::contact {

/// One master segment as the selector sees it: its id, its global node ids (to recognise shared
/// vertices between neighbours) and the current positions of its nodes.
using MasterSegment2D = MasterFacetNodes<Line2Facet>;

enum class SelectionKind {
  OnSegment,  ///< ξ̄ inside [−1 − tol, 1 + tol] of `segment`
  AtVertex,   ///< closest point is a vertex shared by two candidate segments (corner region)
  None        ///< no valid projection: the node has left the master surface, not in contact
};

struct SegmentSelection {
  SelectionKind kind = SelectionKind::None;
  int segment = -1;     ///< segment on which the node-to-segment element is evaluated
  int vertexNode = -1;  ///< AtVertex: the global node id of the vertex
  ProjectionResult<Line2Facet> projection{};  ///< projection on `segment`, unclamped
  double gap = 0.0;        ///< signed distance to the closest point, eq. (4) (vertex distance for AtVertex)
  Vector<2> normal{};      ///< unit normal at the closest point, g_N = (x^k − closest point)·normal
  Vector<2> closestPoint{};

  /// eq. (6): only a penetrating node carries a contact force.
  bool isPenetrating() const { return kind != SelectionKind::None && gap < 0.0; }
};

struct SegmentSelectorOptions {
  /// A projection with |ξ̄| ≤ 1 + insideTolerance counts as inside its segment. Slightly positive so a
  /// node sitting exactly on a vertex does not flicker between "on segment" and "at vertex".
  double insideTolerance = 1e-8;
  /// A PENETRATING node past a free end of the master surface stays on the end segment while
  /// |ξ̄| ≤ 1 + freeEndTolerance (0.1: 5 % of the segment length), so a slave node on a flush edge
  /// is not dropped when the end segment tilts under load.
  double freeEndTolerance = 0.1;
  ProjectionOptions projection{};
};

/// Chooses the master segment of one slave node among candidates:
///  - projections inside their segment (eq. 1–4) are preferred; when several are inside (a node above
///    a concave corner of the master body, or a penetrating node near a convex one), the smaller |g_N|
///    wins: the node is pushed out the shortest way. A node sliding from one segment to the next
///    therefore switches segment exactly when its projection leaves the first one.
///  - when a vertex shared by two candidates is the clamped closest point of both (the node is in the
///    corner region: outside a convex corner, or under a concave corner of the master body), the
///    closest VERTEX is the contact point: g_N = ±‖x^k − x_v‖, signed by the averaged normal of the two
///    segments, normal along x^k − x_v. We chose the vertex rather than extending one segment because it
///    is the true closest point of the piecewise-linear surface: the gap stays continuous as the node
///    goes round the corner, which the load-step predictor of eq. (11) relies on. A vertex wins over an
///    inside projection only when it is strictly closer (possible only for non-adjacent candidates).
///    The element is then evaluated on `segment`, the neighbour whose projection overshoots least
///    (i.e. on that segment extended by the overshoot).
///  - a PENETRATING node just past a free end (|ξ̄| ≤ 1 + freeEndTolerance) stays on the end segment:
///    on a flush edge the end segment tilts under load and the edge node projects slightly outside.
///  - otherwise a node whose projections all fall outside and whose clamped vertex is a free end of
///    the candidate set has left the master surface: kind None, not in contact.
class SegmentSelector2D {
 public:
  explicit SegmentSelector2D(SegmentSelectorOptions options = {}) : options_(options) {}

  SegmentSelection select(const Vector<2>& slave, const std::vector<MasterSegment2D>& candidates) const;

  const SegmentSelectorOptions& options() const { return options_; }

 private:
  SegmentSelectorOptions options_;
};

}  // namespace contessa::contact
