#include "common/ParameterPublishing.hpp"

#include <cmath>

#include <Teuchos_StandardParameterEntryValidators.hpp>

namespace contessa {

void setPositive(Teuchos::ParameterList& list, const std::string& name, double value, const std::string& doc) {
  auto v = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>());
  v->setMin(std::nextafter(0.0, 1.0));
  list.set(name, value, doc + " (> 0)", v);
}

void setPositiveInt(Teuchos::ParameterList& list, const std::string& name, int value, const std::string& doc) {
  auto v = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>());
  v->setMin(1);
  list.set(name, value, doc + " (>= 1)", v);
}

void setChoice(Teuchos::ParameterList& list, const std::string& name, const std::string& value,
               const std::vector<std::string>& choices, const std::string& doc) {
  std::string names;
  for (const auto& c : choices) names += (names.empty() ? "" : ", ") + c;
  auto v = Teuchos::rcp(new Teuchos::StringValidator(Teuchos::Array<std::string>(choices.begin(), choices.end())));
  list.set(name, value, doc + " (one of: " + names + ")", v);
}

}  // namespace contessa
