#pragma once
// The text of a deck value ("2.0", "true", "{0.0, -75.2}") read as one of the deck's types. One reader
// serves the XML deck and --set, so both accept the same spellings and refuse the same mistakes: a
// number is decimal and finite (no inf, nan, hexadecimal or overflow: a Dirichlet value of inf must
// never reach the solver), an int fits in 32 bits, a bool is true or false, an array is {a, b, ...}.
#include <string>
#include <vector>

#include <Teuchos_ParameterEntry.hpp>

namespace contessa::deck {

/// The type attributes a deck may use: string, double, int, bool, Array(string), Array(double), Array(int).
const std::vector<std::string>& deckTypes();

/// The deck type of an entry ("double", "Array(int)", ...); empty for any other type.
std::string deckTypeOf(const Teuchos::ParameterEntry& entry);

/// Why a text is not a value of the type asked for.
enum class ValueProblem {
  None,       ///< the text is a value of the type
  Malformed,  ///< not a number, not a bool, not an array {...}: the text is of another type
  NotFinite,  ///< inf, nan or a number too large for a double
  OutOfRange  ///< an int that does not fit in 32 bits
};

struct ParsedValue {
  ValueProblem problem = ValueProblem::None;
  std::string message;  ///< one line, e.g. "'inf' is not a finite number"; empty when problem is None
  Teuchos::ParameterEntry entry;
};

/// Reads `text` as a value of deck type `type` (one of deckTypes()). An array is "{a, b, ...}"; with
/// `bracesOptional` (the command line) "a, b, ..." is read as the same array.
ParsedValue parseValue(const std::string& type, const std::string& text, bool bracesOptional = false);

}  // namespace contessa::deck
