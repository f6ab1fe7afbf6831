#pragma once
// Which contact couplings the matrix graph reserves: for each slave node, the deformable master nodes its
// rows may ever couple to. The graph is built once (model::ContactMechanicsModel::buildGraph), so this set
// must cover every master facet the run-time search (ContactInterface::evaluate) can pair the node with.
//
// Reach rule (docs/user-guide.md, "Matrix graph of a contact interface"), deck parameter Search Reach:
//   - automatic (Search Reach < 0, the default): a small interface (slave nodes × master nodes ≤
//     kWholeSurfacePairs) reserves the whole master surface for every slave node, so a node may slide
//     anywhere on it; a larger one is searched as below with Search Reach = 0;
//   - search-based (any larger interface, or Search Reach ≥ 0 given) reserves, for slave node k, the nodes of the master facets whose reference bounding box
//     enlarged by the reach r = kFacetSizes · h + Search Reach contains the node's reference position, h
//     the largest master facet size (its longest node-to-node distance). One h is the run-time search's own
//     enlargement of the current boxes; the other h plus Search Reach is the relative motion (sliding plus
//     relative deformation, per component) a slave node may make against a master facet before the facet
//     can become a candidate the graph does not hold. Found with a BoundingBoxTree: O((n + m) log m).
//   - a rigid master has no unknowns: it needs no coupling beyond the slave node's own DOFs.
// A pairing outside the reserved set at run time stops the run with a message naming the interface, the
// slave node and Search Reach (ContactMechanicsModel::assemble).
#include <cstddef>
#include <vector>

#include "contact/InterfaceSpec.hpp"

namespace contessa::contact {

struct CouplingReservation {
  /// Up to this many (slave node, master node) pairs an interface reserves its whole master surface: every
  /// existing 2D deck stays there (a tube's surfaces hold a few hundred nodes), and the reservation then
  /// costs at most 2 · dim² · 250 000 matrix entries (4.5 M in 3D).
  static constexpr std::size_t kWholeSurfacePairs = 250000;
  /// The reach in largest master facet sizes, before Search Reach.
  static constexpr double kFacetSizes = 2.0;

  bool wholeSurface = false;  ///< every slave node reserves every master node
  bool rigidMaster = false;   ///< nothing to reserve
  double reach = 0;           ///< kFacetSizes · h + max(0, Search Reach) (search-based reservation only)
  /// Master nodes (sorted) of slave node k: masterNodes[offsets[k]] … masterNodes[offsets[k + 1] − 1];
  /// empty for slave nodes not asked for. With wholeSurface, only allMasterNodes is filled.
  std::vector<std::size_t> offsets;
  std::vector<GlobalIndex> masterNodes;
  std::vector<GlobalIndex> allMasterNodes;  ///< the master surface's nodes, sorted

  /// The master nodes slave node k may couple to: [first, last).
  const GlobalIndex* begin(std::size_t k) const {
    return wholeSurface ? allMasterNodes.data() : masterNodes.data() + offsets[k];
  }
  const GlobalIndex* end(std::size_t k) const {
    return wholeSurface ? allMasterNodes.data() + allMasterNodes.size() : masterNodes.data() + offsets[k + 1];
  }
  /// Reserved (slave node, master node) pairs over the slave nodes asked for.
  std::size_t numPairs(const std::vector<char>& slaves) const;
};

/// The couplings of interface `spec` for the slave nodes k with slaves[k] != 0 (a rank's owned ones), from
/// the mesh's reference coordinates (spec.dimension values per node). `wholeSurfacePairs` is the rule's
/// automatic threshold (a parameter so tests and benchmarks can vary it).
CouplingReservation reserveCouplings(const ContactInterfaceSpec& spec, const std::vector<double>& referenceCoordinates,
                                     const std::vector<char>& slaves,
                                     std::size_t wholeSurfacePairs = CouplingReservation::kWholeSurfacePairs);

/// Whether master node `node` is reserved for slave node k (binary search in its sorted list).
bool isReserved(const CouplingReservation& reservation, std::size_t k, GlobalIndex node);

}  // namespace contessa::contact
