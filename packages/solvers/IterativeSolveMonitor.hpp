#pragma once
// Watches an iterative linear solver (Belos through Stratimikos) for the run's output and its stop
// message: the Krylov iterations of every solve, and a solve that did not converge.
//
// The wrapped solver is given no solve criteria of its own caller's: NOX would otherwise impose its
// "Linear Solver/Tolerance" (1e-6 by default) over the deck's Belos "Convergence Tolerance". The deck's
// tolerance governs, so what a user writes is what runs, except that a Newton step whose linear residual
// at that tolerance could exceed a tenth of the Newton target is solved to a tighter one (the forcing term
// of KrylovForcing.hpp, Piro/NOX/Direction/Forcing Term); a tightened solve that stops between the two
// tolerances is accepted.
//
// A solve that stops at Maximum Iterations without reaching the tolerance throws (as a failed MUMPS
// factorization does): NOX would otherwise "rescue" the unconverged direction and carry on, and a poor
// direction would show up as a Newton failure many iterations later, far from its cause. The failure
// is kept in the log for the one-line stop message (NewtonStatusTests::linearSolverFailure).
#include <memory>
#include <string>

#include <Thyra_LinearOpWithSolveFactoryBase.hpp>
#include <Thyra_PreconditionerFactoryBase.hpp>

namespace contessa::solvers {

/// Iterative solves so far, the same on every rank (Krylov iteration counts are global).
struct IterativeSolveLog {
  long solves = 0;
  long iterations = 0;      ///< Krylov iterations summed over the solves
  long failures = 0;        ///< solves that did not converge
  std::string lastFailure;  ///< why the latest of them did not, one line
};

/// The log of the iterative solver of this process (one linear solver per run).
IterativeSolveLog& iterativeSolveLog();

/// What an unconverged solve is measured against, for its message.
struct IterativeSolveLimits {
  double tolerance = 0;   ///< Convergence Tolerance (relative residual)
  int maxIterations = 0;  ///< Maximum Iterations
};

/// `inner` (Stratimikos' Belos factory) with every solve recorded in iterativeSolveLog(). `solverName`
/// names it in messages, e.g. "Belos Pseudo Block GMRES with MueLu".
Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> monitorIterativeSolver(
    const Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>>& inner, const std::string& solverName,
    const IterativeSolveLimits& limits);

/// The preconditioner factory that a monitored solver factory's getPreconditionerFactory() wraps (it hands
/// out a timed wrapper, since NOX builds the preconditioner through it); `factory` itself when it is no such
/// wrapper. For settings made on the concrete factory, e.g. MueLu's near-null space.
Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>> unmonitored(
    const Teuchos::RCP<Thyra::PreconditionerFactoryBase<double>>& factory);

}  // namespace contessa::solvers
