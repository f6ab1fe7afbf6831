#include "output/PointHistories.hpp"

#include <algorithm>

#include <Teuchos_CommHelpers.hpp>

#include "common/Error.hpp"

namespace contessa::output {

namespace {
using deck::HistoryQuantity;
constexpr int kContactPressure = 0, kContactSlip = 3;  // columns of ContactMechanicsModel::contactNodalFields
}  // namespace

PointHistories::PointHistories(const deck::ProblemDefinition& problem, const model::ContactMechanicsModel& model,
                               const std::vector<std::string>& taken)
    : problem_(problem), model_(model) {
  std::vector<std::string> all = taken;
  for (const auto& request : problem.history) {
    for (const auto& column : request.columns(problem.dimension())) {
      requireInput(std::find(all.begin(), all.end(), column) == all.end(),
                   "Problem/Output/History/" + request.name + ": its column " + column +
                       " is already a history column; rename the request");
      all.push_back(column);
      columns_.push_back(column);
    }
    addColumns(request);
  }
}

bool PointHistories::hasLoadsOnSets() const {
  return std::any_of(problem_.loads.begin(), problem_.loads.end(),
                     [](const deck::LoadDefinition& l) { return l.type != deck::LoadType::Spring; });
}

void PointHistories::addColumns(const deck::HistoryRequest& request) {
  const int dim = problem_.dimension();
  const mesh::DistributedMesh& part = problem_.mesh;
  const model::Map& dofs = *model_.ownedDofMap();
  const model::Map& nodes = *model_.ownedNodeMap();
  const auto invalid = Teuchos::OrdinalTraits<model::LO>::invalid();
  // The part's nodes measured, by global id: the request's node, or its node set's (owned or not; each
  // owned row is counted once, by its owner).
  std::vector<model::GO> measured;
  if (request.node >= 0) {
    measured.push_back(request.node);
  } else {
    for (auto localNode : part.local().nodeSet(request.nodeSet).nodes) measured.push_back(part.part.globalNodes[localNode]);
  }
  if (request.quantity == HistoryQuantity::ContactPressure || request.quantity == HistoryQuantity::ContactSlip) {
    Column column;
    column.source = request.quantity == HistoryQuantity::ContactPressure ? Column::Source::ContactPressure
                                                                         : Column::Source::ContactSlip;
    const model::LO row = nodes.getLocalElement(request.node);
    if (row != invalid) {
      column.rows.push_back(row);
      column.weights.push_back(1.0);
    }
    sources_.push_back(column);
    return;
  }
  // A node set's mean displacement divides by its number of nodes over all ranks.
  double owned = 0, setSize = 1;
  for (model::GO node : measured) owned += nodes.getLocalElement(node) != invalid ? 1 : 0;
  Teuchos::reduceAll(*dofs.getComm(), Teuchos::REDUCE_SUM, 1, &owned, &setSize);
  const auto& reactionSets = problem_.reactionNodeSets;
  for (int c = 0; c < dim; ++c) {
    Column column;
    column.component = c;
    if (request.quantity == HistoryQuantity::ReactionForce) {
      column.source = Column::Source::Reaction;
      column.reaction = static_cast<std::size_t>(
          std::find(reactionSets.begin(), reactionSets.end(), request.nodeSet) - reactionSets.begin());
    } else if (request.quantity == HistoryQuantity::AppliedForce) {
      // f_ext as the model builds it (BoundaryConditions): each Nodal Force shared equally by its set's nodes.
      column.source = Column::Source::Applied;
      for (const auto& force : problem_.nodalForces) {
        if (force.component != c) continue;
        const auto& forceSet = part.local().nodeSet(force.nodeSet);
        const auto setIndex = static_cast<std::size_t>(&forceSet - part.local().nodeSets.data());
        const double setSize = static_cast<double>(part.globalNodeSetSizes[setIndex]);
        const double share = force.totalForce / setSize;
        double fraction = 0.0;
        for (auto localNode : forceSet.nodes) {
          const model::GO node = part.part.globalNodes[localNode];
          if (nodes.getLocalElement(node) != invalid && std::find(measured.begin(), measured.end(), node) != measured.end()) {
            column.appliedPerLoadFactor += share;
            fraction += 1.0 / setSize;
          }
        }
        column.appliedFractions.emplace_back(force.name, fraction);
      }
      // The loads on sets (pressure, traction, body force) on the set's nodes, from the model's vector.
      if (hasLoadsOnSets())
        for (model::GO node : measured) {
          const model::LO row = dofs.getLocalElement(node * dim + c);
          if (row != invalid) column.loadRows.push_back(row);
        }
    } else {
      for (model::GO node : measured) {
        const model::LO row = dofs.getLocalElement(node * dim + c);
        if (row == invalid) continue;
        column.rows.push_back(row);
        column.weights.push_back(1.0 / setSize);
      }
    }
    sources_.push_back(column);
  }
}

std::vector<double> PointHistories::values(const model::Vector& x, double loadFactor,
                                           const std::vector<model::NodeSetReaction>& reactions, int loadStep) const {
  const bool contact = std::any_of(sources_.begin(), sources_.end(), [](const Column& c) {
    return c.source == Column::Source::ContactPressure || c.source == Column::Source::ContactSlip;
  });
  Teuchos::RCP<const model::MultiVector> fields;
  if (contact && model_.hasContact()) fields = model_.contactNodalFields();
  const auto u = x.getData(0);
  // Collective where needed: every rank has the same columns.
  const bool applied = hasLoadsOnSets() && std::any_of(sources_.begin(), sources_.end(), [](const Column& c) {
    return c.source == Column::Source::Applied;
  });
  Teuchos::RCP<const model::Vector> loads = applied ? model_.loadsOnSets(x, loadFactor) : Teuchos::null;
  std::vector<double> local(sources_.size(), 0.0), global(sources_.size(), 0.0);
  for (std::size_t k = 0; k < sources_.size(); ++k) {
    const Column& column = sources_[k];
    Teuchos::ArrayRCP<const double> source = u;
    if (column.source == Column::Source::ContactPressure || column.source == Column::Source::ContactSlip) {
      if (fields.is_null()) continue;
      source = fields->getData(column.source == Column::Source::ContactPressure ? kContactPressure : kContactSlip);
    }
    for (std::size_t r = 0; r < column.rows.size(); ++r) local[k] += column.weights[r] * source[column.rows[r]];
    if (problem_.loadSteps.empty()) {
      local[k] += loadFactor * column.appliedPerLoadFactor;
    } else {
      // Load steps: each nodal force at its scheduled value (continuation::LoadSchedule).
      for (const auto& [name, fraction] : column.appliedFractions)
        local[k] += fraction * model_.loadSchedule().value(loadStep, model::loadKey(name), loadFactor)[0];
    }
    if (!column.loadRows.empty()) {
      const auto f = loads->getData(0);
      for (int row : column.loadRows) local[k] += f[row];
    }
  }
  if (!sources_.empty())
    Teuchos::reduceAll(*x.getMap()->getComm(), Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(),
                       global.data());
  for (std::size_t k = 0; k < sources_.size(); ++k)
    if (sources_[k].source == Column::Source::Reaction)
      global[k] = reactions[sources_[k].reaction].force[sources_[k].component];
  return global;
}

}  // namespace contessa::output
