#include "solvers/StaticSolveDriver.hpp"

#include <chrono>

#include <NOX_Utils.H>
#include <Piro_NOXSolver.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

#include "solvers/MumpsSolver.hpp"

namespace contessa::solvers {

using Teuchos::RCP;
using Teuchos::rcp;

namespace {

// Piro builds NOX's status tests from the NOX factory's parameter format: translate the deck's. The
// factory's NormF is absolute (a relative one needs a group), so a single solve uses the absolute
// residual tolerance and the iteration limit; the update test belongs to the continuation driver.
void addStatusTests(Teuchos::ParameterList& nox, const Teuchos::ParameterList& deckTests) {
  auto& tests = nox.sublist("Status Tests");
  tests.set("Test Type", "Combo");
  tests.set("Combo Type", "OR");
  int n = 0;
  auto& finite = tests.sublist("Test " + std::to_string(n++));
  finite.set("Test Type", "FiniteValue");
  auto& absolute = tests.sublist("Test " + std::to_string(n++));
  absolute.set("Test Type", "NormF");
  absolute.set("Tolerance", deckTests.get<double>("Absolute Residual Tolerance"));
  auto& maxIters = tests.sublist("Test " + std::to_string(n++));
  maxIters.set("Test Type", "MaxIters");
  maxIters.set("Maximum Iterations", deckTests.get<int>("Maximum Iterations"));
  tests.set("Number of Tests", n);
}

}  // namespace

RunSummary solveStatic(const RCP<model::ContactMechanicsModel>& model, const Teuchos::ParameterList& piro,
                       IncrementObserver& observer) {
  const auto start = std::chrono::steady_clock::now();
  const auto& deckNox = piro.sublist("NOX");
  auto appParams = rcp(new Teuchos::ParameterList("Piro"));
  appParams->set("Exit on Failed NOX Solve", true);
  auto& nox = appParams->sublist("NOX");
  nox.set("Nonlinear Solver", deckNox.get<std::string>("Nonlinear Solver"));
  nox.sublist("Direction").set("Method", deckNox.get<std::string>("Nonlinear Solver") == "Line Search Based"
                                             ? deckNox.sublist("Direction").get<std::string>("Method")
                                             : std::string("Newton"));
  nox.sublist("Line Search").set("Method", deckNox.sublist("Line Search").get<std::string>("Method"));
  nox.sublist("Printing").set("Output Information", deckNox.sublist("Printing").get<bool>("Newton Details")
                                                        ? NOX::Utils::Error | NOX::Utils::OuterIteration
                                                        : static_cast<int>(NOX::Utils::Error));
  addStatusTests(nox, deckNox.sublist("Status Tests"));

  // The initial state, as a continuation run reports it.
  auto x0 = model->getNominalValues().get_x();
  IncrementReport initial;
  observer.incrementConverged(*Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>::getConstTpetraVector(x0),
                              initial);

  RunSummary summary;
  const long solvesBefore = mumpsCounters().solves;
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
    r.residualNorm = results.get<double>("2-Norm of Residual", 0.0);
    r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    observer.incrementConverged(*Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>::getConstTpetraVector(x), r);
    summary.finished = true;
    summary.increments = 1;
    summary.newtonIterations = r.newtonIterations;
    summary.finalLambda = 1.0;
  } catch (const std::exception& e) {
    std::string msg = e.what();
    for (auto& c : msg)
      if (c == '\n') c = ' ';
    summary.message = "the NOX solve at load factor 1 did not converge (" + msg.substr(0, 200) + ")";
    summary.failedAttempts = 1;
  }
  summary.linearSolves = static_cast<int>(mumpsCounters().solves - solvesBefore);
  return summary;
}

}  // namespace contessa::solvers
