#include "solvers/IncrementBookkeeper.hpp"

#include <NOX_Thyra_Vector.H>
#include <Thyra_TpetraThyraWrappers.hpp>

#include "solvers/LocaResume.hpp"

namespace contessa::solvers {

using Teuchos::rcp;

IncrementBookkeeper::IncrementBookkeeper(model::IncrementalState& state, const continuation::ContactEventSource& events,
                                         IncrementObserver& observer, const NewtonCounter& newton,
                                         const StepControl& stepControl, continuation::CountedEvents counted,
                                         double initialLambda)
    : state_(state),
      events_(events),
      observer_(observer),
      newton_(newton),
      stepControl_(stepControl),
      counted_(counted),
      lastLambda_(initialLambda),
      start_(Clock::now()) {}

void IncrementBookkeeper::postProcessContinuationStep(LOCA::Abstract::Iterator::StepStatus status) {
  if (resuming_) return;  // the resumed stepper re-creating LOCA's predictor state: the model's state stays
  if (status == LOCA::Abstract::Iterator::Successful) {
    state_.commitState();
    pendingSuccess_ = true;
    return;
  }
  state_.rollbackState();
  ++failedAttempts;
  ++attempts_;
  IncrementReport r = report(state_.lastLoadFactor());
  r.dlambda = r.lambda - lastLambda_;
  lastFailure = newton_.failure;
  lastFailedTarget = r.lambda;
  lastAttemptFailed = true;
  r.failure = lastFailure.reason;
  r.betaRestart = stepControl_.correctionRequested();
  if (r.betaRestart) r.beta = stepControl_.correctionFactor();
  observer_.attemptFailed(r);
  // A stop requested during failed attempts: the restart file of the last converged increment (the
  // model is back at its state), from which the restarted run tries again.
  if (increments > 0) checkpoint(false);
}

void IncrementBookkeeper::saveSolution(const NOX::Abstract::Vector& x, double lambda) {
  if (!first_ && !pendingSuccess_) return;
  const auto& tx = dynamic_cast<const NOX::Thyra::Vector&>(x);
  auto tpetraX = Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>::getConstTpetraVector(
      Teuchos::rcpFromRef(tx.getThyraVector()));
  if (first_) state_.commitState();
  lastAttemptFailed = false;
  IncrementReport r = report(lambda);
  r.dlambda = first_ ? 0.0 : lambda - lastLambda_;
  r.newEvents = first_ ? 0 : continuation::countEvents(events_.committedIncrement(), counted_);
  if (!first_ || reportInitial_) observer_.incrementConverged(*tpetraX, r);
  const bool initial = first_;
  if (!first_) ++increments;
  previousLambda_ = lastLambda_;
  lastLambda_ = lambda;
  first_ = false;
  pendingSuccess_ = false;
  attempts_ = 1;
  if (checkpoint_ == nullptr) return;
  previousX_ = currentX_;
  currentX_ = rcp(new model::Vector(*tpetraX, Teuchos::Copy));
  if (initial) return;
  rememberPoint(lambda, r);
  // After the increment that reaches Max Value the run ends anyway.
  if (lambda < finalLambda_ * (1.0 - 1.0e-15)) checkpoint(true);
}

void IncrementBookkeeper::rememberPoint(double lambda, const IncrementReport& r) {
  point_.increments = increments;
  point_.failedAttempts = failedAttempts;
  point_.loadStep = loadStep_;
  point_.stepIncrements = increments - stepFirstIncrement_;
  point_.stepFailedAttempts = failedAttempts - stepFirstFailure_;
  point_.newtonIterations = newton_.iterations;
  point_.runNewtonIterations = runNewtonIterations();
  point_.lambda = lambda;
  point_.previousLambda = previousLambda_;
  point_.stepSize = stepper_ != nullptr ? stepper_->currentStepSize() : 0.0;
  point_.wallSeconds = r.wallSeconds;
  point_.stepSizeState = stepper_ != nullptr ? stepper_->stepSizeState() : StateRecord();
  point_.x = currentX_;
  point_.previousX = previousX_;
}

void IncrementBookkeeper::enableCheckpoints(CheckpointControl* control, double finalLambda, int dimension) {
  checkpoint_ = control;
  finalLambda_ = finalLambda;
  dimension_ = dimension;
}

void IncrementBookkeeper::resumeAt(const ContinuationPoint& p) {
  point_ = p;
  increments = p.increments;
  failedAttempts = p.failedAttempts;
  loadStep_ = p.loadStep;
  stepFirstIncrement_ = p.increments - p.stepIncrements;
  stepFirstFailure_ = p.failedAttempts - p.stepFailedAttempts;
  earlierNewtonIterations = p.runNewtonIterations;
  lastLambda_ = p.lambda;
  previousLambda_ = p.previousLambda;
  currentX_ = p.x;
  previousX_ = p.previousX;
  first_ = false;
  start_ = Clock::now() - std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(p.wallSeconds));
}

void IncrementBookkeeper::startLoadStep(int loadStep, const IncrementBookkeeper* earlier) {
  loadStep_ = loadStep;
  if (earlier == nullptr) return;
  increments = stepFirstIncrement_ = earlier->increments;
  failedAttempts = stepFirstFailure_ = earlier->failedAttempts;
  earlierNewtonIterations = earlier->runNewtonIterations();
  start_ = earlier->start_;
  point_ = earlier->point_;  // a checkpoint before this step's first increment is of the last step's end
  reportInitial_ = false;
}

void IncrementBookkeeper::startLoadStepAfter(int loadStep, const ContinuationPoint& p) {
  loadStep_ = loadStep;
  increments = stepFirstIncrement_ = p.increments;
  failedAttempts = stepFirstFailure_ = p.failedAttempts;
  earlierNewtonIterations = p.runNewtonIterations;
  start_ = Clock::now() - std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(p.wallSeconds));
  point_ = p;
  reportInitial_ = false;
}

IncrementReport IncrementBookkeeper::report(double lambda) const {
  IncrementReport r;
  r.loadStep = loadStep_;
  r.step = first_ ? (reportInitial_ ? 0 : increments) : increments + 1;
  r.beta = first_ ? 1.0 : stepControl_.correctionFactor();
  r.lambda = lambda;
  r.attempts = attempts_;
  r.newtonIterations = newton_.iterations;
  r.linearIterations = newton_.linearIterations;
  r.residualNorm = newton_.residualNorm;
  r.wallSeconds = std::chrono::duration<double>(Clock::now() - start_).count();
  return r;
}

void IncrementBookkeeper::checkpoint(bool converged) {
  if (checkpoint_ == nullptr) return;
  const auto decision = checkpoint_->decide(increments, converged);
  if (decision.write) checkpoint_->write(continuationState(point_, dimension_));
  if (decision.stop) throw CheckpointStop{decision.reason};
}

}  // namespace contessa::solvers
