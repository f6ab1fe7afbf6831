#include "output/ResultsOutput.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <ctime>

#include <Teuchos_CommHelpers.hpp>

#include "common/Error.hpp"
#include "common/Version.hpp"
#include "io/OutputWriteError.hpp"

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
// The history's columns before the reactions and contact forces (which are also Exodus globals).
const std::vector<std::string> kFixedColumns = {"step", "lambda", "dlambda", "beta", "attempts",
                                                "newton_iterations", "active_contacts", "new_contacts",
                                                "new_events", "stick", "slip", "residual_norm", "wall_s",
                                                "linear_iterations"};

// Rank 0's message on every rank ("" when rank 0 succeeded): only rank 0 writes, so only it knows.
std::string agree(const model::Comm& comm, std::string message) {
  int size = static_cast<int>(message.size());
  Teuchos::broadcast(comm, 0, &size);
  message.resize(static_cast<std::size_t>(size));
  if (size > 0) Teuchos::broadcast(comm, 0, size, message.data());
  return message;
}

std::string formatTime(const char* format) {
  const std::time_t t = std::time(nullptr);
  char text[64] = {};
  std::strftime(text, sizeof text, format, std::localtime(&t));
  return text;
}

std::string version() {
  const std::string git = kGitDescription;
  return std::string(kVersion) + (git.empty() || git == "unknown" ? "" : " " + git);
}

// Exodus records: who wrote the file, when, from which command and deck.
io::ExodusRecords runRecords(const std::string& title, const RunDescription& run, int ranks) {
  io::ExodusRecords records;
  records.title = title.empty() ? "Contessa results" : title;
  records.qa.push_back({"contessa", version(), formatTime("%Y/%m/%d"), formatTime("%H:%M:%S")});
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) != 0) host[0] = '\0';
  records.info = {"Contessa " + version(),
                  "run " + formatTime("%Y-%m-%d %H:%M:%S") + " on " + std::to_string(ranks) + " rank(s), host " + host};
  if (!run.commandLine.empty()) records.info.push_back("command: " + run.commandLine);
  if (!run.deck.empty()) {
    records.info.push_back("deck as run (after --set overrides):");
    records.info.insert(records.info.end(), run.deck.begin(), run.deck.end());
  }
  return records;
}

}  // namespace

ResultsOutput::ResultsOutput(const deck::ProblemDefinition& problem, const model::ContactMechanicsModel& model,
                             const std::string& directory, const std::string& name, bool printTable,
                             const RunDescription& run)
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

  columns_ = kFixedColumns;
  const char* axes[] = {"x", "y", "z"};
  for (const auto& set : problem.reactionNodeSets)
    for (int c = 0; c < dim; ++c) columns_.push_back("reaction_" + set + "_" + axes[c]);
  for (const auto& [name, force] : model.contactForces())
    for (int c = 0; c < dim; ++c) columns_.push_back("contact_force_" + columnName(name) + "_" + axes[c]);

  // Rigid contact surfaces are not part of the mesh: each becomes a line block of its own, named
  // after its interface, so that ParaView shows the plate moving with λ.
  std::vector<io::ExodusLineBlock> lineBlocks;
  for (const auto& contact : problem.contacts) {
    if (!contact.rigidMaster) continue;
    std::string blockName = contact.name;
    if (problem.mesh.hasBlock(blockName)) blockName += "_rigid";
    const auto& surface = contact.rigidSurface;
    io::ExodusLineBlock line{blockName, {}};
    for (const auto& point : surface.points)
      for (int c = 0; c < dim; ++c) line.points.push_back(c < 2 ? point[c] : 0.0);
    lineBlocks.push_back(line);
    RigidSurface rigid{blockName, surface.points.size(), std::vector<double>(dim, 0.0)};
    for (int c = 0; c < dim && c < 2; ++c) rigid.motion[c] = surface.motion[c];
    rigidSurfaces_.push_back(rigid);
  }

  exodusPath_ = directory + "/" + name + ".exo";
  historyPath_ = directory + "/" + name + ".history.csv";
  std::string error;
  if (root_) {
    try {
      lock_ = std::make_unique<io::OutputLock>(directory, name);
      warning_ = lock_->warning();
      io::ExodusFields fields;
      for (int c = 0; c < dim; ++c) fields.nodal.push_back(std::string("displ_") + axes[c]);
      if (model.hasContact())
        for (const auto& f : model::ContactMechanicsModel::contactFieldNames()) fields.nodal.push_back(f);
      fields.element = model::ContactMechanicsModel::elementStressNames(dim);
      // The history's reactions and contact forces are globals too: force-displacement curves can
      // be plotted from the Exodus file alone, under the same names.
      fields.global = kGlobals;
      fields.global.insert(fields.global.end(), columns_.begin() + kFixedColumns.size(), columns_.end());
      exodus_ = std::make_unique<io::ExodusWriter>(exodusPath_, problem.mesh, fields,
                                                   runRecords(problem.title, run, comm->getSize()), lineBlocks);
      const std::vector<std::string> integerColumns = {"step", "attempts", "newton_iterations", "active_contacts",
                                                       "new_contacts", "new_events", "stick", "slip",
                                                       "linear_iterations"};
      history_ = std::make_unique<io::HistoryWriter>(historyPath_, columns_, integerColumns);
    } catch (const std::exception& e) {
      error = e.what();
      history_.reset();
      exodus_.reset();
      lock_.reset();
    }
  }
  error = agree(*comm, error);
  if (!error.empty()) throw InputError(error);
  if (root_ && printTable_) {
    std::printf("%5s %12s %12s %7s %4s %6s %7s %11s %9s\n", "incr", "lambda", "dlambda", "beta", "att", "newton",
                "contact", "|f|", "time[s]");
    std::fflush(stdout);
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

  std::string error;
  if (root_) {
    std::vector<double> row = {static_cast<double>(report.step), report.lambda, report.dlambda, report.beta,
                               static_cast<double>(report.attempts), static_cast<double>(report.newtonIterations),
                               static_cast<double>(counts.active), static_cast<double>(counts.newlyActive),
                               static_cast<double>(report.newEvents), static_cast<double>(counts.stick),
                               static_cast<double>(counts.slip),
                               report.residualNorm, report.wallSeconds,
                               static_cast<double>(report.linearIterations)};
    for (const auto& r : reactions)
      for (int c = 0; c < dim; ++c) row.push_back(r.force[c]);
    for (const auto& [name, force] : contactForces)
      for (int c = 0; c < dim; ++c) row.push_back(force[c]);

    // Nodal values: the mesh nodes, then the rigid surfaces' points (displaced by λ · motion, no
    // contact values of their own).
    const model::GO meshNodes = problem_.mesh.numNodes();
    const auto totalNodes = static_cast<std::size_t>(exodus_->numNodes());
    const auto u = allX.getData(0);
    std::vector<std::vector<double>> nodal(dim, std::vector<double>(totalNodes, 0.0));
    for (model::GO n = 0; n < meshNodes; ++n)
      for (int c = 0; c < dim; ++c) nodal[c][n] = u[n * dim + c];
    std::size_t point = static_cast<std::size_t>(meshNodes);
    for (const auto& surface : rigidSurfaces_)
      for (std::size_t p = 0; p < surface.points; ++p, ++point)
        for (int c = 0; c < dim; ++c) nodal[c][point] = report.lambda * surface.motion[c];
    if (model_.hasContact())
      for (std::size_t v = 0; v < 4; ++v) {
        const auto col = allContact.getData(v);
        nodal.emplace_back(col.begin(), col.end());
        nodal.back().resize(totalNodes, 0.0);
      }
    std::vector<std::vector<double>> element(allStress.getNumVectors());
    for (std::size_t v = 0; v < element.size(); ++v) {
      const auto col = allStress.getData(v);
      element[v].assign(col.begin(), col.end());
    }
    std::vector<double> globals = {report.lambda, report.dlambda, report.beta, static_cast<double>(counts.active),
                                   static_cast<double>(report.newtonIterations)};
    globals.insert(globals.end(), row.begin() + kFixedColumns.size(), row.end());

    // The Exodus step first, then the history row: a history row always has its Exodus step. Both
    // files' disk space is reserved before either is written, so a full disk stops the run with
    // the two files holding the same increments.
    try {
      history_->reserveRow();
      exodus_->writeStep(report.lambda, nodal, element, globals);
      history_->writeRow(row);
      rows_.push_back(row);
    } catch (const io::OutputWriteError& e) {
      error = "cannot write step " + std::to_string(report.step) + " to " + e.path() + ": " + e.reason();
    } catch (const std::exception& e) {
      error = "cannot write step " + std::to_string(report.step) + ": " + e.what();
    }
    // What the user still has: both files hold the same increments, up to the last one written.
    if (!error.empty())
      error += rows_.empty() ? " (no step was written)"
                             : " (the results keep steps 0 to " + std::to_string(std::llround(rows_.back()[0])) + ")";
  }
  error = agree(*model_.ownedDofMap()->getComm(), error);
  if (!error.empty()) {
    failure_ = error;
    throw std::runtime_error(error);
  }
  if (root_ && printTable_) {
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
