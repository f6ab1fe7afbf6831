#pragma once
// One static solve at load factor 1 through Piro::NOXSolver ("Piro/Solver Type" = "NOX"), for
// problems that need no continuation; the result is reported as a single increment.
#include <Teuchos_ParameterList.hpp>

#include <NOX_Observer.hpp>

#include "solvers/RunReports.hpp"
#include "solvers/SolverModel.hpp"

namespace contessa::solvers {

/// `piro` is the validated deck list; NOX settings and status tests come from Piro/NOX.
/// `iterationObserver` (optional) also sees the Newton solve (e.g. JacobianCheckObserver).
RunSummary solveStatic(const SolverModel& model, const Teuchos::ParameterList& piro,
                       IncrementObserver& observer, const Teuchos::RCP<NOX::Observer>& iterationObserver = Teuchos::null);

}  // namespace contessa::solvers
