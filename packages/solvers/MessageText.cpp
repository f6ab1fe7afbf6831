#include "solvers/MessageText.hpp"

#include <algorithm>
#include <cstdio>

#include "common/NumberText.hpp"

namespace contessa::solvers {

std::string shortNumber(double value) { return threeDigits(value); }

std::string loadFactorText(double lambda) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", lambda);
  return text;
}

std::string oneLine(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  text.erase(0, text.find_first_not_of(" \t"));
  text.erase(text.find_last_not_of(" \t") + 1);
  return text;
}

}  // namespace contessa::solvers
