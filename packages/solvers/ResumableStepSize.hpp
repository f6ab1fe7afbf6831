#pragma once
// A step-size strategy whose state a restart file keeps (checkpoint and restart, docs/architecture.md):
// what it learned and decided up to the last converged increment, as named fields (the restart file's
// group "step_size", common/StateRecord.hpp), and putting it back.
// LOCA's own Constant and Adaptive keep only "first step or not", which ContinuationDriver re-creates by
// one call; Contessa's strategies implement this.
#include "common/StateRecord.hpp"

namespace contessa::solvers {

class ResumableStepSize {
 public:
  virtual ~ResumableStepSize() = default;
  virtual void saveState(StateRecord& state) const = 0;
  /// InputError naming a field that is missing, of another shape or not finite.
  virtual void loadState(const StateRecord& state) = 0;
};

}  // namespace contessa::solvers
