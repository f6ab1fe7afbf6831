#pragma once
// "Contact Beta": the paper's load-step regulation (section 2.1, Table 1) as a LOCA step-size strategy,
// registered through StepSizeFactory. Two modes:
//  - Restart (Table 1 as written): at the first Newton iteration of an increment the β of eq. (10)–(13)
//    is computed from the slave nodes; if the step must change, the solve is stopped (the status test
//    below reports failure), the contact state is rolled back and the increment restarts once with βΔt.
//  - Predictor: the same β from the slave nodes at the predicted state (LOCA's predictor) before the
//    solve, so the corrected step is taken without a restarted solve.
// The decisions are continuation::ContactBetaControl's; the classes here relay LOCA's and NOX's calls
// to it and give it the slave nodes (continuation::ContactEventSource, implemented by the model).
// ContactBetaStepControl (the method's hooks into the driver) builds both.
#include <LOCA_StepSize_AbstractStrategy.H>
#include <NOX_StatusTest_Generic.H>

#include "continuation/ContactBetaControl.hpp"
#include "continuation/ContactEventSource.hpp"
#include "solvers/ContactBetaStepControl.hpp"
#include "solvers/ResumableStepSize.hpp"

namespace contessa::solvers {

/// Restart mode: fails the Newton solve at its first iteration when β asks for another step. It only
/// tests: the decision is ContactBetaStepControl::iterateSet's, made before the status tests.
class ContactBetaRestartTest : public NOX::StatusTest::Generic {
 public:
  explicit ContactBetaRestartTest(const ContactBetaStepControl& control) : control_(control) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) override;
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& os, int indent) const override;

 private:
  const ContactBetaStepControl& control_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

class ContactBetaStepSize : public LOCA::StepSize::AbstractStrategy, public ResumableStepSize {
 public:
  ContactBetaStepSize(continuation::ContactEventSource& events, continuation::ContactBetaControl& control)
      : events_(events), control_(control) {}

  NOX::Abstract::Group::ReturnType computeStepSize(LOCA::MultiContinuation::AbstractStrategy& curGroup,
                                                   const LOCA::MultiContinuation::ExtendedVector& predictor,
                                                   const NOX::Solver::Generic& solver,
                                                   const LOCA::Abstract::Iterator::StepStatus& stepStatus,
                                                   const LOCA::Abstract::Iterator& stepper, double& stepSize) override;
  double getPrevStepSize() const override { return previous_; }
  double getStartStepSize() const override { return control_.settings().initialStep; }
  /// First step or not, the previous step, and the control's whole state in the child "contact_beta".
  void saveState(StateRecord& state) const override;
  void loadState(const StateRecord& state) override;

 private:
  /// Predictor mode: the slave nodes at x_t + Δλ dx/dλ.
  std::vector<continuation::SlaveNodeIncrement> predictedNodes(LOCA::MultiContinuation::AbstractStrategy& curGroup,
                                                               const LOCA::MultiContinuation::ExtendedVector& predictor,
                                                               double stepSize) const;

  continuation::ContactEventSource& events_;
  continuation::ContactBetaControl& control_;
  double previous_ = 0;
  bool first_ = true;
  template <class Self, class Fields>
  static void stateFields(Self& self, Fields& field) {
    field("first_step", self.first_);
    field("previous_step", self.previous_);
  }
};

}  // namespace contessa::solvers
