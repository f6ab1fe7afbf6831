#pragma once
// Runs the finite-difference check of the Jacobian (model/JacobianCheck) at the first Newton iterate of
// chosen increments (`--check-jacobian`): a NOX observer for the solves, and an increment observer
// placed before the output's, to know which increment a solve is for. It prints one line per checked
// increment (rank 0) and leaves the run unchanged.
// The model is named, not included: the check needs the concrete model (its evaluation state, who
// couples two DOFs), the solvers' headers do not.
#include <cstdio>
#include <memory>
#include <vector>

#include <NOX_Observer.hpp>

#include "solvers/RunReports.hpp"

namespace contessa::model {
class ContactMechanicsModel;
class JacobianCheck;
}  // namespace contessa::model

namespace contessa::solvers {

class JacobianCheckObserver : public NOX::Observer, public IncrementObserver {
 public:
  /// `increments`: the increment numbers to check (history `step`, 1 = the first after the initial
  /// state); empty = every increment. `next` receives every increment report. A solve whose group
  /// carries no load factor (Piro/Solver Type = NOX) is at `plainSolveLoadFactor`.
  JacobianCheckObserver(const model::ContactMechanicsModel& model, std::vector<int> increments, IncrementObserver& next,
                        std::FILE* out = stdout, double plainSolveLoadFactor = 1.0);
  ~JacobianCheckObserver() override;

  void runPreIterate(const NOX::Solver::Generic& solver) override;
  void incrementConverged(const model::Vector& x, const IncrementReport& report) override;
  void attemptFailed(const IncrementReport& report) override { next_.attemptFailed(report); }

  int checksDone() const { return checks_; }

 private:
  const model::ContactMechanicsModel& model_;
  std::vector<int> increments_;
  IncrementObserver& next_;
  std::FILE* out_;
  double plainSolveLoadFactor_;
  std::unique_ptr<model::JacobianCheck> check_;
  int increment_ = 0;        ///< the increment the current solve is for (0 = the initial state)
  int lastChecked_ = 0;      ///< checked once per increment (its first attempt)
  int checks_ = 0;
};

}  // namespace contessa::solvers
