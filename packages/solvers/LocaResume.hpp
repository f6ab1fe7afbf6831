#pragma once
// The one place that knows LOCA's internals (Trilinos 13.2; docs/architecture.md, "Checkpoint and
// restart"): continuing a continuation from a restart file's converged increment k as the uninterrupted
// run would have gone on. LOCA 13.2 has no public way to start a stepper anywhere but at its initial
// solve, so ResumableStepper replaces LOCA::Stepper::start() and re-seeds the protected members that
// start() sets (LOCA::Stepper: curGroupPtr, prevGroupPtr, curPredictorPtr, prevPredictorPtr, solverPtr,
// stepSize, stepSizeStrategyPtr; LOCA::Abstract::Iterator: stepNumber, numFailedSteps, numTotalSteps),
// and hands LOCA's step-size strategy a NOX solver that reports increment k's Newton iterations
// (ResumedSolver). tests/unit/solvers/LocaResumeTest.cpp fails when the Trilinos version changes: then
// compare LOCA::Stepper::start() of the new version with ResumableStepper::start() and run the restart
// tests (ctest -L restart) before moving the version on.
#include <functional>

#include <LOCA_Stepper.H>
#include <Teuchos_RCP.hpp>

#include "common/StateRecord.hpp"
#include "model/TpetraTypes.hpp"

namespace contessa::solvers {

/// The Trilinos version (TRILINOS_MAJOR_MINOR_VERSION) whose LOCA internals ResumableStepper re-seeds.
constexpr int kLocaInternalsVersion = 130200;

/// What LOCA's stepper needs to take increment k + 1 exactly as the uninterrupted run does.
struct LocaResumePoint {
  int increments = 0, failedAttempts = 0;  ///< converged increments (k) and failed attempts so far
  int newtonIterations = 0;                ///< of increment k's solve (what the step-size strategy reads)
  double stepSize = 0;                     ///< LOCA's step size of increment k (after its capping)
  double previousLambda = 0;               ///< λ_{k-1}
  Teuchos::RCP<const model::Vector> previousX;  ///< x_{k-1} (the secant predictor's)
  bool secantPredictor = false;            ///< Piro/LOCA/Predictor/Method = Secant
  /// A ResumableStepSize's state (the restart file's group "step_size"): loaded, then checked for fields
  /// it does not know.
  const StateRecord* stepSizeState = nullptr;
};

// LOCA's stepper, able to continue from a converged increment (a restart file) instead of solving the
// initial state, and to tell what a restart file must keep of it. Every value it sets is the
// uninterrupted run's, bit for bit, so the restarted run takes the same increments.
class ResumableStepper : public LOCA::Stepper {
 public:
  using LOCA::Stepper::Stepper;
  /// Continue from `point` at run() (it must outlive run()): the group must hold x_k and λ_k already.
  /// `quiet(true)` while start() re-creates LOCA's state: the step notifications it makes are not steps.
  void resumeFrom(const LocaResumePoint& point, std::function<void(bool)> quiet) {
    resume_ = &point;
    quiet_ = std::move(quiet);
  }
  double currentStepSize() const { return stepSize; }
  /// The group the Newton solver iterates on (LOCA's continuation group, curGroupPtr): a step-size method
  /// may change what it evaluates between the line search and the status tests (StepControlRelay).
  NOX::Abstract::Group& solverGroup();
  /// The step-size strategy's state (nothing for LOCA's own).
  StateRecord stepSizeState() const;

 protected:
  LOCA::Abstract::Iterator::IteratorStatus start() override;

 private:
  const LocaResumePoint* resume_ = nullptr;
  std::function<void(bool)> quiet_;
};

}  // namespace contessa::solvers
