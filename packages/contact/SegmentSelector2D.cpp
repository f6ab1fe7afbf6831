#include "contact/SegmentSelector2D.hpp"

#include <cmath>
#include <limits>

namespace contessa::contact {

namespace {

/// How far ξ̄ lies beyond the parent domain [−1, 1] (0 inside).
double overshoot(double xi) { return std::max(0.0, std::abs(xi) - 1.0); }

}  // namespace

SegmentSelection SegmentSelector2D::select(const Vector<2>& slave,
                                           const std::vector<MasterSegment2D>& candidates) const {
  const SegmentProjection2D projection(options_.projection);
  std::vector<ProjectionResult<Line2Facet>> projected;
  projected.reserve(candidates.size());
  for (const MasterSegment2D& segment : candidates) projected.push_back(projection.project(slave, segment.x));

  SegmentSelection best;
  double bestDistance = std::numeric_limits<double>::infinity();
  // The node is on candidate c's segment if its projection is closer than the best so far.
  const auto considerOnSegment = [&](std::size_t c) {
    const auto& p = projected[c];
    if (!(std::abs(p.gap) < bestDistance)) return;
    bestDistance = std::abs(p.gap);
    best.kind = SelectionKind::OnSegment;
    best.segment = candidates[c].id;
    best.vertexNode = -1;
    best.projection = p;
    best.gap = p.gap;
    best.normal = p.normal;
    best.closestPoint = p.position;
  };

  // 1. Projections inside their segment: the smaller |g_N| wins (concave corners, eq. 4).
  for (std::size_t c = 0; c < candidates.size(); ++c)
    if (projected[c].converged && projected[c].isInside(options_.insideTolerance)) considerOnSegment(c);

  // 2. Corner regions: a vertex that is the clamped closest point of two candidate segments.
  for (std::size_t a = 0; a < candidates.size(); ++a) {
    const auto& pa = projected[a];
    if (!pa.converged || pa.isInside(options_.insideTolerance)) continue;
    const int endA = pa.xi[0] > 0.0 ? 1 : 0;
    const int vertex = candidates[a].nodes[endA];
    for (std::size_t b = a + 1; b < candidates.size(); ++b) {
      const auto& pb = projected[b];
      if (!pb.converged || pb.isInside(options_.insideTolerance)) continue;
      const int endB = pb.xi[0] > 0.0 ? 1 : 0;
      if (candidates[b].nodes[endB] != vertex) continue;

      const Vector<2>& xv = candidates[a].x[endA];
      const Vector<2> d = subtract(slave, xv);
      const double distance = norm(d);
      if (!(distance < bestDistance)) continue;  // ties go to the inside projection
      // Sign of the gap from the averaged outward normal of the two segments (eq. 5 on each).
      const Vector<2> averaged = add(pa.normal, pb.normal);
      const double side = dot(d, averaged) >= 0.0 ? 1.0 : -1.0;
      const bool aOvershootsLess = overshoot(pa.xi[0]) <= overshoot(pb.xi[0]);
      bestDistance = distance;
      best.kind = SelectionKind::AtVertex;
      best.segment = aOvershootsLess ? candidates[a].id : candidates[b].id;
      best.vertexNode = vertex;
      best.projection = aOvershootsLess ? pa : pb;
      best.gap = side * distance;
      best.normal = distance > 0.0 ? scaled(side / distance, d) : scaled(1.0 / norm(averaged), averaged);
      best.closestPoint = xv;
    }
  }

  // 3. A penetrating node just past a free end of the master surface (a flush edge: the end segment
  //    tilts as it deforms, so a node sitting on the edge projects a little outside): it stays in
  //    contact with that segment, extended by at most freeEndTolerance in ξ.
  if (best.kind == SelectionKind::None)
    for (std::size_t c = 0; c < candidates.size(); ++c)
      if (projected[c].converged && projected[c].isPenetrating() && projected[c].isInside(options_.freeEndTolerance))
        considerOnSegment(c);

  // 4. Nothing inside and no corner: the node has left the master surface.
  if (best.kind == SelectionKind::None) best.gap = std::numeric_limits<double>::infinity();
  return best;
}

}  // namespace contessa::contact
