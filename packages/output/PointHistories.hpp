#pragma once
// The values of the deck's point histories (Problem/Output/History, deck/OutputRequests.hpp) at a
// converged increment: a node's displacement or a node set's mean, a node set's reaction or applied
// force (its nodal forces and the loads on sets that act on its nodes), an interface slave node's contact
// pressure or slip. Each rank adds what it owns and the sums
// are reduced, so every rank gets the same row whichever rank owns the node.
#include <string>
#include <utility>
#include <vector>

#include "deck/ProblemDefinition.hpp"
#include "model/ContactMechanicsModel.hpp"

namespace contessa::output {

class PointHistories {
 public:
  /// Throws InputError naming the request when one of its columns repeats another history column
  /// (`taken`: the history's other columns) or another request's.
  PointHistories(const deck::ProblemDefinition& problem, const model::ContactMechanicsModel& model,
                 const std::vector<std::string>& taken);

  /// The requests' columns, in deck order (also their Exodus globals).
  const std::vector<std::string>& columns() const { return columns_; }
  /// Collective: the values of columns() at the converged displacement `x` and load factor λ of load step
  /// `loadStep` (0 without Problem/Load Steps), given the model's reactions there (over
  /// problem.reactionNodeSets).
  std::vector<double> values(const model::Vector& x, double loadFactor,
                             const std::vector<model::NodeSetReaction>& reactions, int loadStep = 0) const;

 private:
  /// What this rank adds to one column: Σ weight · source[row] over its owned rows, plus a constant that
  /// the load factor multiplies (Applied Force); Reaction Force columns are copied from the reactions.
  struct Column {
    enum class Source { Displacement, ContactPressure, ContactSlip, Reaction, Applied };
    Source source = Source::Displacement;
    std::vector<int> rows;          ///< owned local rows of x (displacement) or of the contact fields
    std::vector<double> weights;    ///< per row
    double appliedPerLoadFactor = 0;  ///< Applied: this rank's share of Σ f_ext on the set's nodes
    /// Applied, with load steps: per nodal force (its name), the fraction of its total on this rank's
    /// nodes of the set (the force's value comes from the schedule).
    std::vector<std::pair<std::string, double>> appliedFractions;
    /// Applied: the owned rows (of x's map) of the set's nodes in this component, where the loads on sets
    /// (ContactMechanicsModel::loadsOnSets) are summed.
    std::vector<int> loadRows;
    std::size_t reaction = 0;       ///< Reaction: index into the reactions
    int component = 0;
  };

  void addColumns(const deck::HistoryRequest& request);
  /// The deck has loads on sets (Problem/Loads other than springs).
  bool hasLoadsOnSets() const;

  const deck::ProblemDefinition& problem_;
  const model::ContactMechanicsModel& model_;
  std::vector<std::string> columns_;
  std::vector<Column> sources_;
};

}  // namespace contessa::output
