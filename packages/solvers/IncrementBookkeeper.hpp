#pragma once
// The increments of a continuation as LOCA reports them to its group (a LOCA::Thyra::SaveDataStrategy):
// commit or roll back the model's state, count increments and failed attempts, report each to the
// IncrementObserver (with the step-size method's words: StepControl), and write a restart file when the
// CheckpointControl asks (stopping the run with CheckpointStop when it says so).
#include <chrono>
#include <string>

#include <LOCA_Thyra_SaveDataStrategy.H>

#include "continuation/ContactEventSource.hpp"
#include "model/IncrementalState.hpp"
#include "solvers/ContinuationRestart.hpp"
#include "solvers/NewtonCounter.hpp"
#include "solvers/RunReports.hpp"
#include "solvers/StepControl.hpp"

namespace contessa::solvers {

class ResumableStepper;

// Thrown at an increment boundary once the restart file is written, to leave LOCA's stepper.
struct CheckpointStop {
  std::string reason;
};

class IncrementBookkeeper : public LOCA::Thyra::SaveDataStrategy {
 public:
  /// `counted`: the status changes the history's new_events counts (Step Size/Counted Events).
  IncrementBookkeeper(model::IncrementalState& state, const continuation::ContactEventSource& events,
                      IncrementObserver& observer, const NewtonCounter& newton, const StepControl& stepControl,
                      continuation::CountedEvents counted, double initialLambda);

  void postProcessContinuationStep(LOCA::Abstract::Iterator::StepStatus status) override;
  // Called by LOCA after a successful step (and once for the initial state).
  void saveSolution(const NOX::Abstract::Vector& x, double lambda) override;

  /// Restart files: `control` decides when (none after the increment that reaches `finalLambda`).
  void enableCheckpoints(CheckpointControl* control, double finalLambda, int dimension);
  /// LOCA's stepper, asked for its step size and its step-size strategy's state.
  void setStepper(const ResumableStepper* stepper) { stepper_ = stepper; }
  /// The run continues from a restart file's increment: counters, load factors and the vectors as they were.
  void resumeAt(const ContinuationPoint& p);
  /// Load steps: this bookkeeper's continuation is load step `loadStep` of the run; `earlier` (the
  /// previous step's bookkeeper, or null for the run's first) holds the run's counts and clock so far.
  /// After the run's first step the step's initial state (the previous step's end) is no new increment:
  /// it is committed, not reported.
  void startLoadStep(int loadStep, const IncrementBookkeeper* earlier);
  /// The continuation resumed from a restart file's point at the end of load step `p.loadStep` goes on
  /// with load step `loadStep` from its start.
  void startLoadStepAfter(int loadStep, const ContinuationPoint& p);
  /// While the resumed stepper re-creates LOCA's state, LOCA's calls leave the model alone.
  void setResuming(bool resuming) { resuming_ = resuming; }

  int increments = 0, failedAttempts = 0;  ///< of the whole run (every load step)
  /// Newton iterations before this load step's continuation: the jobs before this one (0 for a new run;
  /// from the restart file's point) and the earlier load steps of this job.
  int earlierNewtonIterations = 0;
  /// Newton iterations of the run so far (earlier jobs and steps, failed attempts included).
  int runNewtonIterations() const { return earlierNewtonIterations + newton_.total; }
  double lastLambda() const { return lastLambda_; }
  bool initialStateSolved() const { return !first_; }
  bool lastAttemptFailed = false;  ///< the latest attempt failed (no converged increment since)
  SolveFailure lastFailure;        ///< why it failed
  double lastFailedTarget = 0;     ///< the load factor it aimed at

 private:
  using Clock = std::chrono::steady_clock;
  IncrementReport report(double lambda) const;
  /// What a restart file of the converged increment at `lambda` needs (LOCA's state now is the
  /// uninterrupted run's).
  void rememberPoint(double lambda, const IncrementReport& r);
  /// Asks the control after an increment (or a failed attempt); writes and stops as it says.
  void checkpoint(bool converged);

  CheckpointControl* checkpoint_ = nullptr;
  const ResumableStepper* stepper_ = nullptr;
  ContinuationPoint point_;
  Teuchos::RCP<const model::Vector> currentX_, previousX_;
  double previousLambda_ = 0, finalLambda_ = 1;
  int dimension_ = 1;
  bool resuming_ = false;
  model::IncrementalState& state_;
  const continuation::ContactEventSource& events_;
  IncrementObserver& observer_;
  const NewtonCounter& newton_;
  const StepControl& stepControl_;
  continuation::CountedEvents counted_;
  double lastLambda_;
  Clock::time_point start_;
  int loadStep_ = 0;
  int stepFirstIncrement_ = 0, stepFirstFailure_ = 0;  ///< the run's counts when the load step began
  bool reportInitial_ = true;  ///< the initial state is the run's (false: a later load step's start)
  bool first_ = true, pendingSuccess_ = false;
  int attempts_ = 1;
};

}  // namespace contessa::solvers
