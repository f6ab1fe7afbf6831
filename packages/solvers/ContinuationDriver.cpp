#include "solvers/ContinuationDriver.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>
#include <sstream>
#include <cmath>

#include <LOCA.H>
#include <LOCA_Thyra.H>
#include <LOCA_Thyra_SaveDataStrategy.H>
#include <NOX_Observer.hpp>
#include <NOX_Solver_LineSearchBased.H>
#include <NOX_StatusTest_Combo.H>
#include <NOX_StatusTest_FiniteValue.H>
#include <NOX_StatusTest_MaxIters.H>
#include <NOX_Thyra_Vector.H>
#include <Thyra_TpetraThyraWrappers.hpp>

#include "solvers/ContactBetaStepSize.hpp"
#include "solvers/MumpsSolver.hpp"
#include "solvers/StepSizeFactory.hpp"

namespace contessa::solvers {

using Teuchos::RCP;
using Teuchos::rcp;

namespace {

using Clock = std::chrono::steady_clock;

// Converged when ||f|| ≤ max(absolute, relative · ||f|| at the solve's first iterate), or when the
// Newton update has shrunk to round-off: ||Δx|| ≤ update · ||x||. (NOX's relative NormF is relative
// to a fixed group, not to each increment's start, hence this test.) The update test matters with
// penalty contact: a penalty of 1e9 on coordinates of order 100 leaves residual noise of about
// 1e9 · 1e-14 that no iteration can remove, while the update keeps converging quadratically.
class ResidualTest : public NOX::StatusTest::Generic {
 public:
  /// `mayConverge` vetoes convergence (Contact Beta: not while new contacts are frozen);
  /// `updateMeaningful` disables the update test at an iterate whose update was computed for another
  /// residual (Contact Beta: new contacts just switched on).
  ResidualTest(double absolute, double relative, double update, std::function<bool()> mayConverge,
               std::function<bool()> updateMeaningful)
      : absolute_(absolute),
        relative_(relative),
        update_(update),
        mayConverge_(std::move(mayConverge)),
        updateMeaningful_(std::move(updateMeaningful)) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) override {
    const double norm = solver.getSolutionGroup().getNormF();
    if (solver.getNumIterations() == 0) {
      initial_ = norm;
      updateNorm_ = -1;
    } else {
      auto dx = solver.getSolutionGroup().getX().clone(NOX::DeepCopy);
      dx->update(-1.0, solver.getPreviousSolutionGroup().getX(), 1.0);
      // The Newton direction, not the damped step: a line search that shrinks the step must not
      // pass for convergence.
      const auto* lineSearch = dynamic_cast<const NOX::Solver::LineSearchBased*>(&solver);
      const double step = lineSearch != nullptr ? lineSearch->getStepSize() : 1.0;
      updateNorm_ = step > 0 ? dx->norm() / step : std::numeric_limits<double>::infinity();
      xNorm_ = solver.getSolutionGroup().getX().norm();
    }
    norm_ = norm;
    const bool residualSmall = std::isfinite(norm) && norm <= std::max(absolute_, relative_ * initial_);
    const bool updateSmall =
        std::isfinite(norm) && updateNorm_ >= 0 && updateNorm_ <= update_ * xNorm_ && updateMeaningful_();
    status_ = (residualSmall || updateSmall) && mayConverge_() ? NOX::StatusTest::Converged : NOX::StatusTest::Unconverged;
    return status_;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& os, int indent) const override {
    for (int i = 0; i < indent; ++i) os << ' ';
    os << status_ << "||f|| = " << norm_ << " <= max(" << absolute_ << ", " << relative_ << " * " << initial_
       << ") or ||dx|| = " << updateNorm_ << " <= " << update_ << " * " << xNorm_ << "\n";
    return os;
  }

 private:
  double absolute_, relative_, update_, initial_ = 0, norm_ = 0, updateNorm_ = -1, xNorm_ = 0;
  std::function<bool()> mayConverge_, updateMeaningful_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

// Newton statistics of the current solve, read when the increment ends. (NOX also calls
// runPostIterate when the initial guess already converges, so iterations are read from the solver.)
class NewtonCounter : public NOX::Observer {
 public:
  void runPreSolve(const NOX::Solver::Generic&) override { iterations = 0; }
  void runPostSolve(const NOX::Solver::Generic& solver) override {
    iterations = solver.getNumIterations();
    total += iterations;
    residualNorm = solver.getSolutionGroup().getNormF();
  }
  int iterations = 0, total = 0;
  double residualNorm = 0;
};

// LOCA tells the group about every step: commit or roll back the model state, report to the observer.
class IncrementBookkeeper : public LOCA::Thyra::SaveDataStrategy {
 public:
  IncrementBookkeeper(model::ContactMechanicsModel& model, IncrementObserver& observer, const NewtonCounter& newton,
                      const continuation::ContactBetaControl* contactBeta, continuation::CountedEvents counted,
                      double initialLambda)
      : model_(model),
        observer_(observer),
        newton_(newton),
        contactBeta_(contactBeta),
        counted_(counted),
        lastLambda_(initialLambda),
        start_(Clock::now()) {}

  void postProcessContinuationStep(LOCA::Abstract::Iterator::StepStatus status) override {
    if (status == LOCA::Abstract::Iterator::Successful) {
      model_.commitState();
      pendingSuccess_ = true;
    } else {
      model_.rollbackState();
      ++failedAttempts;
      ++attempts_;
      IncrementReport r = report(model_.lastLoadFactor());
      r.dlambda = r.lambda - lastLambda_;
      r.betaRestart = contactBeta_ != nullptr && contactBeta_->restartRequested();
      if (r.betaRestart) r.beta = contactBeta_->beta();
      observer_.attemptFailed(r);
    }
  }

  // Called by LOCA after a successful step (and once for the initial state).
  void saveSolution(const NOX::Abstract::Vector& x, double lambda) override {
    if (!first_ && !pendingSuccess_) return;
    const auto& tx = dynamic_cast<const NOX::Thyra::Vector&>(x);
    auto tpetraX = Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>::getConstTpetraVector(
        Teuchos::rcpFromRef(tx.getThyraVector()));
    if (first_) model_.commitState();
    IncrementReport r = report(lambda);
    r.dlambda = first_ ? 0.0 : lambda - lastLambda_;
    r.newEvents = first_ ? 0 : continuation::countEvents(model_.committedIncrement(), counted_);
    observer_.incrementConverged(*tpetraX, r);
    if (!first_) ++increments;
    lastLambda_ = lambda;
    first_ = false;
    pendingSuccess_ = false;
    attempts_ = 1;
  }

  int increments = 0, failedAttempts = 0;
  double lastLambda() const { return lastLambda_; }

 private:
  IncrementReport report(double lambda) const {
    IncrementReport r;
    r.step = first_ ? 0 : increments + 1;
    r.beta = contactBeta_ != nullptr && !first_ ? contactBeta_->beta() : 1.0;
    r.lambda = lambda;
    r.attempts = attempts_;
    r.newtonIterations = newton_.iterations;
    r.residualNorm = newton_.residualNorm;
    r.wallSeconds = std::chrono::duration<double>(Clock::now() - start_).count();
    return r;
  }

  model::ContactMechanicsModel& model_;
  IncrementObserver& observer_;
  const NewtonCounter& newton_;
  const continuation::ContactBetaControl* contactBeta_;
  continuation::CountedEvents counted_;
  double lastLambda_;
  Clock::time_point start_;
  bool first_ = true, pendingSuccess_ = false;
  int attempts_ = 1;
};

// The parameter list LOCA and NOX read, made from the validated deck list.
RCP<Teuchos::ParameterList> locaParameters(const Teuchos::ParameterList& piro, const RCP<NOX::Observer>& observer,
                                           const RCP<std::ostream>& errors) {
  auto top = rcp(new Teuchos::ParameterList("Contessa solver"));
  const auto& deckNox = piro.sublist("NOX");
  auto& nox = top->sublist("NOX");
  nox.set("Nonlinear Solver", deckNox.get<std::string>("Nonlinear Solver"));
  nox.sublist("Direction").set("Method", deckNox.sublist("Direction").get<std::string>("Method"));
  nox.sublist("Line Search").set("Method", deckNox.sublist("Line Search").get<std::string>("Method"));
  const bool details = deckNox.sublist("Printing").get<bool>("Newton Details");
  nox.sublist("Printing").set("Output Information",
                              details ? NOX::Utils::Error | NOX::Utils::Warning | NOX::Utils::OuterIteration |
                                            NOX::Utils::StepperIteration
                                      : static_cast<int>(NOX::Utils::Error));
  // NOX/LOCA errors are collected and reported in Contessa's one-line message, not spread on stderr.
  nox.sublist("Printing").set("Error Stream", errors);
  nox.sublist("Solver Options").set("Observer", observer);
  // An exception in an evaluation fails the solve (and the increment is cut back), not the run.
  nox.set("Catch Throws During Solve", true);

  const auto& deckLoca = piro.sublist("LOCA");
  auto& loca = top->sublist("LOCA");
  auto& stepper = loca.sublist("Stepper");
  stepper.setParameters(deckLoca.sublist("Stepper"));
  stepper.set("Continuation Method", "Natural");
  stepper.set("Continuation Parameter", "Load Factor");
  stepper.set("Compute Eigenvalues", false);
  loca.sublist("Predictor").setParameters(deckLoca.sublist("Predictor"));
  loca.sublist("Step Size").setParameters(deckLoca.sublist("Step Size"));
  return top;
}

}  // namespace

ContinuationDriver::ContinuationDriver(const RCP<model::ContactMechanicsModel>& model,
                                       const Teuchos::ParameterList& piro, IncrementObserver& observer)
    : model_(model), piro_(piro), observer_(observer) {}

RunSummary ContinuationDriver::run() {
  auto newton = rcp(new NewtonCounter());
  auto errors = rcp(new std::ostringstream());
  auto params = locaParameters(piro_, newton, errors);
  const auto& stepSize = piro_.sublist("LOCA").sublist("Step Size");
  const bool contactBeta = stepSize.get<std::string>("Method") == "Contact Beta";
  continuation::ContactBetaControl betaState(
      contactBetaSettings(stepSize, piro_.sublist("LOCA").sublist("Stepper").get<double>("Max Value")));
  auto globalData = LOCA::createGlobalData(params, rcp(new StepSizeFactory(*model_, betaState)));

  const double lambda0 = params->sublist("LOCA").sublist("Stepper").get<double>("Initial Value");
  LOCA::ParameterVector p;
  p.addParameter("Load Factor", lambda0);
  auto x0 = model_->getNominalValues().get_x()->clone_v();
  NOX::Thyra::Vector initialGuess(x0);
  auto group = rcp(new LOCA::Thyra::Group(globalData, initialGuess, model_, p, 0, true));
  auto bookkeeper = rcp(new IncrementBookkeeper(*model_, observer_, *newton, contactBeta ? &betaState : nullptr,
                                                betaState.settings().counted, lambda0));
  group->setSaveDataStrategy(bookkeeper);

  const auto& tests = piro_.sublist("NOX").sublist("Status Tests");
  auto combo = rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
  // Order matters: the Contact Beta check may recompute the residual before the residual test reads it.
  combo->addStatusTest(rcp(new NOX::StatusTest::FiniteValue()));
  if (contactBeta && betaState.settings().mode == continuation::ContactBetaSettings::Mode::Restart)
    combo->addStatusTest(rcp(new ContactBetaRestartTest(*model_, betaState)));
  const auto* model = model_.get();
  combo->addStatusTest(rcp(new ResidualTest(tests.get<double>("Absolute Residual Tolerance"),
                                            tests.get<double>("Relative Residual Tolerance"),
                                            tests.get<double>("Update Tolerance"),
                                            [model] { return !model->newContactsFrozen(); },
                                            [&betaState] { return !betaState.newContactsJustReleased(); })));
  combo->addStatusTest(rcp(new NOX::StatusTest::MaxIters(tests.get<int>("Maximum Iterations"))));

  RunSummary summary;
  const long solvesBefore = mumpsCounters().solves;
  const int jacobiansBefore = model_->jacobianEvaluations();
  try {
    LOCA::Stepper stepper(globalData, group, combo, params);
    const auto status = stepper.run();
    summary.finished = status == LOCA::Abstract::Iterator::Finished;
    if (!summary.finished) {
      std::string why = errors->str();
      std::replace(why.begin(), why.end(), '\n', ' ');
      why.erase(0, why.find_first_not_of(" \t"));
      why.erase(why.find_last_not_of(" \t") + 1);
      summary.message = "continuation stopped at load factor " + std::to_string(bookkeeper->lastLambda()) + " (" +
                        (!why.empty()                ? "LOCA: " + why
                         : betaState.hitMinimumStep() ? std::string("the step size fell below Min Step Size")
                                                    : std::string("maximum number of steps reached")) +
                        ")";
    }
  } catch (const std::exception& e) {
    summary.message = std::string("solver error: ") + e.what();
  } catch (const char* e) {
    summary.message = std::string("solver error: ") + e;
  }
  summary.increments = bookkeeper->increments;
  summary.failedAttempts = bookkeeper->failedAttempts;
  summary.newtonIterations = newton->total;
  // A direct solver solves once per Jacobian; iterative solvers are counted as Jacobian evaluations.
  const long mumpsSolves = mumpsCounters().solves - solvesBefore;
  summary.linearSolves = mumpsSolves > 0 ? static_cast<int>(mumpsSolves) : model_->jacobianEvaluations() - jacobiansBefore;
  summary.finalLambda = bookkeeper->lastLambda();
  LOCA::destroyGlobalData(globalData);
  return summary;
}

}  // namespace contessa::solvers
