#pragma once
// Runs LOCA natural continuation in the load factor λ over the model evaluator, with NOX Newton
// solves. Built by hand (LOCA::Stepper + LOCA::Thyra::Group) rather than through Piro, because
// Piro::LOCASolver in Trilinos 13.2 cannot take a user LOCA factory, and Contessa's step-size
// strategies are registered through one (StepSizeFactory).
#include <memory>
#include <string>

#include <NOX_Observer.hpp>
#include <Teuchos_ParameterList.hpp>

#include "common/StateRecord.hpp"
#include "model/ContactMechanicsModel.hpp"

namespace contessa::solvers {

/// What is known of one increment when it ends.
struct IncrementReport {
  int step = 0;              ///< converged increments so far (0 = the initial state)
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
  long linearIterations = 0;  ///< Krylov iterations of every linear solve (0 with a direct solver)
  double finalLambda = 0;
};

struct ContinuationPoint;

/// A restart file's continuation point: its groups "continuation" and "nodes" (this rank's x_k and
/// x_{k-1}); InputError naming a field that is missing, of another shape or not finite. Its group
/// "step_size" is read when the driver re-creates LOCA's state (`state` must outlive the driver's run()).
std::shared_ptr<const ContinuationPoint> readContinuationPoint(const model::ContactMechanicsModel& model,
                                                               const StateRecord& state);

class ContinuationDriver {
 public:
  /// `piro` is the validated deck list (Piro/NOX, Piro/LOCA); the model and observer must outlive run().
  /// `iterationObserver` (optional) also sees every Newton solve (e.g. JacobianCheckObserver).
  ContinuationDriver(const Teuchos::RCP<model::ContactMechanicsModel>& model, const Teuchos::ParameterList& piro,
                     IncrementObserver& observer, Teuchos::RCP<NOX::Observer> iterationObserver = Teuchos::null);
  /// Writes restart files and stops for them as `control` decides (it must outlive run()).
  void setCheckpointControl(CheckpointControl* control) { checkpoint_ = control; }
  /// Continues from a restart file's continuation point (readContinuationPoint) instead of solving the
  /// initial state. The model's committed state must be restored already
  /// (ContactMechanicsModel::restoreCommittedState).
  void resumeFrom(std::shared_ptr<const ContinuationPoint> point) { resume_ = std::move(point); }
  RunSummary run();

 private:
  CheckpointControl* checkpoint_ = nullptr;
  std::shared_ptr<const ContinuationPoint> resume_;
  Teuchos::RCP<model::ContactMechanicsModel> model_;
  Teuchos::ParameterList piro_;
  IncrementObserver& observer_;
  Teuchos::RCP<NOX::Observer> iterationObserver_;
};

}  // namespace contessa::solvers
