#pragma once
// Which contact couplings the matrix graph reserves: for each slave node, the deformable master nodes its
// rows may couple to, around one configuration of the interface. The model reserves around the
// reference configuration at set-up, and again around the current configuration whenever a Jacobian
// evaluation pairs a slave node with a master facet outside the reservation: the contact part of the graph
// is then rebuilt and the Jacobian re-created on it (model::ContactMechanicsModel::rebuildGraph), so the
// graph follows the contact however far it slides.
//
// Reach rule (docs/user-guide.md, "Matrix graph of a contact interface"), deck parameter Search Reach:
//   - automatic (Search Reach < 0, the default): a small interface (slave nodes × master nodes ≤
//     kWholeSurfacePairs) reserves the whole master surface for every slave node, so a node may slide
//     anywhere on it and the graph is never rebuilt; a larger one is searched as below with Search Reach = 0;
//   - search-based (any larger interface, or Search Reach ≥ 0 given) reserves, for slave node k, the nodes
//     of the master facets whose bounding box in the configuration reserved around, enlarged by the reach
//     r = kFacetSizes · h + Search Reach, contains the node's position there, h the largest master facet
//     size (its longest node-to-node distance) in that configuration. One h is the run-time search's own
//     enlargement of the current boxes (ContactInterface::evaluate), so every pairing the search can make
//     in that configuration is reserved, and a rebuild around it always holds the pairing that asked for
//     it; the other h plus Search Reach is the margin: the relative motion (sliding plus relative
//     deformation, per component) a slave node may make against a master facet before the next rebuild.
//     Found with a BoundingBoxTree: O((n + m) log m).
//   - a rigid master has no unknowns: it needs no coupling beyond the slave node's own DOFs.
#include <cstddef>
#include <functional>
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

/// Position of a mesh node in the configuration reserved around: writes spec.dimension values to x.
using ReservedPosition = std::function<void(GlobalIndex node, double* x)>;

/// The couplings of interface `spec` for the slave nodes k with slaves[k] != 0 (a rank's owned ones),
/// around the configuration `position` gives (the reference one at set-up, the current one at a rebuild;
/// only the interface's slave and master nodes are asked for). `wholeSurfacePairs` is the rule's
/// automatic threshold (a parameter so tests and benchmarks can vary it).
CouplingReservation reserveCouplings(const ContactInterfaceSpec& spec, const ReservedPosition& position,
                                     const std::vector<char>& slaves,
                                     std::size_t wholeSurfacePairs = CouplingReservation::kWholeSurfacePairs);
/// The same around coordinates given for every mesh node (spec.dimension values per node).
CouplingReservation reserveCouplings(const ContactInterfaceSpec& spec, const std::vector<double>& coordinates,
                                     const std::vector<char>& slaves,
                                     std::size_t wholeSurfacePairs = CouplingReservation::kWholeSurfacePairs);

/// Whether master node `node` is reserved for slave node k (binary search in its sorted list).
bool isReserved(const CouplingReservation& reservation, std::size_t k, GlobalIndex node);

}  // namespace contessa::contact
