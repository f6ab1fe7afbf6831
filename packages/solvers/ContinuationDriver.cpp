#include "solvers/ContinuationDriver.hpp"

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
RCP<Teuchos::ParameterList> locaParameters(const Teuchos::ParameterList& piro, const RCP<NOX::Observer>& observer,
                                           const RCP<std::ostringstream>& errors) {
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
  loca.sublist("Step Size").setParameters(deckLoca.sublist("Step Size"));
  return top;
}

// The Newton tests of every solve: the deck's tolerances in the ResidualTest, and what the step-size
// method adds.
std::unique_ptr<NewtonStatusTests> newtonTests(const SolverModel& model, const Teuchos::ParameterList& deckTests,
                                               StepControl& stepControl) {
  auto convergence = rcp(new ResidualTest(deckTests.get<double>("Absolute Residual Tolerance"),
                                          deckTests.get<double>("Relative Residual Tolerance"),
                                          deckTests.get<double>("Update Tolerance"), stepControl));
  return std::make_unique<NewtonStatusTests>(*model.diagnostics, model.evaluator->get_W_factory(), convergence,
                                             deckTests.get<int>("Maximum Iterations"), &stepControl);
}

// How the continuation ended, when it did not reach Max Value.
StopCause stopCause(const IncrementBookkeeper& bookkeeper, const NewtonCounter& newton, const StepControl& stepControl,
                    const Teuchos::ParameterList& loca, double initialLambda, const std::string& locaErrors) {
  StopCause cause;
  cause.initialStateSolved = bookkeeper.initialStateSolved();
  cause.initialLambda = initialLambda;
  cause.lambda = bookkeeper.lastLambda();
  cause.increments = bookkeeper.increments;
  cause.maxSteps = loca.sublist("Stepper").get<int>("Max Steps");
  cause.maxStepsReached = bookkeeper.increments + bookkeeper.failedAttempts >= cause.maxSteps;
  cause.minStep = loca.sublist("Step Size").get<double>("Min Step Size");
  cause.lastAttemptFailed = bookkeeper.lastAttemptFailed;
  // The initial solve is no step of LOCA's: its failure is the latest solve's.
  cause.failure = cause.initialStateSolved ? bookkeeper.lastFailure : newton.failure;
  cause.failedTarget = bookkeeper.lastFailedTarget;
  if (!bookkeeper.lastAttemptFailed) cause.methodReason = stepControl.stopReason();
  cause.locaErrors = locaErrors;
  return cause;
}

}  // namespace

ContinuationDriver::ContinuationDriver(const SolverModel& model, const Teuchos::ParameterList& piro,
                                       IncrementObserver& observer, Teuchos::RCP<NOX::Observer> iterationObserver)
    : model_(model), piro_(piro), observer_(observer), iterationObserver_(std::move(iterationObserver)) {}

RunSummary ContinuationDriver::run() {
  const auto& loca = piro_.sublist("LOCA");
  const auto& stepSize = loca.sublist("Step Size");
  auto stepControl = createStepControl({stepSize, loca.sublist("Stepper").get<double>("Max Value"), *model_.events});
  auto tests = newtonTests(model_, piro_.sublist("NOX").sublist("Status Tests"), *stepControl);

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
  auto params = locaParameters(piro_, observers, errors);
  auto globalData = LOCA::createGlobalData(params, rcp(new StepSizeFactory(*stepControl)));

  // A restarted run starts from the restart file's increment k: x_k and λ_k are the initial guess and
  // LOCA's Initial Value (taken as converged, not solved again).
  if (resume_ != nullptr) params->sublist("LOCA").sublist("Stepper").set("Initial Value", resume_->lambda);
  const double lambda0 = params->sublist("LOCA").sublist("Stepper").get<double>("Initial Value");
  LOCA::ParameterVector p;
  p.addParameter("Load Factor", lambda0);
  RCP<Thyra::VectorBase<double>> x0 =
      resume_ != nullptr
          ? Thyra::createVector(Teuchos::rcp_const_cast<model::Vector>(resume_->x), model_.evaluator->get_x_space())->clone_v()
          : model_.evaluator->getNominalValues().get_x()->clone_v();
  NOX::Thyra::Vector initialGuess(x0);
  auto group = rcp(new LOCA::Thyra::Group(globalData, initialGuess, model_.evaluator, p, 0, true));
  auto bookkeeper = rcp(new IncrementBookkeeper(
      *model_.state, *model_.events, observer_, *newton, *stepControl,
      continuation::countedEventsByName(stepSize.get<std::string>("Counted Events")), lambda0));
  if (checkpoint_ != nullptr)
    bookkeeper->enableCheckpoints(checkpoint_, loca.sublist("Stepper").get<double>("Max Value"), model_.dimension);
  if (resume_ != nullptr) bookkeeper->resumeAt(*resume_);
  group->setSaveDataStrategy(bookkeeper);

  RunSummary summary;
  const long solvesBefore = mumpsCounters().solves;
  const int jacobiansBefore = model_.diagnostics->jacobianEvaluations();
  const long krylovBefore = iterativeSolveLog().iterations;
  try {
    ResumableStepper stepper(globalData, group, tests->test(), params);
    bookkeeper->setStepper(&stepper);
    relay->setStepper(&stepper);
    LocaResumePoint locaPoint;
    if (resume_ != nullptr) {
      locaPoint = locaResumePoint(*resume_, loca.sublist("Predictor").get<std::string>("Method") == "Secant");
      stepper.resumeFrom(locaPoint, [bookkeeper](bool resuming) { bookkeeper->setResuming(resuming); });
    }
    summary.finished = stepper.run() == LOCA::Abstract::Iterator::Finished;
    if (!summary.finished) summary.message = stopMessage(stopCause(*bookkeeper, *newton, *stepControl, loca, lambda0, errors->str()));
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
  summary.newtonIterations = newton->total;
  summary.runNewtonIterations = bookkeeper->earlierNewtonIterations + newton->total;
  // A direct solver solves once per Jacobian; iterative solvers are counted as Jacobian evaluations.
  const long mumpsSolves = mumpsCounters().solves - solvesBefore;
  summary.linearSolves =
      mumpsSolves > 0 ? static_cast<int>(mumpsSolves) : model_.diagnostics->jacobianEvaluations() - jacobiansBefore;
  summary.linearIterations = iterativeSolveLog().iterations - krylovBefore;
  summary.finalLambda = bookkeeper->lastLambda();
  LOCA::destroyGlobalData(globalData);
  return summary;
}

}  // namespace contessa::solvers
