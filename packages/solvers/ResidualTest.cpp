#include "solvers/ResidualTest.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <NOX_Abstract_Group.H>
#include <NOX_Abstract_Vector.H>
#include <NOX_Solver_LineSearchBased.H>

#include "solvers/KrylovForcing.hpp"

namespace contessa::solvers {

NOX::StatusTest::StatusType ResidualTest::checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) {
  const double norm = solver.getSolutionGroup().getNormF();
  if (solver.getNumIterations() == 0) {
    initial_ = norm;
    updateNorm_ = -1;
  } else if (update_ > 0) {
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
  // F of the iterate just evaluated (the model's latest pass is at the solver's x: NOX computes f before
  // it checks). The force-scaled bound is a force: it bounds the out-of-balance force, f without its
  // prescribed rows (x − ū, whose round-off is a length); the deck's absolute tolerance bounds ||f|| as
  // it always has.
  forceScale_ = forces_ != nullptr ? forces_->forceScale() : 0.0;
  // Under the force-scaled bound, not below the round-off of the out-of-balance force itself (at most
  // kLooseFraction · F; ResidualTolerance.hpp): displacements near the positions' round-off leave rounding
  // far above 1e-10 F, and a Newton step from it would only move an exact answer.
  floor_ = forces_ != nullptr ? bound_.floorAt(forceScale_, forces_->forceRoundOff()) : 0.0;
  absolute_ = std::max(bound_.boundAt(forceScale_), floor_);
  const double judged = bound_.isForceScaled() && forces_ != nullptr && std::isfinite(norm) ? forces_->outOfBalanceNorm() : norm;
  judged_ = judged;
  // The Krylov forcing term aims at the same target (KrylovForcing.hpp), set before the step's solve.
  krylovForcing().absolute = absolute_;
  const double relativeBound = relative_ > 0 ? relative_ * initial_ : 0.0;
  const bool residualSmall = std::isfinite(norm) && (judged <= absolute_ || norm <= relativeBound);
  // The update test's bound is relative to ||x|| (the displacements); near λ = 0 they are tiny and the update
  // can stall at the round-off of the positions X + u instead (a penalty contact's gaps are differences of
  // positions): an update below kPositionRoundOff of the largest |X| is converged too (roller_on_axle's first
  // attempt: ||dx|| 4e-15 at positions of 50 mm, ||f|| stalled at 2e-10 under a force-scaled bound of 1e-12).
  // Only under the force-scaled bound: a deck's absolute tolerance and its update test decide as they always have.
  const double positionFloor =
      bound_.isForceScaled() && forces_ != nullptr ? kPositionRoundOff * forces_->lengthScale() : 0.0;
  const bool updateSmall = std::isfinite(norm) && update_ > 0 && updateNorm_ >= 0 &&
                           updateNorm_ <= std::max(update_ * xNorm_, positionFloor) &&
                           (stepControl_ == nullptr || stepControl_->updateMeaningful());
  const bool mayConverge = stepControl_ == nullptr || stepControl_->mayConverge();
  status_ = (residualSmall || updateSmall) && mayConverge ? NOX::StatusTest::Converged : NOX::StatusTest::Unconverged;
  if (status_ == NOX::StatusTest::Converged && record_ != nullptr && std::isfinite(forceScale_))
    record_->accepted(bound_, forceScale_, judged, absolute_, residualSmall && norm > relativeBound,
                      judged > bound_.boundAt(forceScale_));
  return status_;
}

std::ostream& ResidualTest::print(std::ostream& os, int indent) const {
  for (int i = 0; i < indent; ++i) os << ' ';
  os << status_;
  if (bound_.isForceScaled())
    os << "||f_free|| = " << judged_ << " <= " << absolute_ << " = max(" << bound_.boundAt(1.0) << " * F, round-off floor "
       << floor_ << ") (F = " << forceScale_ << ") or ||f|| = " << norm_ << " <= " << relative_ << " * " << initial_;
  else
    os << "||f|| = " << norm_ << " <= max(" << absolute_ << ", " << relative_ << " * " << initial_ << ")";
  if (update_ > 0) os << " or ||dx|| = " << updateNorm_ << " <= " << update_ << " * " << xNorm_;
  os << "\n";
  return os;
}

}  // namespace contessa::solvers
