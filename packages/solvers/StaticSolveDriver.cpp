#include "solvers/StaticSolveDriver.hpp"

#include <chrono>
#include <sstream>

#include <NOX_Observer.hpp>
#include <NOX_Observer_Vector.hpp>
#include <NOX_StatusTest_NormF.H>
#include <NOX_Utils.H>
#include <Piro_NOXSolver.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

#include "solvers/IterativeSolveMonitor.hpp"
#include "solvers/MumpsSolver.hpp"
#include "solvers/NewtonStatusTests.hpp"

namespace contessa::solvers {

using Teuchos::RCP;
using Teuchos::rcp;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>;

namespace {

// Why the solve failed, read when it ends (on every rank: the diagnosis may communicate).
class SolveObserver : public NOX::Observer {
 public:
  SolveObserver(NewtonStatusTests& tests, const std::ostringstream& noxOutput) : tests_(tests), noxOutput_(noxOutput) {}
  void runPreSolve(const NOX::Solver::Generic&) override { tests_.startSolve(); }
  void runPostSolve(const NOX::Solver::Generic& solver) override { failure = tests_.diagnose(solver, noxOutput_.str()); }
  SolveFailure failure;

 private:
  NewtonStatusTests& tests_;
  const std::ostringstream& noxOutput_;
};

// The initial state, as a continuation run reports and commits it: the reference of the contact
// history and of the tunnelling check (the solve goes from here to load factor 1 in one step).
void reportInitialState(model::ContactMechanicsModel& model, IncrementObserver& observer) {
  auto x0 = model.getNominalValues().get_x();
  auto in = model.createInArgs();
  in.set_x(x0);
  auto p0 = Thyra::createMember(model.get_p_space(0));
  Thyra::set_ele(0, 0.0, p0.ptr());
  in.set_p(0, p0);
  auto out = model.createOutArgs();
  auto f0 = Thyra::createMember(model.get_f_space());
  out.set_f(f0);
  model.evalModel(in, out);
  model.commitState();
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

RunSummary solveStatic(const RCP<model::ContactMechanicsModel>& model, const Teuchos::ParameterList& piro,
                       IncrementObserver& observer, const RCP<NOX::Observer>& iterationObserver) {
  const auto start = std::chrono::steady_clock::now();
  const auto& deckNox = piro.sublist("NOX");
  const auto& deckTests = deckNox.sublist("Status Tests");
  // The convergence test of a single solve is the absolute residual tolerance (a relative one has no
  // increment start to refer to; the update test belongs to the continuation driver), within the same
  // tests as the continuation: finite residual, no tunnelling, the iteration limit.
  // The unscaled 2-norm, as NOX's status-test factory builds NormF from a parameter list.
  NewtonStatusTests tests(*model,
                          rcp(new NOX::StatusTest::NormF(deckTests.get<double>("Absolute Residual Tolerance"),
                                                         NOX::Abstract::Vector::TwoNorm, NOX::StatusTest::NormF::Unscaled)),
                          deckTests.get<int>("Maximum Iterations"));
  auto noxOutput = rcp(new std::ostringstream());
  auto solveObserver = rcp(new SolveObserver(tests, *noxOutput));

  auto appParams = rcp(new Teuchos::ParameterList("Piro"));
  appParams->set("Exit on Failed NOX Solve", true);
  auto& nox = appParams->sublist("NOX");
  nox.set("Nonlinear Solver", deckNox.get<std::string>("Nonlinear Solver"));
  nox.sublist("Direction").set("Method", deckNox.get<std::string>("Nonlinear Solver") == "Line Search Based"
                                             ? deckNox.sublist("Direction").get<std::string>("Method")
                                             : std::string("Newton"));
  nox.sublist("Line Search").set("Method", deckNox.sublist("Line Search").get<std::string>("Method"));
  const bool details = deckNox.sublist("Printing").get<bool>("Newton Details");
  nox.sublist("Printing").set("Output Information", details ? NOX::Utils::Error | NOX::Utils::OuterIteration
                                                            : static_cast<int>(NOX::Utils::Error));
  // NOX's errors and the exceptions it catches go into the one-line message, not onto stderr/stdout.
  nox.sublist("Printing").set("Error Stream", Teuchos::rcp_implicit_cast<std::ostream>(noxOutput));
  if (!details) nox.sublist("Printing").set("Output Stream", Teuchos::rcp_implicit_cast<std::ostream>(noxOutput));
  nox.set("Catch Throws During Solve", true);
  auto observers = rcp(new NOX::ObserverVector());
  observers->pushBack(solveObserver);
  if (!iterationObserver.is_null()) observers->pushBack(iterationObserver);
  nox.sublist("Solver Options").set("Observer", Teuchos::rcp_implicit_cast<NOX::Observer>(observers));
  auto& statusTests = nox.sublist("Status Tests");
  statusTests.set("Test Type", "User Defined");
  statusTests.set("User Status Test", tests.test());

  reportInitialState(*model, observer);

  RunSummary summary;
  const long solvesBefore = mumpsCounters().solves;
  const long krylovBefore = iterativeSolveLog().iterations;
  try {
    Piro::NOXSolver<double> solver(appParams, model);
    auto in = solver.createInArgs();
    auto p = Thyra::createMember(model->get_p_space(0));
    Thyra::set_ele(0, 1.0, p.ptr());
    in.set_p(0, p);
    auto out = solver.createOutArgs();
    auto x = Thyra::createMember(model->get_x_space());
    out.set_g(out.Ng() - 1, x);  // Piro returns the solution as its last response
    solver.evalModel(in, out);
    model->commitState();
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
    summary.finalLambda = 1.0;
  } catch (const std::exception& e) {
    summary.message = "the Newton solve from load factor 0 to 1 (Piro/Solver Type = NOX) failed: " +
                      failureReason(solveObserver->failure, tests, e);
    summary.failedAttempts = 1;
  }
  summary.linearSolves = static_cast<int>(mumpsCounters().solves - solvesBefore);
  summary.linearIterations = iterativeSolveLog().iterations - krylovBefore;
  return summary;
}

}  // namespace contessa::solvers
