#include "ProcessEnvironment.hpp"

#include <dlfcn.h>
#include <malloc.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>

#include "common/PhaseTimers.hpp"

namespace contessa::app {
namespace {

bool inEnvironment(const char* name) { return std::getenv(name) != nullptr; }

// Launched by mpirun/mpiexec (Open MPI, or any PMIx/PMI launcher such as srun or MPICH's hydra)?
bool launchedByMpirun() {
  return inEnvironment("OMPI_COMM_WORLD_SIZE") || inEnvironment("PMIX_RANK") || inEnvironment("PMI_RANK");
}

// A process started without mpirun is an Open MPI "singleton", which MPI_Init makes slow in two ways
// (Open MPI 4.1, measured on a bare MPI_Init: 0.38 s, 0.04 s with both settings):
// - it forks an orted daemon so that the process could spawn more (MPI_Comm_spawn): 0.13 s. Contessa
//   never spawns, so the singleton runs isolated (MCA parameter ess_singleton_isolated);
// - it opens every point-to-point messaging layer to choose the fastest network (UCX, PSM2, OFI, ...,
//   whose libraries initialise hardware that a lone process never talks to): 0.21 s. A lone process
//   only talks to itself, which the basic layer does (MCA parameter pml = ob1).
// Under mpirun neither is set: there the user's and the site's MPI configuration choose the network.
// A value the user put in the environment wins.
//
// Isolated singletons all take the same job family (0), hence the same session directory
// (<tmp>/ompi.<host>.<uid>/jf.0): one run ending removes it while another, starting on the same node,
// creates its own inside, and MPI_Init of the second fails ("orte_init failed", measured once in 120
// staggered concurrent starts: a parameter sweep of serial jobs would meet it). Each singleton therefore
// gets a private session directory base, made here and removed when the process exits.
std::string& privateSessionBase() {
  static std::string base;
  return base;
}

void removePrivateSessionBase() {
  std::error_code ignored;
  if (!privateSessionBase().empty()) std::filesystem::remove_all(privateSessionBase(), ignored);
}

void fastSingletonStart() {
  if (launchedByMpirun()) return;
  const bool isolatedHere = !inEnvironment("OMPI_MCA_ess_singleton_isolated");
  setenv("OMPI_MCA_ess_singleton_isolated", "1", /*overwrite=*/0);
  setenv("OMPI_MCA_pml", "ob1", /*overwrite=*/0);
  if (!isolatedHere || inEnvironment("OMPI_MCA_orte_tmpdir_base")) return;
  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp != nullptr && *tmp != '\0' ? tmp : "/tmp") + "/contessa-mpi-XXXXXX";
  if (mkdtemp(pattern.data()) == nullptr) return;  // Open MPI's default then, with the race above
  privateSessionBase() = pattern;
  setenv("OMPI_MCA_orte_tmpdir_base", pattern.c_str(), /*overwrite=*/1);
  std::atexit(removePrivateSessionBase);
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

// MUMPS allocates its workspaces at every factorisation and frees them after; glibc returns such
// blocks to the system (mmap above a threshold that starts at 128 KiB, heap trimming above 128 KiB), so
// every factorisation faulted its workspace in again page by page: half of the tube's 18 700 page
// faults, and page faults are slow in virtual machines. Blocks up to 32 MiB (glibc's largest threshold)
// now come from the heap, and up to 1 GiB of freed memory stays with the process for the next
// factorisation (measured: 9 600 page faults, a quarter less system time). The peak memory is
// unchanged. A user's GLIBC_TUNABLES wins.
void keepWorkspacesForReuse() {
  if (inEnvironment("GLIBC_TUNABLES")) return;
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
}

// The rank this process will have, from its launcher's environment (before MPI_Init): Open MPI's mpirun,
// a PMIx or PMI launcher, srun. A process without any is a singleton, rank 0. SLURM_PROCID comes last:
// mpirun's ranks inside a batch job inherit the batch step's SLURM_PROCID=0.
bool becomesRankZero() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK", "SLURM_PROCID"})
    if (const char* value = std::getenv(name)) return std::strcmp(value, "0") == 0;
  return true;
}

bool allDigits(const std::string& text) {
  return !text.empty() && text.size() <= 18 && text.find_first_not_of("0123456789") == std::string::npos;
}

// Slurm 22.05 has no variable with the job's end time (later versions set SLURM_JOB_END_TIME): squeue
// prints it, as seconds since the epoch with SLURM_TIME_FORMAT=%s (no time zone to get wrong). The
// query runs before MPI_Init (no fork under MPI), bounded by `timeout` so that a slurmctld that does not
// answer delays the start by 10 s at most.
std::optional<BatchJobEnd> readBatchJobEnd() {
  const char* job = std::getenv("SLURM_JOB_ID");
  if (job == nullptr || !allDigits(job) || !becomesRankZero()) return std::nullopt;
  const std::string jobName = std::string("Slurm job ") + job;
  if (const char* end = std::getenv("SLURM_JOB_END_TIME")) {
    if (auto time = parseEpochSeconds(end)) return BatchJobEnd{jobName, *time};
  }
  const std::string command =
      std::string("SLURM_TIME_FORMAT=%s timeout 10 squeue -h -j ") + job + " -o %e 2>/dev/null";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return std::nullopt;
  char line[128] = {0};
  const bool read = std::fgets(line, sizeof line, pipe) != nullptr;
  pclose(pipe);
  if (!read) return std::nullopt;
  std::string text(line);
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  if (auto time = parseEpochSeconds(text)) return BatchJobEnd{jobName, *time};
  return std::nullopt;
}

std::optional<BatchJobEnd>& batchJobEndStore() {
  static std::optional<BatchJobEnd> end;
  return end;
}

}  // namespace

std::optional<std::chrono::system_clock::time_point> parseEpochSeconds(const std::string& text) {
  if (!allDigits(text)) return std::nullopt;
  return std::chrono::system_clock::time_point(std::chrono::seconds(std::stoll(text)));
}

const std::optional<BatchJobEnd>& batchJobEnd() { return batchJobEndStore(); }

void setBatchJobEndMargin(double seconds) {
  if (batchJobEndStore()) batchJobEndStore()->marginSeconds = seconds;
}

void prepareProcess(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--timers") == 0) timers::enable();
  fastSingletonStart();
  oneBlasThreadPerRank();
  keepWorkspacesForReuse();
  batchJobEndStore() = readBatchJobEnd();
}

}  // namespace contessa::app
