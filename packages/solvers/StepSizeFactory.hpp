#pragma once
// Contessa's LOCA factory: LOCA offers every "Step Size/Method" name to it first, so step-size
// strategies that LOCA does not know are registered here by name.
#include <LOCA_Abstract_Factory.H>

#include "continuation/ContactBetaControl.hpp"
#include "continuation/ContactEventSource.hpp"

namespace contessa::solvers {

class StepSizeFactory : public LOCA::Abstract::Factory {
 public:
  /// `events` and `contactBeta` serve the "Contact Beta" strategy; both outlive the run.
  StepSizeFactory(continuation::ContactEventSource& events, continuation::ContactBetaControl& contactBeta)
      : events_(events), contactBeta_(contactBeta) {}
  // LOCA's global data owns this factory: keeping a strong reference back would leak both.
  void init(const Teuchos::RCP<LOCA::GlobalData>& /*globalData*/) override {}
  bool createStepSizeStrategy(const std::string& strategyName,
                              const Teuchos::RCP<LOCA::Parameter::SublistParser>& topParams,
                              const Teuchos::RCP<Teuchos::ParameterList>& stepsizeParams,
                              Teuchos::RCP<LOCA::StepSize::AbstractStrategy>& strategy) override;

 private:
  continuation::ContactEventSource& events_;
  continuation::ContactBetaControl& contactBeta_;
};

}  // namespace contessa::solvers
