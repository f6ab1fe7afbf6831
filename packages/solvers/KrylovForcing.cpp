#include "solvers/KrylovForcing.hpp"

#include <algorithm>
#include <cmath>

#include <NOX_Observer.hpp>
#include <NOX_Solver_Generic.H>

namespace contessa::solvers {

double newtonStepTolerance(double deckTolerance, double residualNorm, double target) {
  if (!(residualNorm > 0) || !std::isfinite(residualNorm) || !(target > 0)) return deckTolerance;
  const double allowed = kTargetFraction * target;  // the linear residual the step may leave
  if (deckTolerance * residualNorm <= allowed) return deckTolerance;
  return std::max(allowed / residualNorm, kTightestFactor * deckTolerance);
}

double KrylovForcing::target() const { return std::max(absolute, relative * initialNorm); }

double KrylovForcing::takeTolerance(double deckTolerance, double rhsNorm) {
  if (term == ForcingTerm::Constant || !inStep) return deckTolerance;
  if (firstStep) initialNorm = rhsNorm;
  inStep = firstStep = false;
  return newtonStepTolerance(deckTolerance, rhsNorm, target());
}

KrylovForcing& krylovForcing() {
  static KrylovForcing forcing;
  return forcing;
}

namespace {

// NOX calls runPreIterate before the Newton step's direction, i.e. before its linear solve (at the first
// iterate possibly before f is computed, hence the norm taken from the solve's right-hand side).
class KrylovForcingObserver : public NOX::Observer {
 public:
  void runPreIterate(const NOX::Solver::Generic& solver) override {
    auto& forcing = krylovForcing();
    forcing.inStep = true;
    // ResidualTest's ‖f‖ at the first iterate (kept over the augmented Lagrangian's updates, as there).
    forcing.firstStep = solver.getNumIterations() == 0;
  }
  void runPostIterate(const NOX::Solver::Generic&) override { krylovForcing().inStep = false; }
  void runPostSolve(const NOX::Solver::Generic&) override { krylovForcing().inStep = false; }
};

}  // namespace

Teuchos::RCP<NOX::Observer> krylovForcingObserver() { return Teuchos::rcp(new KrylovForcingObserver); }

}  // namespace contessa::solvers
