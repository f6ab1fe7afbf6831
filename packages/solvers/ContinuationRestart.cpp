#include "solvers/ContinuationRestart.hpp"

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "common/Error.hpp"
#include "solvers/LocaResume.hpp"

namespace contessa::solvers {

using Teuchos::RCP;
using Teuchos::rcp;

namespace {

// The owned DOFs of x_k and x_{k-1} as rows of the table "nodes" (id: node, displacement and
// previous_displacement: dim values each): any rank count reads it.
void saveNodeTable(const model::Vector& x, const model::Vector& previousX, int dim, StateRecord& table) {
  const auto& map = *x.getMap();
  const auto values = x.getData(0), previous = previousX.getData(0);
  std::map<model::GO, std::pair<std::vector<double>, std::vector<double>>> nodes;
  for (std::size_t i = 0; i < map.getNodeNumElements(); ++i) {
    const model::GO dof = map.getGlobalElement(static_cast<model::LO>(i));
    auto& node = nodes[dof / dim];
    node.first.resize(static_cast<std::size_t>(dim), 0.0);
    node.second.resize(static_cast<std::size_t>(dim), 0.0);
    node.first[static_cast<std::size_t>(dof % dim)] = values[i];
    node.second[static_cast<std::size_t>(dof % dim)] = previous[i];
  }
  StateTableWriter rows(table);
  for (const auto& [node, v] : nodes) {
    rows.beginRow(node);
    rows("displacement", v.first);
    rows("previous_displacement", v.second);
  }
  rows.finish();
}

RCP<model::Vector> vectorFromNodeTable(const RCP<const model::Map>& map, int dim, const std::string& column,
                                       const StateRecord& table) {
  auto v = rcp(new model::Vector(map));
  auto values = v->getDataNonConst(0);
  StateTableReader rows(table);
  std::vector<double> node;
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const model::GO dof = map->getGlobalElement(static_cast<model::LO>(i));
    rows.seek(dof / dim, "node " + std::to_string(dof / dim + 1));
    rows(column, node);
    requireInput(node.size() == static_cast<std::size_t>(dim),
                 table.origin() + ": " + table.path() + column + ": " + std::to_string(node.size()) +
                     " components per node, the mesh has " + std::to_string(dim));
    values[i] = node[static_cast<std::size_t>(dof % dim)];
  }
  return v;
}

}  // namespace

std::shared_ptr<const ContinuationPoint> readContinuationPoint(const RCP<const model::Map>& ownedDofMap, int dimension,
                                                               const StateRecord& state) {
  auto point = std::make_shared<ContinuationPoint>();
  StateReader continuation(state.child("continuation"));
  ContinuationPoint::stateFields(*point, continuation);
  point->resumedStepSizeState = &state.claim("step_size");
  const StateRecord& nodes = state.child("nodes");
  point->x = vectorFromNodeTable(ownedDofMap, dimension, "displacement", nodes);
  point->previousX = vectorFromNodeTable(ownedDofMap, dimension, "previous_displacement", nodes);
  return point;
}

StateRecord continuationState(const ContinuationPoint& point, int dimension) {
  StateRecord out;
  if (point.x->getMap()->getComm()->getRank() == 0) {
    StateWriter continuation(out.child("continuation"));
    ContinuationPoint::stateFields(point, continuation);
    out.child("step_size").merge(point.stepSizeState);
  }
  saveNodeTable(*point.x, *point.previousX, dimension, out.child("nodes"));
  return out;
}

LocaResumePoint locaResumePoint(const ContinuationPoint& point, bool secantPredictor) {
  LocaResumePoint loca;
  loca.increments = point.stepIncrements;
  loca.failedAttempts = point.stepFailedAttempts;
  loca.newtonIterations = point.newtonIterations;
  loca.stepSize = point.stepSize;
  loca.previousLambda = point.previousLambda;
  loca.previousX = point.previousX;
  loca.secantPredictor = secantPredictor;
  loca.stepSizeState = point.resumedStepSizeState;
  return loca;
}

}  // namespace contessa::solvers
