#pragma once
// Newton statistics of the current solve, read when an increment ends, and why the solve failed when it
// did (NewtonStatusTests::diagnose). NOX also calls runPostIterate when the initial guess already
// converges, so iterations are read from the solver. runPostSolve runs on every rank after every solve,
// so the diagnosis may communicate. Both drivers use it (ContinuationDriver, solveStatic).
#include <cstddef>
#include <sstream>

#include <NOX_Observer.hpp>

#include "solvers/NewtonStatusTests.hpp"

namespace contessa::solvers {

class NewtonCounter : public NOX::Observer {
 public:
  /// `noxOutput`: where NOX prints (an exception it caught is read from it); both outlive the counter.
  NewtonCounter(NewtonStatusTests& tests, const std::ostringstream& noxOutput) : tests_(tests), noxOutput_(noxOutput) {}
  void runPreSolve(const NOX::Solver::Generic& solver) override;
  void runPostSolve(const NOX::Solver::Generic& solver) override;

  int iterations = 0, total = 0;
  long linearIterations = 0;  ///< Krylov iterations of the latest solve's Newton directions
  double residualNorm = 0;
  SolveFailure failure;  ///< of the latest solve (kind None when it converged)

 private:
  long linearIterationsAtStart_ = 0;
  NewtonStatusTests& tests_;
  const std::ostringstream& noxOutput_;
  std::size_t outputAtStart_ = 0;
};

}  // namespace contessa::solvers
