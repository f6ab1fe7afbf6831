#include "solvers/NewtonCounter.hpp"

#include <NOX_Abstract_Group.H>
#include <NOX_Solver_Generic.H>

#include "solvers/IterativeSolveMonitor.hpp"

namespace contessa::solvers {

void NewtonCounter::runPreSolve(const NOX::Solver::Generic&) {
  iterations = 0;
  linearIterationsAtStart_ = iterativeSolveLog().iterations;
  tests_.startSolve();
  outputAtStart_ = noxOutput_.str().size();
}

void NewtonCounter::runPostSolve(const NOX::Solver::Generic& solver) {
  iterations = solver.getNumIterations();
  linearIterations = iterativeSolveLog().iterations - linearIterationsAtStart_;
  total += iterations;
  residualNorm = solver.getSolutionGroup().getNormF();
  failure = tests_.diagnose(solver, noxOutput_.str().substr(outputAtStart_));
}

}  // namespace contessa::solvers
