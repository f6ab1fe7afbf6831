#include "contact/CouplingReservation.hpp"

#include <algorithm>
#include <cmath>

#include "contact/BoundingBoxTree.hpp"

namespace contessa::contact {

namespace {

template <int Dim>
Vector<Dim> pointOf(const ReservedPosition& position, GlobalIndex node) {
  Vector<Dim> p{};
  position(node, p.data());
  return p;
}

/// The search-based branch: master nodes of the facets whose box, enlarged by the reach, contains the
/// slave node, both in the configuration reserved around.
template <int Dim>
void reserveBySearch(const ContactInterfaceSpec& spec, const ReservedPosition& position, const std::vector<char>& slaves,
                     CouplingReservation& out) {
  const std::size_t perFacet = static_cast<std::size_t>(spec.nodesPerFacet());
  const std::size_t numFacets = spec.numMasterFacets();
  // h: the largest master facet size, as the run-time search measures it (longest node-to-node distance).
  double h = 0;
  std::vector<BoundingBox<Dim>> boxes(numFacets);
  std::vector<Vector<Dim>> x(perFacet);
  for (std::size_t f = 0; f < numFacets; ++f) {
    for (std::size_t a = 0; a < perFacet; ++a) {
      x[a] = pointOf<Dim>(position, spec.masterFacets[f * perFacet + a]);
      boxes[f].include(x[a]);
    }
    for (std::size_t a = 0; a < perFacet; ++a)
      for (std::size_t b = a + 1; b < perFacet; ++b) h = std::max(h, norm(subtract(x[b], x[a])));
  }
  out.reach = CouplingReservation::kFacetSizes * h + std::max(0.0, spec.searchReach);
  for (auto& box : boxes) box.enlarge(out.reach);
  const BoundingBoxTree<Dim> tree(std::move(boxes));

  out.offsets.assign(spec.slaveNodes.size() + 1, 0);
  std::vector<int> hits;
  std::vector<GlobalIndex> nodes;
  for (std::size_t k = 0; k < spec.slaveNodes.size(); ++k) {
    if (slaves[k]) {
      hits.clear();
      tree.query(pointOf<Dim>(position, spec.slaveNodes[k]), hits);
      nodes.clear();
      for (int f : hits)
        for (std::size_t a = 0; a < perFacet; ++a)
          nodes.push_back(spec.masterFacets[static_cast<std::size_t>(f) * perFacet + a]);
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
      out.masterNodes.insert(out.masterNodes.end(), nodes.begin(), nodes.end());
    }
    out.offsets[k + 1] = out.masterNodes.size();
  }
}

}  // namespace

std::size_t CouplingReservation::numPairs(const std::vector<char>& slaves) const {
  std::size_t pairs = 0;
  for (std::size_t k = 0; k < slaves.size(); ++k)
    if (slaves[k]) pairs += static_cast<std::size_t>(end(k) - begin(k));
  return pairs;
}

CouplingReservation reserveCouplings(const ContactInterfaceSpec& spec, const ReservedPosition& position,
                                     const std::vector<char>& slaves, std::size_t wholeSurfacePairs) {
  CouplingReservation out;
  if (spec.rigidMaster) {
    out.rigidMaster = true;
    out.offsets.assign(spec.slaveNodes.size() + 1, 0);
    return out;
  }
  out.allMasterNodes = spec.masterFacets;
  std::sort(out.allMasterNodes.begin(), out.allMasterNodes.end());
  out.allMasterNodes.erase(std::unique(out.allMasterNodes.begin(), out.allMasterNodes.end()), out.allMasterNodes.end());
  // Automatic (Search Reach < 0) counts the whole interface (all ranks' slave nodes), so the choice does
  // not depend on the number of ranks.
  if (spec.searchReach < 0 && spec.slaveNodes.size() * out.allMasterNodes.size() <= wholeSurfacePairs) {
    out.wholeSurface = true;
    return out;
  }
  if (spec.dimension == 2)
    reserveBySearch<2>(spec, position, slaves, out);
  else
    reserveBySearch<3>(spec, position, slaves, out);
  return out;
}

CouplingReservation reserveCouplings(const ContactInterfaceSpec& spec, const std::vector<double>& coordinates,
                                     const std::vector<char>& slaves, std::size_t wholeSurfacePairs) {
  const auto dim = static_cast<std::size_t>(spec.dimension);
  const ReservedPosition position = [&](GlobalIndex node, double* x) {
    for (std::size_t c = 0; c < dim; ++c) x[c] = coordinates[static_cast<std::size_t>(node) * dim + c];
  };
  return reserveCouplings(spec, position, slaves, wholeSurfacePairs);
}

bool isReserved(const CouplingReservation& reservation, std::size_t k, GlobalIndex node) {
  if (reservation.rigidMaster) return node < 0;
  return std::binary_search(reservation.begin(k), reservation.end(k), node);
}

}  // namespace contessa::contact
