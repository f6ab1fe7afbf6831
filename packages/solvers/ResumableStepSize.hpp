#pragma once
// A step-size strategy whose state a restart file keeps (checkpoint and restart, docs/architecture.md):
// what it learned and decided up to the last converged increment, as numbers, and putting it back.
// LOCA's own Constant and Adaptive keep only "first step or not", which ContinuationDriver re-creates by
// one call; Contessa's strategies implement this.
#include <vector>

namespace contessa::solvers {

class ResumableStepSize {
 public:
  virtual ~ResumableStepSize() = default;
  virtual std::vector<double> saveState() const = 0;
  /// Throws std::invalid_argument for a state of another size.
  virtual void restoreState(const std::vector<double>& state) = 0;
};

}  // namespace contessa::solvers
