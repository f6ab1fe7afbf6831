#pragma once
// Numbers in messages and warnings: three significant digits ("1.21e+05", "0.004"), the precision of the
// run's one-line reports.
#include <cstdio>
#include <string>

namespace contessa {

inline std::string threeDigits(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

}  // namespace contessa
