#pragma once
// The deck's "Piro" part: which parameters Contessa accepts for NOX, LOCA and Stratimikos, with
// docs and defaults (names follow NOX/LOCA/Albany decks, so these lists pass through unchanged).
// Light on headers: only Teuchos, so the deck reference and validation do not pull in the solvers.
#include <set>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "deck/ProblemDefinition.hpp"

#include "solvers/StepSizeMethods.hpp"  // stepSizeMethods()

namespace contessa::solvers {

/// Stratimikos' linear solvers and preconditioners that work on Contessa's Tpetra matrices (MUMPS is
/// registered by Contessa; Stratimikos' Epetra solvers are left out).
std::vector<std::string> linearSolverTypes();
std::vector<std::string> preconditionerTypes();

/// The valid "Piro" list without the Stratimikos part (Stratimikos validates its own sublist).
Teuchos::RCP<const Teuchos::ParameterList> piroValidParameters();

/// Validates the deck's "Piro" list in place (defaults filled in); `numRanks` rejects solvers that
/// are wrong in parallel in this Trilinos build. Throws InputError naming the deck path.
void validatePiro(Teuchos::ParameterList& piro, int numRanks);

/// Each load step's Step Size list (Problem/Load Steps): the step's own, validated as Piro/LOCA/Step Size
/// (defaults filled in), or the validated `piro`'s; none without load steps. InputError naming the step.
/// Load steps need the continuation (Solver Type LOCA) from Initial Value 0 to Max Value 1.
std::vector<Teuchos::ParameterList> loadStepSizes(const deck::ProblemDefinition& problem,
                                                  const Teuchos::ParameterList& piro);

}  // namespace contessa::solvers
