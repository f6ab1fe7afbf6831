#pragma once
// Builds the linear solver from the deck's Piro/Stratimikos list: Stratimikos' own solvers plus the
// ones registered by hand here (MUMPS; the Ifpack2 preconditioners for Belos).
#include <Teuchos_ParameterList.hpp>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

namespace contessa::solvers {

/// Throws InputError naming Piro/Stratimikos when Stratimikos rejects the list.
Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> createLinearSolverFactory(Teuchos::ParameterList& stratimikos);

/// The valid Stratimikos list (with MUMPS and Ifpack2), for the deck reference.
Teuchos::RCP<const Teuchos::ParameterList> stratimikosValidParameters();

}  // namespace contessa::solvers
