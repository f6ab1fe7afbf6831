#pragma once
// "Contact Beta": the paper's load-step regulation (section 2.1, Table 1) as a LOCA step-size strategy,
// registered through StepSizeFactory. Two modes:
//  - Restart (Table 1 as written): at the first Newton iteration of an increment the β of eq. (10)–(13)
//    is computed from the slave gaps; if the step must change, the solve is stopped (the status test
//    below reports failure), the contact state is rolled back and the increment restarts once with βΔt.
//  - Predictor: the same β from the gaps at the predicted state (LOCA's predictor) before the solve,
//    so the corrected step is taken without a restarted solve.
// Both also cut back on a failed Newton solve, and both grow the step (up to the cap) when fewer than
// N_c nodes are about to close.
#include <LOCA_StepSize_AbstractStrategy.H>
#include <NOX_StatusTest_Generic.H>

#include "continuation/ContactBeta.hpp"
#include "model/ContactMechanicsModel.hpp"

namespace contessa::solvers {

/// State shared by the step-size strategy and the Newton status test of one run.
struct ContactBetaState {
  enum class Mode { Restart, Predictor };
  Mode mode = Mode::Restart;
  continuation::BetaOptions options;
  double restartTolerance = 0.1;  ///< Restart: no restart when |β − 1| ≤ this
  bool checkThisAttempt = false;  ///< Restart: the first iteration of this attempt is checked (I_cor = 0)
  bool restartRequested = false;  ///< Restart: the attempt was stopped for a β correction
  double stepSize = 0, minStep = 0, maxStep = 0;  ///< the attempt's Δλ and its bounds
  double finalLoadFactor = 1;                      ///< the Stepper's Max Value
  double startLoadFactor = 0;                      ///< λ at the start of the attempt
  bool hitMinimumStep = false;                     ///< the strategy stopped the run at Min Step Size
  double carriedBeta = 1;         ///< Restart: β measured but not applied (within tolerance) — used for the next base step
  bool afterFailure = false;      ///< the attempt follows a failed Newton solve: β may not grow it back
  bool justUnfrozen = false;      ///< new contacts were switched on at this iterate: its update proves nothing
  double beta = 1;                ///< β of the current increment (1 = no correction), for the history
  int predictedContacts = 0;
};

/// Restart mode: fails the Newton solve at its first iteration when β asks for another step.
class ContactBetaRestartTest : public NOX::StatusTest::Generic {
 public:
  ContactBetaRestartTest(const model::ContactMechanicsModel& model, ContactBetaState& state)
      : model_(model), state_(state) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) override;
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& os, int indent) const override;

 private:
  const model::ContactMechanicsModel& model_;
  ContactBetaState& state_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

class ContactBetaStepSize : public LOCA::StepSize::AbstractStrategy {
 public:
  ContactBetaStepSize(const Teuchos::ParameterList& stepSizeParams, const model::ContactMechanicsModel& model,
                      ContactBetaState& state);

  NOX::Abstract::Group::ReturnType computeStepSize(LOCA::MultiContinuation::AbstractStrategy& curGroup,
                                                   const LOCA::MultiContinuation::ExtendedVector& predictor,
                                                   const NOX::Solver::Generic& solver,
                                                   const LOCA::Abstract::Iterator::StepStatus& stepStatus,
                                                   const LOCA::Abstract::Iterator& stepper, double& stepSize) override;
  double getPrevStepSize() const override { return previous_; }
  double getStartStepSize() const override { return initial_; }

 private:
  /// Predictor mode: β from the gaps at x_t + Δλ dx/dλ.
  double predictedBeta(LOCA::MultiContinuation::AbstractStrategy& curGroup,
                       const LOCA::MultiContinuation::ExtendedVector& predictor, double stepSize);

  const model::ContactMechanicsModel& model_;
  ContactBetaState& state_;
  double initial_, min_, max_, failedFactor_;
  double previous_ = 0;
  bool first_ = true;
};

/// The β of the current attempt's gaps, never growing the step right after a failed solve, and
/// within the step bounds (β·Δλ in [min, max]).
continuation::BetaResult currentBeta(const ContactBetaState& state, const std::vector<contact::SlaveGapChange>& gaps);

/// The deck's "Contact Beta" parameters (Piro/LOCA/Step Size) as the shared state's options.
ContactBetaState contactBetaState(const Teuchos::ParameterList& stepSizeParams);

}  // namespace contessa::solvers
