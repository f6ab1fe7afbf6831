#pragma once
// The convergence test of Contessa's Newton solves (NewtonStatusTests puts it among the others).
// Converged when ||f|| ≤ max(bound, relative · ||f|| at the solve's first iterate), or when the Newton
// update has shrunk to round-off: ||Δx|| ≤ update · ||x||. The bound is the deck's absolute tolerance or
// the force-scaled one, c · F at the judged state, not below the round-off of the out-of-balance force
// (ResidualTolerance.hpp); the force-scaled bound is compared with the out-of-balance force, ||f|| over the
// free DOFs (model/ForceScale.hpp). (NOX's relative NormF is
// relative to a fixed group, not to each increment's start, hence this test.) The update test matters with
// penalty contact: a penalty of 1e9 on coordinates of order 100 leaves residual noise of about
// 1e9 · 1e-14 that no iteration can remove, while the update keeps converging quadratically. The single
// solve (StaticSolveDriver) uses it without the relative and update tests.
#include <NOX_StatusTest_Generic.H>

#include "model/ForceScale.hpp"
#include "solvers/ResidualTolerance.hpp"
#include "solvers/StepControl.hpp"

namespace contessa::solvers {

class ResidualTest : public NOX::StatusTest::Generic {
 public:
  /// An update below this fraction of the mesh's largest |X| is at the positions' round-off (about 4500
  /// machine epsilons): converged whatever ||x|| (ResidualTest.cpp).
  static constexpr double kPositionRoundOff = 1e-12;
  /// `bound`: the absolute part; `forces` gives F at the iterate (may be null: F = 0). `relative` and
  /// `update` ≤ 0 switch those tests off. `stepControl` (may be null) may veto convergence
  /// (StepControl::mayConverge, e.g. while new contacts are frozen) and disable the update test at an
  /// iterate whose update was computed for another residual (StepControl::updateMeaningful). `record`
  /// (may be null) is told of every state the residual test accepts. All outlive the test.
  ResidualTest(const ResidualTolerance& bound, const model::ForceScale* forces, double relative, double update,
               const StepControl* stepControl, ResidualToleranceRecord* record = nullptr)
      : bound_(bound), forces_(forces), relative_(relative), update_(update), stepControl_(stepControl), record_(record) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) override;
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& os, int indent) const override;

 private:
  ResidualTolerance bound_;
  const model::ForceScale* forces_;
  double relative_, update_, initial_ = 0, norm_ = 0, updateNorm_ = -1, xNorm_ = 0, forceScale_ = 0, absolute_ = 0,
         judged_ = 0, floor_ = 0;
  const StepControl* stepControl_;
  ResidualToleranceRecord* record_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

}  // namespace contessa::solvers
