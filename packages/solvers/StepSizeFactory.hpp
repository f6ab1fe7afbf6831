#pragma once
// Contessa's LOCA factory: LOCA offers every "Step Size/Method" name to it first; the method's control
// (StepControl.hpp) builds the strategy of a method Contessa adds, LOCA's own fall through to LOCA.
#include <LOCA_Abstract_Factory.H>

#include "solvers/StepControl.hpp"

namespace contessa::solvers {

class StepSizeFactory : public LOCA::Abstract::Factory {
 public:
  /// `control` is the deck's method's (createStepControl); it outlives the run.
  explicit StepSizeFactory(StepControl& control) : control_(control) {}
  // LOCA's global data owns this factory: keeping a strong reference back would leak both.
  void init(const Teuchos::RCP<LOCA::GlobalData>& /*globalData*/) override {}
  bool createStepSizeStrategy(const std::string& strategyName,
                              const Teuchos::RCP<LOCA::Parameter::SublistParser>& topParams,
                              const Teuchos::RCP<Teuchos::ParameterList>& stepsizeParams,
                              Teuchos::RCP<LOCA::StepSize::AbstractStrategy>& strategy) override;

 private:
  StepControl& control_;
};

}  // namespace contessa::solvers
