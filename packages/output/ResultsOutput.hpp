#pragma once
// Everything a run writes after each converged increment: the Exodus II results, the history CSV and
// the progress table on stdout (DESIGN.md contracts). The Exodus results are one file, gathered to
// rank 0 which writes it, or (Problem/Output/Exodus Layout = Per Rank) one piece per rank, written by
// each rank from what it holds; the history is written by rank 0. Whether the writes succeeded is then
// agreed by all ranks, so that an output error ends the run on every rank instead of leaving the
// others waiting in the next collective call.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "deck/ProblemDefinition.hpp"
#include "io/ExodusWriter.hpp"
#include "io/HistoryWriter.hpp"
#include "io/OutputLock.hpp"
#include "mesh/MeshPiece.hpp"
#include "model/ContactMechanicsModel.hpp"
#include "output/PointHistories.hpp"
#include "output/RegularisationWarnings.hpp"
#include "solvers/RunReports.hpp"

namespace contessa::output {

/// What the results file records about the run besides the results (Exodus QA and information
/// records): the command line and the deck as run.
struct RunDescription {
  std::string commandLine;  ///< e.g. "contessa tube.xml --set ..."
  std::vector<std::string> deck;  ///< the deck after --set overrides (before defaults are filled in), by line
};

class ResultsOutput : public solvers::IncrementObserver {
 public:
  /// Locks `<directory>/<name>.lock` and creates `<directory>/<name>.exo` and
  /// `<directory>/<name>.history.csv` on rank 0 (per rank: `<directory>/<name>.exo.N.r` on each rank r
  /// of N, the rank zero-padded to the digits of N as SEACAS names them). Collective: when another run
  /// holds the lock or a file cannot be created, every rank throws InputError with the one-line reason
  /// of the lowest rank that failed, and no file is left. Each Exodus file (ExodusNaming::AtFirstStep)
  /// and the history take their names with their first step, so an earlier run's files stay until then.
  /// A restarted run (`restartRows`: the history rows of steps 0..k from the restart file) continues the
  /// files of the run it continues: each Exodus file is re-created with its first k + 1 steps copied from
  /// the old one (so steps written after the restart file, before a kill, are gone) and the history is
  /// re-written with those rows; the old Exodus file must be there (InputError otherwise).
  ResultsOutput(const deck::ProblemDefinition& problem, const model::ContactMechanicsModel& model,
                const std::string& directory, const std::string& name, bool printTable,
                const RunDescription& run = {}, const std::vector<std::vector<double>>* restartRows = nullptr);

  /// A run that wrote no step (it failed before its first one) leaves no results: this rank's Exodus
  /// file and, on rank 0, the history are removed.
  ~ResultsOutput() override;
  ResultsOutput(const ResultsOutput&) = delete;
  ResultsOutput& operator=(const ResultsOutput&) = delete;

  /// Collective. When a rank cannot write the increment, every rank throws std::runtime_error with
  /// the reason (also kept in failure()); the files keep every increment before it.
  void incrementConverged(const model::Vector& x, const solvers::IncrementReport& report) override;
  void attemptFailed(const solvers::IncrementReport& report) override;

  /// The history so far, by column name (for the deck's regression checks).
  const std::vector<std::string>& historyColumns() const { return columns_; }
  const std::vector<std::vector<double>>& historyRows() const { return rows_; }
  /// The Exodus file, or for a per-rank set its pattern, e.g. "out/tube.exo.2.*".
  std::string exodusPath() const { return exodusPath_; }
  std::string historyPath() const { return historyPath_; }
  /// Why the output failed ("" while it has not), on every rank.
  const std::string& failure() const { return failure_; }
  /// Where the contact regularisation spoils the answer of the last converged increment, one line per
  /// interface and kind (output::regularisationWarnings); the same on every rank; none before a step.
  std::vector<std::string> regularisationWarnings() const;
  /// A note for the user about the output (e.g. no lock on this file system), rank 0; "" if none.
  const std::string& warning() const { return warning_; }

 private:
  /// One rigid contact surface drawn as a block of its own (BAR2 in 2D, SHELL4 in 3D): its points move by λ · motion.
  struct RigidSurface {
    std::string name;
    std::size_t points = 0;
    std::vector<double> motion;  ///< displacement at λ = 1, one entry per component
    std::string interfaceName;   ///< its contact interface (the load steps' schedule key)
  };

  /// What the Exodus file(s) are made of.
  struct ExodusSetup {
    io::ExodusFields fields;
    io::ExodusRecords records;
    std::vector<io::ExodusSurfaceBlock> surfaces;  ///< the rigid surfaces, whole
    std::string base;                              ///< <directory>/<name>.exo
    const std::vector<std::vector<double>>* restartRows = nullptr;
  };

  /// What this rank's Exodus file shows of an increment, in the file's order.
  struct FileValues {
    model::Vector displacement;
    model::MultiVector stress, contact;
  };

  /// Collective: the increment's values imported into the file maps.
  FileValues fileValues(const model::Vector& x) const;
  /// Collective: the history row (sums over the ranks, the same on every rank).
  using Regularisation = RegularisationByInterface;
  std::vector<double> historyRow(const model::Vector& x, const solvers::IncrementReport& report,
                                 const contact::ContactCounts& counts, const Regularisation& regularisation) const;
  /// This rank's Exodus step: nodal, element and global values.
  void writeExodusStep(const FileValues& values, const solvers::IncrementReport& report,
                       const contact::ContactCounts& counts, const std::vector<double>& row);
  /// The maps of what this rank's file shows and the imports into them.
  void makeFileMaps();
  /// The rigid surfaces' blocks (and rigidSurfaces_, their motion).
  std::vector<io::ExodusSurfaceBlock> rigidSurfaceBlocks();
  io::ExodusFields exodusFields() const;
  /// Collective: the lock, the Exodus file(s) and the history, in that order (InputError, and no file
  /// left, when one cannot be made).
  void openFiles(const std::string& directory, const std::string& name, const ExodusSetup& exodus);
  /// Rank 0: the whole mesh's file.
  void createWholeExodus(const mesh::Mesh& whole, const ExodusSetup& exodus);
  /// Per rank: this rank's piece, the rigid surfaces in rank 0's.
  void createPieceExodus(const ExodusSetup& exodus);
  /// `create` makes the Exodus file `path`; for a restarted run, the old file's first steps are copied in.
  void continueRun(const std::string& path, const std::vector<std::vector<double>>* restartRows,
                   const std::function<void()>& create);
  /// Rank 0: the history file (with the restart rows); the reason it cannot be made, "" if it can.
  std::string createHistory(const std::vector<std::vector<double>>* restartRows);
  void removeUnwrittenFiles();
  std::string historyStartingPath() const;
  void nameHistory();

  const deck::ProblemDefinition& problem_;
  const model::ContactMechanicsModel& model_;
  bool root_, printTable_;
  std::string exodusPath_, historyPath_, failure_, warning_;
  std::vector<RigidSurface> rigidSurfaces_;
  // Declared before the writers: the lock is released after the files are closed.
  std::unique_ptr<io::OutputLock> lock_;
  std::unique_ptr<io::ExodusWriter> exodus_;
  std::unique_ptr<io::HistoryWriter> history_;
  bool historyNamed_ = false;  ///< the history has its name (historyPath_), after its first row
  std::unique_ptr<PointHistories> histories_;  ///< the deck's point histories, the history's last columns
  std::vector<std::string> columns_;
  Regularisation lastRegularisation_;  ///< of the last converged increment
  int lastStep_ = 0;
  double lastLambda_ = 0.0;
  std::vector<std::vector<double>> rows_;
  // What this rank's Exodus file shows (Single File: the whole mesh on rank 0, nothing elsewhere; Per
  // Rank: this rank's piece), as maps numbered in the file's order, and the imports of the owned values.
  bool perRank_ = false;
  const mesh::MeshPiece* piece_ = nullptr;  ///< per-rank output: this rank's part of the mesh
  Teuchos::RCP<const model::Map> fileDofMap_, fileElementMap_, fileNodeMap_;
  Teuchos::RCP<const model::Import> dofToFile_, elementToFile_, nodeToFile_;
};

}  // namespace contessa::output
