#pragma once
// Numbers and text as the one-line messages of the solvers write them.
#include <string>

namespace contessa::solvers {

/// A number for messages: 3 significant digits, exponent when needed ("3.2e-02", "0.5").
std::string shortNumber(double value);
/// A load factor for messages: 6 significant digits ("0.106383").
std::string loadFactorText(double lambda);
/// `text` on one line: line breaks as spaces, no leading or trailing blanks.
std::string oneLine(std::string text);

}  // namespace contessa::solvers
