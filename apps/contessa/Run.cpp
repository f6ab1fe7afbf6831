#include "Run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>

#include "Checkpoint.hpp"
#include "Failure.hpp"
#include "RunReport.hpp"
#include "StopSignals.hpp"
#include "common/Error.hpp"
#include "common/MpiCommOf.hpp"
#include "common/PhaseTimers.hpp"
#include "deck/DeckReader.hpp"
#include "deck/ParameterValidation.hpp"
#include "deck/ProblemDefinition.hpp"
#include "io/ExodusWriter.hpp"
#include "io/RestartFile.hpp"
#include "mesh/MemoryEstimate.hpp"
#include "model/ContactMechanicsModel.hpp"
#include "output/DeckText.hpp"
#include "output/ResultsOutput.hpp"
#include "solvers/ContinuationDriver.hpp"
#include "solvers/JacobianCheckObserver.hpp"
#include "solvers/LinearSolverFactory.hpp"
#include "solvers/MumpsSolver.hpp"
#include "solvers/PreconditionerReuse.hpp"
#include "solvers/ResidualTolerance.hpp"
#include "solvers/SolverParameters.hpp"
#include "solvers/StaticSolveDriver.hpp"

namespace contessa::app {
namespace {

namespace fs = std::filesystem;

// Regression quantities must name history columns: checked before the run, on every rank.
void requireHistoryColumns(const deck::ProblemDefinition& problem, const std::vector<std::string>& columns) {
  for (const auto& check : problem.regression) {
    if (std::find(columns.begin(), columns.end(), check.quantity) != columns.end()) continue;
    std::string known;
    for (const auto& c : columns) known += (known.empty() ? "" : ", ") + c;
    throw InputError("Problem/Regression/" + check.name + "/Quantity: '" + check.quantity +
                     "' is not a history column (known: " + known + ")");
  }
}

// The last history row of load step `loadStep` (the history's load_step column, 1 for the first); -1 when
// the run did not finish it (its last row is not at lambda 1).
int lastRowOfLoadStep(const std::vector<std::string>& columns, const std::vector<std::vector<double>>& rows,
                      int loadStep) {
  const auto stepColumn = std::find(columns.begin(), columns.end(), "load_step") - columns.begin();
  const auto lambdaColumn = std::find(columns.begin(), columns.end(), "lambda") - columns.begin();
  int last = -1;
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (rows[r][stepColumn] == loadStep) last = static_cast<int>(r);
  return last >= 0 && rows[static_cast<std::size_t>(last)][lambdaColumn] >= 1.0 - 1e-12 ? last : -1;
}

// The deck's own expected answers ("Problem/Regression"); returns the number of failed checks.
int checkRegression(const deck::ProblemDefinition& problem, const output::ResultsOutput& results) {
  int failed = 0;
  const auto& columns = results.historyColumns();
  const auto& rows = results.historyRows();
  for (const auto& check : problem.regression) {
    const auto col = std::find(columns.begin(), columns.end(), check.quantity);
    int step = check.step < 0 ? static_cast<int>(rows.size()) - 1 : check.step;
    if (check.loadStep > 0) step = lastRowOfLoadStep(columns, rows, check.loadStep);
    if (step < 0 || step >= static_cast<int>(rows.size())) {
      if (check.loadStep > 0)
        std::printf("regression %-24s FAILED: load step %d was not reached\n", check.name.c_str(), check.loadStep);
      else
        std::printf("regression %-24s FAILED: step %d was not reached\n", check.name.c_str(), check.step);
      ++failed;
      continue;
    }
    const double value = rows[step][col - columns.begin()];
    const double error = std::abs(value - check.expected);
    const bool ok = error <= check.absoluteTolerance || error <= check.relativeTolerance * std::abs(check.expected);
    std::printf("regression %-24s %s: %s = %.10g, expected %.10g (rel. error %.3e)\n", check.name.c_str(),
                ok ? "passed" : "FAILED", check.quantity.c_str(), value, check.expected,
                check.expected != 0 ? error / std::abs(check.expected) : error);
    if (!ok) ++failed;
  }
  return failed;
}

// The command line as the results file records it (words with spaces quoted).
std::string commandLineText(const CommandLine& cl) {
  auto word = [](const std::string& w) { return w.find_first_of(" \t'") == std::string::npos ? w : "\"" + w + "\""; };
  std::string text = "contessa " + word(cl.deck);
  if (cl.outputDirectory != ".") text += " --output-dir " + word(cl.outputDirectory);
  for (const auto& o : cl.overrides) text += " --set " + word(o);
  if (cl.quiet) text += " --quiet";
  if (cl.checkJacobian) {
    text += " --check-jacobian";
    for (std::size_t k = 0; k < cl.checkJacobianIncrements.size(); ++k)
      text += (k == 0 ? "=" : ",") + std::to_string(cl.checkJacobianIncrements[k]);
  }
  if (!cl.restart.empty()) text += " --restart " + word(cl.restart);
  return text;
}

// The deck, validated, and what it makes before the model: the problem (its mesh part on this rank),
// the linear solver, and the run's description for the results file.
struct ValidatedInput {
  Teuchos::RCP<Teuchos::ParameterList> deck;
  std::shared_ptr<const deck::ProblemDefinition> problem;  ///< shared with the model
  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> linearSolver;
  solvers::LinearSolverChoice linearSolverChoice;  ///< what the linear solver is and why, for the log
  output::RunDescription description;
  std::vector<Teuchos::ParameterList> stepSizes;  ///< per load step (none without Problem/Load Steps)
};

// The whole deck is validated before anything runs. Rank 0 reads the deck file once; every rank
// validates it and reads the mesh, and a failure on any rank (a file only some ranks can read) stops
// every rank with one message (agreeOnInput).
ValidatedInput readInput(const CommandLine& cl, const Teuchos::RCP<const Teuchos::Comm<int>>& comm) {
  const std::string deckText = shareDeckText(*comm, cl.deck);
  mesh::agreeOnMachineMemory(mpiCommOf(*comm));
  ValidatedInput input;
  agreeOnInput(*comm, [&] {
    input.deck = deck::parseDeck(deckText, cl.deck);
    deck::applyOverrides(*input.deck, cl.overrides);
    input.description = {commandLineText(cl), output::deckText(*input.deck)};
    Teuchos::ParameterList validTop("Contessa deck");
    validTop.sublist("Problem", false, "The model: mesh, blocks, materials, boundary conditions, output");
    validTop.sublist("Piro", false, "Solvers: NOX, LOCA, Stratimikos");
    deck::validateAndSetDefaults(*input.deck, validTop, "", {"Problem", "Piro"});
    requireInput(input.deck->isSublist("Problem") && input.deck->sublist("Problem").isSublist("Mesh"),
                 "Problem/Mesh: required (the deck has no mesh)");

    const std::string deckDirectory = fs::path(cl.deck).parent_path().string();
    input.problem = std::make_shared<const deck::ProblemDefinition>(
        deck::buildProblem(input.deck->sublist("Problem"), deckDirectory, mpiCommOf(*comm)));
    // The linear solver is chosen once the mesh is read: by its size and dimension unless the deck names one.
    const solvers::ProblemSize size{input.problem->dimension(),
                                    static_cast<long long>(input.problem->mesh.numGlobalNodes) * input.problem->dimension()};
    input.linearSolverChoice = solvers::validatePiro(input.deck->sublist("Piro"), comm->getSize(), size);
    input.stepSizes = solvers::loadStepSizes(*input.problem, input.deck->sublist("Piro"));
    input.linearSolver = solvers::createLinearSolverFactory(input.deck->sublist("Piro").sublist("Stratimikos"), comm);

    std::error_code ec;
    fs::create_directories(cl.outputDirectory, ec);
    requireInput(fs::is_directory(cl.outputDirectory), "--output-dir " + cl.outputDirectory + ": cannot create the directory");
  });
  return input;
}

// The model on this rank's part of the mesh (partitioned as it was made, deck/ProblemDefinition).
Teuchos::RCP<model::ContactMechanicsModel> buildModel(const CommandLine& cl,
                                                      const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                                                      const ValidatedInput& input) {
  auto model = Teuchos::rcp(new model::ContactMechanicsModel(comm, input.problem, input.linearSolver));
  // A rebuild of the matrix graph (the contact left the couplings reserved for it) is a line in the log.
  if (comm->getRank() == 0 && !cl.quiet)
    model->onGraphRebuild([](const model::GraphRebuild& r) {
      std::printf("contessa: matrix graph rebuilt (%d): %s; contact couplings reserved around the current "
                  "configuration, %lld entries, %.3g s\n",
                  r.count, r.reason.c_str(), r.entries, r.seconds);
      std::fflush(stdout);
    });
  // MueLu's coarse spaces need the rigid-body modes (nothing happens for other linear solvers).
  solvers::provideNearNullSpace(*input.linearSolver, *model->ownedDofMap(), input.problem->mesh);
  return model;
}

// The solve: one static solve, or the continuation in the load factor (resumed from `resumed` with
// --restart). An output error ends the run on every rank (ResultsOutput agrees on it): the drivers
// report it as a stopped run, or it reaches here from the initial state. Its own message is the one to
// show; it is thrown on every rank alike, so FailureReporter prints it once (exit status 1).
solvers::RunSummary solve(const CommandLine& cl, const Teuchos::RCP<model::ContactMechanicsModel>& model,
                          Teuchos::ParameterList& piro, bool continuation, output::ResultsOutput& results,
                          RunCheckpoints& checkpoints,
                          const std::shared_ptr<const solvers::ContinuationPoint>& resumed,
                          const std::vector<Teuchos::ParameterList>& stepSizes) {
  timers::switchTo(timers::Phase::Other);
  solvers::RunSummary summary;
  // --check-jacobian: a NOX observer of the solves that sees the increment reports before the output.
  Teuchos::RCP<solvers::JacobianCheckObserver> jacobianCheck;
  if (cl.checkJacobian)
    jacobianCheck = Teuchos::rcp(new solvers::JacobianCheckObserver(*model, cl.checkJacobianIncrements, results));
  solvers::IncrementObserver& observer = jacobianCheck.is_null() ? static_cast<solvers::IncrementObserver&>(results)
                                                                 : *jacobianCheck;
  try {
    if (!continuation) {
      summary = solvers::solveStatic(solvers::SolverModel::of(model), piro, observer, jacobianCheck);
    } else {
      solvers::ContinuationDriver driver(solvers::SolverModel::of(model), piro, observer, jacobianCheck);
      driver.setCheckpointControl(&checkpoints);
      if (resumed) driver.resumeFrom(resumed);
      driver.setLoadSteps(stepSizes);
      summary = driver.run();
    }
  } catch (const std::exception&) {
    if (results.failure().empty() && checkpoints.failure().empty()) throw;
  }
  if (!results.failure().empty()) throw std::runtime_error(results.failure());
  if (!checkpoints.failure().empty()) throw std::runtime_error(checkpoints.failure());
  return summary;
}

// What the run says at its end, and its exit status: 0 finished (and the deck's own checks passed), 3 a
// check failed, 4 stopped for a restart (not an error: the run can go on from its restart file,
// docs/user-guide.md), 1 stopped.
int reportOutcome(const solvers::RunSummary& summary, const deck::ProblemDefinition& problem,
                  const output::ResultsOutput& results, const std::string& restartPath,
                  const std::string& continueCommand, const Teuchos::Comm<int>& comm) {
  const bool root = comm.getRank() == 0;
  if (root) {
    std::printf("contessa: %s after %d increments (%d failed attempts), %d Newton iterations, %d linear solves; "
                "load factor %.6g\n",
                summary.finished ? "finished" : summary.checkpointed ? "stopped for a restart" : "STOPPED", summary.increments, summary.failedAttempts,
                summary.newtonIterations, summary.linearSolves, summary.finalLambda);
    std::printf("contessa: wrote %s and %s\n", results.exodusPath().c_str(), results.historyPath().c_str());
    if (summary.forceScale > 0 || summary.residualBound > 0)
      std::printf("contessa: Newton residual test at the last increment: force scale F = ||f_int|| = %.3g, "
                  "absolute bound %.3g (%.3g F)\n",
                  summary.forceScale, summary.residualBound,
                  summary.forceScale > 0 ? summary.residualBound / summary.forceScale : 0.0);
    if (!summary.toleranceFloor.empty())
      std::printf("contessa: Newton residual test: %s\n", summary.toleranceFloor.c_str());
    if (!summary.stepSizeChoice.empty()) std::printf("contessa: %s\n", summary.stepSizeChoice.c_str());
    std::fflush(stdout);
    if (!summary.toleranceWarning.empty())
      std::fprintf(stderr, "contessa: warning: %s\n", summary.toleranceWarning.c_str());
    for (const auto& warning : results.regularisationWarnings())  // issue 21: the final state's contact
      std::fprintf(stderr, "contessa: warning: %s\n", warning.c_str());
  }
  timers::printTable(mpiCommOf(comm), stdout);
  if (summary.checkpointed) {
    if (root)
      std::printf("contessa: stopped: %s; restart file %s holds step %d (load factor %.6g); continue with: %s\n",
                  summary.message.c_str(), restartPath.c_str(), summary.increments, summary.finalLambda,
                  continueCommand.c_str());
    return 4;
  }
  if (!summary.finished) {
    if (root) std::fprintf(stderr, "contessa: error: %s\n", summary.message.c_str());
    return 1;
  }
  int failedChecks = root ? checkRegression(problem, results) : 0;
  Teuchos::broadcast(comm, 0, &failedChecks);
  if (failedChecks == 0) return 0;
  if (root) std::fprintf(stderr, "contessa: error: %d regression check(s) of the deck failed\n", failedChecks);
  return 3;
}

// The summary for batch logs and scripts, beside the history (a failure to write it is a warning: the
// results are complete). Collective (peak memory and mesh parts are gathered).
void writeRunReport(const CommandLine& cl, const std::string& name, const solvers::RunSummary& summary, int exitStatus,
                    const solvers::LinearSolverChoice& linearSolver, const model::ContactMechanicsModel& model, const mesh::DistributedMesh& mesh,
                    std::chrono::steady_clock::time_point start, const std::optional<EarlierJobs>& earlier,
                    const Teuchos::Comm<int>& comm) {
  RunReport report;
  report.earlier = earlier;
  report.deck = cl.deck;
  report.ranks = comm.getSize();
  report.summary = summary;
  report.exitStatus = exitStatus;
  report.linearSolver = linearSolver.solver;
  report.linearSolverAutomatic = linearSolver.automatic;
  report.preconditionerRebuildsOnNewGraph = solvers::GraphKeyedPreconditionerFactory::freshSetUps();
  report.preconditionerRefusedReuses = solvers::GraphKeyedPreconditionerFactory::refusedReuses();
  const auto& setUps = solvers::GraphKeyedPreconditionerFactory::counts();
  report.preconditionerReusedSetUps = setUps.reused;
  report.preconditionerPatternRestarts = setUps.patternGrew;
  report.preconditionerCoarseZeroRestarts = setUps.coarseZeros;
  report.directFactorizations = solvers::mumpsCounters().factorizations;
  report.symmetricFactorizations = solvers::mumpsCounters().symmetricFactorizations;
  report.reusedFactorizations = solvers::mumpsCounters().reusedFactorizations;
  report.preconditionerUnchangedSetUps = setUps.unchanged;
  report.preconditionerLargeChangeRestarts = setUps.largeChange;
  report.graphRebuilds = model.graphRebuilds();
  report.graphRebuildSeconds = model.graphRebuildSeconds();
  report.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  gatherPeakMemory(comm, report);
  gatherMeshParts(comm, mesh, report);
  if (comm.getRank() == 0) {
    const std::string path = cl.outputDirectory + "/" + name + ".summary.json";
    std::printf("%s\n", summaryLine(report).c_str());
    const std::string error = io::writeFileAtomically(path, summaryJson(report));
    if (!error.empty()) std::printf("contessa: warning: no run summary: %s\n", error.c_str());
    std::fflush(stdout);
  }
}

}  // namespace

int run(const CommandLine& cl, const Teuchos::RCP<const Teuchos::Comm<int>>& comm) {
  const bool root = comm->getRank() == 0;
  const auto start = std::chrono::steady_clock::now();
  // Before the first HDF5 call (the mesh reader may make it): readers may open the results while
  // the run writes them (io/ExodusWriter.hpp).
  io::disableHdf5FileLocking();
  // 1. The deck, validated on every rank, and the mesh.
  ValidatedInput input = readInput(cl, comm);
  const deck::ProblemDefinition& problem = *input.problem;
  auto& piro = input.deck->sublist("Piro");
  const std::string name = fs::path(cl.deck).stem().string();
  const bool continuation = piro.get<std::string>("Solver Type") != "NOX";
  // Checkpoint and restart: the deck and mesh a restart file must match; with --restart, the file is read
  // and checked before any output is touched.
  const io::RestartContent identity = restartIdentity(*input.deck, problem.mesh);
  const std::string restartPath = cl.outputDirectory + "/" + name + ".restart";
  RestartInput restart;
  if (!cl.restart.empty()) {
    requireInput(continuation, "--restart " + cl.restart +
                                   ": a static solve (Piro/Solver Type = NOX) has no increments to continue");
    restart = readRestart(*comm, cl.restart, identity, problem.dimension());
  }
  // A continuation acts on stop signals at its next increment; a single solve has none, so it leaves them
  // to their default action.
  if (continuation) installStopSignalHandlers();

  // 2. Model and output on this rank's part of the mesh.
  auto model = buildModel(cl, comm, input);
  // The restart file's state into the model and the continuation point, before the output is touched;
  // then every field of the file has been read by someone (the step size's, read when LOCA's state is
  // made, checks its own).
  std::shared_ptr<const solvers::ContinuationPoint> resumed;
  if (!cl.restart.empty())
    agreeOnInput(*comm, [&] {
      model->restoreCommittedState(restart.content.state);
      resumed = solvers::readContinuationPoint(model->ownedDofMap(), model->dimension(), restart.content.state);
      restart.content.state.requireAllRead();
    });
  output::ResultsOutput results(problem, *model, cl.outputDirectory, name, !cl.quiet, input.description,
                                cl.restart.empty() ? nullptr : &restart.historyRows);
  if (root && !results.warning().empty()) std::printf("contessa: warning: %s\n", results.warning().c_str());
  // Two-pass node-to-facet over-constrains faces that do not match (issue 25, point 3;
  // docs/verification-contact.md §9.1): said once per interface, pointing to mortar.
  for (const auto& spec : problem.contacts)
    if (root && spec.secondPass)
      std::fprintf(stderr,
                   "contessa: warning: contact interface '%s': Two Pass = true enforces both sides' nodes on the "
                   "other's facets; on non-matching faces that over-constrains the interface and Newton may not "
                   "converge: use Discretization = Mortar (single pass) instead\n",
                   spec.name.c_str());
  requireHistoryColumns(problem, results.historyColumns());
  if (root && !cl.quiet)
    std::printf("contessa: %s on %d rank(s): %lld nodes, %lld elements, %lld unknowns\n", cl.deck.c_str(),
                comm->getSize(), static_cast<long long>(problem.mesh.numGlobalNodes),
                static_cast<long long>(problem.mesh.numGlobalElements),
                static_cast<long long>(model->ownedDofMap()->getGlobalNumElements()));
  if (root && !cl.quiet)
    std::printf("contessa: linear solver %s (%s)\n", input.linearSolverChoice.solver.c_str(),
                input.linearSolverChoice.reason.c_str());
  if (root && !cl.quiet)
    std::printf("contessa: Newton residual test %s\n",
                solvers::ResidualTolerance::fromDeck(piro.sublist("NOX").sublist("Status Tests")).describe().c_str());

  // 3. The solve, its outcome and the run's summary.
  RunCheckpoints checkpoints(comm, *model, results, restartPath, identity, problem.checkpointEvery,
                             problem.maxWallSeconds, start, !cl.quiet);
  const solvers::RunSummary summary = solve(cl, model, piro, continuation, results, checkpoints, resumed,
                                                input.stepSizes);
  CommandLine continued = cl;  // the command that continues the run, literally (with the same launcher)
  continued.restart = restartPath;
  const int exitStatus = reportOutcome(summary, problem, results, restartPath, commandLineText(continued), *comm);
  std::optional<EarlierJobs> earlier;
  if (!cl.restart.empty()) earlier = earlierJobs(results.historyColumns(), restart.historyRows);
  writeRunReport(cl, name, summary, exitStatus, input.linearSolverChoice, *model, problem.mesh, start, earlier, *comm);
  return exitStatus;
}

}  // namespace contessa::app
