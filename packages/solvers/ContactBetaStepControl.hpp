#pragma once
// Contact Beta's hooks into the continuation (StepControl): the paper's load-step regulation (section
// 2.1, Table 1) through continuation::ContactBetaControl, which makes every decision. It builds the LOCA
// strategy (ContactBetaStepSize), adds the Restart mode's first-iterate test, switches new contacts on
// when the first iterate's step stands (the model's state changes here, before the status tests, which
// only test), vetoes convergence while new contacts are frozen and at a converged state with other than
// N_c events, and gives β, its restarts and its stop reason to the reports. It declares and reads its
// deck parameters (Piro/LOCA/Step Size), each once with its default.
#include <memory>

#include "continuation/ContactBetaControl.hpp"
#include "solvers/StepControl.hpp"

namespace contessa::solvers {

class ContactBetaStepControl : public StepControl {
 public:
  explicit ContactBetaStepControl(const StepControlContext& context);

  /// Contact Beta's parameters of the Step Size list, with docs and the defaults of ContactBetaSettings.
  static void addParameters(Teuchos::ParameterList& stepSize);
  /// Counted Events of a validated Step Size list (every method's history counts them: StepSizeMethods).
  static continuation::CountedEvents countedEvents(const Teuchos::ParameterList& stepSize);
  /// The settings from the validated Step Size list and the stepper's Max Value.
  static continuation::ContactBetaSettings settings(const Teuchos::ParameterList& stepSize, double finalLoadFactor);

  Teuchos::RCP<LOCA::StepSize::AbstractStrategy> createStrategy() override;
  Teuchos::RCP<NOX::StatusTest::Generic> correctionTest() override;
  void startIterate() override;
  void iterateSet(const std::function<NOX::Abstract::Group&()>& iterate, int iteration) override;
  bool mayConverge() const override;
  bool updateMeaningful() const override { return !control_.newContactsJustReleased(); }
  std::string redoAtConvergence() override;
  std::string correctionName() const override { return "a Contact Beta step correction"; }
  double correctionFactor() const override { return control_.beta(); }
  bool correctionRequested() const override { return control_.restartRequested(); }
  std::string stopReason() const override;
  std::string choiceMade() const override;

  /// Restart mode: the current iterate is the first of a checked attempt and β asked for another step.
  bool firstIterateRejected() const { return firstIterateRejected_; }
  const continuation::ContactBetaControl& control() const { return control_; }

 private:
  continuation::ContactEventSource& events_;
  continuation::ContactBetaControl control_;
  bool firstIterateRejected_ = false;
};

}  // namespace contessa::solvers
