#include "output/ResultsOutput.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <algorithm>
#include <functional>

#include <Teuchos_CommHelpers.hpp>

#include "common/Error.hpp"
#include "common/Version.hpp"
#include "io/DecomposedMesh.hpp"
#include "io/ExodusResults.hpp"
#include "io/OutputWriteError.hpp"
#include "mesh/DecomposedExodusReader.hpp"
#include "mesh/MeshDistribution.hpp"
#include "model/RankAgreement.hpp"

#include "common/PhaseTimers.hpp"

namespace contessa::output {

using Teuchos::RCP;
using Teuchos::rcp;
using Teuchos::rcpFromRef;

namespace {

// A map with every global id 0..n-1 on rank 0: the target of the gathers for writing one file.
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

const char* const kAxes[] = {"x", "y", "z"};

// Whether the deck asked for a set's reaction columns (Reaction Node Sets): a Reaction Force history
// request may have added its set to the model's list (deck::HistoryRequest::addedReactionSet).
bool hasReactionColumns(const deck::ProblemDefinition& problem, const std::string& set) {
  return std::none_of(problem.history.begin(), problem.history.end(),
                      [&set](const deck::HistoryRequest& r) { return r.addedReactionSet && r.nodeSet == set; });
}

// The history's columns before the point histories: the fixed ones, then each reaction node set's and
// each interface's contact force, one per component.
std::vector<std::string> forceColumns(const deck::ProblemDefinition& problem,
                                      const model::ContactMechanicsModel& model) {
  const int dim = problem.dimension();
  std::vector<std::string> columns = kFixedColumns;
  // Load steps: the step (1 for the first) and the time that runs on across steps (lambda is λ_s of the step).
  if (!problem.loadSteps.empty()) columns.insert(columns.end(), {"load_step", "time"});
  for (const auto& set : problem.reactionNodeSets)
    if (hasReactionColumns(problem, set))
      for (int c = 0; c < dim; ++c) columns.push_back("reaction_" + set + "_" + kAxes[c]);
  for (const auto& [name, force] : model.contactForces())
    for (int c = 0; c < dim; ++c) columns.push_back("contact_force_" + columnName(name) + "_" + kAxes[c]);
  // How far the regularisation is from exact contact (contact::RegularisationMeasures), per interface.
  for (const auto& [name, force] : model.contactForces())
    for (const char* measure : {"max_penetration_", "max_elastic_slip_", "max_slip_", "mean_slip_"})
      columns.push_back(measure + columnName(name));
  return columns;
}

// A map of the given global ids, in that order, on this rank (others have their own).
RCP<const model::Map> mapOf(const std::vector<model::GO>& ids, const RCP<const model::Comm>& comm) {
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  return rcp(new model::Map(invalid, Teuchos::ArrayView<const model::GO>(ids), 0, comm));
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

std::string formatNumber(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", x);
  return text;
}

// Exodus records: who wrote the file, when, from which command and deck, and the node (Exodus
// numbering) each point history at given coordinates measures.
io::ExodusRecords runRecords(const std::string& title, const RunDescription& run, int ranks,
                             const std::vector<deck::HistoryRequest>& histories) {
  io::ExodusRecords records;
  records.title = title.empty() ? "Contessa results" : title;
  records.qa.push_back({"contessa", version(), formatTime("%Y/%m/%d"), formatTime("%H:%M:%S")});
  char host[256] = {};
  if (gethostname(host, sizeof host - 1) != 0) host[0] = '\0';
  records.info = {"Contessa " + version(),
                  "run " + formatTime("%Y-%m-%d %H:%M:%S") + " on " + std::to_string(ranks) + " rank(s), host " + host};
  if (!run.commandLine.empty()) records.info.push_back("command: " + run.commandLine);
  for (const auto& request : histories) {
    if (request.node < 0) continue;
    std::string at;
    for (double x : request.nodeCoordinates) at += (at.empty() ? "" : ", ") + formatNumber(x);
    records.info.push_back("history " + request.name + ": node " + std::to_string(request.node + 1) + " at (" + at + ")");
  }
  if (!run.deck.empty()) {
    records.info.push_back("deck as run (after --set overrides):");
    records.info.insert(records.info.end(), run.deck.begin(), run.deck.end());
  }
  return records;
}

}  // namespace

ResultsOutput::ResultsOutput(const deck::ProblemDefinition& problem, const model::ContactMechanicsModel& model,
                             const std::string& directory, const std::string& name, bool printTable,
                             const RunDescription& run, const std::vector<std::vector<double>>* restartRows)
    : problem_(problem), model_(model), printTable_(printTable) {
  const auto comm = model.ownedDofMap()->getComm();
  root_ = comm->getRank() == 0;
  perRank_ = problem.exodusPerRank;
  makeFileMaps();
  columns_ = forceColumns(problem, model);
  histories_ = std::make_unique<PointHistories>(problem, model, columns_);
  columns_.insert(columns_.end(), histories_->columns().begin(), histories_->columns().end());
  const int ranks = comm->getSize();
  exodusPath_ = directory + "/" + name + ".exo" + (perRank_ ? "." + std::to_string(ranks) + ".*" : "");
  historyPath_ = directory + "/" + name + ".history.csv";
  ExodusSetup exodus{exodusFields(), runRecords(problem.title, run, ranks, problem.history), rigidSurfaceBlocks(),
                     directory + "/" + name + ".exo", restartRows};
  openFiles(directory, name, exodus);
  if (restartRows != nullptr) {
    for (const auto& row : *restartRows)
      requireInput(row.size() == columns_.size(), "restart file: a history row has " + std::to_string(row.size()) +
                                                      " columns, this deck's history " + std::to_string(columns_.size()));
    rows_ = *restartRows;
  }
  if (root_ && printTable_) {
    std::printf("%5s %12s %12s %7s %4s %6s %7s %11s %9s\n", "incr", "lambda", "dlambda", "beta", "att", "newton",
                "contact", "|f|", "time[s]");
    std::fflush(stdout);
  }
}

void ResultsOutput::makeFileMaps() {
  const auto comm = model_.ownedDofMap()->getComm();
  const int dim = problem_.dimension();
  const mesh::DistributedMesh& part = problem_.mesh;
  if (perRank_) {
    // Each rank's file is its part of the mesh: the elements it assembles and the nodes they use.
    piece_ = &part.part;
    std::vector<model::GO> dofs;
    for (model::GO node : piece_->globalNodes)
      for (int c = 0; c < dim; ++c) dofs.push_back(node * dim + c);
    fileDofMap_ = mapOf(dofs, comm);
    fileElementMap_ = mapOf(piece_->globalElements, comm);
    fileNodeMap_ = mapOf(piece_->globalNodes, comm);
  } else {
    fileDofMap_ = rootMap(part.numGlobalNodes * dim, comm);
    fileElementMap_ = rootMap(part.numGlobalElements, comm);
    fileNodeMap_ = rootMap(part.numGlobalNodes, comm);
  }
  dofToFile_ = rcp(new model::Import(model_.ownedDofMap(), fileDofMap_));
  elementToFile_ = rcp(new model::Import(model_.ownedElementMap(), fileElementMap_));
  nodeToFile_ = rcp(new model::Import(model_.ownedNodeMap(), fileNodeMap_));
}

std::vector<io::ExodusSurfaceBlock> ResultsOutput::rigidSurfaceBlocks() {
  // Rigid contact surfaces are not part of the mesh: each becomes a block of its own, named after its
  // interface, so that ParaView shows the plate moving with λ: its facets on its points, segments (BAR2)
  // in 2D, quadrilaterals (SHELL4, drawn as surfaces) in 3D.
  const int dim = problem_.dimension();
  std::vector<io::ExodusSurfaceBlock> surfaceBlocks;
  for (const auto& contact : problem_.contacts) {
    if (!contact.rigidMaster) continue;
    std::string blockName = contact.name;
    if (problem_.mesh.local().hasBlock(blockName)) blockName += "_rigid";
    const auto& surface = contact.rigidSurface;
    io::ExodusSurfaceBlock block{blockName, surface.points, contact.nodesPerFacet(),
                                 {surface.facets.begin(), surface.facets.end()}};
    const auto points = static_cast<mesh::GlobalIndex>(surface.points.size()) / dim;
    rigidSurfaces_.push_back(RigidSurface{blockName, static_cast<std::size_t>(points),
                                          std::vector<double>(surface.motion.begin(), surface.motion.end()),
                                          contact.name});
    surfaceBlocks.push_back(std::move(block));
  }
  return surfaceBlocks;
}

io::ExodusFields ResultsOutput::exodusFields() const {
  const int dim = problem_.dimension();
  io::ExodusFields fields;
  for (int c = 0; c < dim; ++c) fields.nodal.push_back(std::string("displ_") + kAxes[c]);
  if (model_.hasContact())
    for (const auto& f : model::ContactMechanicsModel::contactFieldNames()) fields.nodal.push_back(f);
  fields.element = model::ContactMechanicsModel::elementStressNames(dim, problem_.axisymmetric);
  // The history's reactions and contact forces are globals too: force-displacement curves can
  // be plotted from the Exodus file alone, under the same names.
  fields.global = kGlobals;
  fields.global.insert(fields.global.end(), columns_.begin() + kFixedColumns.size(), columns_.end());
  return fields;
}

void ResultsOutput::openFiles(const std::string& directory, const std::string& name, const ExodusSetup& exodus) {
  // Rank 0 takes the lock before any file is created, so a second run on the same files stops before
  // it touches them; per rank, every rank creates its piece once the lock is held. The history is
  // created (replacing an earlier run's) once every Exodus file is.
  const auto& comm = *model_.ownedDofMap()->getComm();
  // One file: rank 0 writes the whole mesh, gathered from the parts (collective) for the writer only.
  const mesh::Mesh whole = perRank_ ? mesh::Mesh{} : mesh::gatherMeshOnRoot(problem_.mesh);
  std::string error;
  if (root_) {
    try {
      lock_ = std::make_unique<io::OutputLock>(directory, name);
      warning_ = lock_->warning();
      if (!perRank_) createWholeExodus(whole, exodus);
    } catch (const std::exception& e) {
      error = e.what();
      exodus_.reset();
      lock_.reset();
    }
  }
  error = model::firstMessageOfAnyRank(comm, error);
  if (!error.empty()) throw InputError(error);
  if (perRank_) {
    try {
      createPieceExodus(exodus);
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  if (root_ && error.empty()) error = createHistory(exodus.restartRows);
  error = model::firstMessageOfAnyRank(comm, error);
  if (!error.empty()) {
    removeUnwrittenFiles();
    lock_.reset();
    throw InputError(error);
  }
}

void ResultsOutput::createWholeExodus(const mesh::Mesh& whole, const ExodusSetup& exodus) {
  continueRun(exodusPath_, exodus.restartRows, [&] {
    exodus_ = std::make_unique<io::ExodusWriter>(exodusPath_, whole, exodus.fields, exodus.records, exodus.surfaces,
                                                 nullptr, io::ExodusNaming::AtFirstStep);
  });
}

void ResultsOutput::createPieceExodus(const ExodusSetup& exodus) {
  // The rigid surfaces are drawn by rank 0's piece; the other pieces hold their blocks empty.
  const int dim = problem_.dimension();
  io::ExodusDecomposition decomposition = io::decompositionOf(problem_.mesh);
  std::vector<io::ExodusSurfaceBlock> pieceSurfaces = exodus.surfaces;
  for (auto& surface : pieceSurfaces) {
    const auto points = static_cast<mesh::GlobalIndex>(surface.points.size()) / dim;
    const mesh::GlobalIndex elements = surface.numElements();
    decomposition.globalBlockSizes.push_back(elements);
    if (root_) {
      for (mesh::GlobalIndex p = 0; p < points; ++p) decomposition.globalNodes.push_back(decomposition.globalNumNodes + p);
      for (mesh::GlobalIndex e = 0; e < elements; ++e)
        decomposition.globalElements.push_back(decomposition.globalNumElements + e);
    } else {
      surface.points.clear();
      surface.connectivity.clear();
    }
    decomposition.globalNumNodes += points;
    decomposition.globalNumElements += elements;
  }
  if (!root_) rigidSurfaces_.clear();
  const std::string piecePath =
      mesh::decomposedFileName(exodus.base, decomposition.processors, decomposition.processor);
  continueRun(piecePath, exodus.restartRows, [&] {
    exodus_ = std::make_unique<io::ExodusWriter>(piecePath, piece_->mesh, exodus.fields, exodus.records,
                                                 pieceSurfaces, &decomposition, io::ExodusNaming::AtFirstStep);
  });
}

void ResultsOutput::continueRun(const std::string& path, const std::vector<std::vector<double>>* restartRows,
                                const std::function<void()>& create) {
  // A restart re-creates each Exodus file with the steps up to the restart file's increment, copied
  // from the file it replaces (set aside until then, and put back if that fails).
  if (restartRows == nullptr) return create();
  const std::string old = path + ".before-restart";
  requireInput(std::filesystem::exists(path) || std::filesystem::exists(old),
               path + ": the results file of the run to continue is missing (a restart appends to it; with Exodus "
                      "Layout = Per Rank, run on as many ranks as before)");
  std::error_code ec;
  if (std::filesystem::exists(path)) std::filesystem::rename(path, old, ec);
  requireInput(!ec, path + ": cannot set the results file aside for the restart (" + ec.message() + ")");
  try {
    create();
    exodus_->copySteps(io::ExodusResults(old), static_cast<int>(restartRows->size()));
  } catch (...) {
    exodus_.reset();
    std::filesystem::rename(old, path, ec);
    throw;
  }
  std::filesystem::remove(old, ec);
}

std::string ResultsOutput::createHistory(const std::vector<std::vector<double>>* restartRows) {
  try {
    const std::vector<std::string> integerColumns = {"step", "attempts", "newton_iterations", "active_contacts",
                                                     "new_contacts", "new_events", "stick", "slip",
                                                     "linear_iterations"};
    // A directory in the way would only show at the rename: say it now, as creating the file would.
    if (std::filesystem::is_directory(historyPath_))
      throw io::OutputWriteError(historyPath_, "cannot create", std::strerror(EISDIR));
    history_ = std::make_unique<io::HistoryWriter>(historyStartingPath(), columns_, integerColumns);
    if (restartRows != nullptr) {
      for (const auto& row : *restartRows) history_->writeRow(row);
      nameHistory();
    }
  } catch (const std::exception& e) {
    std::string error = e.what();
    const std::size_t at = error.find(historyStartingPath());  // the history by its name
    if (at != std::string::npos) error.replace(at, historyStartingPath().size(), historyPath_);
    return error;
  }
  return "";
}

ResultsOutput::~ResultsOutput() { removeUnwrittenFiles(); }

void ResultsOutput::removeUnwrittenFiles() {
  if (!rows_.empty()) return;
  exodus_.reset();  // a writer without a step removes its file
  if (history_ && !historyNamed_) {
    history_.reset();
    std::error_code ignored;
    std::filesystem::remove(historyStartingPath(), ignored);
  }
}

// The history, like the Exodus file, takes its name with its first row: until then an earlier run's
// history stays.
std::string ResultsOutput::historyStartingPath() const { return historyPath_ + ".starting"; }

void ResultsOutput::nameHistory() {
  std::error_code ec;
  std::filesystem::rename(historyStartingPath(), historyPath_, ec);
  if (ec) throw io::OutputWriteError(historyPath_, "cannot create", ec.message());
  historyNamed_ = true;
}

void ResultsOutput::incrementConverged(const model::Vector& x, const solvers::IncrementReport& report) {
  timers::Scope timed(timers::Phase::Output);
  const auto& comm = *model_.ownedDofMap()->getComm();
  // Collective part: every rank computes and sends what the Exodus files show (to rank 0's file, or
  // to each rank's piece), and the history row (its sums are known everywhere).
  const FileValues values = fileValues(x);
  const auto counts = model_.contactCounts();
  const auto regularisation = model_.contactRegularisation(x);
  const std::vector<double> row = historyRow(x, report, counts, regularisation);

  const std::string stepText = "cannot write step " + std::to_string(report.step);
  const auto describe = [this, &stepText](const std::exception& e) {
    if (const auto* w = dynamic_cast<const io::OutputWriteError*>(&e))  // the history by its name
      return stepText + " to " + (w->path() == historyStartingPath() ? historyPath_ : w->path()) + ": " + w->reason();
    return stepText + ": " + e.what();
  };
  // What the user still has: the history's steps, which every Exodus file holds too.
  const auto kept = [this]() {
    return rows_.empty() ? std::string(" (no step was written)")
                         : " (the results keep steps 0 to " + std::to_string(std::llround(rows_.back()[0])) + ")";
  };
  // The Exodus step(s) first, then the history row: a history row always has its Exodus step. The
  // history's disk space is reserved before any Exodus file is written, so a full disk stops the
  // run with the files holding the same increments.
  std::string error;
  try {
    if (history_) history_->reserveRow();
    if (exodus_) writeExodusStep(values, report, counts, row);
  } catch (const std::exception& e) {
    error = describe(e) + kept();
  }
  error = model::firstMessageOfAnyRank(comm, error);
  if (error.empty() && history_) {
    try {
      history_->writeRow(row);
      if (!historyNamed_) nameHistory();
    } catch (const std::exception& e) {
      error = describe(e) + kept();
    }
  }
  error = model::firstMessageOfAnyRank(comm, error);
  if (!error.empty()) {
    failure_ = error;
    throw std::runtime_error(error);
  }
  rows_.push_back(row);  // on every rank, so that any rank can say which steps the files keep
  lastRegularisation_ = regularisation;
  lastStep_ = report.step;
  lastLambda_ = report.lambda;
  if (root_ && printTable_) {
    std::printf("%5d %12.6g %12.6g %7.3g %4d %6d %7d %11.3e %9.2f\n", report.step, report.lambda, report.dlambda,
                report.beta, report.attempts, report.newtonIterations, counts.active, report.residualNorm,
                report.wallSeconds);
    std::fflush(stdout);
  }
}

ResultsOutput::FileValues ResultsOutput::fileValues(const model::Vector& x) const {
  const auto stresses = model_.elementStresses(x);
  FileValues values{model::Vector(fileDofMap_), model::MultiVector(fileElementMap_, stresses->getNumVectors()),
                    model::MultiVector(fileNodeMap_, 4)};
  values.displacement.doImport(x, *dofToFile_, Tpetra::INSERT);
  values.stress.doImport(*stresses, *elementToFile_, Tpetra::INSERT);
  if (model_.hasContact()) values.contact.doImport(*model_.contactNodalFields(), *nodeToFile_, Tpetra::INSERT);
  return values;
}

std::vector<double> ResultsOutput::historyRow(const model::Vector& x, const solvers::IncrementReport& report,
                                              const contact::ContactCounts& counts,
                                              const Regularisation& regularisation) const {
  const int dim = problem_.dimension();
  std::vector<double> row = {static_cast<double>(report.step), report.lambda, report.dlambda, report.beta,
                             static_cast<double>(report.attempts), static_cast<double>(report.newtonIterations),
                             static_cast<double>(counts.active), static_cast<double>(counts.newlyActive),
                             static_cast<double>(report.newEvents), static_cast<double>(counts.stick),
                             static_cast<double>(counts.slip),
                             report.residualNorm, report.wallSeconds,
                             static_cast<double>(report.linearIterations)};
  if (!problem_.loadSteps.empty()) {
    row.push_back(report.loadStep + 1);
    row.push_back(model_.loadSchedule().time(report.loadStep, report.lambda));
  }
  const auto reactions = model_.reactions(x, report.lambda);
  for (const auto& r : reactions)
    if (hasReactionColumns(problem_, r.nodeSet))
      for (int c = 0; c < dim; ++c) row.push_back(r.force[c]);
  for (const auto& [name, force] : model_.contactForces())
    for (int c = 0; c < dim; ++c) row.push_back(force[c]);
  for (const auto& [name, m] : regularisation) row.insert(row.end(), {m.penetration, m.elasticSlip, m.slip, m.meanSlip()});
  const auto histories = histories_->values(x, report.lambda, reactions, report.loadStep);
  row.insert(row.end(), histories.begin(), histories.end());
  return row;
}

void ResultsOutput::writeExodusStep(const FileValues& values, const solvers::IncrementReport& report,
                                    const contact::ContactCounts& counts, const std::vector<double>& row) {
  // Nodal values: the file's mesh nodes, then the rigid surfaces' points (displaced by their scheduled
  // motion, λ · Motion without load steps; no contact values of their own).
  const int dim = problem_.dimension();
  const auto meshNodes = static_cast<std::size_t>(fileNodeMap_->getNodeNumElements());
  const auto totalNodes = static_cast<std::size_t>(exodus_->numNodes());
  const auto u = values.displacement.getData(0);
  std::vector<std::vector<double>> nodal(dim, std::vector<double>(totalNodes, 0.0));
  for (std::size_t n = 0; n < meshNodes; ++n)
    for (int c = 0; c < dim; ++c) nodal[c][n] = u[n * dim + c];
  std::size_t point = meshNodes;
  const auto& schedule = model_.loadSchedule();
  for (const auto& surface : rigidSurfaces_) {
    const auto motion = problem_.loadSteps.empty()
                            ? surface.motion
                            : schedule.value(report.loadStep, model::motionKey(surface.interfaceName), report.lambda);
    const double scale = problem_.loadSteps.empty() ? report.lambda : 1.0;
    for (std::size_t p = 0; p < surface.points; ++p, ++point)
      for (int c = 0; c < dim; ++c) nodal[c][point] = scale * motion[c];
  }
  if (model_.hasContact())
    for (std::size_t v = 0; v < 4; ++v) {
      const auto col = values.contact.getData(v);
      nodal.emplace_back(col.begin(), col.end());
      nodal.back().resize(totalNodes, 0.0);
    }
  std::vector<std::vector<double>> element(values.stress.getNumVectors());
  for (std::size_t v = 0; v < element.size(); ++v) {
    const auto col = values.stress.getData(v);
    element[v].assign(col.begin(), col.end());
  }
  std::vector<double> globals = {report.lambda, report.dlambda, report.beta, static_cast<double>(counts.active),
                                 static_cast<double>(report.newtonIterations)};
  globals.insert(globals.end(), row.begin() + kFixedColumns.size(), row.end());
  const double time =
      problem_.loadSteps.empty() ? report.lambda : model_.loadSchedule().time(report.loadStep, report.lambda);
  exodus_->writeStep(time, nodal, element, globals);
}

std::vector<std::string> ResultsOutput::regularisationWarnings() const {
  if (rows_.empty()) return {};
  return output::regularisationWarnings(problem_.contacts, lastRegularisation_, lastStep_, lastLambda_);
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
