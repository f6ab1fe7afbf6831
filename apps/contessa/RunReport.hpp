#pragma once
// The run's summary for batch logs and scripts: increments, Newton and linear iterations, wall time
// and each rank's memory high-water mark, printed on rank 0 and written to `<name>.summary.json`
// beside the history (docs/user-guide.md, "Batch runs").
#include <optional>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>

#include "mesh/DistributedMesh.hpp"
#include "solvers/ContinuationDriver.hpp"

namespace contessa::app {

/// This process's peak resident memory in bytes: VmHWM of /proc/self/status, else getrusage's
/// ru_maxrss; 0 when neither is available.
long long peakResidentBytes();

/// What the earlier jobs of a continued run (--restart) did, from the restart file's history rows (their
/// Newton iterations, failed attempts included, come with the driver's summary: RunSummary::
/// runNewtonIterations).
struct EarlierJobs {
  int step = 0;                 ///< the restart file's step: this job began after it
  double wallSeconds = 0;       ///< the run's wall time at that step (history column wall_s)
};

/// From the restart file's history rows (steps 0..k) and the history's columns: k and wall_s of step k.
EarlierJobs earlierJobs(const std::vector<std::string>& columns, const std::vector<std::vector<double>>& rows);

struct RunReport {
  std::string deck;
  int ranks = 1;
  solvers::RunSummary summary;
  int exitStatus = 0;
  double wallSeconds = 0;
  std::string linearSolver;          ///< the linear solver and why (solvers::LinearSolverChoice)
  bool linearSolverAutomatic = false;  ///< chosen by the problem's size, not named by the deck
  long preconditionerRebuildsOnNewGraph = 0;  ///< MueLu hierarchies started over on a rebuilt graph
  long preconditionerRefusedReuses = 0;       ///< MueLu re-set-ups refused, then started over
  long preconditionerReusedSetUps = 0;        ///< MueLu re-set-ups of a kept hierarchy (aggregates, P kept)
  long preconditionerPatternRestarts = 0;     ///< started over: an entry zero at the set-up is nonzero now
  long preconditionerCoarseZeroRestarts = 0;  ///< started over: exact zeros in the coarse matrices, 2+ ranks
  long directFactorizations = 0;     ///< MUMPS factorisations of the run
  long symmetricFactorizations = 0;  ///< of them, LDLᵀ (a symmetric Jacobian on one rank)
  long reusedFactorizations = 0;     ///< Jacobians equal to the last factorised one: no factorisation
  long preconditionerUnchangedSetUps = 0;  ///< MueLu set-ups skipped: the values as at the last set-up
  long preconditionerLargeChangeRestarts = 0;  ///< MueLu started over: a row changed by more than its coarse levels allow
  int graphRebuilds = 0;             ///< rebuilds of the matrix graph (contact beyond its reserved couplings)
  double graphRebuildSeconds = 0;    ///< their total time
  std::vector<long long> peakBytesPerRank;  ///< rank 0 only (gathered)
  /// Each rank's part of the mesh (rank 0 only, gathered): elements, nodes held (owned and halo), and the
  /// bytes of its containers (mesh::DistributedMesh::bytes), beside the whole mesh's counts.
  std::vector<long long> partElements, partNodes, partBytes;
  long long meshElements = 0, meshNodes = 0;
  /// A continued run: the earlier jobs (the summary then states this job and the whole run apart).
  std::optional<EarlierJobs> earlier;
};

/// Collective: gathers every rank's peak memory to rank 0 into `report`.
void gatherPeakMemory(const Teuchos::Comm<int>& comm, RunReport& report);
/// Collective: gathers the sizes of every rank's part of the mesh into `report`.
void gatherMeshParts(const Teuchos::Comm<int>& comm, const mesh::DistributedMesh& part, RunReport& report);

/// Rank 0: the log line ("contessa: summary: ..."); a continued run's states this job and the whole run.
std::string summaryLine(const RunReport& report);

/// Rank 0: the JSON text of `<name>.summary.json`.
std::string summaryJson(const RunReport& report);

}  // namespace contessa::app
