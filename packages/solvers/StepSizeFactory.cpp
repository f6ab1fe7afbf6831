#include "solvers/StepSizeFactory.hpp"

namespace contessa::solvers {

bool StepSizeFactory::createStepSizeStrategy(const std::string& /*strategyName*/,
                                             const Teuchos::RCP<LOCA::Parameter::SublistParser>& /*topParams*/,
                                             const Teuchos::RCP<Teuchos::ParameterList>& /*stepsizeParams*/,
                                             Teuchos::RCP<LOCA::StepSize::AbstractStrategy>& /*strategy*/) {
  // No strategy of Contessa's own yet: LOCA's "Constant" and "Adaptive" are used as they are.
  return false;
}

}  // namespace contessa::solvers
