#pragma once
// Publishing a parameter with its documented range (docs/style.md 5): the validator enforces the range
// (the deck's validateAndSetDefaults reports a violation with the parameter's path) and the doc string
// states it for the deck reference. In common/ so that packages below the deck (mesh) publish theirs
// the same way as the deck does.
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

namespace contessa {

void setPositive(Teuchos::ParameterList& list, const std::string& name, double value, const std::string& doc);
void setPositiveInt(Teuchos::ParameterList& list, const std::string& name, int value, const std::string& doc);
void setChoice(Teuchos::ParameterList& list, const std::string& name, const std::string& value,
               const std::vector<std::string>& choices, const std::string& doc);

}  // namespace contessa
