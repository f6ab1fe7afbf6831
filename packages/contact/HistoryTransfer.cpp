#include "contact/HistoryTransfer.hpp"

#include "contact/Projection.hpp"

#include <cmath>

namespace contessa::contact {

template <>
ContactHistory<1> transferHistory<Line2Facet>(const ContactHistory<1>& committed, const MasterFacetNodes<Line2Facet>& from,
                                              const MasterFacetNodes<Line2Facet>& to) {
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

/// Quadratic segments (Line3Facet): as straight ones, with ā_1 taken where the contact point is (at the shared
/// vertex when the node slides across it), so the arc length slid past the vertex is kept to first order.
template <>
ContactHistory<1> transferHistory<Line3Facet>(const ContactHistory<1>& committed, const MasterFacetNodes<Line3Facet>& from,
                                              const MasterFacetNodes<Line3Facet>& to) {
  ContactHistory<1> moved = committed;
  moved.segment = to.id;
  if (!committed.isInContact() || from.id == to.id) return moved;
  const auto tangentAt = [](const MasterFacetNodes<Line3Facet>& f, double xi) {
    return Projection<Line3Facet>::evaluateAt(Line3Facet::Point{}, f.x, {xi}).covariantBasis[0];
  };
  const double xiFrom = committed.xi[0];
  double orientation = 1.0;
  double lengthRatio = 1.0;
  if (from.nodes[1] == to.nodes[0] || from.nodes[0] == to.nodes[1]) {
    // The shared vertex: ξ = +1 of `from` and −1 of `to`, or the reverse.
    const double end = from.nodes[1] == to.nodes[0] ? 1.0 : -1.0;
    lengthRatio = norm(tangentAt(from, end)) / norm(tangentAt(to, -end));
    moved.xi[0] = -end - (end - xiFrom) * lengthRatio;
  } else {
    const Line3Facet::Point oldPoint = Projection<Line3Facet>::evaluateAt(Line3Facet::Point{}, from.x, committed.xi).position;
    moved.xi = Projection<Line3Facet>().project(oldPoint, to.x).xi;
    const auto aFrom = tangentAt(from, xiFrom), aTo = tangentAt(to, moved.xi[0]);
    lengthRatio = norm(aFrom) / norm(aTo);
    orientation = dot(aFrom, aTo) >= 0.0 ? 1.0 : -1.0;
  }
  moved.tangentialTraction[0] = orientation * committed.tangentialTraction[0] / lengthRatio;
  return moved;
}

template <class Facet>
ContactHistory<Facet::kSurfaceDim> transferHistory(const ContactHistory<Facet::kSurfaceDim>& committed,
                                                   const MasterFacetNodes<Facet>& from,
                                                   const MasterFacetNodes<Facet>& to) {
  constexpr int M = Facet::kSurfaceDim;
  using Point = typename Facet::Point;
  ContactHistory<M> moved = committed;
  moved.segment = to.id;
  if (!committed.isInContact() || from.id == to.id) return moved;

  // The old contact point and its physical traction t = t_α ā^α (eq. 14) on `from`.
  const auto old = Projection<Facet>::evaluateAt(Point{}, from.x, committed.xi);
  Point traction{};
  for (int al = 0; al < M; ++al) addScaled(traction, committed.tangentialTraction[al], old.contravariantBasis[al]);
  const double magnitude = norm(traction);

  // A shared edge: two nodes with the same ids (local indices in `from` and `to`).
  std::array<int, 2> inFrom{-1, -1}, inTo{-1, -1};
  int shared = 0;
  for (int i = 0; i < Facet::kNodes; ++i)
    for (int j = 0; j < Facet::kNodes; ++j)
      if (from.nodes[i] == to.nodes[j] && shared < 2) {
        inFrom[shared] = i;
        inTo[shared] = j;
        ++shared;
      }

  Point point = old.position;
  Point movedTraction = traction;
  if (shared == 2) {
    // Unfold about the edge e0 → e1: the component along the edge is kept; the component across it, in
    // the plane of `from` (pointing into `from`), turns into the plane of `to`, pointing out of `to`.
    const Point& e0 = to.x[inTo[0]];
    const Point edge = subtract(to.x[inTo[1]], e0);
    const Point along = scaled(1.0 / norm(edge), edge);
    // Unit vectors perpendicular to the edge, in each facet's tangent plane at the edge's midpoint,
    // pointing into that facet (towards its centre).
    auto inward = [&](const MasterFacetNodes<Facet>& f, const std::array<int, 2>& local) {
      const auto mid = scaled(0.5, add(Facet::nodeCoords(local[0]), Facet::nodeCoords(local[1])));
      const auto atEdge = Projection<Facet>::evaluateAt(Point{}, f.x, mid);
      Point m = cross(atEdge.normal, along);
      const auto centre = Projection<Facet>::evaluateAt(Point{}, f.x, Facet::center()).position;
      if (dot(m, subtract(centre, atEdge.position)) < 0.0) m = scaled(-1.0, m);
      return m;
    };
    const Point inFromFacet = inward(from, inFrom);
    const Point inToFacet = inward(to, inTo);
    const Point relative = subtract(old.position, e0);
    point = add(e0, add(scaled(dot(relative, along), along), scaled(-dot(relative, inFromFacet), inToFacet)));
    movedTraction = add(scaled(dot(traction, along), along), scaled(-dot(traction, inFromFacet), inToFacet));
  }
  const auto onTo = Projection<Facet>().project(point, to.x);
  moved.xi = onTo.xi;
  // Tangential part on `to`, with the magnitude of the old traction.
  const Point tangential = subtract(movedTraction, scaled(dot(movedTraction, onTo.normal), onTo.normal));
  const double tangentialNorm = norm(tangential);
  const Point carried = tangentialNorm > 0.0 ? scaled(magnitude / tangentialNorm, tangential) : Point{};
  for (int al = 0; al < M; ++al) moved.tangentialTraction[al] = dot(carried, onTo.covariantBasis[al]);  // t_α = t·ā_α
  return moved;
}

template ContactHistory<2> transferHistory<Quad4Facet>(const ContactHistory<2>&, const MasterFacetNodes<Quad4Facet>&,
                                                       const MasterFacetNodes<Quad4Facet>&);

template ContactHistory<2> transferHistory<Tri3Facet>(const ContactHistory<2>&, const MasterFacetNodes<Tri3Facet>&,
                                                      const MasterFacetNodes<Tri3Facet>&);
template ContactHistory<2> transferHistory<Tri6Facet>(const ContactHistory<2>&, const MasterFacetNodes<Tri6Facet>&,
                                                      const MasterFacetNodes<Tri6Facet>&);
template ContactHistory<2> transferHistory<Quad8Facet>(const ContactHistory<2>&, const MasterFacetNodes<Quad8Facet>&,
                                                      const MasterFacetNodes<Quad8Facet>&);
template ContactHistory<2> transferHistory<Quad9Facet>(const ContactHistory<2>&, const MasterFacetNodes<Quad9Facet>&,
                                                      const MasterFacetNodes<Quad9Facet>&);

}  // namespace contessa::contact
