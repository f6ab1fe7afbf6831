#pragma once
// Reading a deck (XML as a Teuchos::ParameterList, as Albany decks are) and applying the command
// line's --set PATH=VALUE overrides before validation.
#include <set>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

namespace contessa::deck {

/// Reads an XML deck; InputError naming the file when it is missing or not a valid XML ParameterList.
Teuchos::RCP<Teuchos::ParameterList> readDeck(const std::string& path);

/// Applies overrides "A/B/C=VALUE": an existing parameter keeps its type (VALUE must parse as
/// that type); a new one is stored as a string and typed by validation (validateAndSetDefaults).
/// Returns the paths that were set. InputError on a malformed override or a path through a
/// parameter that is not a sublist.
std::set<std::string> applyOverrides(Teuchos::ParameterList& deck, const std::vector<std::string>& overrides);

/// Stores `text` into list[name] with the type of `typed` (string, double, int, bool); false when
/// the text does not parse as that type.
bool setTypedFromText(Teuchos::ParameterList& list, const std::string& name, const Teuchos::ParameterEntry& typed,
                      const std::string& text);

}  // namespace contessa::deck
