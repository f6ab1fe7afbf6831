#pragma once
// What Contact Beta needs to know of the contact problem: every slave node's change over the current
// and the last converged increment. The model implements it (gathered over all interfaces and ranks, so
// every rank sees the same nodes in the same order and computes the same β). No Trilinos, no contact
// types: the step-size strategy depends on this, not on the model's internals.
#include <vector>

#include "continuation/ContactEvents.hpp"

namespace contessa::continuation {

class ContactEventSource {
 public:
  virtual ~ContactEventSource() = default;
  /// The last commit against the latest trial evaluation (a Newton iterate).
  virtual std::vector<SlaveNodeIncrement> trialIncrement() const = 0;
  /// The last converged increment: its start against its converged end (what happened in it).
  virtual std::vector<SlaveNodeIncrement> committedIncrement() const = 0;
};

}  // namespace contessa::continuation
