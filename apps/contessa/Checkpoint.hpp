#pragma once
// Checkpoint and restart for a run (docs/user-guide.md, "Checkpoint and restart"): when the restart file is
// written (every N increments, a stop signal, Max Wall Time), writing it (every rank's records gathered to
// rank 0, written atomically), and reading one back for --restart with the checks that it belongs to this
// deck and mesh.
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include "deck/ProblemDefinition.hpp"
#include "io/RestartFile.hpp"
#include "model/ContactMechanicsModel.hpp"
#include "output/ResultsOutput.hpp"
#include "solvers/ContinuationDriver.hpp"

namespace contessa::app {

/// The deck as a restart must match it: "path = value" lines of the validated deck (defaults filled in),
/// without the run-control parameters a restart may change: Problem/Title, Problem/Output/Checkpoint,
/// Problem/Regression, Piro/LOCA/Stepper/Max Steps and Piro/NOX/Printing.
std::string restartDeckText(const Teuchos::ParameterList& deck);

/// What identifies the run in its restart file: the deck text above and the mesh (node and element
/// counts, a hash of the coordinates and connectivity by global id, the same on every rank count).
/// Collective.
io::RestartContent restartIdentity(const Teuchos::ParameterList& deck, const mesh::DistributedMesh& part);

/// A restart file read for --restart: its state and the history rows it keeps (steps 0..k).
struct RestartInput {
  io::RestartContent content;
  std::vector<std::vector<double>> historyRows;
};
/// Collective: rank 0 reads `path`, every rank checks it against `identity` and throws InputError alike
/// ("--restart PATH: written for another deck: ..."; missing, truncated or corrupt files too), and checks
/// the table "nodes": a row for every node, `dimension` finite displacements in each.
RestartInput readRestart(const Teuchos::Comm<int>& comm, const std::string& path, const io::RestartContent& identity,
                         int dimension);

/// `--restart auto`: the restart file of this deck in the output directory (DIR/<deck name>.restart) when
/// there is one, else "" (a new run); any other value as given. Collective: rank 0 looks, every rank gets
/// its answer. A restart file found is read and checked as any --restart FILE is (an invalid one is an
/// input error, never silently replaced by a new run that would overwrite the results).
std::string resolveRestart(const Teuchos::Comm<int>& comm, const std::string& restart, const std::string& deck,
                           const std::string& outputDirectory, bool verbose);

/// The run's policy: a restart file every `every` increments, and a stop (with one) on a signal, when the
/// next increment would not fit in `maxWallSeconds` of the run, or when it would not end before the batch
/// job's time limit (ProcessEnvironment.hpp, batchJobEnd: Slurm's end of the job, read by rank 0 when
/// the process started).
class RunCheckpoints : public solvers::CheckpointControl {
 public:
  RunCheckpoints(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const model::ContactMechanicsModel& model,
                 const output::ResultsOutput& results, std::string path, io::RestartContent identity, int every,
                 double maxWallSeconds, std::chrono::steady_clock::time_point runStart, bool verbose);
  Decision decide(int increments, bool converged) override;
  void write(StateRecord driverState) override;
  /// Why the restart file could not be written ("" while it could), on every rank.
  const std::string& failure() const { return failure_; }

 private:
  using Clock = std::chrono::steady_clock;
  Teuchos::RCP<const Teuchos::Comm<int>> comm_;
  const model::ContactMechanicsModel& model_;
  const output::ResultsOutput& results_;
  std::string path_;
  io::RestartContent identity_;
  int every_;
  double maxWallSeconds_;
  Clock::time_point runStart_, lastIncrement_;
  std::optional<std::chrono::system_clock::time_point> jobEnd_;  ///< rank 0: the batch job's end
  std::string jobName_;
  double jobEndMargin_ = 0;
  double longestIncrement_ = 0, writeSeconds_ = 0;
  bool verbose_, stopping_ = false;
  std::string failure_;
};

}  // namespace contessa::app
