#pragma once
// Runs LOCA natural continuation in the load factor λ over the model evaluator, with NOX Newton
// solves. Built by hand (LOCA::Stepper + LoadFactorDerivativeGroup, a LOCA::Thyra::Group taking ∂f/∂λ
// from the model) rather than through Piro, because
// Piro::LOCASolver in Trilinos 13.2 cannot take a user LOCA factory, and Contessa's step-size
// strategies are registered through one (StepSizeFactory). The driver knows no step-size method: what
// a method adds (Newton tests, reports, stop words) comes through its StepControl.
// With load steps (Problem/Load Steps) it runs one continuation per step, each in the step's own load
// factor from 0 to 1 with the step's Step Size list, from the previous step's end state.
// Its parts: ContinuationRestart (restart file), IncrementBookkeeper (commit, report, checkpoint),
// NewtonStatusTests with ResidualTest (convergence), NewtonCounter, StepControlRelay, StopMessage.
#include <memory>
#include <string>
#include <vector>

#include <NOX_Observer.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Thyra_VectorBase.hpp>

#include "solvers/ContinuationRestart.hpp"
#include "solvers/ResidualTolerance.hpp"
#include "solvers/RunReports.hpp"
#include "solvers/SolverModel.hpp"

namespace contessa::solvers {

class ContinuationDriver {
 public:
  /// `piro` is the validated deck list (Piro/NOX, Piro/LOCA); the model and observer must outlive run().
  /// `iterationObserver` (optional) also sees every Newton solve (e.g. JacobianCheckObserver).
  ContinuationDriver(const SolverModel& model, const Teuchos::ParameterList& piro, IncrementObserver& observer,
                     Teuchos::RCP<NOX::Observer> iterationObserver = Teuchos::null);
  /// Writes restart files and stops for them as `control` decides (it must outlive run()).
  void setCheckpointControl(CheckpointControl* control) { checkpoint_ = control; }
  /// Continues from a restart file's continuation point (readContinuationPoint) instead of solving the
  /// initial state. The model's committed state must be restored already.
  void resumeFrom(std::shared_ptr<const ContinuationPoint> point) { resume_ = std::move(point); }
  /// Load steps (Problem/Load Steps): each step's validated Step Size list, in order; one continuation
  /// each, in the step's own load factor, through the model's LoadStepping. Without: one continuation
  /// with Piro/LOCA/Step Size.
  void setLoadSteps(std::vector<Teuchos::ParameterList> stepSizes) { stepSizes_ = std::move(stepSizes); }
  RunSummary run();

 private:
  /// What the continuation of one load step starts from and hands on to the next.
  struct StepStart {
    int step = 0;
    const ContinuationPoint* resume = nullptr;        ///< inside the step (LOCA resumes there)
    const ContinuationPoint* afterResume = nullptr;   ///< at the end of the previous step (a fresh start)
    Teuchos::RCP<const Thyra::VectorBase<double>> x;  ///< the previous step's end (null: the nominal x)
    const class IncrementBookkeeper* earlier = nullptr;
  };
  struct StepOutcome;
  /// LOCA natural continuation of one load step with its Step Size list.
  StepOutcome runStep(const StepStart& start, const Teuchos::ParameterList& stepSize, bool lastStep);

  std::vector<Teuchos::ParameterList> stepSizes_;
  CheckpointControl* checkpoint_ = nullptr;
  std::shared_ptr<const ContinuationPoint> resume_;
  SolverModel model_;
  Teuchos::ParameterList piro_;
  IncrementObserver& observer_;
  Teuchos::RCP<NOX::Observer> iterationObserver_;
  ResidualToleranceRecord tolerance_;  ///< the Newton test's force scale over every load step
};

}  // namespace contessa::solvers
