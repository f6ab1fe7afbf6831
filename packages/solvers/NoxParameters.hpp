#pragma once
// The NOX list of Contessa's Newton solves, made in one place from the validated deck list Piro/NOX, for
// both drivers: LOCA's stepper (ContinuationDriver) and Piro's single solve (solveStatic). The status
// tests are not in it: each driver hands NOX its NewtonStatusTests.
#include <ostream>

#include <NOX_Observer.hpp>
#include <Teuchos_ParameterList.hpp>

namespace contessa::solvers {

enum class NoxPrinting {
  Solve,         ///< a single solve: errors, warnings, Newton iterations (with Newton Details)
  Continuation,  ///< also LOCA's stepper iterations
};

/// Fills `nox` (the sublist "NOX" of LOCA's or Piro's list): the solver, direction and line search of the
/// deck, `observer` on every solve (after the Krylov forcing term's observer, KrylovForcing.hpp, whose
/// choice and Newton target it sets from the deck's Direction and Status Tests), NOX's errors (and, without Newton Details, its output) into
/// `messages` for the one-line stop message, and exceptions of an evaluation caught (the solve fails,
/// not the run).
void setNoxParameters(Teuchos::ParameterList& nox, const Teuchos::ParameterList& deckNox,
                      const Teuchos::RCP<NOX::Observer>& observer, const Teuchos::RCP<std::ostream>& messages,
                      NoxPrinting printing);

}  // namespace contessa::solvers
