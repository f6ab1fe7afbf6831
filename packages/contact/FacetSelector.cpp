#include "contact/FacetSelector.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace contessa::contact {

namespace {

/// How far ξ̄ lies beyond the parent domain [−1, 1] of a segment (0 inside).
double overshoot(double xi) { return std::max(0.0, std::abs(xi) - 1.0); }

/// The node is on candidate c's facet if its projection is closer than the best so far.
template <class Facet>
void considerOnFacet(const ProjectionResult<Facet>& p, int facet, FacetSelection<Facet>& best, double& bestDistance) {
  if (!(std::abs(p.gap) < bestDistance)) return;
  bestDistance = std::abs(p.gap);
  best.kind = SelectionKind::OnFacet;
  best.facet = facet;
  best.vertexNode = -1;
  best.edgeNodes = {-1, -1};
  best.projection = p;
  best.gap = p.gap;
  best.normal = p.normal;
  best.closestPoint = p.position;
}

/// How far the projection x̄(ξ̄) lies beyond the facet, on its extension: the distance to x̄ at ξ̄ clamped to
/// the parent domain (0 inside).
template <class Facet>
double distanceBeyond(const ProjectionResult<Facet>& p, const std::array<typename Facet::Point, Facet::kNodes>& x) {
  const typename Facet::SurfaceCoords clamped = Facet::clampToDomain(p.xi).xi;
  if (clamped == p.xi) return 0.0;
  return norm(subtract(p.position, Projection<Facet>::evaluateAt(typename Facet::Point{}, x, clamped).position));
}

/// A node in contact (g_N < heldGap: the penalty law's g_N < 0, or the augmented λ_N + ε_N g_N < 0 of
/// eq. 15.1) past a free boundary of the master surface that stays in contact with the boundary facet
/// (FacetSelectorOptions::freeEdgeTolerance): past it by at most `reach`.
template <class Facet>
bool withinFreeEdgeReach(const ProjectionResult<Facet>& p, const std::array<typename Facet::Point, Facet::kNodes>& x,
                         double reach, double heldGap) {
  return p.converged && p.gap < heldGap && distanceBeyond(p, x) <= reach;
}


/// Whether unit normals at a shared vertex or edge point agree to within `angle`: the surface is flat there
/// (FacetSelectorOptions::flatAngle).
template <class Point>
bool flatAcross(const std::vector<Point>& normals, double angle) {
  for (std::size_t h = 1; h < normals.size(); ++h)
    if (norm(subtract(normals[h], normals[0])) > angle) return false;
  return true;
}

/// Rule 3 of both selectors: a node in contact (g_N < heldGap) past the free boundary of the master surface
/// by at most `reach` stays on a facet there, extended (`usable`: the candidates the rule may take); of
/// several in reach, the smaller |g_N|.
template <class Facet>
void keepPastFreeBoundary(const std::vector<ProjectionResult<Facet>>& projected,
                          const std::vector<MasterFacetNodes<Facet>>& candidates, const std::vector<char>& usable,
                          double reach, double heldGap, FacetSelection<Facet>& best, double& bestDistance) {
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (!usable[c] || !withinFreeEdgeReach(projected[c], candidates[c].x, reach, heldGap)) continue;
    considerOnFacet(projected[c], candidates[c].id, best, bestDistance);
  }
}

// ---- 2D node-to-segment (Line2Facet, Line3Facet) ----------------------------------------------------------
//
// A segment's ends (ξ = −1, +1) are its nodes 0 and 1, straight or quadratic, 1 and 2 smoothed
// (segmentEndNode): neighbours share an end.

template <class Facet>
FacetSelection<Facet> selectOnSegments(const FacetSelectorOptions& options_, const typename Facet::Point& slave,
                                       const std::vector<MasterFacetNodes<Facet>>& candidates, double slaveSize,
                                       double heldGap) {
  const Projection<Facet> projection(options_.projection);
  std::vector<ProjectionResult<Facet>> projected;
  projected.reserve(candidates.size());
  for (const auto& segment : candidates) projected.push_back(projection.project(slave, segment.x));

  FacetSelection<Facet> best;
  double bestDistance = std::numeric_limits<double>::infinity();

  // 1. Projections inside their segment: the smaller |g_N| wins (concave corners, eq. 4).
  for (std::size_t c = 0; c < candidates.size(); ++c)
    if (projected[c].converged && projected[c].isInside(options_.insideTolerance))
      considerOnFacet(projected[c], candidates[c].id, best, bestDistance);

  // 2. Corner regions: a vertex that is the clamped closest point of two candidate segments, unless a free
  //    end of the surface is closer (the node is then past that end, as in 3D).
  double freeEndDistance = std::numeric_limits<double>::infinity();
  const std::array<int, 2> ends{segmentEndNode<Facet>(0), segmentEndNode<Facet>(1)};  // local nodes at ξ = ∓1
  for (std::size_t c = 0; c < candidates.size(); ++c)
    for (int end = 0; end < 2; ++end) {
      const int vertex = candidates[c].nodes[ends[end]];
      bool shared = false;
      for (std::size_t o = 0; o < candidates.size() && !shared; ++o)
        shared = o != c && (candidates[o].nodes[ends[0]] == vertex || candidates[o].nodes[ends[1]] == vertex);
      if (!shared) freeEndDistance = std::min(freeEndDistance, norm(subtract(slave, candidates[c].x[ends[end]])));
    }
  for (std::size_t a = 0; a < candidates.size(); ++a) {
    const auto& pa = projected[a];
    if (!pa.converged || pa.isInside(options_.insideTolerance)) continue;
    const int endA = ends[pa.xi[0] > 0.0 ? 1 : 0];
    const int vertex = candidates[a].nodes[endA];
    for (std::size_t b = a + 1; b < candidates.size(); ++b) {
      const auto& pb = projected[b];
      if (!pb.converged || pb.isInside(options_.insideTolerance)) continue;
      const int endB = ends[pb.xi[0] > 0.0 ? 1 : 0];
      if (candidates[b].nodes[endB] != vertex) continue;

      const Vector<2>& xv = candidates[a].x[endA];
      const Vector<2> d = subtract(slave, xv);
      const double distance = norm(d);
      if (!(distance < bestDistance)) continue;  // ties go to the inside projection
      if (!(distance <= freeEndDistance)) continue;  // past a free end: not this corner
      // Sign of the gap from the averaged outward normal of the two segments (eq. 5 on each).
      const Vector<2> averaged = add(pa.normal, pb.normal);
      const double side = dot(d, averaged) >= 0.0 ? 1.0 : -1.0;
      const bool aOvershootsLess = overshoot(pa.xi[0]) <= overshoot(pb.xi[0]);
      if (flatAcross(std::vector<Vector<2>>{pa.normal, pb.normal}, options_.flatAngle)) {
        // Collinear segments: no corner; the segment overshot least, extended (FacetSelectorOptions::flatAngle).
        bestDistance = std::numeric_limits<double>::infinity();
        considerOnFacet(aOvershootsLess ? pa : pb, aOvershootsLess ? candidates[a].id : candidates[b].id, best,
                        bestDistance);
        continue;
      }
      bestDistance = distance;
      best.kind = SelectionKind::AtVertex;
      best.facet = aOvershootsLess ? candidates[a].id : candidates[b].id;
      best.vertexNode = vertex;
      best.projection = aOvershootsLess ? pa : pb;
      best.gap = side * distance;
      best.normal = distance > 0.0 ? scaled(side / distance, d) : scaled(1.0 / norm(averaged), averaged);
      best.closestPoint = xv;
    }
  }

  // 3. A node in contact (g_N < heldGap) just past a free end of the master surface (a flush edge: the end
  //    segment tilts as it deforms, so a node sitting on the edge projects a little outside): it stays in
  //    contact with that segment, extended, while it is past the end by at most freeEdgeTolerance × L_k.
  if (best.kind == SelectionKind::None)
    keepPastFreeBoundary(projected, candidates, std::vector<char>(candidates.size(), 1),
                         options_.freeEdgeTolerance * slaveSize, heldGap, best, bestDistance);

  // 4. Nothing inside and no corner: the node has left the master surface.
  if (best.kind == SelectionKind::None) best.gap = std::numeric_limits<double>::infinity();
  return best;
}

// ---- 3D node-to-face (Tri3, Quad4, Tri6, Quad8, Quad9 facets) ----------------------------------------------
//
// A face's boundary is walked along its boundarySegments() (MasterFacet.hpp): the edges of a linear face, which
// are straight (a bilinear face is linear along each edge), and the halves, corner – mid-edge node, of a
// quadratic face's edges, straight on a face with straight edges; a curved edge is measured on these two
// chords, where the boundary-point element (NodeToFacetContact.cpp) evaluates it too. The closest point of a
// face's boundary is found segment by segment, in closed form. Rules beyond the common ones of FacetSelector.hpp:
//  - an EDGE (two node ids) is interior when two candidate faces hold it as an edge (a ridge or a valley);
//    a free edge belongs to one face only;
//  - a VERTEX is interior when the candidate faces holding it close a fan around it: every edge leaving it
//    (collapsed edges, a node id twice, aside) is held by exactly two of them. A vertex on the free boundary
//    is shared by two faces too, but its fan is open, so a node beyond the free boundary near it is not in
//    contact (the 2D free end);
//  - the element is evaluated on the face, among those holding the edge or vertex, whose unit normal at
//    that point best matches the direction from the point to the node (signed as the gap): the face the
//    node is most "above";
//  - a projection where the face's area Jacobian has nearly vanished (the apex of a collapsed face, with
//    a node id twice) is not inside: the neighbours, or the apex as a vertex, take the node.


/// Local index of global node `id` in face f, or −1.
template <class Facet>
int localIndex(const MasterFacetNodes<Facet>& f, int id) {
  for (int i = 0; i < Facet::kNodes; ++i)
    if (f.nodes[i] == id) return i;
  return -1;
}

/// Face f holds the edge a–b (the two ends of one of its boundary segments).
template <class Facet>
bool holdsEdge(const MasterFacetNodes<Facet>& f, int a, int b) {
  for (const auto& [i, j] : Facet::boundarySegments())
    if ((f.nodes[i] == a && f.nodes[j] == b) || (f.nodes[i] == b && f.nodes[j] == a)) return true;
  return false;
}

/// The candidate faces around vertex v close a fan (see above): every boundary segment leaving v is held by
/// exactly two of them.
template <class Facet>
bool interiorVertex(const std::vector<MasterFacetNodes<Facet>>& candidates, int v) {
  std::vector<int> neighbours;
  for (const auto& f : candidates)
    for (const auto& [i, j] : Facet::boundarySegments()) {
      if (f.nodes[i] == v && f.nodes[j] != v) neighbours.push_back(f.nodes[j]);
      if (f.nodes[j] == v && f.nodes[i] != v) neighbours.push_back(f.nodes[i]);
    }
  if (neighbours.empty()) return false;
  std::sort(neighbours.begin(), neighbours.end());
  for (std::size_t i = 0; i < neighbours.size();) {
    std::size_t j = i;
    while (j < neighbours.size() && neighbours[j] == neighbours[i]) ++j;
    if (j - i != 2) return false;
    i = j;
  }
  return true;
}

/// The candidate faces holding a point of a face's boundary (with `atVertex` the vertex `vertex`, else the
/// point at t on the edge a–b; rigid points have negative ids), with their unit normals there (eq. 5) and
/// the normals' sum; the apex of a collapsed face does not hold it.
template <class Facet>
struct PointHolders {
  std::vector<std::size_t> faces;
  std::vector<typename Facet::Point> normals;
  typename Facet::Point averaged{};
};

template <class Facet>
PointHolders<Facet> holdersOf(const std::vector<MasterFacetNodes<Facet>>& candidates, const typename Facet::Point& slave,
                              bool atVertex, int vertex, int a, int b, double t) {
  PointHolders<Facet> held;
  for (std::size_t f = 0; f < candidates.size(); ++f) {
    typename Facet::SurfaceCoords xi{};
    if (atVertex) {
      const int l = localIndex(candidates[f], vertex);
      if (l < 0) continue;
      xi = Facet::nodeCoords(l);
    } else {
      if (!holdsEdge(candidates[f], a, b)) continue;
      const int la = localIndex(candidates[f], a), lb = localIndex(candidates[f], b);
      xi = add(scaled(1.0 - t, Facet::nodeCoords(la)), scaled(t, Facet::nodeCoords(lb)));
    }
    const auto at = Projection<Facet>::evaluateAt(slave, candidates[f].x, xi);
    if (!(norm(Facet::areaNormal(at.covariantBasis)) > 0.0)) continue;  // the apex of a collapsed face
    held.faces.push_back(f);
    held.normals.push_back(at.normal);
    held.averaged = add(held.averaged, at.normal);
  }
  return held;
}

/// Area Jacobian ‖ā_1 × ā_2‖ of face x at ξ.
template <class Facet>
double areaJacobian(const std::array<typename Facet::Point, Facet::kNodes>& x, const typename Facet::SurfaceCoords& xi) {
  return norm(Facet::areaNormal(Projection<Facet>::evaluateAt(typename Facet::Point{}, x, xi).covariantBasis));
}

/// Of the faces holding an edge or vertex point, the one whose unit normal best matches the signed
/// direction point → node, side · d / ‖d‖ (the first on a tie, and at d = 0).
template <class Point>
std::size_t bestMatchingNormal(const std::vector<Point>& normals, const Point& d, double side, double distance) {
  std::size_t chosen = 0;
  double match = -std::numeric_limits<double>::infinity();
  for (std::size_t h = 0; h < normals.size(); ++h) {
    const double m = distance > 0.0 ? side * dot(normals[h], d) / distance : 0.0;
    if (m > match) {
      match = m;
      chosen = h;
    }
  }
  return chosen;
}

/// Of the holders of a point across which the surface is flat, the candidate whose projection overshoots
/// its face least (FacetSelectorOptions::flatAngle): the face the node stays on.
template <class Facet>
std::size_t leastOvershooting(const std::vector<std::size_t>& holders, const std::vector<ProjectionResult<Facet>>& projected,
                              const std::vector<MasterFacetNodes<Facet>>& candidates) {
  std::size_t face = candidates.size();
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t h : holders) {
    const double beyond = distanceBeyond(projected[h], candidates[h].x);
    if (beyond < least) {
      least = beyond;
      face = h;
    }
  }
  return face;
}

template <class Facet>
FacetSelection<Facet> selectOnFaces(const FacetSelectorOptions& options_, const typename Facet::Point& slave,
                                    const std::vector<MasterFacetNodes<Facet>>& candidates, double slaveSize,
                                    double heldGap) {
  using Point = typename Facet::Point;
  const Projection<Facet> projection(options_.projection);
  const std::size_t n = candidates.size();
  std::vector<ProjectionResult<Facet>> projected(n);
  std::vector<char> regular(n), inside(n);  // regular: converged and not at a collapsed apex
  for (std::size_t c = 0; c < n; ++c) {
    projected[c] = projection.project(slave, candidates[c].x);
    const auto& p = projected[c];
    regular[c] = p.converged && areaJacobian<Facet>(candidates[c].x, p.xi) >=
                                    options_.collapsedJacobianRatio * areaJacobian<Facet>(candidates[c].x, Facet::center());
    inside[c] = regular[c] && p.isInside(options_.insideTolerance);
  }

  FacetSelection<Facet> best;
  double bestDistance = std::numeric_limits<double>::infinity();
  std::size_t flatFace = n;  // the chosen edge or vertex is flat across: the face to stay on (flatAngle)

  // 1. Projections inside their face: the smaller |g_N| wins (valleys, concave corners).
  for (std::size_t c = 0; c < n; ++c)
    if (inside[c]) considerOnFacet(projected[c], candidates[c].id, best, bestDistance);

  // 2. Interior edges and vertices: the closest point of each outside face's boundary. A point of the free
  //    boundary (a free edge, a vertex of an open fan) closer than the chosen interior point means the node
  //    is past the surface's free boundary: the interior point is not the surface's closest point then (a
  //    node beside a split punch was held by the punch's interior edge 36 mm away).
  double freeBoundaryDistance = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < n; ++c) {
    if (inside[c]) continue;
    const MasterFacetNodes<Facet>& face = candidates[c];
    for (const auto& [i, j] : Facet::boundarySegments()) {
      if (face.nodes[i] == face.nodes[j]) continue;  // a collapsed edge
      const Point edge = subtract(face.x[j], face.x[i]);
      const double length2 = dot(edge, edge);
      if (!(length2 > 0.0)) continue;
      const double t = std::clamp(dot(subtract(slave, face.x[i]), edge) / length2, 0.0, 1.0);
      const bool atVertex = t <= 0.0 || t >= 1.0;
      const int vertex = t <= 0.0 ? face.nodes[i] : face.nodes[j];
      const Point point = atVertex ? (t <= 0.0 ? face.x[i] : face.x[j]) : add(face.x[i], scaled(t, edge));
      const Point d = subtract(slave, point);
      const double distance = norm(d);
      if (!(distance < bestDistance)) continue;  // ties go to the inside projection / the first point
      if (atVertex && !interiorVertex(candidates, vertex)) {
        freeBoundaryDistance = std::min(freeBoundaryDistance, distance);
        continue;
      }
      // The faces holding the point, and their unit normals there (eq. 5).
      const PointHolders<Facet> held = holdersOf(candidates, slave, atVertex, vertex, face.nodes[i], face.nodes[j], t);
      const std::vector<std::size_t>& holders = held.faces;
      const std::vector<Point>& normals = held.normals;
      const Point& averaged = held.averaged;
      if (holders.size() < 2) {  // a free edge (or a vertex held by one face)
        freeBoundaryDistance = std::min(freeBoundaryDistance, distance);
        continue;
      }
      const double side = dot(d, averaged) >= 0.0 ? 1.0 : -1.0;
      const std::size_t chosen = bestMatchingNormal(normals, d, side, distance);
      const double averagedNorm = norm(averaged);
      // Flat across the point: the holder whose projection overshoots its face least (FacetSelectorOptions::flatAngle).
      flatFace = flatAcross(normals, options_.flatAngle) ? leastOvershooting(holders, projected, candidates) : n;
      bestDistance = distance;
      best.kind = atVertex ? SelectionKind::AtVertex : SelectionKind::AtEdge;
      best.facet = candidates[holders[chosen]].id;
      best.vertexNode = atVertex ? vertex : -1;
      best.edgeNodes = atVertex ? std::array<int, 2>{-1, -1} : std::array<int, 2>{face.nodes[i], face.nodes[j]};
      best.projection = projected[holders[chosen]];
      best.gap = side * distance;
      best.normal = distance > 0.0 ? scaled(side / distance, d)
                    : averagedNorm > 0.0 ? scaled(1.0 / averagedNorm, averaged) : normals[chosen];
      best.closestPoint = point;
    }
  }

  if ((best.kind == SelectionKind::AtEdge || best.kind == SelectionKind::AtVertex) &&
      freeBoundaryDistance < bestDistance) {
    best = FacetSelection<Facet>{};
    bestDistance = std::numeric_limits<double>::infinity();
  } else if ((best.kind == SelectionKind::AtEdge || best.kind == SelectionKind::AtVertex) && flatFace < n) {
    best = FacetSelection<Facet>{};
    bestDistance = std::numeric_limits<double>::infinity();
    considerOnFacet(projected[flatFace], candidates[flatFace].id, best, bestDistance);
  }

  // 3. A node in contact (g_N < heldGap) just past a free boundary: it stays on the boundary face, extended.
  if (best.kind == SelectionKind::None)
    keepPastFreeBoundary(projected, candidates, regular, options_.freeEdgeTolerance * slaveSize, heldGap, best,
                         bestDistance);

  // 4. Nothing inside and no interior edge or vertex: the node has left the master surface.
  if (best.kind == SelectionKind::None) best.gap = std::numeric_limits<double>::infinity();
  return best;
}

}  // namespace

template <class Facet>
FacetSelection<Facet> FacetSelector<Facet>::select(const typename Facet::Point& slave,
                                                   const std::vector<MasterFacetNodes<Facet>>& candidates,
                                                   double slaveSize, double heldGap) const {
  if constexpr (Facet::kSurfaceDim == 1)
    return selectOnSegments<Facet>(options_, slave, candidates, slaveSize, heldGap);
  else
    return selectOnFaces<Facet>(options_, slave, candidates, slaveSize, heldGap);
}

#define CONTESSA_INSTANTIATE_FACET_SELECTOR(F) template class FacetSelector<F>;
CONTESSA_FOR_EACH_FACET(CONTESSA_INSTANTIATE_FACET_SELECTOR)
#undef CONTESSA_INSTANTIATE_FACET_SELECTOR

}  // namespace contessa::contact
