#include "ProcessEnvironment.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <cstring>

#include "common/PhaseTimers.hpp"

namespace contessa::app {
namespace {

bool inEnvironment(const char* name) { return std::getenv(name) != nullptr; }

// Launched by mpirun/mpiexec (Open MPI, or any PMIx/PMI launcher such as srun or MPICH's hydra)?
bool launchedByMpirun() {
  return inEnvironment("OMPI_COMM_WORLD_SIZE") || inEnvironment("PMIX_RANK") || inEnvironment("PMI_RANK");
}

// A process started without mpirun is an Open MPI "singleton": by default MPI_Init then forks an orted
// daemon so that the process could spawn more (MPI_Comm_spawn), which costs about 0.2 s. Contessa never
// spawns, so the singleton runs isolated (MCA parameter ess_singleton_isolated, Open MPI >= 4.0). Under
// mpirun the parameter has no effect, and it is not set there.
void fastSingletonStart() {
  if (!launchedByMpirun()) setenv("OMPI_MCA_ess_singleton_isolated", "1", /*overwrite=*/0);
}

// OpenBLAS (the BLAS MUMPS uses) starts one thread per core by default; with one MPI rank per core
// the threads of the ranks would compete for the same cores, and the fronts of 2D contact problems are
// too small to gain from threads. OpenBLAS reads OPENBLAS_NUM_THREADS when it is loaded, before main,
// so the count is set through its API (found at run time: no link dependency on OpenBLAS), unless the
// user chose one in the environment.
void oneBlasThreadPerRank() {
  if (inEnvironment("OPENBLAS_NUM_THREADS") || inEnvironment("OMP_NUM_THREADS")) return;
  using SetThreads = void (*)(int);
  if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"))) set(1);
}

}  // namespace

void prepareProcess(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--timers") == 0) timers::enable();
  fastSingletonStart();
  oneBlasThreadPerRank();
}

}  // namespace contessa::app
