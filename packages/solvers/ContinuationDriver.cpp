#include "solvers/ContinuationDriver.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>
#include <sstream>
#include <cmath>

#include <LOCA.H>
#include <LOCA_Factory.H>
#include <LOCA_MultiContinuation_AbstractStrategy.H>
#include <LOCA_MultiContinuation_ExtendedVector.H>
#include <LOCA_Parameter_SublistParser.H>
#include <LOCA_Thyra.H>
#include <LOCA_Thyra_SaveDataStrategy.H>
#include <NOX_Observer.hpp>
#include <NOX_Observer_Vector.hpp>
#include <NOX_Solver_Factory.H>
#include <NOX_Solver_LineSearchBased.H>
#include <NOX_Thyra_Vector.H>
#include <Thyra_TpetraThyraWrappers.hpp>

#include "solvers/ContactBetaStepSize.hpp"
#include "solvers/IterativeSolveMonitor.hpp"
#include "solvers/LocaResume.hpp"
#include "solvers/MumpsSolver.hpp"
#include "common/Error.hpp"
#include "solvers/NewtonStatusTests.hpp"
#include "solvers/ResumableStepSize.hpp"
#include "solvers/StepSizeFactory.hpp"
#include "solvers/StepSizeMethods.hpp"

namespace contessa::solvers {

using Teuchos::RCP;
using Teuchos::rcp;

// The continuation at a converged increment k, as the restart file keeps it: what LOCA's stepper, its
// predictor and its step-size strategy need to take increment k + 1 exactly as the uninterrupted run does.
struct ContinuationPoint {
  int increments = 0, failedAttempts = 0;  ///< converged increments (k) and failed attempts so far
  int newtonIterations = 0;                ///< of increment k's solve (what the step-size strategy reads)
  double lambda = 0, previousLambda = 0;   ///< λ_k, λ_{k-1}
  double stepSize = 0;                     ///< LOCA's step size of increment k (after its capping)
  double wallSeconds = 0;                  ///< wall time of the run (all its parts) at increment k
  StateRecord stepSizeState;               ///< a ResumableStepSize's state (empty for LOCA's own)
  const StateRecord* resumedStepSizeState = nullptr;  ///< the restart file's, read when LOCA's state is made
  RCP<const model::Vector> x, previousX;   ///< x_k, x_{k-1}

  /// The restart file's group "continuation" (common/StateRecord.hpp).
  template <class Self, class Fields>
  static void stateFields(Self& self, Fields& field) {
    field("increments", self.increments);
    field("failed_attempts", self.failedAttempts);
    field("newton_iterations", self.newtonIterations);
    field("lambda", self.lambda);
    field("previous_lambda", self.previousLambda);
    field("step_size", self.stepSize);
    field("wall_seconds", self.wallSeconds);
  }
};

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

// Newton statistics of the current solve, read when the increment ends, and why it failed when it did.
// (NOX also calls runPostIterate when the initial guess already converges, so iterations are read from
// the solver.) runPostSolve runs on every rank after every solve, so the diagnosis may communicate.
class NewtonCounter : public NOX::Observer {
 public:
  NewtonCounter(NewtonStatusTests& tests, const std::ostringstream& noxOutput) : tests_(tests), noxOutput_(noxOutput) {}
  void runPreSolve(const NOX::Solver::Generic&) override {
    iterations = 0;
    linearIterationsAtStart_ = iterativeSolveLog().iterations;
    tests_.startSolve();
    outputAtStart_ = noxOutput_.str().size();
  }
  void runPostSolve(const NOX::Solver::Generic& solver) override {
    iterations = solver.getNumIterations();
    linearIterations = iterativeSolveLog().iterations - linearIterationsAtStart_;
    total += iterations;
    residualNorm = solver.getSolutionGroup().getNormF();
    failure = tests_.diagnose(solver, noxOutput_.str().substr(outputAtStart_));
  }
  int iterations = 0, total = 0;
  long linearIterations = 0;  ///< Krylov iterations of the latest solve's Newton directions
  double residualNorm = 0;
  SolveFailure failure;  ///< of the latest solve (kind None when it converged)

 private:
  long linearIterationsAtStart_ = 0;
  NewtonStatusTests& tests_;
  const std::ostringstream& noxOutput_;
  std::size_t outputAtStart_ = 0;
};

// ---- Checkpoint and restart (docs/architecture.md, "Checkpoint and restart").

// The owned DOFs of x_k and x_{k-1} as rows of the table "nodes" (id: node, displacement and
// previous_displacement: dim values each): any rank count reads it.
void saveNodeTable(const model::Vector& x, const model::Vector& previousX, int dim, StateRecord& table) {
  const auto& map = *x.getMap();
  const auto values = x.getData(0), previous = previousX.getData(0);
  std::map<model::GO, std::pair<std::vector<double>, std::vector<double>>> nodes;
  for (std::size_t i = 0; i < map.getNodeNumElements(); ++i) {
    const model::GO dof = map.getGlobalElement(static_cast<model::LO>(i));
    auto& node = nodes[dof / dim];
    node.first.resize(static_cast<std::size_t>(dim), 0.0);
    node.second.resize(static_cast<std::size_t>(dim), 0.0);
    node.first[static_cast<std::size_t>(dof % dim)] = values[i];
    node.second[static_cast<std::size_t>(dof % dim)] = previous[i];
  }
  StateTableWriter rows(table);
  for (const auto& [node, v] : nodes) {
    rows.beginRow(node);
    rows("displacement", v.first);
    rows("previous_displacement", v.second);
  }
  rows.finish();
}

RCP<model::Vector> vectorFromNodeTable(const RCP<const model::Map>& map, int dim, const std::string& column,
                                       const StateRecord& table) {
  auto v = rcp(new model::Vector(map));
  auto values = v->getDataNonConst(0);
  StateTableReader rows(table);
  std::vector<double> node;
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const model::GO dof = map->getGlobalElement(static_cast<model::LO>(i));
    rows.seek(dof / dim, "node " + std::to_string(dof / dim + 1));
    rows(column, node);
    requireInput(node.size() == static_cast<std::size_t>(dim),
                 table.origin() + ": " + table.path() + column + ": " + std::to_string(node.size()) +
                     " components per node, the mesh has " + std::to_string(dim));
    values[i] = node[static_cast<std::size_t>(dof % dim)];
  }
  return v;
}

// Thrown at an increment boundary once the restart file is written, to leave LOCA's stepper.
struct CheckpointStop {
  std::string reason;
};

// LOCA tells the group about every step: commit or roll back the model state, report to the observer.
class IncrementBookkeeper : public LOCA::Thyra::SaveDataStrategy {
 public:
  IncrementBookkeeper(model::IncrementalState& state, const continuation::ContactEventSource& events,
                      IncrementObserver& observer, const NewtonCounter& newton,
                      const continuation::ContactBetaControl* contactBeta, continuation::CountedEvents counted,
                      double initialLambda)
      : state_(state),
        events_(events),
        observer_(observer),
        newton_(newton),
        contactBeta_(contactBeta),
        counted_(counted),
        lastLambda_(initialLambda),
        start_(Clock::now()) {}

  void postProcessContinuationStep(LOCA::Abstract::Iterator::StepStatus status) override {
    if (resuming_) return;  // the resumed stepper re-creating LOCA's predictor state: the model's state stays
    if (status == LOCA::Abstract::Iterator::Successful) {
      state_.commitState();
      pendingSuccess_ = true;
    } else {
      state_.rollbackState();
      ++failedAttempts;
      ++attempts_;
      IncrementReport r = report(state_.lastLoadFactor());
      r.dlambda = r.lambda - lastLambda_;
      lastFailure = newton_.failure;
      lastFailedTarget = r.lambda;
      lastAttemptFailed = true;
      r.failure = lastFailure.reason;
      r.betaRestart = contactBeta_ != nullptr && contactBeta_->restartRequested();
      if (r.betaRestart) r.beta = contactBeta_->beta();
      observer_.attemptFailed(r);
      // A stop requested during failed attempts: the restart file of the last converged increment (the
      // model is back at its state), from which the restarted run tries again.
      if (increments > 0) checkpoint(false);
    }
  }

  // Called by LOCA after a successful step (and once for the initial state).
  void saveSolution(const NOX::Abstract::Vector& x, double lambda) override {
    if (!first_ && !pendingSuccess_) return;
    const auto& tx = dynamic_cast<const NOX::Thyra::Vector&>(x);
    auto tpetraX = Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>::getConstTpetraVector(
        Teuchos::rcpFromRef(tx.getThyraVector()));
    if (first_) state_.commitState();
    lastAttemptFailed = false;
    IncrementReport r = report(lambda);
    r.dlambda = first_ ? 0.0 : lambda - lastLambda_;
    r.newEvents = first_ ? 0 : continuation::countEvents(events_.committedIncrement(), counted_);
    observer_.incrementConverged(*tpetraX, r);
    const bool initial = first_;
    if (!first_) ++increments;
    previousLambda_ = lastLambda_;
    lastLambda_ = lambda;
    first_ = false;
    pendingSuccess_ = false;
    attempts_ = 1;
    if (checkpoint_ == nullptr) return;
    // What a restart file of this increment needs (LOCA's state now is the uninterrupted run's).
    previousX_ = currentX_;
    currentX_ = rcp(new model::Vector(*tpetraX, Teuchos::Copy));
    if (initial) return;
    point_.increments = increments;
    point_.failedAttempts = failedAttempts;
    point_.newtonIterations = newton_.iterations;
    point_.lambda = lambda;
    point_.previousLambda = previousLambda_;
    point_.stepSize = stepper_ != nullptr ? stepper_->currentStepSize() : 0.0;
    point_.wallSeconds = r.wallSeconds;
    point_.stepSizeState = stepper_ != nullptr ? stepper_->stepSizeState() : StateRecord();
    point_.x = currentX_;
    point_.previousX = previousX_;
    // After the increment that reaches Max Value the run ends anyway.
    if (lambda < finalLambda_ * (1.0 - 1.0e-15)) checkpoint(true);
  }

  /// Restart files: `control` decides when; `stepper` is asked for LOCA's state.
  void enableCheckpoints(CheckpointControl* control, double finalLambda, int dimension) {
    checkpoint_ = control;
    finalLambda_ = finalLambda;
    dimension_ = dimension;
  }
  void setStepper(const ResumableStepper* stepper) { stepper_ = stepper; }
  /// The run continues from a restart file's increment: counters, load factors and the vectors as they were.
  void resumeAt(const ContinuationPoint& p) {
    point_ = p;
    increments = p.increments;
    failedAttempts = p.failedAttempts;
    lastLambda_ = p.lambda;
    previousLambda_ = p.previousLambda;
    currentX_ = p.x;
    previousX_ = p.previousX;
    first_ = false;
    start_ = Clock::now() - std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(p.wallSeconds));
  }
  /// While the resumed stepper re-creates LOCA's state, LOCA's calls leave the model alone.
  void setResuming(bool resuming) { resuming_ = resuming; }

  int increments = 0, failedAttempts = 0;
  double lastLambda() const { return lastLambda_; }
  /// The restart file's continuation, step size (rank 0) and nodes (this rank's) of the last converged
  /// increment.
  StateRecord restartState() const {
    StateRecord out;
    if (currentX_->getMap()->getComm()->getRank() == 0) {
      StateWriter continuation(out.child("continuation"));
      ContinuationPoint::stateFields(point_, continuation);
      out.child("step_size").merge(point_.stepSizeState);
    }
    saveNodeTable(*point_.x, *point_.previousX, dimension_, out.child("nodes"));
    return out;
  }
  bool initialStateSolved() const { return !first_; }
  bool lastAttemptFailed = false;  ///< the latest attempt failed (no converged increment since)
  SolveFailure lastFailure;        ///< why it failed
  double lastFailedTarget = 0;     ///< the load factor it aimed at

 private:
  IncrementReport report(double lambda) const {
    IncrementReport r;
    r.step = first_ ? 0 : increments + 1;
    r.beta = contactBeta_ != nullptr && !first_ ? contactBeta_->beta() : 1.0;
    r.lambda = lambda;
    r.attempts = attempts_;
    r.newtonIterations = newton_.iterations;
    r.linearIterations = newton_.linearIterations;
    r.residualNorm = newton_.residualNorm;
    r.wallSeconds = std::chrono::duration<double>(Clock::now() - start_).count();
    return r;
  }

  /// Asks the control after an increment (or a failed attempt); writes and stops as it says.
  void checkpoint(bool converged) {
    if (checkpoint_ == nullptr) return;
    const auto decision = checkpoint_->decide(increments, converged);
    if (decision.write) checkpoint_->write(restartState());
    if (decision.stop) throw CheckpointStop{decision.reason};
  }

  CheckpointControl* checkpoint_ = nullptr;
  const ResumableStepper* stepper_ = nullptr;
  ContinuationPoint point_;
  RCP<const model::Vector> currentX_, previousX_;
  double previousLambda_ = 0, finalLambda_ = 1;
  int dimension_ = 1;
  bool resuming_ = false;
  model::IncrementalState& state_;
  const continuation::ContactEventSource& events_;
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
                                           const RCP<std::ostringstream>& errors) {
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
  // NOX/LOCA errors, and the exceptions NOX catches during a solve, are collected for Contessa's
  // one-line message, not spread on stderr and stdout.
  nox.sublist("Printing").set("Error Stream", Teuchos::rcp_implicit_cast<std::ostream>(errors));
  if (!details) nox.sublist("Printing").set("Output Stream", Teuchos::rcp_implicit_cast<std::ostream>(errors));
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

// Everything the stop message needs to know about how the continuation ended.
struct StopCause {
  bool initialStateSolved = true;
  double initialLambda = 0, lambda = 0;  ///< where it started, the last converged load factor
  int increments = 0;
  bool maxStepsReached = false;
  int maxSteps = 0;
  double minStep = 0;
  bool lastAttemptFailed = false;
  SolveFailure failure;       ///< why the last attempt failed
  double failedTarget = 0;    ///< the load factor it aimed at
  bool contactBetaBelowMinimum = false;
  int contactsPerStep = 0;
  std::string locaErrors;
};

std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  text.erase(0, text.find_first_not_of(" \t"));
  text.erase(text.find_last_not_of(" \t") + 1);
  return text;
}

// The one-line reason a continuation stopped: where, why it could not go on, and the real reason of the
// last failed attempt (not only "maximum number of steps").
std::string stopMessage(const StopCause& c) {
  const std::string reason =
      c.failure.reason.empty() ? std::string("the continuation rejected the step (no Newton failure)") : c.failure.reason;
  if (!c.initialStateSolved)
    return "the initial state at load factor " + loadFactorText(c.initialLambda) + " could not be solved: " + reason;
  std::string out = "continuation stopped at load factor " + loadFactorText(c.lambda);
  const std::string attempt = "the attempt from load factor " + loadFactorText(c.lambda) + " to " +
                              loadFactorText(c.failedTarget) + " failed: " + reason;
  if (c.maxStepsReached) {
    if (c.lastAttemptFailed) return out + " (Max Steps = " + std::to_string(c.maxSteps) + " used up): " + attempt;
    return out + " (Max Steps = " + std::to_string(c.maxSteps) + " used up while the run was still making progress: " +
           std::to_string(c.increments) + " increments converged); raise Piro/LOCA/Stepper/Max Steps";
  }
  if (c.contactBetaBelowMinimum)
    return out + " (Contact Beta asked for a step below Min Step Size = " + shortNumber(c.minStep) + " to let only " +
           std::to_string(c.contactsPerStep) + " contacts close per increment)";
  if (c.lastAttemptFailed)
    return out + " (the step cannot be cut below Min Step Size = " + shortNumber(c.minStep) + "): " + attempt;
  std::string loca = oneLine(c.locaErrors);
  if (loca.size() > 300) loca = "..." + loca.substr(loca.size() - 300);
  return out + (loca.empty() ? std::string(" (LOCA gave no reason)") : " (LOCA: " + loca + ")");
}

// LOCA itself threw (outside a Newton solve, e.g. in the tangent predictor): the linear solver's failure
// when there was one, else the exception's text.
std::string solverErrorMessage(const NewtonStatusTests& tests, double lambda, const std::string& what) {
  const SolveFailure linear = tests.linearSolverFailure();
  return "continuation stopped at load factor " + loadFactorText(lambda) + ": " +
         (linear.kind != SolveFailure::Kind::None ? linear.reason : "solver error: " + oneLine(what));
}

}  // namespace

ContinuationDriver::ContinuationDriver(const RCP<model::ContactMechanicsModel>& model,
                                       const Teuchos::ParameterList& piro, IncrementObserver& observer,
                                       Teuchos::RCP<NOX::Observer> iterationObserver)
    : model_(model), piro_(piro), observer_(observer), iterationObserver_(std::move(iterationObserver)) {}

std::shared_ptr<const ContinuationPoint> readContinuationPoint(const model::ContactMechanicsModel& model,
                                                               const StateRecord& state) {
  auto point = std::make_shared<ContinuationPoint>();
  StateReader continuation(state.child("continuation"));
  ContinuationPoint::stateFields(*point, continuation);
  point->resumedStepSizeState = &state.claim("step_size");
  const StateRecord& nodes = state.child("nodes");
  point->x = vectorFromNodeTable(model.ownedDofMap(), model.dimension(), "displacement", nodes);
  point->previousX = vectorFromNodeTable(model.ownedDofMap(), model.dimension(), "previous_displacement", nodes);
  return point;
}

RunSummary ContinuationDriver::run() {
  const auto& stepSize = piro_.sublist("LOCA").sublist("Step Size");
  const bool contactBeta = stepSizeMethod(stepSize.get<std::string>("Method")).regulatesContactEvents;
  continuation::ContactBetaControl betaState(
      contactBetaSettings(stepSize, piro_.sublist("LOCA").sublist("Stepper").get<double>("Max Value")));

  const auto& tests = piro_.sublist("NOX").sublist("Status Tests");
  const auto* model = model_.get();
  // The Contact Beta check may recompute the residual before the residual test reads it.
  NewtonStatusTests newtonTests(
      *model_,
      rcp(new ResidualTest(tests.get<double>("Absolute Residual Tolerance"), tests.get<double>("Relative Residual Tolerance"),
                           tests.get<double>("Update Tolerance"), [model] { return !model->newContactsFrozen(); },
                           [&betaState] { return !betaState.newContactsJustReleased(); })),
      tests.get<int>("Maximum Iterations"),
      contactBeta && betaState.settings().mode == continuation::ContactBetaSettings::Mode::Restart
          ? Teuchos::RCP<NOX::StatusTest::Generic>(rcp(new ContactBetaRestartTest(*model_, betaState)))
          : Teuchos::null,
      contactBeta ? std::function<std::string()>([&betaState, model] {
        return betaState.redoAtConvergence(model->trialIncrement());
      })
                  : std::function<std::string()>());

  auto errors = rcp(new std::ostringstream());
  auto newton = rcp(new NewtonCounter(newtonTests, *errors));
  auto observers = rcp(new NOX::ObserverVector());
  observers->pushBack(newton);
  if (!iterationObserver_.is_null()) observers->pushBack(iterationObserver_);
  auto params = locaParameters(piro_, observers, errors);
  auto globalData = LOCA::createGlobalData(params, rcp(new StepSizeFactory(StepSizeContext{*model_, betaState})));

  // A restarted run starts from the restart file's increment k: x_k and λ_k are the initial guess and
  // LOCA's Initial Value (taken as converged, not solved again).
  static const ContinuationPoint fresh;
  const ContinuationPoint& resumed = resume_ != nullptr ? *resume_ : fresh;
  if (resume_ != nullptr) params->sublist("LOCA").sublist("Stepper").set("Initial Value", resumed.lambda);
  const double lambda0 = params->sublist("LOCA").sublist("Stepper").get<double>("Initial Value");
  LOCA::ParameterVector p;
  p.addParameter("Load Factor", lambda0);
  RCP<Thyra::VectorBase<double>> x0 =
      resume_ != nullptr ? Thyra::createVector(Teuchos::rcp_const_cast<model::Vector>(resumed.x), model_->get_x_space())
                               ->clone_v()
                         : model_->getNominalValues().get_x()->clone_v();
  NOX::Thyra::Vector initialGuess(x0);
  auto group = rcp(new LOCA::Thyra::Group(globalData, initialGuess, model_, p, 0, true));
  auto bookkeeper = rcp(new IncrementBookkeeper(*model_, *model_, observer_, *newton, contactBeta ? &betaState : nullptr,
                                                betaState.settings().counted, lambda0));
  if (checkpoint_ != nullptr)
    bookkeeper->enableCheckpoints(checkpoint_, piro_.sublist("LOCA").sublist("Stepper").get<double>("Max Value"),
                                  model_->dimension());
  if (resume_ != nullptr) bookkeeper->resumeAt(resumed);
  group->setSaveDataStrategy(bookkeeper);

  RunSummary summary;
  const long solvesBefore = mumpsCounters().solves;
  const int jacobiansBefore = model_->jacobianEvaluations();
  const long krylovBefore = iterativeSolveLog().iterations;
  try {
    ResumableStepper stepper(globalData, group, newtonTests.test(), params);
    bookkeeper->setStepper(&stepper);
    LocaResumePoint locaPoint;
    if (resume_ != nullptr) {
      locaPoint.increments = resumed.increments;
      locaPoint.failedAttempts = resumed.failedAttempts;
      locaPoint.newtonIterations = resumed.newtonIterations;
      locaPoint.stepSize = resumed.stepSize;
      locaPoint.previousLambda = resumed.previousLambda;
      locaPoint.previousX = resumed.previousX;
      locaPoint.secantPredictor = piro_.sublist("LOCA").sublist("Predictor").get<std::string>("Method") == "Secant";
      locaPoint.stepSizeState = resumed.resumedStepSizeState;
      stepper.resumeFrom(locaPoint, [bookkeeper](bool resuming) { bookkeeper->setResuming(resuming); });
    }
    const auto status = stepper.run();
    summary.finished = status == LOCA::Abstract::Iterator::Finished;
    if (!summary.finished) {
      StopCause cause;
      cause.initialStateSolved = bookkeeper->initialStateSolved();
      cause.initialLambda = lambda0;
      cause.lambda = bookkeeper->lastLambda();
      cause.increments = bookkeeper->increments;
      cause.maxSteps = piro_.sublist("LOCA").sublist("Stepper").get<int>("Max Steps");
      cause.maxStepsReached = bookkeeper->increments + bookkeeper->failedAttempts >= cause.maxSteps;
      cause.minStep = stepSize.get<double>("Min Step Size");
      cause.lastAttemptFailed = bookkeeper->lastAttemptFailed;
      // The initial solve is no step of LOCA's: its failure is the latest solve's.
      cause.failure = cause.initialStateSolved ? bookkeeper->lastFailure : newton->failure;
      cause.failedTarget = bookkeeper->lastFailedTarget;
      cause.contactBetaBelowMinimum = betaState.hitMinimumStep() && !bookkeeper->lastAttemptFailed;
      cause.contactsPerStep = betaState.settings().beta.contactsPerStep;
      cause.locaErrors = errors->str();
      summary.message = stopMessage(cause);
    }
  } catch (const CheckpointStop& stop) {
    summary.checkpointed = true;
    summary.message = stop.reason;
  } catch (const InputError&) {
    throw;  // the restart file's step-size state did not fit (read when LOCA's state is re-created)
  } catch (const std::exception& e) {
    summary.message = solverErrorMessage(newtonTests, bookkeeper->lastLambda(), e.what());
  } catch (const char* e) {
    summary.message = solverErrorMessage(newtonTests, bookkeeper->lastLambda(), e);
  }
  summary.increments = bookkeeper->increments;
  summary.failedAttempts = bookkeeper->failedAttempts;
  summary.newtonIterations = newton->total;
  // A direct solver solves once per Jacobian; iterative solvers are counted as Jacobian evaluations.
  const long mumpsSolves = mumpsCounters().solves - solvesBefore;
  summary.linearSolves = mumpsSolves > 0 ? static_cast<int>(mumpsSolves) : model_->jacobianEvaluations() - jacobiansBefore;
  summary.linearIterations = iterativeSolveLog().iterations - krylovBefore;
  summary.finalLambda = bookkeeper->lastLambda();
  LOCA::destroyGlobalData(globalData);
  return summary;
}

}  // namespace contessa::solvers
