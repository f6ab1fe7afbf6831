#pragma once
// Everything a run writes after each converged increment: the Exodus II file, the history CSV and
// the progress table on stdout (DESIGN.md contracts). Fields are gathered to rank 0, which writes.
#include <memory>
#include <string>
#include <vector>

#include "deck/ProblemDefinition.hpp"
#include "io/ExodusWriter.hpp"
#include "io/HistoryWriter.hpp"
#include "model/ContactMechanicsModel.hpp"
#include "solvers/ContinuationDriver.hpp"

namespace contessa::output {

class ResultsOutput : public solvers::IncrementObserver {
 public:
  /// Writes `<directory>/<name>.exo` and `<directory>/<name>.history.csv`.
  ResultsOutput(const deck::ProblemDefinition& problem, const model::ContactMechanicsModel& model,
                const std::string& directory, const std::string& name, bool printTable);

  void incrementConverged(const model::Vector& x, const solvers::IncrementReport& report) override;
  void attemptFailed(const solvers::IncrementReport& report) override;

  /// The last converged row of the history, by column name (for the deck's regression checks).
  const std::vector<std::string>& historyColumns() const { return columns_; }
  const std::vector<std::vector<double>>& historyRows() const { return rows_; }
  std::string exodusPath() const { return exodusPath_; }
  std::string historyPath() const { return historyPath_; }

 private:
  const deck::ProblemDefinition& problem_;
  const model::ContactMechanicsModel& model_;
  bool root_, printTable_;
  std::string exodusPath_, historyPath_;
  std::unique_ptr<io::ExodusWriter> exodus_;
  std::unique_ptr<io::HistoryWriter> history_;
  std::vector<std::string> columns_;
  std::vector<std::vector<double>> rows_;
  Teuchos::RCP<const model::Map> rootDofMap_, rootElementMap_;
  Teuchos::RCP<const model::Map> rootNodeMap_;
  Teuchos::RCP<const model::Import> dofToRoot_, elementToRoot_, nodeToRoot_;
};

}  // namespace contessa::output
