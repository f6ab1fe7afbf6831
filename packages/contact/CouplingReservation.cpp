#include "contact/CouplingReservation.hpp"

#include <algorithm>
#include <cmath>

#include "contact/BoundingBoxTree.hpp"

namespace contessa::contact {

namespace {

template <int Dim>
Vector<Dim> referencePoint(const std::vector<double>& X, GlobalIndex node) {
  Vector<Dim> p{};
  for (int c = 0; c < Dim; ++c) p[c] = X[static_cast<std::size_t>(node) * Dim + c];
  return p;
}

/// The search-based branch: master nodes of the facets whose reference box, enlarged by the reach,
/// contains the slave node's reference position.
template <int Dim>
void reserveBySearch(const ContactInterfaceSpec& spec, const std::vector<double>& X, const std::vector<char>& slaves,
                     CouplingReservation& out) {
  const std::size_t perFacet = static_cast<std::size_t>(spec.nodesPerFacet());
  const std::size_t numFacets = spec.numMasterFacets();
  // h: the largest master facet size, as the run-time search measures it (longest node-to-node distance).
  double h = 0;
  std::vector<BoundingBox<Dim>> boxes(numFacets);
  for (std::size_t f = 0; f < numFacets; ++f)
    for (std::size_t a = 0; a < perFacet; ++a) {
      const auto xa = referencePoint<Dim>(X, spec.masterFacets[f * perFacet + a]);
      boxes[f].include(xa);
      for (std::size_t b = a + 1; b < perFacet; ++b)
        h = std::max(h, norm(subtract(referencePoint<Dim>(X, spec.masterFacets[f * perFacet + b]), xa)));
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
      tree.query(referencePoint<Dim>(X, spec.slaveNodes[k]), hits);
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

CouplingReservation reserveCouplings(const ContactInterfaceSpec& spec, const std::vector<double>& referenceCoordinates,
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
    reserveBySearch<2>(spec, referenceCoordinates, slaves, out);
  else
    reserveBySearch<3>(spec, referenceCoordinates, slaves, out);
  return out;
}

bool isReserved(const CouplingReservation& reservation, std::size_t k, GlobalIndex node) {
  if (reservation.rigidMaster) return node < 0;
  return std::binary_search(reservation.begin(k), reservation.end(k), node);
}

}  // namespace contessa::contact
