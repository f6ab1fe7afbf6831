#include "solvers/StepSizeFactory.hpp"

#include <LOCA_StepSize_AbstractStrategy.H>

namespace contessa::solvers {

bool StepSizeFactory::createStepSizeStrategy(const std::string& strategyName,
                                             const Teuchos::RCP<LOCA::Parameter::SublistParser>& /*topParams*/,
                                             const Teuchos::RCP<Teuchos::ParameterList>& /*stepsizeParams*/,
                                             Teuchos::RCP<LOCA::StepSize::AbstractStrategy>& strategy) {
  // Names LOCA does not know are offered here first; LOCA's own ("Constant", "Adaptive") fall through.
  for (const auto& method : stepSizeMethodRegistry())
    if (method.name == strategyName && method.create) {
      strategy = method.create(context_);
      return true;
    }
  return false;
}

}  // namespace contessa::solvers
