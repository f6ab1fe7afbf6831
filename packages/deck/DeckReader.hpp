#pragma once
// Reading a deck (XML as a Teuchos::ParameterList, as Albany decks are) and applying the command
// line's --set PATH=VALUE overrides before validation.
#include <set>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "deck/ValueText.hpp"

namespace contessa::deck {

/// The content of the deck file `path`, read once (a named pipe can be read only once). InputError
/// naming the file when it does not exist, is a directory or cannot be read.
std::string readDeckText(const std::string& path);

/// The deck `text` as a ParameterList; `file` names the deck in messages ("FILE:LINE: what"). Refuses
/// malformed XML, elements and attributes a deck does not have, a missing name, type or value, types
/// other than deckTypes(), a parameter or sublist given twice in one list, and values that do not read
/// as their type (numbers must be finite). Each parameter keeps its file and line (declaredAt).
Teuchos::RCP<Teuchos::ParameterList> parseDeck(const std::string& text, const std::string& file);

/// "FILE:LINE" of the <Parameter> an entry of parseDeck's list was read from (kept as the entry's
/// documentation string, which a deck's entries have no other use for); "" for a value that came from
/// elsewhere (--set, a default). Validation names it when the declared type is not the expected one.
std::string declaredAt(const Teuchos::ParameterEntry& entry);

/// parseDeck(readDeckText(path), path).
Teuchos::RCP<Teuchos::ParameterList> readDeck(const std::string& path);

/// Applies overrides "A/B/C=VALUE": an existing parameter keeps its type (VALUE must read as that
/// type; an array is "{a, b}" or "a, b"); a new one is stored as a string and typed by validation
/// (validateAndSetDefaults). Returns the paths that were set. InputError on a malformed override or a
/// path through a parameter that is not a sublist.
std::set<std::string> applyOverrides(Teuchos::ParameterList& deck, const std::vector<std::string>& overrides);

/// Stores `text` into list[name] with the type of `typed` (any deck type, see ValueText.hpp; array
/// braces optional). Returns the outcome: on failure nothing is stored and the message says why the
/// text does not read as that type (e.g. "'inf' is not a finite number").
ParsedValue setTypedFromText(Teuchos::ParameterList& list, const std::string& name, const Teuchos::ParameterEntry& typed,
                             const std::string& text);

}  // namespace contessa::deck
