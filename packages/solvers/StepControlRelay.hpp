#pragma once
// Relays the Newton solver's iterations to the step-size method's hooks (StepControl): an iteration
// starts; the iterate is set and its status tests come next. The second hook gets the group the solver
// iterates on from LOCA's stepper (ResumableStepper::solverGroup), the only writable handle on it: NOX
// hands its observers and status tests a const solver.
#include <NOX_Observer.hpp>

#include "solvers/StepControl.hpp"

namespace contessa::solvers {

class ResumableStepper;

class StepControlRelay : public NOX::Observer {
 public:
  explicit StepControlRelay(StepControl& control) : control_(control) {}
  /// The stepper whose solver is observed (set once it exists; it outlives the solves).
  void setStepper(ResumableStepper* stepper) { stepper_ = stepper; }
  void runPreIterate(const NOX::Solver::Generic& solver) override;
  /// NOX 13.2's LineSearchBased::step calls it after the line search has set x, before it computes f at x
  /// and checks the status tests.
  void runPostLineSearch(const NOX::Solver::Generic& solver) override;

 private:
  StepControl& control_;
  ResumableStepper* stepper_ = nullptr;
};

}  // namespace contessa::solvers
