#pragma once
// Checkpoint and restart of the continuation (docs/architecture.md, "Checkpoint and restart"): the
// continuation point of a converged increment k as the restart file keeps it (its groups "continuation",
// "step_size" and "nodes"), read back, and handed to LOCA's stepper (LocaResume.hpp) so that increment
// k + 1 is taken exactly as in the uninterrupted run.
#include <memory>

#include <Teuchos_RCP.hpp>

#include "common/StateRecord.hpp"
#include "model/TpetraTypes.hpp"

namespace contessa::solvers {

struct LocaResumePoint;

// The continuation at a converged increment k: what LOCA's stepper, its predictor and its step-size
// strategy need to take increment k + 1 exactly as the uninterrupted run does.
struct ContinuationPoint {
  int increments = 0, failedAttempts = 0;  ///< converged increments (k) and failed attempts so far
  int loadStep = 0;                        ///< the load step of increment k (0-based; 0 without steps)
  /// Of those, the load step's own (LOCA's stepper counts them, each load step from 0).
  int stepIncrements = 0, stepFailedAttempts = 0;
  int newtonIterations = 0;                ///< of increment k's solve (what the step-size strategy reads)
  int runNewtonIterations = 0;             ///< of the whole run up to increment k, failed attempts included
  double lambda = 0, previousLambda = 0;   ///< λ_k, λ_{k-1}
  double stepSize = 0;                     ///< LOCA's step size of increment k (after its capping)
  double wallSeconds = 0;                  ///< wall time of the run (all its parts) at increment k
  StateRecord stepSizeState;               ///< a ResumableStepSize's state (empty for LOCA's own)
  const StateRecord* resumedStepSizeState = nullptr;  ///< the restart file's, read when LOCA's state is made
  Teuchos::RCP<const model::Vector> x, previousX;     ///< x_k, x_{k-1}

  /// The restart file's group "continuation" (common/StateRecord.hpp).
  template <class Self, class Fields>
  static void stateFields(Self& self, Fields& field) {
    field("increments", self.increments);
    field("failed_attempts", self.failedAttempts);
    field("load_step", self.loadStep);
    field("load_step_increments", self.stepIncrements);
    field("load_step_failed_attempts", self.stepFailedAttempts);
    field("newton_iterations", self.newtonIterations);
    field("run_newton_iterations", self.runNewtonIterations);
    field("lambda", self.lambda);
    field("previous_lambda", self.previousLambda);
    field("step_size", self.stepSize);
    field("wall_seconds", self.wallSeconds);
  }
};

/// A restart file's continuation point: its groups "continuation" and "nodes" (this rank's x_k and
/// x_{k-1} on `ownedDofMap`, `dimension` components per node); InputError naming a field that is
/// missing, of another shape or not finite. Its group "step_size" is read when the driver re-creates
/// LOCA's state (`state` must outlive the driver's run()).
std::shared_ptr<const ContinuationPoint> readContinuationPoint(const Teuchos::RCP<const model::Map>& ownedDofMap,
                                                               int dimension, const StateRecord& state);

/// The driver's part of a restart file at `point`: "continuation" and "step_size" on rank 0, this rank's
/// rows of "nodes" (any rank count reads them).
StateRecord continuationState(const ContinuationPoint& point, int dimension);

/// What LOCA's stepper needs to continue from `point` (which must outlive the stepper's run()).
LocaResumePoint locaResumePoint(const ContinuationPoint& point, bool secantPredictor);

}  // namespace contessa::solvers
