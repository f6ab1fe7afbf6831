#include "solvers/StepSizeFactory.hpp"

#include <LOCA_StepSize_AbstractStrategy.H>

namespace contessa::solvers {

bool StepSizeFactory::createStepSizeStrategy(const std::string& /*strategyName*/,
                                             const Teuchos::RCP<LOCA::Parameter::SublistParser>& /*topParams*/,
                                             const Teuchos::RCP<Teuchos::ParameterList>& /*stepsizeParams*/,
                                             Teuchos::RCP<LOCA::StepSize::AbstractStrategy>& strategy) {
  // LOCA asks for the deck's method, whose control was built from the same name: a strategy of its own,
  // or none and LOCA's ("Constant", "Adaptive") is built by LOCA.
  auto own = control_.createStrategy();
  if (own.is_null()) return false;
  strategy = own;
  return true;
}

}  // namespace contessa::solvers
