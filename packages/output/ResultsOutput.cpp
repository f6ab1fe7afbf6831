#include "output/ResultsOutput.hpp"

#include <cstdio>

#include "common/PhaseTimers.hpp"

namespace contessa::output {

using Teuchos::RCP;
using Teuchos::rcp;

namespace {

// A map with every global id 0..n-1 on rank 0: the target of the gathers for writing.
RCP<const model::Map> rootMap(model::GO n, const RCP<const model::Comm>& comm) {
  std::vector<model::GO> ids;
  if (comm->getRank() == 0)
    for (model::GO i = 0; i < n; ++i) ids.push_back(i);
  return rcp(new model::Map(n, Teuchos::ArrayView<const model::GO>(ids), 0, comm));
}

// History column names cannot hold spaces (interface names may).
std::string columnName(std::string name) {
  for (auto& c : name)
    if (c == ' ' || c == ',') c = '_';
  return name;
}

const std::vector<std::string> kGlobals = {"load_factor", "step_size", "beta", "active_contacts", "newton_iterations"};

}  // namespace

ResultsOutput::ResultsOutput(const deck::ProblemDefinition& problem, const model::ContactMechanicsModel& model,
                             const std::string& directory, const std::string& name, bool printTable)
    : problem_(problem), model_(model), printTable_(printTable) {
  const auto comm = model.ownedDofMap()->getComm();
  root_ = comm->getRank() == 0;
  const int dim = problem.mesh.dimension;
  rootDofMap_ = rootMap(problem.mesh.numNodes() * dim, comm);
  rootElementMap_ = rootMap(problem.mesh.numElements(), comm);
  dofToRoot_ = rcp(new model::Import(model.ownedDofMap(), rootDofMap_));
  elementToRoot_ = rcp(new model::Import(model.ownedElementMap(), rootElementMap_));
  rootNodeMap_ = rootMap(problem.mesh.numNodes(), comm);
  nodeToRoot_ = rcp(new model::Import(model.ownedNodeMap(), rootNodeMap_));

  columns_ = {"step", "lambda", "dlambda", "beta", "attempts", "newton_iterations", "active_contacts",
              "new_contacts", "stick", "slip", "residual_norm", "wall_s"};
  const char* axes[] = {"x", "y", "z"};
  for (const auto& set : problem.reactionNodeSets)
    for (int c = 0; c < dim; ++c) columns_.push_back("reaction_" + set + "_" + axes[c]);
  for (const auto& [name, force] : model.contactForces())
    for (int c = 0; c < dim; ++c) columns_.push_back("contact_force_" + columnName(name) + "_" + axes[c]);

  exodusPath_ = directory + "/" + name + ".exo";
  historyPath_ = directory + "/" + name + ".history.csv";
  if (root_) {
    io::ExodusFields fields;
    for (int c = 0; c < dim; ++c) fields.nodal.push_back(std::string("displ_") + axes[c]);
    if (model.hasContact())
      for (const auto& f : model::ContactMechanicsModel::contactFieldNames()) fields.nodal.push_back(f);
    fields.element = model::ContactMechanicsModel::elementStressNames(dim);
    fields.global = kGlobals;
    exodus_ = std::make_unique<io::ExodusWriter>(exodusPath_, problem.mesh, fields,
                                                 problem.title.empty() ? "Contessa results" : problem.title);
    const std::vector<std::string> integerColumns = {"step", "attempts", "newton_iterations", "active_contacts",
                                                     "new_contacts", "stick", "slip"};
    history_ = std::make_unique<io::HistoryWriter>(historyPath_, columns_, integerColumns);
    if (printTable_) {
      std::printf("%5s %12s %12s %7s %4s %6s %7s %11s %9s\n", "incr", "lambda", "dlambda", "beta", "att", "newton",
                  "contact", "|f|", "time[s]");
      std::fflush(stdout);
    }
  }
}

void ResultsOutput::incrementConverged(const model::Vector& x, const solvers::IncrementReport& report) {
  timers::Scope timed(timers::Phase::Output);
  const int dim = problem_.mesh.dimension;
  // Collective part: every rank computes and sends.
  model::Vector allX(rootDofMap_);
  allX.doImport(x, *dofToRoot_, Tpetra::INSERT);
  const auto stresses = model_.elementStresses(x);
  model::MultiVector allStress(rootElementMap_, stresses->getNumVectors());
  allStress.doImport(*stresses, *elementToRoot_, Tpetra::INSERT);
  const auto reactions = model_.reactions(x, report.lambda);
  const auto counts = model_.contactCounts();
  const auto contactForces = model_.contactForces();
  model::MultiVector allContact(rootNodeMap_, 4);
  if (model_.hasContact()) allContact.doImport(*model_.contactNodalFields(), *nodeToRoot_, Tpetra::INSERT);
  if (!root_) return;

  std::vector<double> row = {static_cast<double>(report.step), report.lambda, report.dlambda, report.beta,
                             static_cast<double>(report.attempts), static_cast<double>(report.newtonIterations),
                             static_cast<double>(counts.active), static_cast<double>(counts.newlyActive),
                             static_cast<double>(counts.stick), static_cast<double>(counts.slip),
                             report.residualNorm, report.wallSeconds};
  for (const auto& r : reactions)
    for (int c = 0; c < dim; ++c) row.push_back(r.force[c]);
  for (const auto& [name, force] : contactForces)
    for (int c = 0; c < dim; ++c) row.push_back(force[c]);
  history_->writeRow(row);
  rows_.push_back(row);

  const auto u = allX.getData(0);
  std::vector<std::vector<double>> nodal(dim, std::vector<double>(problem_.mesh.numNodes()));
  for (model::GO n = 0; n < problem_.mesh.numNodes(); ++n)
    for (int c = 0; c < dim; ++c) nodal[c][n] = u[n * dim + c];
  if (model_.hasContact())
    for (std::size_t v = 0; v < 4; ++v) {
      const auto col = allContact.getData(v);
      nodal.emplace_back(col.begin(), col.end());
    }
  std::vector<std::vector<double>> element(allStress.getNumVectors());
  for (std::size_t v = 0; v < element.size(); ++v) {
    const auto col = allStress.getData(v);
    element[v].assign(col.begin(), col.end());
  }
  const std::vector<double> globals = {report.lambda, report.dlambda, report.beta, static_cast<double>(counts.active),
                                       static_cast<double>(report.newtonIterations)};
  exodus_->writeStep(report.lambda, nodal, element, globals);

  if (printTable_) {
    std::printf("%5d %12.6g %12.6g %7.3g %4d %6d %7d %11.3e %9.2f\n", report.step, report.lambda, report.dlambda,
                report.beta, report.attempts, report.newtonIterations, counts.active, report.residualNorm,
                report.wallSeconds);
    std::fflush(stdout);
  }
}

void ResultsOutput::attemptFailed(const solvers::IncrementReport& report) {
  if (root_ && printTable_) {
    if (report.betaRestart)
      std::printf("%5s %12.6g %12.6g %7.3g %4d %6d %7s %11s %9.2f  restart with beta\n", "-", report.lambda,
                  report.dlambda, report.beta, report.attempts, report.newtonIterations, "-", "-", report.wallSeconds);
    else
      std::printf("%5s %12.6g %12.6g %7s %4d %6d %7s %11s %9.2f  failed: cut back\n", "-", report.lambda,
                  report.dlambda, "-", report.attempts, report.newtonIterations, "-", "-", report.wallSeconds);
    std::fflush(stdout);
  }
}

}  // namespace contessa::output
