#pragma once
// Point histories: the deck's named output requests (Problem/Output/History/<name>), each a quantity
// at a node or over a node set, written every increment as history columns and Exodus globals. Parsed
// and checked here (node sets, interfaces, coordinates), the nearest node found over every rank's
// part; the values are taken by output/PointHistories.
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "mesh/Mesh.hpp"

namespace contessa::deck {

struct ProblemDefinition;

/// What a request measures.
enum class HistoryQuantity {
  Displacement,     ///< a node's displacement, or the mean over a node set; one column per component
  ReactionForce,    ///< Σ (f_int + contact − λ f_ext) over a node set (as Reaction Node Sets); per component
  AppliedForce,     ///< λ × the deck's Nodal Forces on a node set's nodes, summed; per component
  ContactPressure,  ///< contact_pressure of an interface's slave node; one column
  ContactSlip,      ///< contact_slip (accumulated slip g_T) of an interface's slave node; one column
};

/// One request, checked against the mesh and the interfaces.
struct HistoryRequest {
  std::string name;  ///< the deck's sublist name
  HistoryQuantity quantity = HistoryQuantity::Displacement;
  std::string nodeSet;          ///< the set measured, or "" for one node
  mesh::GlobalIndex node = -1;  ///< the node nearest Coordinates (global id), or -1 for a set
  std::vector<double> nodeCoordinates;  ///< that node's reference coordinates
  std::string interface;                ///< contact quantities: the interface's deck name
  /// Reaction Force: the model sums reactions over ProblemDefinition::reactionNodeSets only, so the set
  /// was appended there for this request (it was not a Reaction Node Set of the deck): no reaction_<set>
  /// columns of its own.
  bool addedReactionSet = false;

  /// One value per space dimension (Displacement and the forces), or a scalar.
  bool isVector() const {
    return quantity != HistoryQuantity::ContactPressure && quantity != HistoryQuantity::ContactSlip;
  }
  /// Its history columns and Exodus globals: <name>_x, <name>_y[, <name>_z] or <name> (spaces and
  /// commas in the name as underscores).
  std::vector<std::string> columns(int dimension) const;
};

/// The parameters of one request (Problem/Output/History/<name>).
Teuchos::RCP<const Teuchos::ParameterList> historyRequestValidParameters();
/// Problem/Output/History as published for the deck reference: one sublist "<name>" of the request's
/// parameters (the deck's children are validated one by one, buildHistoryRequests).
Teuchos::RCP<const Teuchos::ParameterList> historyListValidParameters();
/// The quantities by their deck names.
std::vector<std::string> historyQuantityNames();

/// Validates every child of `history` (Problem/Output/History, defaults filled in) and resolves it on
/// `problem`'s mesh and contact interfaces (built before): InputError naming the parameter otherwise.
/// Collective over the mesh's communicator (the node nearest given coordinates is searched in every rank's part).
/// Appends the sets of Reaction Force requests to problem.reactionNodeSets when missing there.
std::vector<HistoryRequest> buildHistoryRequests(Teuchos::ParameterList& history, ProblemDefinition& problem);

}  // namespace contessa::deck
