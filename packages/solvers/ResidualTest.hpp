#pragma once
// The convergence test of the continuation's Newton solves (NewtonStatusTests puts it among the others).
// Converged when ||f|| ≤ max(absolute, relative · ||f|| at the solve's first iterate), or when the
// Newton update has shrunk to round-off: ||Δx|| ≤ update · ||x||. (NOX's relative NormF is relative
// to a fixed group, not to each increment's start, hence this test.) The update test matters with
// penalty contact: a penalty of 1e9 on coordinates of order 100 leaves residual noise of about
// 1e9 · 1e-14 that no iteration can remove, while the update keeps converging quadratically.
#include <NOX_StatusTest_Generic.H>

#include "solvers/StepControl.hpp"

namespace contessa::solvers {

class ResidualTest : public NOX::StatusTest::Generic {
 public:
  /// `stepControl` may veto convergence (StepControl::mayConverge, e.g. while new contacts are frozen)
  /// and disable the update test at an iterate whose update was computed for another residual
  /// (StepControl::updateMeaningful); it outlives the test.
  ResidualTest(double absolute, double relative, double update, const StepControl& stepControl)
      : absolute_(absolute), relative_(relative), update_(update), stepControl_(stepControl) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) override;
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& os, int indent) const override;

 private:
  double absolute_, relative_, update_, initial_ = 0, norm_ = 0, updateNorm_ = -1, xNorm_ = 0;
  const StepControl& stepControl_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

}  // namespace contessa::solvers
