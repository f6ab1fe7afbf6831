#include "contact/SmoothedMaster.hpp"

#include <map>

#include "contact/Projection.hpp"

namespace contessa::contact {

std::vector<GlobalIndex> hermiteMasterFacets(const std::vector<GlobalIndex>& segments) {
  // The segments leaving and entering each node (−1: none, −2: more than one, a junction).
  std::map<GlobalIndex, GlobalIndex> next, previous;
  const auto note = [](std::map<GlobalIndex, GlobalIndex>& links, GlobalIndex at, GlobalIndex other) {
    const auto [it, inserted] = links.emplace(at, other);
    if (!inserted) it->second = -2;
  };
  for (std::size_t f = 0; f + 1 < segments.size(); f += 2) {
    note(next, segments[f], segments[f + 1]);
    note(previous, segments[f + 1], segments[f]);
  }
  const auto neighbour = [](const std::map<GlobalIndex, GlobalIndex>& links, GlobalIndex at) {
    const auto it = links.find(at);
    return it == links.end() || it->second < 0 ? at : it->second;
  };
  std::vector<GlobalIndex> facets;
  facets.reserve(2 * segments.size());
  for (std::size_t f = 0; f + 1 < segments.size(); f += 2) {
    const GlobalIndex a = segments[f], b = segments[f + 1];
    facets.insert(facets.end(), {neighbour(previous, a), a, b, neighbour(next, b)});
  }
  return facets;
}

template <>
ContactHistory<1> transferHistory<HermiteLine4Facet>(const ContactHistory<1>& committed,
                                                     const MasterFacetNodes<HermiteLine4Facet>& from,
                                                     const MasterFacetNodes<HermiteLine4Facet>& to) {
  using F = HermiteLine4Facet;
  ContactHistory<1> moved = committed;
  moved.segment = to.id;
  if (!committed.isInContact() || from.id == to.id) return moved;
  const auto tangentAt = [](const MasterFacetNodes<F>& f, double xi) {
    return Projection<F>::evaluateAt(F::Point{}, f.x, {xi}).covariantBasis[0];
  };
  const double xiFrom = committed.xi[0];
  double orientation = 1.0;
  double lengthRatio = 1.0;
  if (from.nodes[2] == to.nodes[1] || from.nodes[1] == to.nodes[2]) {
    // The shared end: ξ = +1 of `from` and −1 of `to`, or the reverse; the ratio is 1 where both
    // segments see the same neighbours (C¹), not at a free end's stand-in.
    const double end = from.nodes[2] == to.nodes[1] ? 1.0 : -1.0;
    lengthRatio = norm(tangentAt(from, end)) / norm(tangentAt(to, -end));
    moved.xi[0] = -end - (end - xiFrom) * lengthRatio;
  } else {
    const F::Point oldPoint = Projection<F>::evaluateAt(F::Point{}, from.x, committed.xi).position;
    moved.xi = Projection<F>().project(oldPoint, to.x).xi;
    const auto aFrom = tangentAt(from, xiFrom), aTo = tangentAt(to, moved.xi[0]);
    lengthRatio = norm(aFrom) / norm(aTo);
    orientation = dot(aFrom, aTo) >= 0.0 ? 1.0 : -1.0;
  }
  moved.tangentialTraction[0] = orientation * committed.tangentialTraction[0] / lengthRatio;
  return moved;
}

template <>
SweptCrossing sweptCrossing<HermiteLine4Facet>(const HermiteLine4Facet::Point& slave0,
                                               const HermiteLine4Facet::Point& slave1,
                                               const std::array<HermiteLine4Facet::Point, 4>& facet0,
                                               const std::array<HermiteLine4Facet::Point, 4>& facet1,
                                               double insideTolerance) {
  return sweptCrossing<Line2Facet>(slave0, slave1, {facet0[1], facet0[2]}, {facet1[1], facet1[2]}, insideTolerance);
}

}  // namespace contessa::contact
