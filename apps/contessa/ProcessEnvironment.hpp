#pragma once
// What the process sets up for itself before MPI_Init: a fast MPI start when it was not launched by
// mpirun, one OpenBLAS thread per MPI rank, the phase timers when `--timers` is on the command line, and
// the end of the batch job it runs in.
#include <chrono>
#include <optional>
#include <string>

namespace contessa::app {

/// Call first in main, before MPI_Init (Tpetra::ScopeGuard). Settings the user made in the environment
/// are left alone (docs/user-guide.md, "Performance").
void prepareProcess(int argc, char** argv);

/// The end of the Slurm job this process runs in (its time limit), read by prepareProcess on the process
/// that becomes rank 0 only (one query to Slurm per run, not one per rank): SLURM_JOB_END_TIME where
/// Slurm sets it, else `squeue -h -j $SLURM_JOB_ID -o %e` (Slurm 22.05). Empty outside a Slurm job,
/// for a job without a time limit, on the other ranks, or when Slurm did not answer in 10 s.
struct BatchJobEnd {
  std::string job;                             ///< "Slurm job 1234"
  std::chrono::system_clock::time_point time;  ///< when Slurm ends the job
  /// Seconds kept free at the end of the job, besides the longest increment (--job-end-margin): for the
  /// process's exit and the job script's own last steps.
  double marginSeconds = 10;
};
const std::optional<BatchJobEnd>& batchJobEnd();
/// --job-end-margin: sets marginSeconds (where there is a job end).
void setBatchJobEndMargin(double seconds);

/// "1795738263" (seconds since the epoch, as squeue prints with SLURM_TIME_FORMAT=%s) → that time;
/// empty for anything else ("Unknown", "NONE", "N/A", an empty answer). For the unit tests.
std::optional<std::chrono::system_clock::time_point> parseEpochSeconds(const std::string& text);

}  // namespace contessa::app
