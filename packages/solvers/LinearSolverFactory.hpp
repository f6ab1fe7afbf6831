#pragma once
// Builds the linear solver from the deck's Piro/Stratimikos list: Stratimikos' own solvers plus the
// ones registered by hand here (MUMPS; the Ifpack2 and MueLu preconditioners for Belos).
#include <Teuchos_ParameterList.hpp>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

#include "model/TpetraTypes.hpp"

namespace contessa::mesh {
class DistributedMesh;
}

namespace contessa::solvers {

/// Throws InputError naming Piro/Stratimikos when Stratimikos rejects the list. An iterative solver
/// (Belos) is tried once on a small matrix first, so that its parameters (Belos', Ifpack2's, MueLu's) are
/// checked before the run (collectively on `comm`, the run's ranks), and it is wrapped by
/// monitorIterativeSolver (iteration counts, failures).
Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> createLinearSolverFactory(
    Teuchos::ParameterList& stratimikos, const Teuchos::RCP<const Teuchos::Comm<int>>& comm);

/// With MueLu as the preconditioner: gives it the rigid-body modes of the owned nodes (reference
/// coordinates from this rank's part of the mesh, about the whole mesh's centroid; RigidBodyModes.hpp)
/// as its near-null space, and the number of DOFs per node (the mesh dimension) as its "number of
/// equations" unless the deck sets it. Nothing for other solvers. Collective.
void provideNearNullSpace(Thyra::LinearOpWithSolveFactoryBase<double>& factory, const model::Map& ownedDofMap,
                          const mesh::DistributedMesh& part);

/// The valid Stratimikos list (with MUMPS and Ifpack2), for the deck reference.
Teuchos::RCP<const Teuchos::ParameterList> stratimikosValidParameters();

}  // namespace contessa::solvers
