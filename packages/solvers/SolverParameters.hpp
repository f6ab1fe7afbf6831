#pragma once
// The deck's "Piro" part: which parameters Contessa accepts for NOX, LOCA and Stratimikos, with
// docs and defaults (names follow NOX/LOCA/Albany decks, so these lists pass through unchanged).
// Light on headers: only Teuchos, so the deck reference and validation do not pull in the solvers.
#include <set>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "solvers/StepSizeMethods.hpp"  // stepSizeMethods()

namespace contessa::deck {
struct ProblemDefinition;  // deck/ProblemDefinition.hpp: solvers/ headers include no deck header
}

namespace contessa::solvers {

/// Stratimikos' linear solvers and preconditioners that work on Contessa's Tpetra matrices (MUMPS is
/// registered by Contessa; Stratimikos' Epetra solvers are left out), and "Automatic": one of MUMPS and
/// Belos + MueLu chosen by the problem's size and dimension (chooseLinearSolver).
std::vector<std::string> linearSolverTypes();
std::vector<std::string> preconditionerTypes();

/// The valid "Piro" list without the Stratimikos part (Stratimikos validates its own sublist).
Teuchos::RCP<const Teuchos::ParameterList> piroValidParameters();

/// The problem as the automatic linear solver choice sees it: the whole mesh's dimension and unknowns
/// (nodes × dimension, the same on every rank).
struct ProblemSize {
  int dimension = 0;
  long long unknowns = 0;
};

/// The largest problems the automatic choice gives to the direct solver (MUMPS); larger ones get Belos
/// GMRES + MueLu. 3D: decided per Newton iteration (the choice is made before the first Jacobian, so not
/// for one run's reuse of repeated Jacobians), measured on the 3D punch: the two within 6 % from 7.8·10^3
/// to 1.9·10^4 unknowns where Jacobians repeat, Belos + MueLu 1.9× cheaper at 1.5·10^4 where every
/// Jacobian is new (bench/README.md, "Issue 23, seventh round"). 2D: the 2D
/// factor grows as N^1.2 in entries and N^1.66 in operations (the tube refined, bench/README.md), so MUMPS
/// stays the cheaper and the more robust for penalty contact far longer (docs/user-guide.md, "Linear solver").
inline constexpr long long kDirectSolverLimit2D = 500000;
inline constexpr long long kDirectSolverLimit3D = 15000;

/// The linear solver of a run and why: printed once in the log and kept in the run's summary.
struct LinearSolverChoice {
  std::string solver;  ///< "MUMPS", "Belos with MueLu", ... (Linear Solver Type with its preconditioner)
  bool automatic = false;
  std::string reason;
};

/// Where Piro/Stratimikos/Linear Solver Type is absent or "Automatic", sets it (and, for Belos, the
/// Preconditioner Type MueLu unless the deck gives one) from `size`; otherwise leaves the deck's choice.
/// Returns what was chosen and why.
LinearSolverChoice chooseLinearSolver(Teuchos::ParameterList& stratimikos, const ProblemSize& size);

/// Validates the deck's "Piro" list in place (defaults filled in, the linear solver chosen by
/// chooseLinearSolver); `numRanks` rejects solvers that are wrong in parallel in this Trilinos build.
/// Throws InputError naming the deck path.
LinearSolverChoice validatePiro(Teuchos::ParameterList& piro, int numRanks, const ProblemSize& size);

/// Each load step's Step Size list (Problem/Load Steps): the step's own, validated as Piro/LOCA/Step Size
/// (defaults filled in), or the validated `piro`'s; none without load steps. InputError naming the step.
/// Load steps need the continuation (Solver Type LOCA) from Initial Value 0 to Max Value 1.
std::vector<Teuchos::ParameterList> loadStepSizes(const deck::ProblemDefinition& problem,
                                                  const Teuchos::ParameterList& piro);

}  // namespace contessa::solvers
