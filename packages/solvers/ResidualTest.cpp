#include "solvers/ResidualTest.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <NOX_Abstract_Group.H>
#include <NOX_Abstract_Vector.H>
#include <NOX_Solver_LineSearchBased.H>

namespace contessa::solvers {

NOX::StatusTest::StatusType ResidualTest::checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) {
  const double norm = solver.getSolutionGroup().getNormF();
  if (solver.getNumIterations() == 0) {
    initial_ = norm;
    updateNorm_ = -1;
  } else {
    auto dx = solver.getSolutionGroup().getX().clone(NOX::DeepCopy);
    dx->update(-1.0, solver.getPreviousSolutionGroup().getX(), 1.0);
    // The Newton direction, not the damped step: a line search that shrinks the step must not
    // pass for convergence.
    const auto* lineSearch = dynamic_cast<const NOX::Solver::LineSearchBased*>(&solver);
    const double step = lineSearch != nullptr ? lineSearch->getStepSize() : 1.0;
    updateNorm_ = step > 0 ? dx->norm() / step : std::numeric_limits<double>::infinity();
    xNorm_ = solver.getSolutionGroup().getX().norm();
  }
  norm_ = norm;
  const bool residualSmall = std::isfinite(norm) && norm <= std::max(absolute_, relative_ * initial_);
  const bool updateSmall = std::isfinite(norm) && updateNorm_ >= 0 && updateNorm_ <= update_ * xNorm_ &&
                           stepControl_.updateMeaningful();
  status_ = (residualSmall || updateSmall) && stepControl_.mayConverge() ? NOX::StatusTest::Converged
                                                                          : NOX::StatusTest::Unconverged;
  return status_;
}

std::ostream& ResidualTest::print(std::ostream& os, int indent) const {
  for (int i = 0; i < indent; ++i) os << ' ';
  os << status_ << "||f|| = " << norm_ << " <= max(" << absolute_ << ", " << relative_ << " * " << initial_
     << ") or ||dx|| = " << updateNorm_ << " <= " << update_ << " * " << xNorm_ << "\n";
  return os;
}

}  // namespace contessa::solvers
