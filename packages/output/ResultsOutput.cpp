#include "output/ResultsOutput.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <functional>

#include <Teuchos_CommHelpers.hpp>

#include "common/Error.hpp"
#include "common/Version.hpp"
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
                             const RunDescription& run, const std::vector<std::vector<double>>* restartRows)
    : problem_(problem), model_(model), printTable_(printTable) {
  const auto comm = model.ownedDofMap()->getComm();
  root_ = comm->getRank() == 0;
  const int dim = problem.dimension();
  const mesh::DistributedMesh& part = problem.mesh;
  perRank_ = problem.exodusPerRank;
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
  dofToFile_ = rcp(new model::Import(model.ownedDofMap(), fileDofMap_));
  elementToFile_ = rcp(new model::Import(model.ownedElementMap(), fileElementMap_));
  nodeToFile_ = rcp(new model::Import(model.ownedNodeMap(), fileNodeMap_));

  columns_ = kFixedColumns;
  const char* axes[] = {"x", "y", "z"};
  for (const auto& set : problem.reactionNodeSets)
    for (int c = 0; c < dim; ++c) columns_.push_back("reaction_" + set + "_" + axes[c]);
  for (const auto& [name, force] : model.contactForces())
    for (int c = 0; c < dim; ++c) columns_.push_back("contact_force_" + columnName(name) + "_" + axes[c]);

  // Rigid contact surfaces are not part of the mesh: each becomes a block of its own, named after its
  // interface, so that ParaView shows the plate moving with λ: its facets on its points, segments (BAR2)
  // in 2D, quadrilaterals (SHELL4, drawn as surfaces) in 3D.
  std::vector<io::ExodusSurfaceBlock> surfaceBlocks;
  for (const auto& contact : problem.contacts) {
    if (!contact.rigidMaster) continue;
    std::string blockName = contact.name;
    if (part.local().hasBlock(blockName)) blockName += "_rigid";
    const auto& surface = contact.rigidSurface;
    io::ExodusSurfaceBlock block{blockName, surface.points, contact.nodesPerFacet(),
                                 {surface.facets.begin(), surface.facets.end()}};
    const auto points = static_cast<mesh::GlobalIndex>(surface.points.size()) / dim;
    rigidSurfaces_.push_back(RigidSurface{blockName, static_cast<std::size_t>(points),
                                          std::vector<double>(surface.motion.begin(), surface.motion.end())});
    surfaceBlocks.push_back(std::move(block));
  }

  const int ranks = comm->getSize();
  exodusPath_ = directory + "/" + name + ".exo" + (perRank_ ? "." + std::to_string(ranks) + ".*" : "");
  historyPath_ = directory + "/" + name + ".history.csv";
  io::ExodusFields fields;
  for (int c = 0; c < dim; ++c) fields.nodal.push_back(std::string("displ_") + axes[c]);
  if (model.hasContact())
    for (const auto& f : model::ContactMechanicsModel::contactFieldNames()) fields.nodal.push_back(f);
  fields.element = model::ContactMechanicsModel::elementStressNames(dim, problem.axisymmetric);
  // The history's reactions and contact forces are globals too: force-displacement curves can
  // be plotted from the Exodus file alone, under the same names.
  fields.global = kGlobals;
  fields.global.insert(fields.global.end(), columns_.begin() + kFixedColumns.size(), columns_.end());
  // A restart re-creates each Exodus file with the steps up to the restart file's increment, copied
  // from the file it replaces (set aside until then, and put back if that fails).
  const auto continuing = [&](const std::string& path, const std::function<void()>& create) {
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
  };
  // One file: rank 0 writes the whole mesh, gathered from the parts for the writer only.
  const mesh::Mesh whole = perRank_ ? mesh::Mesh{} : mesh::gatherMeshOnRoot(part);
  const auto createExodus = [&]() {
    if (!perRank_) {
      continuing(exodusPath_, [&] {
        exodus_ = std::make_unique<io::ExodusWriter>(exodusPath_, whole, fields, runRecords(problem.title, run, ranks),
                                                     surfaceBlocks, nullptr, io::ExodusNaming::AtFirstStep);
      });
      return;
    }
    // The rigid surfaces are drawn by rank 0's piece; the other pieces hold their blocks empty.
    io::ExodusDecomposition decomposition;
    decomposition.processor = comm->getRank();
    decomposition.processors = ranks;
    decomposition.globalNodes = piece_->globalNodes;
    decomposition.globalElements = piece_->globalElements;
    decomposition.sharedWith = piece_->sharedWith;
    decomposition.globalNumNodes = part.numGlobalNodes;
    decomposition.globalNumElements = part.numGlobalElements;
    decomposition.globalBlockSizes = part.globalBlockSizes;
    std::vector<io::ExodusSurfaceBlock> pieceSurfaces = surfaceBlocks;
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
    const std::string piecePath = mesh::decomposedFileName(directory + "/" + name + ".exo", ranks, comm->getRank());
    continuing(piecePath, [&] {
      exodus_ = std::make_unique<io::ExodusWriter>(piecePath, piece_->mesh, fields, runRecords(problem.title, run, ranks),
                                                   pieceSurfaces, &decomposition, io::ExodusNaming::AtFirstStep);
    });
  };
  // Rank 0 takes the lock before any file is created, so a second run on the same files stops before
  // it touches them; per rank, every rank creates its piece once the lock is held. The history is
  // created (replacing an earlier run's) once every Exodus file is.
  std::string error;
  if (root_) {
    try {
      lock_ = std::make_unique<io::OutputLock>(directory, name);
      warning_ = lock_->warning();
      if (!perRank_) createExodus();
    } catch (const std::exception& e) {
      error = e.what();
      exodus_.reset();
      lock_.reset();
    }
  }
  error = model::firstMessageOfAnyRank(*comm, error);
  if (!error.empty()) throw InputError(error);
  if (perRank_) {
    try {
      createExodus();
    } catch (const std::exception& e) {
      error = e.what();
    }
  }
  if (root_ && error.empty()) {
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
      error = e.what();
      const std::size_t at = error.find(historyStartingPath());  // the history by its name
      if (at != std::string::npos) error.replace(at, historyStartingPath().size(), historyPath_);
    }
  }
  error = model::firstMessageOfAnyRank(*comm, error);
  if (!error.empty()) {
    removeUnwrittenFiles();
    lock_.reset();
    throw InputError(error);
  }
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
  const int dim = problem_.dimension();
  const auto& comm = *model_.ownedDofMap()->getComm();
  // Collective part: every rank computes and sends what the Exodus files show (to rank 0's file, or
  // to each rank's piece).
  model::Vector fileX(fileDofMap_);
  fileX.doImport(x, *dofToFile_, Tpetra::INSERT);
  const auto stresses = model_.elementStresses(x);
  model::MultiVector fileStress(fileElementMap_, stresses->getNumVectors());
  fileStress.doImport(*stresses, *elementToFile_, Tpetra::INSERT);
  const auto reactions = model_.reactions(x, report.lambda);
  const auto counts = model_.contactCounts();
  const auto contactForces = model_.contactForces();
  model::MultiVector fileContact(fileNodeMap_, 4);
  if (model_.hasContact()) fileContact.doImport(*model_.contactNodalFields(), *nodeToFile_, Tpetra::INSERT);

  // The history row (its reactions and contact forces are sums over the ranks, known everywhere).
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
    if (exodus_) {
      // Nodal values: the file's mesh nodes, then the rigid surfaces' points (displaced by λ · motion,
      // no contact values of their own).
      const auto meshNodes = static_cast<std::size_t>(fileNodeMap_->getNodeNumElements());
      const auto totalNodes = static_cast<std::size_t>(exodus_->numNodes());
      const auto u = fileX.getData(0);
      std::vector<std::vector<double>> nodal(dim, std::vector<double>(totalNodes, 0.0));
      for (std::size_t n = 0; n < meshNodes; ++n)
        for (int c = 0; c < dim; ++c) nodal[c][n] = u[n * dim + c];
      std::size_t point = meshNodes;
      for (const auto& surface : rigidSurfaces_)
        for (std::size_t p = 0; p < surface.points; ++p, ++point)
          for (int c = 0; c < dim; ++c) nodal[c][point] = report.lambda * surface.motion[c];
      if (model_.hasContact())
        for (std::size_t v = 0; v < 4; ++v) {
          const auto col = fileContact.getData(v);
          nodal.emplace_back(col.begin(), col.end());
          nodal.back().resize(totalNodes, 0.0);
        }
      std::vector<std::vector<double>> element(fileStress.getNumVectors());
      for (std::size_t v = 0; v < element.size(); ++v) {
        const auto col = fileStress.getData(v);
        element[v].assign(col.begin(), col.end());
      }
      std::vector<double> globals = {report.lambda, report.dlambda, report.beta, static_cast<double>(counts.active),
                                     static_cast<double>(report.newtonIterations)};
      globals.insert(globals.end(), row.begin() + kFixedColumns.size(), row.end());
      exodus_->writeStep(report.lambda, nodal, element, globals);
    }
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
