#pragma once
// What the process sets up for itself before MPI_Init: a fast MPI start when it was not launched by
// mpirun, one OpenBLAS thread per MPI rank, and the phase timers when `--timers` is on the command line.

namespace contessa::app {

/// Call first in main, before MPI_Init (Tpetra::ScopeGuard). Settings the user made in the environment
/// are left alone (docs/user-guide.md, "Performance").
void prepareProcess(int argc, char** argv);

}  // namespace contessa::app
