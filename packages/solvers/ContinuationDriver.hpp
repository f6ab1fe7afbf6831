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
#include "solvers/RunReports.hpp"

namespace contessa::solvers {

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
