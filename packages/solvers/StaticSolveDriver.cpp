#include "solvers/StaticSolveDriver.hpp"

#include <chrono>
#include <sstream>

#include <NOX_Observer.hpp>
#include <NOX_Observer_Vector.hpp>
#include <Piro_NOXSolver.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

#include "common/Error.hpp"
#include "solvers/IterativeSolveMonitor.hpp"
#include "solvers/MumpsSolver.hpp"
#include "solvers/NewtonCounter.hpp"
#include "solvers/NewtonStatusTests.hpp"
#include "solvers/NoxParameters.hpp"
#include "solvers/ResidualTest.hpp"

namespace contessa::solvers {

using Teuchos::RCP;
using Teuchos::rcp;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>;

namespace {

// The initial state, as a continuation run reports and commits it: the reference of the contact
// history and of the tunnelling check (the solve goes from here to load factor 1 in one step).
void reportInitialState(const SolverModel& model, IncrementObserver& observer) {
  const auto& evaluator = *model.evaluator;
  auto x0 = evaluator.getNominalValues().get_x();
  auto in = evaluator.createInArgs();
  in.set_x(x0);
  auto p0 = Thyra::createMember(evaluator.get_p_space(0));
  Thyra::set_ele(0, 0.0, p0.ptr());
  in.set_p(0, p0);
  auto out = evaluator.createOutArgs();
  auto f0 = Thyra::createMember(evaluator.get_f_space());
  out.set_f(f0);
  evaluator.evalModel(in, out);
  model.state->commitState();
  IncrementReport initial;
  observer.incrementConverged(*Extract::getConstTpetraVector(x0), initial);
}

// Piro throws when the solve fails: why, in plain words (its exception text is Piro's own, the last
// resort).
std::string failureReason(SolveFailure failure, NewtonStatusTests& tests, const std::exception& e) {
  if (failure.kind == SolveFailure::Kind::None) failure = tests.linearSolverFailure();
  if (!failure.reason.empty()) return failure.reason;
  std::string reason = e.what();
  for (auto& c : reason)
    if (c == '\n') c = ' ';
  return "solver error: " + reason.substr(0, 300);
}

}  // namespace

RunSummary solveStatic(const SolverModel& model, const Teuchos::ParameterList& piro,
                       IncrementObserver& observer, const RCP<NOX::Observer>& iterationObserver) {
  const auto start = std::chrono::steady_clock::now();
  // The single solve has no place to update multipliers and solve again (docs/theory-contact.md §15).
  requireInput(model.augmentation == nullptr || !model.augmentation->hasAugmentedContact(),
               "Piro/Solver Type: NOX (one solve from load factor 0 to 1) does not update the multipliers of "
               "Enforcement = Augmented Lagrangian; use LOCA");
  const auto& deckNox = piro.sublist("NOX");
  const auto& deckTests = deckNox.sublist("Status Tests");
  // The convergence test of a single solve is the absolute bound alone, the deck's or force-scaled
  // (ResidualTolerance.hpp; a relative one has no increment start to refer to, the update test belongs to
  // the continuation driver), within the same tests as the continuation: finite residual, no tunnelling,
  // the iteration limit. ||f|| is the unscaled 2-norm, as NOX's NormF.
  ResidualToleranceRecord record;
  NewtonStatusTests tests(*model.diagnostics, model.evaluator->get_W_factory(),
                          rcp(new ResidualTest(ResidualTolerance::fromDeck(deckTests), model.forces, 0.0, 0.0, nullptr,
                                               &record)),
                          deckTests.get<int>("Maximum Iterations"));
  auto noxOutput = rcp(new std::ostringstream());
  auto solveObserver = rcp(new NewtonCounter(tests, *noxOutput));

  auto appParams = rcp(new Teuchos::ParameterList("Piro"));
  appParams->set("Exit on Failed NOX Solve", true);
  auto& nox = appParams->sublist("NOX");
  auto observers = rcp(new NOX::ObserverVector());
  observers->pushBack(solveObserver);
  if (!iterationObserver.is_null()) observers->pushBack(iterationObserver);
  setNoxParameters(nox, deckNox, observers, Teuchos::rcp_implicit_cast<std::ostream>(noxOutput), NoxPrinting::Solve);
  auto& statusTests = nox.sublist("Status Tests");
  statusTests.set("Test Type", "User Defined");
  statusTests.set("User Status Test", tests.test());

  reportInitialState(model, observer);

  RunSummary summary;
  const long solvesBefore = mumpsCounters().solves;
  const long krylovBefore = iterativeSolveLog().iterations;
  try {
    Piro::NOXSolver<double> solver(appParams, model.evaluator);
    auto in = solver.createInArgs();
    auto p = Thyra::createMember(model.evaluator->get_p_space(0));
    Thyra::set_ele(0, 1.0, p.ptr());
    in.set_p(0, p);
    auto out = solver.createOutArgs();
    auto x = Thyra::createMember(model.evaluator->get_x_space());
    out.set_g(out.Ng() - 1, x);  // Piro returns the solution as its last response
    solver.evalModel(in, out);
    model.state->commitState();
    // NOX leaves its statistics in NOX/Output.
    auto& results = nox.sublist("Output");
    IncrementReport r;
    r.step = 1;
    r.lambda = 1.0;
    r.dlambda = 1.0;
    r.newtonIterations = results.get<int>("Nonlinear Iterations", 0);
    r.linearIterations = iterativeSolveLog().iterations - krylovBefore;
    r.residualNorm = results.get<double>("2-Norm of Residual", 0.0);
    r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    observer.incrementConverged(*Extract::getConstTpetraVector(x), r);
    summary.finished = true;
    summary.increments = 1;
    summary.newtonIterations = r.newtonIterations;
    summary.runNewtonIterations = r.newtonIterations;
    summary.finalLambda = 1.0;
  } catch (const std::exception& e) {
    summary.message = "the Newton solve from load factor 0 to 1 (Piro/Solver Type = NOX) failed: " +
                      failureReason(solveObserver->failure, tests, e);
    summary.failedAttempts = 1;
  }
  summary.linearSolves = static_cast<int>(mumpsCounters().solves - solvesBefore);
  summary.linearIterations = iterativeSolveLog().iterations - krylovBefore;
  summary.forceScale = record.lastForceScale;
  summary.residualBound = record.lastBound;
  summary.toleranceWarning = record.warning;
  summary.toleranceFloor = record.floorSummary();
  return summary;
}

}  // namespace contessa::solvers
