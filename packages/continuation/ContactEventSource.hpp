#pragma once
// What Contact Beta needs of the contact problem: every slave node's change over the current and the last
// converged increment, or at a predicted state, and the switch that keeps new contacts off at the first
// iterate of a checked step. The model implements it (gathered over all interfaces and ranks, so every
// rank sees the same nodes in the same order and computes the same β). No contact types, and of Trilinos
// only the name of a Thyra vector: the step-size strategy depends on this, not on the model's internals.
#include <vector>

#include "continuation/ContactEvents.hpp"

namespace Thyra {
template <class Scalar>
class VectorBase;
}

namespace contessa::continuation {

class ContactEventSource {
 public:
  virtual ~ContactEventSource() = default;
  /// The last commit against the latest trial evaluation (a Newton iterate).
  virtual std::vector<SlaveNodeIncrement> trialIncrement() const = 0;
  /// The last commit against the state (x, λ) (a predicted state): contact evaluated with every node
  /// free to close, no force assembled, no history stored.
  virtual std::vector<SlaveNodeIncrement> trialIncrementAt(const Thyra::VectorBase<double>& x, double loadFactor) const = 0;
  /// The last converged increment: its start against its converged end (what happened in it).
  virtual std::vector<SlaveNodeIncrement> committedIncrement() const = 0;
  /// Contact Beta, Restart mode: while frozen, slave nodes open at the last commit carry no force (their
  /// gaps are still measured), so the first iterate shows where the body goes without new contacts
  /// (eq. 11). Changes what the next evaluation computes.
  virtual void freezeNewContacts(bool frozen) = 0;
  virtual bool newContactsFrozen() const = 0;
};

}  // namespace contessa::continuation
