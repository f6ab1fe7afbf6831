#pragma once
// What the solve drivers (ContinuationDriver, solveStatic) report to the rest of the program: one
// increment's report and its observer, the checkpoint policy they ask, the run's summary. A light header:
// output and the app include it without the drivers' NOX and LOCA headers (issue 18, point 3).
#include <string>

#include "common/StateRecord.hpp"
#include "model/TpetraTypes.hpp"

namespace contessa::solvers {

/// What is known of one increment when it ends.
struct IncrementReport {
  int step = 0;              ///< converged increments so far (0 = the initial state)
  int loadStep = 0;          ///< the load step (0-based; 0 without Problem/Load Steps); lambda is its own λ_s
  double lambda = 0;         ///< load factor reached
  double dlambda = 0;        ///< increment of the load factor
  double beta = 1;           ///< step correction factor of the step-size strategy (1 = none)
  int attempts = 1;          ///< solves tried for this increment (1 + failed attempts)
  int newtonIterations = 0;  ///< Newton iterations of the converged solve
  long linearIterations = 0; ///< Krylov iterations of its linear solves (0 with a direct solver)
  double residualNorm = 0;   ///< ||f|| at convergence
  double wallSeconds = 0;    ///< since the start of the run
  bool betaRestart = false;  ///< a failed attempt stopped for a Contact Beta correction (not a Newton failure)
  int newEvents = 0;         ///< status changes of the increment that Step Size/Counted Events counts
  std::string failure;       ///< a failed attempt: why, in one line (as in the stop message)
};

class IncrementObserver {
 public:
  virtual ~IncrementObserver() = default;
  /// Called after each converged increment, once the model state is committed.
  virtual void incrementConverged(const model::Vector& x, const IncrementReport& report) = 0;
  /// Called after a failed attempt (the model state has been rolled back).
  virtual void attemptFailed(const IncrementReport& /*report*/) {}
};

/// When the run writes a restart file and whether it stops after it (the app's policy: every N increments,
/// signals, wall time; docs/user-guide.md, "Checkpoint and restart"). Both calls are collective.
class CheckpointControl {
 public:
  struct Decision {
    bool write = false, stop = false;
    std::string reason;  ///< why it stops, for the log
  };
  virtual ~CheckpointControl() = default;
  /// After converged increment `increments` (`converged`), or after a failed attempt that followed it: the
  /// same answer on every rank.
  virtual Decision decide(int increments, bool converged) = 0;
  /// Writes the restart file of the last converged increment: the driver's state (this rank's part:
  /// "continuation" and "step_size" on rank 0, its rows of "nodes") plus the model's committed state
  /// (which is that increment's, also after a failed attempt rolled back).
  virtual void write(StateRecord driverState) = 0;
};

struct RunSummary {
  bool finished = false;  ///< reached the final load factor
  bool checkpointed = false;  ///< stopped after writing a restart file (message: why)
  std::string message;    ///< why not, when not
  int increments = 0, failedAttempts = 0, newtonIterations = 0, linearSolves = 0;
  /// Newton iterations of the whole run, failed attempts included: this job's plus, for a run continued
  /// from a restart file, the earlier jobs' (kept in the file). newtonIterations counts this job only.
  int runNewtonIterations = 0;
  long linearIterations = 0;  ///< Krylov iterations of every linear solve (0 with a direct solver)
  double finalLambda = 0;
  /// The Newton residual test at the last converged state (ResidualTolerance.hpp): its force scale F
  /// (||f_int||) and the absolute bound applied; a loose acceptance, said once ("" when none).
  double forceScale = 0, residualBound = 0;
  std::string toleranceWarning;
  /// What the bound's round-off floor decided, for the log ("" when it never did; ResidualToleranceRecord).
  std::string toleranceFloor;
  /// What the step-size method chose by itself (StepControl::choiceMade), for the log ("" when nothing).
  std::string stepSizeChoice;
};

}  // namespace contessa::solvers
