#include "model/BoundaryConditions.hpp"

#include <map>
#include <string>

#include "common/Error.hpp"
#include "model/RankAgreement.hpp"

namespace contessa::model {

BoundaryConditions::BoundaryConditions(const deck::ProblemDefinition& problem, const DofLayout& layout) {
  const mesh::DistributedMesh& part = problem.mesh;  // node sets hold the part's nodes, owned or not
  const auto nodesOf = [&](const std::string& set) {
    std::vector<GO> nodes;
    for (mesh::GlobalIndex n : part.local().nodeSet(set).nodes) nodes.push_back(part.part.globalNodes[n]);
    return nodes;
  };
  const int dim = layout.dimension();
  const Map& owned = *layout.ownedMap();
  // Dirichlet: one value per DOF; the same DOF prescribed twice with different values is an input error.
  // A rank sees the nodes of its part only: the lowest rank that finds a conflict names it on every rank.
  std::map<GO, std::pair<double, std::string>> prescribed;
  std::string conflict;
  for (const auto& bc : problem.dirichlet) {
    for (GO node : nodesOf(bc.nodeSet)) {
      const GO dof = node * dim + bc.component;
      auto [it, inserted] = prescribed.emplace(dof, std::make_pair(bc.value, bc.name));
      if (conflict.empty() && !inserted && it->second.first != bc.value)
        conflict = "Problem/Dirichlet Conditions/" + bc.name + ": prescribes node " + std::to_string(node + 1) +
                   " differently from '" + it->second.second + "'";
    }
  }
  conflict = firstMessageOfAnyRank(*layout.comm(), conflict);
  if (!conflict.empty()) throw InputError(conflict);
  for (const auto& [dof, value] : prescribed) {
    const LO lo = owned.getLocalElement(dof);
    if (lo != Teuchos::OrdinalTraits<LO>::invalid()) {
      prescribedRows_.push_back(lo);
      prescribedValues_.push_back(value.first);
    }
  }
  // Dead loads on sets: each rank integrates its part's facets and elements into overlapped storage,
  // added to the owners' rows.
  const Map& overlap = *layout.overlapMap();
  loads_ = std::make_unique<ExternalLoads>(problem, [&overlap](mesh::GlobalIndex dof) { return overlap.getLocalElement(dof); });
  Vector overlapLoads(layout.overlapMap());
  loads_->addDeadLoads(overlapLoads.getDataNonConst(0).getRawPtr());
  externalForce_ = Teuchos::rcp(new Vector(layout.ownedMap()));
  externalForce_->doExport(overlapLoads, layout.exporter(), Tpetra::ADD);
  // Nodal forces: shared equally by the whole set's nodes; only the owner adds a node's share.
  auto f = externalForce_->getDataNonConst(0);
  for (const auto& force : problem.nodalForces) {
    const auto set = &part.local().nodeSet(force.nodeSet) - part.local().nodeSets.data();
    const double setSize = static_cast<double>(part.globalNodeSetSizes[static_cast<std::size_t>(set)]);
    for (GO node : nodesOf(force.nodeSet)) {
      const LO lo = owned.getLocalElement(node * dim + force.component);
      if (lo != Teuchos::OrdinalTraits<LO>::invalid()) f[lo] += force.totalForce / setSize;
    }
  }
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

BoundaryConditions::~BoundaryConditions() = default;

void BoundaryConditions::residual(const Vector& force, const Vector& x, double lambda, Vector& f) const {
  // Free rows: f_int − λ f_ext + K_s u (equilibrium); prescribed rows: u − λ ū.
  f.update(1.0, force, -lambda, *externalForce_, 0.0);
  auto fv = f.getDataNonConst(0);
  auto xv = x.getData(0);
  for (std::size_t k = 0; k < springRows_.size(); ++k) fv[springRows_[k]] += springStiffness_[k] * xv[springRows_[k]];
  for (std::size_t k = 0; k < prescribedRows_.size(); ++k) {
    const LO r = prescribedRows_[k];
    fv[r] = xv[r] - lambda * prescribedValues_[k];
  }
}

void BoundaryConditions::dResidualdLambda(const Vector& dForcedLambda, Vector& d) const {
  d.putScalar(0.0);  // the caller's storage may hold anything, and 0·NaN is NaN
  d.update(-1.0, *externalForce_, 1.0, dForcedLambda, 1.0);
  auto dv = d.getDataNonConst(0);
  for (std::size_t k = 0; k < prescribedRows_.size(); ++k) dv[prescribedRows_[k]] = -prescribedValues_[k];
}

}  // namespace contessa::model
