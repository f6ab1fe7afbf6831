#include "model/BoundaryConditions.hpp"

#include <map>
#include <string>

#include "common/Error.hpp"
#include "model/LoadStepping.hpp"
#include "model/RankAgreement.hpp"

namespace contessa::model {

namespace {

// A condition's value at the end of every load step (the deck's Value alone without steps): two
// conditions on one DOF must agree at every step's end.
std::vector<double> stepEndValues(const deck::ProblemDefinition& problem, const deck::DirichletCondition& bc) {
  std::vector<double> ends{bc.value};
  for (std::size_t s = 0; s < problem.loadSteps.size(); ++s) {
    const auto& named = problem.loadSteps[s].dirichlet;
    const auto it = named.find(bc.name);
    const double previous = s == 0 ? bc.value : ends.back();
    ends.push_back(it != named.end() ? it->second : previous);
  }
  return ends;
}

// The deck's Total Force of the nodal force `name` (what deadForce reads of the values it is given).
std::vector<double> deckLoadValue(const deck::ProblemDefinition& problem, const std::string& name) {
  for (const auto& force : problem.nodalForces)
    if (force.name == name) return {force.totalForce};
  return {0.0};
}

}  // namespace

BoundaryConditions::BoundaryConditions(const deck::ProblemDefinition& problem, const DofLayout& layout)
    : problem_(problem), layout_(layout) {
  const mesh::DistributedMesh& part = problem.mesh;  // node sets hold the part's nodes, owned or not
  const auto nodesOf = [&](const std::string& set) {
    std::vector<GO> nodes;
    for (mesh::GlobalIndex n : part.local().nodeSet(set).nodes) nodes.push_back(part.part.globalNodes[n]);
    return nodes;
  };
  const int dim = layout.dimension();
  const Map& owned = *layout.ownedMap();
  // Dirichlet: one value per DOF; the same DOF prescribed twice with different values (at the end of any
  // load step) is an input error. A rank sees the nodes of its part only: the lowest rank that finds a
  // conflict names it on every rank.
  std::map<GO, std::pair<std::vector<double>, const deck::DirichletCondition*>> prescribed;
  std::string conflict;
  for (const auto& bc : problem.dirichlet) {
    const auto ends = stepEndValues(problem, bc);
    for (GO node : nodesOf(bc.nodeSet)) {
      const GO dof = node * dim + bc.component;
      auto [it, inserted] = prescribed.emplace(dof, std::make_pair(ends, &bc));
      if (conflict.empty() && !inserted && it->second.first != ends)
        conflict = "Problem/Dirichlet Conditions/" + bc.name + ": prescribes node " + std::to_string(node + 1) +
                   " differently from '" + it->second.second->name + "'";
    }
  }
  conflict = firstMessageOfAnyRank(*layout.comm(), conflict);
  if (!conflict.empty()) throw InputError(conflict);
  for (const auto& [dof, value] : prescribed) {
    const LO lo = owned.getLocalElement(dof);
    if (lo != Teuchos::OrdinalTraits<LO>::invalid()) {
      prescribedRows_.push_back(lo);
      prescribedBy_.push_back(value.second->name);
      prescribedStart_.push_back(0.0);
      prescribedChange_.push_back(value.second->value);
    }
  }
  // Loads on sets: each rank integrates its part's facets and elements.
  const Map& overlap = *layout.overlapMap();
  loads_ = std::make_unique<ExternalLoads>(problem, [&overlap](mesh::GlobalIndex dof) { return overlap.getLocalElement(dof); });
  // Without load steps: f_0 = 0, Δf the deck's loads (the step's values replace them in setLoadStep).
  changeForce_ = deadForce([&problem](const std::string& name) { return deckLoadValue(problem, name); }, true);
  startForce_ = Teuchos::rcp(new Vector(layout.ownedMap()));
  // Springs to ground: k per node and direction, on the owner's rows.
  std::map<GO, double> springs;
  for (const auto& load : problem.loads) {
    if (load.type != deck::LoadType::Spring) continue;
    for (GO node : nodesOf(load.set))
      for (int c = 0; c < dim; ++c)
        if (load.vector[c] != 0.0) springs[node * dim + c] += load.vector[c];
  }
  for (const auto& [dof, k] : springs) {
    const LO lo = owned.getLocalElement(dof);
    if (lo == Teuchos::OrdinalTraits<LO>::invalid()) continue;
    springRows_.push_back(lo);
    springOverlapDofs_.push_back(overlap.getLocalElement(dof));
    springStiffness_.push_back(k);
  }
}

Teuchos::RCP<Vector> BoundaryConditions::deadForce(const std::function<std::vector<double>(const std::string&)>& value,
                                                   bool change) const {
  // Dead loads on sets into overlapped storage, added to the owners' rows; the ExternalLoads' own values
  // (set by setLoadStep or the constructor) are the step's.
  Vector overlapLoads(layout_.overlapMap());
  loads_->addDeadLoads(overlapLoads.getDataNonConst(0).getRawPtr(), change);
  auto force = Teuchos::rcp(new Vector(layout_.ownedMap()));
  force->doExport(overlapLoads, layout_.exporter(), Tpetra::ADD);
  // Nodal forces: shared equally by the whole set's nodes; only the owner adds a node's share.
  const mesh::DistributedMesh& part = problem_.mesh;
  const int dim = layout_.dimension();
  const Map& owned = *layout_.ownedMap();
  auto f = force->getDataNonConst(0);
  for (const auto& nodal : problem_.nodalForces) {
    const double total = value(nodal.name)[0];
    const auto set = &part.local().nodeSet(nodal.nodeSet) - part.local().nodeSets.data();
    const double setSize = static_cast<double>(part.globalNodeSetSizes[static_cast<std::size_t>(set)]);
    for (mesh::GlobalIndex n : part.local().nodeSet(nodal.nodeSet).nodes) {
      const LO lo = owned.getLocalElement(part.part.globalNodes[n] * dim + nodal.component);
      if (lo != Teuchos::OrdinalTraits<LO>::invalid()) f[lo] += total / setSize;
    }
  }
  return force;
}

void BoundaryConditions::setLoadStep(const continuation::LoadSchedule& schedule, int step) {
  for (std::size_t k = 0; k < prescribedRows_.size(); ++k) {
    prescribedStart_[k] = schedule.start(step, dirichletKey(prescribedBy_[k]))[0];
    prescribedChange_[k] = schedule.change(step, dirichletKey(prescribedBy_[k]))[0];
  }
  const auto start = [&](const std::string& name) { return schedule.start(step, loadKey(name)); };
  const auto change = [&](const std::string& name) { return schedule.change(step, loadKey(name)); };
  loads_->setStepValues(start, change);
  startForce_ = deadForce(start, false);
  changeForce_ = deadForce(change, true);
  hasStartForce_ = startForce_->normInf() != 0.0;
}

BoundaryConditions::~BoundaryConditions() = default;

void BoundaryConditions::residual(const Vector& force, const Vector& x, double a, Vector& f) const {
  // Free rows: f_int − f_ext + K_s u (equilibrium); prescribed rows: u − ū.
  f.update(1.0, force, -a, *changeForce_, 0.0);
  if (hasStartForce_) f.update(-1.0, *startForce_, 1.0);
  auto fv = f.getDataNonConst(0);
  auto xv = x.getData(0);
  for (std::size_t k = 0; k < springRows_.size(); ++k) fv[springRows_[k]] += springStiffness_[k] * xv[springRows_[k]];
  for (std::size_t k = 0; k < prescribedRows_.size(); ++k) {
    const LO r = prescribedRows_[k];
    fv[r] = xv[r] - (prescribedStart_[k] + a * prescribedChange_[k]);
  }
}

void BoundaryConditions::dResidualdLambda(const Vector& dForcedLambda, double slope, Vector& d) const {
  d.putScalar(0.0);  // the caller's storage may hold anything, and 0·NaN is NaN
  d.update(-slope, *changeForce_, 1.0, dForcedLambda, 1.0);
  auto dv = d.getDataNonConst(0);
  for (std::size_t k = 0; k < prescribedRows_.size(); ++k) dv[prescribedRows_[k]] = -slope * prescribedChange_[k];
}

void BoundaryConditions::subtractExternalForce(double a, Vector& v) const {
  v.update(-a, *changeForce_, 1.0);
  if (hasStartForce_) v.update(-1.0, *startForce_, 1.0);
}

}  // namespace contessa::model
