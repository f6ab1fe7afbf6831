#pragma once
// The Krylov tolerance of each Newton step: the forcing term η_k of inexact Newton, the solve of
// J δx = −F_k stopping at ‖J δx + F_k‖ ≤ η_k ‖F_k‖ (Eisenstat and Walker 1996, eq. 1.2).
//
// Why not the deck's tolerance alone: the linear residual a step leaves, η ‖F_k‖, is carried into
// F_{k+1} unchanged (F_{k+1} = (J δx + F_k) + O(‖δx‖²)), so a step from ‖F_k‖ = 6·10^9 N at the deck's
// 1e-8 may leave 60 N where Newton asks for 6 N (the 3D punch, bench/README.md, "Issue 23, seventh round").
// Whether the next iterate then passes is luck (the rank count changes where GMRES stops): one rank
// passed, two ranks made a sixth Newton iteration. Under "Forcing Term = Newton Target" (the default) a
// step whose linear residual at the deck's tolerance could exceed a fraction of the Newton target asks
// Belos for that fraction instead, within a bounded tightening; every other step keeps the deck's
// tolerance, so quadratic convergence near the solution stays what it was.
#include <Teuchos_RCP.hpp>

namespace NOX {
class Observer;
}

namespace contessa::solvers {

/// How the Krylov tolerance of a Newton step is chosen (deck: Piro/NOX/Direction/Forcing Term).
enum class ForcingTerm {
  Constant,     ///< the deck's Convergence Tolerance for every solve
  NewtonTarget  ///< tightened where the deck's would leave more than kTargetFraction of the Newton target
};

/// The linear residual a Newton step may leave, as a fraction of the Newton target: a tenth, so that the
/// next iterate's residual is decided by Newton's own (quadratic) remainder, not by where GMRES stopped.
constexpr double kTargetFraction = 0.1;
/// The tightest tolerance asked for, as a factor of the deck's: two decades (1e-10 under the default 1e-8,
/// which GMRES + MueLu reaches on the punch's penalty rows; the cost is bounded at about two decades of
/// Krylov iterations per tightened step).
constexpr double kTightestFactor = 1e-2;

/// η_k for the Newton step from an iterate with residual norm `residualNorm` (‖F_k‖) under Newton target
/// `target` (the residual norm at which the solve converges): the deck's `deckTolerance` unless
/// deckTolerance·‖F_k‖ > kTargetFraction·target; then kTargetFraction·target/‖F_k‖, but not below
/// kTightestFactor·deckTolerance. Never looser than the deck's.
double newtonStepTolerance(double deckTolerance, double residualNorm, double target);

/// The Newton step being solved, as the iterative solver's monitor needs it: kept by the observer of
/// krylovForcingObserver(). A Newton step's right-hand side is F_k itself (NOX's Thyra group solves
/// J δx = F_k and negates), so the monitor gives its norm, global and the same on every rank.
struct KrylovForcing {
  ForcingTerm term = ForcingTerm::Constant;
  double absolute = 0;       ///< the Newton target is max(absolute, relative · ‖F_0‖) ...
  double relative = 0;       ///< ... as in ResidualTest (0 for the single solve's absolute test)
  double initialNorm = 0;    ///< ‖F_0‖ of the current Newton solve
  bool inStep = false;       ///< between the observer's pre- and post-iterate: the next solve is the step's
  bool firstStep = false;    ///< the step from a solve's first iterate (its right-hand side is F_0)
  long tightenedSolves = 0;  ///< solves given a tolerance below the deck's
  long shortfalls = 0;       ///< of them, stopped above the asked tolerance but within the deck's (accepted)

  double target() const;
  /// The tolerance of the solve about to run, whose right-hand side has norm `rhsNorm`: the deck's outside
  /// a Newton step. The step is consumed: a second solve in the same iterate (none today) gets the deck's.
  double takeTolerance(double deckTolerance, double rhsNorm);
};

/// The forcing state of this process (one Newton solver at a time).
KrylovForcing& krylovForcing();

/// A NOX observer that opens krylovForcing()'s step before each Newton step and closes it after. Its settings come from setNoxParameters.
Teuchos::RCP<NOX::Observer> krylovForcingObserver();

}  // namespace contessa::solvers
