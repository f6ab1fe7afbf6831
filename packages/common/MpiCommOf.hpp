#pragma once
// The MPI communicator under a Teuchos one (MPI_COMM_SELF under a serial one), for the MPI C calls of
// common/ (RankAgreement) from code that holds a Teuchos::Comm.
#include <Teuchos_DefaultMpiComm.hpp>

namespace contessa {

inline MPI_Comm mpiCommOf(const Teuchos::Comm<int>& comm) {
  const auto* mpi = dynamic_cast<const Teuchos::MpiComm<int>*>(&comm);
  return mpi != nullptr ? (*mpi->getRawMpiComm())() : MPI_COMM_SELF;
}

}  // namespace contessa
