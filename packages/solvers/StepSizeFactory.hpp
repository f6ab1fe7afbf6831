#pragma once
// Contessa's LOCA factory: LOCA offers every "Step Size/Method" name to it first; the methods of the
// registry (StepSizeMethods.hpp) with a factory of their own are built here, LOCA's fall through to LOCA.
#include <LOCA_Abstract_Factory.H>

#include "solvers/StepSizeMethods.hpp"

namespace contessa::solvers {

class StepSizeFactory : public LOCA::Abstract::Factory {
 public:
  /// `context` serves the strategies (Contact Beta's slave nodes and control); it outlives the run.
  explicit StepSizeFactory(const StepSizeContext& context) : context_(context) {}
  // LOCA's global data owns this factory: keeping a strong reference back would leak both.
  void init(const Teuchos::RCP<LOCA::GlobalData>& /*globalData*/) override {}
  bool createStepSizeStrategy(const std::string& strategyName,
                              const Teuchos::RCP<LOCA::Parameter::SublistParser>& topParams,
                              const Teuchos::RCP<Teuchos::ParameterList>& stepsizeParams,
                              Teuchos::RCP<LOCA::StepSize::AbstractStrategy>& strategy) override;

 private:
  StepSizeContext context_;
};

}  // namespace contessa::solvers
