#include "solvers/StepSizeFactory.hpp"

#include "solvers/ContactBetaStepSize.hpp"

namespace contessa::solvers {

bool StepSizeFactory::createStepSizeStrategy(const std::string& strategyName,
                                             const Teuchos::RCP<LOCA::Parameter::SublistParser>& /*topParams*/,
                                             const Teuchos::RCP<Teuchos::ParameterList>& /*stepsizeParams*/,
                                             Teuchos::RCP<LOCA::StepSize::AbstractStrategy>& strategy) {
  // Names LOCA does not know are offered here first; LOCA's own ("Constant", "Adaptive") fall through.
  if (strategyName == "Contact Beta") {
    strategy = Teuchos::rcp(new ContactBetaStepSize(events_, contactBeta_));
    return true;
  }
  return false;
}

}  // namespace contessa::solvers
