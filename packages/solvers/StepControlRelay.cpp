#include "solvers/StepControlRelay.hpp"

#include <stdexcept>

#include <NOX_Solver_LineSearchBased.H>

#include "solvers/LocaResume.hpp"

namespace contessa::solvers {

void StepControlRelay::runPreIterate(const NOX::Solver::Generic&) { control_.startIterate(); }

void StepControlRelay::runPostLineSearch(const NOX::Solver::Generic& solver) {
  // A failed line search (step 0) ends the iteration before its status tests: no iterate to judge.
  const auto* lineSearch = dynamic_cast<const NOX::Solver::LineSearchBased*>(&solver);
  if (lineSearch != nullptr && lineSearch->getStepSize() == 0.0) return;
  control_.iterateSet(
      [this, &solver]() -> NOX::Abstract::Group& {
        if (stepper_ == nullptr) throw std::logic_error("StepControlRelay: no stepper");
        NOX::Abstract::Group& group = stepper_->solverGroup();
        if (&group != &solver.getSolutionGroup())
          throw std::logic_error("StepControlRelay: the Newton solver no longer iterates on LOCA's continuation group");
        return group;
      },
      solver.getNumIterations());
}

}  // namespace contessa::solvers
