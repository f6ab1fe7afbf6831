#pragma once
// The one-line reason a continuation stopped: where, why it could not go on, and the real reason of the
// last failed attempt (not only "maximum number of steps").
#include <string>

#include "solvers/NewtonStatusTests.hpp"

namespace contessa::solvers {

// Everything the stop message needs to know about how the continuation ended.
struct StopCause {
  bool initialStateSolved = true;
  double initialLambda = 0, lambda = 0;  ///< where it started, the last converged load factor
  int increments = 0;
  bool maxStepsReached = false;
  int maxSteps = 0;
  double minStep = 0;
  bool lastAttemptFailed = false;
  SolveFailure failure;       ///< why the last attempt failed
  double failedTarget = 0;    ///< the load factor it aimed at
  std::string methodReason;   ///< the step-size method's own reason to stop (StepControl::stopReason), or ""
  std::string locaErrors;
};

std::string stopMessage(const StopCause& cause);

/// LOCA itself threw (outside a Newton solve, e.g. in the tangent predictor): the linear solver's failure
/// when there was one, else the exception's text.
std::string solverErrorMessage(const NewtonStatusTests& tests, double lambda, const std::string& what);

}  // namespace contessa::solvers
