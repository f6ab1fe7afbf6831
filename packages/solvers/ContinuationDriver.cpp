#include "solvers/ContinuationDriver.hpp"

#include <cmath>
#include <iostream>
#include <sstream>

#include <LOCA.H>
#include <LOCA_Thyra.H>
#include <NOX_Observer_Vector.hpp>
#include <NOX_Thyra_Vector.H>
#include <Thyra_SpmdVectorSpaceBase.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include "common/Error.hpp"
#include "solvers/IncrementBookkeeper.hpp"
#include "solvers/IterateContactStates.hpp"
#include "solvers/IterativeSolveMonitor.hpp"
#include "solvers/LoadFactorDerivativeGroup.hpp"
#include "solvers/LocaResume.hpp"
#include "solvers/MumpsSolver.hpp"
#include "solvers/NewtonCounter.hpp"
#include "solvers/NewtonStatusTests.hpp"
#include "solvers/NoxParameters.hpp"
#include "solvers/ResidualTest.hpp"
#include "solvers/StepControlRelay.hpp"
#include "solvers/StepSizeFactory.hpp"
#include "solvers/StepSizeMethods.hpp"
#include "solvers/StopMessage.hpp"

namespace contessa::solvers {

using Teuchos::RCP;
using Teuchos::rcp;

namespace {

// The parameter list LOCA and NOX read, made from the validated deck list.
RCP<Teuchos::ParameterList> locaParameters(const Teuchos::ParameterList& piro, const Teuchos::ParameterList& stepSize,
                                           const RCP<NOX::Observer>& observer, const RCP<std::ostringstream>& errors) {
  auto top = rcp(new Teuchos::ParameterList("Contessa solver"));
  setNoxParameters(top->sublist("NOX"), piro.sublist("NOX"), observer, Teuchos::rcp_implicit_cast<std::ostream>(errors),
                   NoxPrinting::Continuation);
  const auto& deckLoca = piro.sublist("LOCA");
  auto& loca = top->sublist("LOCA");
  auto& stepper = loca.sublist("Stepper");
  stepper.setParameters(deckLoca.sublist("Stepper"));
  stepper.set("Continuation Method", "Natural");
  stepper.set("Continuation Parameter", "Load Factor");
  stepper.set("Compute Eigenvalues", false);
  loca.sublist("Predictor").setParameters(deckLoca.sublist("Predictor"));
  loca.sublist("Step Size").setParameters(stepSize);
  return top;
}

// The Newton tests of every solve: the deck's tolerances in the ResidualTest (its absolute bound the deck's
// or force-scaled, ResidualTolerance.hpp), and what the step-size method adds.
std::unique_ptr<NewtonStatusTests> newtonTests(const SolverModel& model, const Teuchos::ParameterList& deckTests,
                                               StepControl& stepControl, ResidualToleranceRecord& record) {
  auto convergence = rcp(new ResidualTest(ResidualTolerance::fromDeck(deckTests), model.forces,
                                          deckTests.get<double>("Relative Residual Tolerance"),
                                          deckTests.get<double>("Update Tolerance"), &stepControl, &record));
  return std::make_unique<NewtonStatusTests>(*model.diagnostics, model.evaluator->get_W_factory(), convergence,
                                             deckTests.get<int>("Maximum Iterations"), &stepControl);
}

// How the continuation ended, when it did not reach Max Value.
StopCause stopCause(const IncrementBookkeeper& bookkeeper, const NewtonCounter& newton, const StepControl& stepControl,
                    const Teuchos::ParameterList& loca, const Teuchos::ParameterList& stepSize, double initialLambda,
                    const std::string& locaErrors) {
  StopCause cause;
  cause.initialStateSolved = bookkeeper.initialStateSolved();
  cause.initialLambda = initialLambda;
  cause.lambda = bookkeeper.lastLambda();
  cause.increments = bookkeeper.increments;
  cause.maxSteps = loca.sublist("Stepper").get<int>("Max Steps");
  cause.maxStepsReached = bookkeeper.increments + bookkeeper.failedAttempts >= cause.maxSteps;
  cause.minStep = stepSize.get<double>("Min Step Size");
  cause.lastAttemptFailed = bookkeeper.lastAttemptFailed;
  // The initial solve is no step of LOCA's: its failure is the latest solve's.
  cause.failure = cause.initialStateSolved ? bookkeeper.lastFailure : newton.failure;
  cause.failedTarget = bookkeeper.lastFailedTarget;
  if (!bookkeeper.lastAttemptFailed) cause.methodReason = stepControl.stopReason();
  cause.locaErrors = locaErrors;
  return cause;
}

}  // namespace

// The continuation of one load step, as the step loop needs it.
struct ContinuationDriver::StepOutcome {
  RunSummary summary;  ///< finished, checkpointed, message, and the run's counts so far
  RCP<IncrementBookkeeper> bookkeeper;
  RCP<const Thyra::VectorBase<double>> x;  ///< the step's last converged state
};

ContinuationDriver::ContinuationDriver(const SolverModel& model, const Teuchos::ParameterList& piro,
                                       IncrementObserver& observer, Teuchos::RCP<NOX::Observer> iterationObserver)
    : model_(model), piro_(piro), observer_(observer), iterationObserver_(std::move(iterationObserver)) {}

RunSummary ContinuationDriver::run() {
  if (stepSizes_.empty()) stepSizes_.push_back(piro_.sublist("LOCA").sublist("Step Size"));
  const int steps = static_cast<int>(stepSizes_.size());
  const long solvesBefore = mumpsCounters().solves;
  const int jacobiansBefore = model_.diagnostics->jacobianEvaluations();
  const long krylovBefore = iterativeSolveLog().iterations;
  const double maxValue = piro_.sublist("LOCA").sublist("Stepper").get<double>("Max Value");

  // A restart file's point inside a load step resumes there; one at a step's end (its λ_s at Max Value)
  // starts the next step from that state, as the uninterrupted run does.
  StepStart start;
  if (resume_ != nullptr) {
    start.step = resume_->loadStep;
    if (resume_->lambda >= maxValue * (1.0 - 1.0e-15) && resume_->loadStep + 1 < steps) {
      ++start.step;
      start.afterResume = resume_.get();
      start.x = Thyra::createVector(Teuchos::rcp_const_cast<model::Vector>(resume_->x), model_.evaluator->get_x_space());
    } else {
      start.resume = resume_.get();
    }
  }
  StepOutcome outcome;
  int newtonThisJob = 0;
  for (; start.step < steps; ++start.step) {
    if (steps > 1 || start.step > 0) model_.loadStepping->setLoadStep(start.step);
    outcome = runStep(start, stepSizes_[static_cast<std::size_t>(start.step)], start.step + 1 == steps);
    newtonThisJob += outcome.summary.newtonIterations;
    if (!outcome.summary.finished) break;
    start = StepStart{start.step, nullptr, nullptr, outcome.x, outcome.bookkeeper.get()};
  }
  RunSummary summary = outcome.summary;
  summary.newtonIterations = newtonThisJob;
  // A direct solver solves once per Jacobian; iterative solvers are counted as Jacobian evaluations.
  const long mumpsSolves = mumpsCounters().solves - solvesBefore;
  summary.linearSolves =
      mumpsSolves > 0 ? static_cast<int>(mumpsSolves) : model_.diagnostics->jacobianEvaluations() - jacobiansBefore;
  summary.linearIterations = iterativeSolveLog().iterations - krylovBefore;
  summary.forceScale = tolerance_.lastForceScale;
  summary.residualBound = tolerance_.lastBound;
  summary.toleranceWarning = tolerance_.warning;
  summary.toleranceFloor = tolerance_.floorSummary();
  return summary;
}

ContinuationDriver::StepOutcome ContinuationDriver::runStep(const StepStart& start, const Teuchos::ParameterList& stepSize,
                                                            bool lastStep) {
  const auto& loca = piro_.sublist("LOCA");
  const ContinuationPoint* resume = start.resume;
  auto stepControl = createStepControl({stepSize, loca.sublist("Stepper").get<double>("Max Value"), *model_.events});
  auto tests = newtonTests(model_, piro_.sublist("NOX").sublist("Status Tests"), *stepControl, tolerance_);

  auto errors = rcp(new std::ostringstream());
  auto newton = rcp(new NewtonCounter(*tests, *errors));
  auto relay = rcp(new StepControlRelay(*stepControl));
  auto observers = rcp(new NOX::ObserverVector());
  observers->pushBack(newton);
  if (!iterationObserver_.is_null()) observers->pushBack(iterationObserver_);
  observers->pushBack(relay);
  if (piro_.sublist("NOX").sublist("Printing").get<bool>("Newton Details")) {
    // The contact states of every iterate next to NOX's own lines (rank 0 writes, as NOX does).
    const auto space = Teuchos::rcp_dynamic_cast<const Thyra::SpmdVectorSpaceBase<double>>(model_.evaluator->get_x_space());
    const bool print = space.is_null() || space->getComm()->getRank() == 0;
    observers->pushBack(rcp(new IterateContactStates(*model_.events, print, std::cout)));
  }
  auto params = locaParameters(piro_, stepSize, observers, errors);
  auto globalData = LOCA::createGlobalData(params, rcp(new StepSizeFactory(*stepControl)));

  // A restarted run starts from the restart file's increment k: x_k and λ_k are the initial guess and
  // LOCA's Initial Value (taken as converged, not solved again). A later load step starts from the
  // previous step's end state, solved again at its own λ_s = Initial Value.
  if (resume != nullptr) params->sublist("LOCA").sublist("Stepper").set("Initial Value", resume->lambda);
  const double lambda0 = params->sublist("LOCA").sublist("Stepper").get<double>("Initial Value");
  LOCA::ParameterVector p;
  p.addParameter("Load Factor", lambda0);
  RCP<Thyra::VectorBase<double>> x0 =
      resume != nullptr ? Thyra::createVector(Teuchos::rcp_const_cast<model::Vector>(resume->x), model_.evaluator->get_x_space())->clone_v()
      : !start.x.is_null() ? start.x->clone_v()
                           : model_.evaluator->getNominalValues().get_x()->clone_v();
  NOX::Thyra::Vector initialGuess(x0);
  // ∂f/∂λ (the tangent predictor's right-hand side) from the model, not a difference in λ.
  auto group = rcp(new LoadFactorDerivativeGroup(globalData, initialGuess, model_.evaluator, p));
  auto bookkeeper = rcp(new IncrementBookkeeper(
      *model_.state, *model_.events, observer_, *newton, *stepControl,
      countedEvents(stepSize), lambda0));
  bookkeeper->startLoadStep(start.step, start.earlier);
  if (start.afterResume != nullptr) bookkeeper->startLoadStepAfter(start.step, *start.afterResume);
  // A checkpoint at the end of every load step but the last (the run ends there anyway).
  const double finalLambda = lastStep ? loca.sublist("Stepper").get<double>("Max Value") : HUGE_VAL;
  if (checkpoint_ != nullptr) bookkeeper->enableCheckpoints(checkpoint_, finalLambda, model_.dimension);
  if (resume != nullptr) bookkeeper->resumeAt(*resume);
  group->setSaveDataStrategy(bookkeeper);

  StepOutcome out;
  RunSummary& summary = out.summary;
  try {
    ResumableStepper stepper(globalData, group, tests->test(), params);
    bookkeeper->setStepper(&stepper);
    relay->setStepper(&stepper);
    tests->enableAugmentation(model_.augmentation,
                              [&stepper]() -> NOX::Abstract::Group& { return stepper.solverGroup(); });
    LocaResumePoint locaPoint;
    if (resume != nullptr) {
      locaPoint = locaResumePoint(*resume, loca.sublist("Predictor").get<std::string>("Method") == "Secant");
      stepper.resumeFrom(locaPoint, [bookkeeper](bool resuming) { bookkeeper->setResuming(resuming); });
    }
    summary.finished = stepper.run() == LOCA::Abstract::Iterator::Finished;
    if (!summary.finished)
      summary.message = stopMessage(stopCause(*bookkeeper, *newton, *stepControl, loca, stepSize, lambda0, errors->str()));
    // The step's end state starts the next load step.
    const auto& end = dynamic_cast<const NOX::Thyra::Vector&>(stepper.getSolutionGroup()->getX());
    out.x = end.getThyraVector().clone_v();
  } catch (const CheckpointStop& stop) {
    summary.checkpointed = true;
    summary.message = stop.reason;
  } catch (const InputError&) {
    throw;  // the restart file's step-size state did not fit (read when LOCA's state is re-created)
  } catch (const std::exception& e) {
    summary.message = solverErrorMessage(*tests, bookkeeper->lastLambda(), e.what());
  } catch (const char* e) {
    summary.message = solverErrorMessage(*tests, bookkeeper->lastLambda(), e);
  }
  summary.increments = bookkeeper->increments;
  summary.failedAttempts = bookkeeper->failedAttempts;
  summary.stepSizeChoice = stepControl->choiceMade();
  summary.newtonIterations = newton->total;
  summary.runNewtonIterations = bookkeeper->runNewtonIterations();
  summary.finalLambda = bookkeeper->lastLambda();
  out.bookkeeper = bookkeeper;
  LOCA::destroyGlobalData(globalData);
  return out;
}

}  // namespace contessa::solvers
