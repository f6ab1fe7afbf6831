#include "solvers/StopMessage.hpp"

#include "solvers/MessageText.hpp"

namespace contessa::solvers {

std::string stopMessage(const StopCause& c) {
  const std::string reason =
      c.failure.reason.empty() ? std::string("the continuation rejected the step (no Newton failure)") : c.failure.reason;
  if (!c.initialStateSolved)
    return "the initial state at load factor " + loadFactorText(c.initialLambda) + " could not be solved: " + reason;
  std::string out = "continuation stopped at load factor " + loadFactorText(c.lambda);
  const std::string attempt = "the attempt from load factor " + loadFactorText(c.lambda) + " to " +
                              loadFactorText(c.failedTarget) + " failed: " + reason;
  if (c.maxStepsReached) {
    if (c.lastAttemptFailed) return out + " (Max Steps = " + std::to_string(c.maxSteps) + " used up): " + attempt;
    return out + " (Max Steps = " + std::to_string(c.maxSteps) + " used up while the run was still making progress: " +
           std::to_string(c.increments) + " increments converged); raise Piro/LOCA/Stepper/Max Steps";
  }
  if (!c.methodReason.empty()) return out + " (" + c.methodReason + ")";
  if (c.lastAttemptFailed)
    return out + " (the step cannot be cut below Min Step Size = " + shortNumber(c.minStep) + "): " + attempt;
  std::string loca = oneLine(c.locaErrors);
  if (loca.size() > 300) loca = "..." + loca.substr(loca.size() - 300);
  return out + (loca.empty() ? std::string(" (LOCA gave no reason)") : " (LOCA: " + loca + ")");
}

std::string solverErrorMessage(const NewtonStatusTests& tests, double lambda, const std::string& what) {
  const SolveFailure linear = tests.linearSolverFailure();
  return "continuation stopped at load factor " + loadFactorText(lambda) + ": " +
         (linear.kind != SolveFailure::Kind::None ? linear.reason : "solver error: " + oneLine(what));
}

}  // namespace contessa::solvers
