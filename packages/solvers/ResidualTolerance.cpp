#include "solvers/ResidualTolerance.hpp"

#include <algorithm>
#include <cstdio>

namespace contessa::solvers {
namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

}  // namespace

ResidualTolerance ResidualTolerance::fromDeck(const Teuchos::ParameterList& statusTests) {
  if (statusTests.isType<double>("Absolute Residual Tolerance"))
    return absolute(statusTests.get<double>("Absolute Residual Tolerance"));
  const char* factor = "Force-Scaled Residual Tolerance";
  return forceScaled(statusTests.isType<double>(factor) ? statusTests.get<double>(factor) : kDefaultFactor);
}

std::string ResidualTolerance::describe() const {
  if (scaled_)
    return "||f|| <= " + number(value_) +
           " * F, F = ||f_int|| of the state (external loads, contact forces and reactions; Piro/NOX/Status "
           "Tests/Force-Scaled Residual Tolerance)";
  return "||f|| <= " + number(value_) + " in the deck's force unit (Piro/NOX/Status Tests/Absolute Residual Tolerance)";
}

void ResidualToleranceRecord::accepted(const ResidualTolerance& rule, double forceScale, double norm, double bound,
                                       bool byAbsolute, bool byFloor) {
  lastForceScale = forceScale;
  lastBound = bound;
  largestForceScale = std::max(largestForceScale, forceScale);
  if (byFloor && byAbsolute) {
    if (floorAcceptances++ == 0)
      floorNote = "||f_free|| = " + number(norm) + " <= " + number(bound) + " = " + number(bound / forceScale) +
                  " F (F = " + number(forceScale) + "), above " + number(rule.boundAt(1.0)) + " F";
  }
  if (!warning.empty() || !byAbsolute || !(forceScale > 0) || !rule.looseAt(forceScale) ||
      !(norm > ResidualTolerance::kLooseFraction * forceScale))
    return;
  warning = "an increment was accepted with ||f|| = " + number(norm) + ", " + number(norm / forceScale) +
            " of its force scale F = " + number(forceScale) + " (||f_int||), under the absolute bound " + number(bound) +
            ": the answer may be far from converged; leave Piro/NOX/Status Tests/Absolute Residual Tolerance out "
            "(the force-scaled test) or set it below " + number(ResidualTolerance::kLooseFraction * forceScale);
}

std::string ResidualToleranceRecord::floorSummary() const {
  if (floorAcceptances == 0) return "";
  return "the internal force's round-off floor decided " + std::to_string(floorAcceptances) +
         " Newton solve(s) (first: " + floorNote +
         "): displacements this small against the coordinates leave rounding above the force-scaled bound, and "
         "a Newton step from that noise would only move the answer";
}

}  // namespace contessa::solvers
