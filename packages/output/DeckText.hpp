#pragma once
// The deck as run, as XML text that Contessa reads back: one parameter per line, doubles with the
// fewest digits that round-trip. Written into the results file's information records, so the file
// says which deck (after --set overrides) produced it.
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

namespace contessa::output {

std::vector<std::string> deckText(const Teuchos::ParameterList& deck);

}  // namespace contessa::output
