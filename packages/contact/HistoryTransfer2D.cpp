#include "contact/HistoryTransfer2D.hpp"

namespace contessa::contact {

ContactHistory<1> transferHistory2D(const ContactHistory<1>& committed, const MasterSegment2D& from,
                                    const MasterSegment2D& to) {
  ContactHistory<1> moved = committed;
  moved.segment = to.id;
  if (!committed.isInContact() || from.id == to.id) return moved;

  const Vector<2> aFrom = scaled(0.5, subtract(from.x[1], from.x[0]));  // ā_1 of `from`
  const Vector<2> aTo = scaled(0.5, subtract(to.x[1], to.x[0]));        // ā_1 of `to`
  const double lengthRatio = norm(aFrom) / norm(aTo);
  const double xiFrom = committed.xi[0];
  double orientation = 1.0;

  if (from.nodes[1] == to.nodes[0]) {
    // Shared vertex at ξ = +1 of `from` and ξ = −1 of `to`.
    moved.xi[0] = -1.0 - (1.0 - xiFrom) * lengthRatio;
  } else if (from.nodes[0] == to.nodes[1]) {
    // Shared vertex at ξ = −1 of `from` and ξ = +1 of `to`.
    moved.xi[0] = 1.0 + (1.0 + xiFrom) * lengthRatio;
  } else {
    const auto h = Line2Facet::shapeFunctions(committed.xi);
    const Vector<2> oldPoint = add(scaled(h[0], from.x[0]), scaled(h[1], from.x[1]));
    moved.xi = SegmentProjection2D().project(oldPoint, to.x).xi;
    orientation = dot(aFrom, aTo) >= 0.0 ? 1.0 : -1.0;
  }
  // t_T1 = t·ā_1: the physical component t·ā_1/‖ā_1‖ is carried over.
  moved.tangentialTraction[0] = orientation * committed.tangentialTraction[0] / lengthRatio;
  return moved;
}

}  // namespace contessa::contact
