#pragma once
// The status tests of one Newton solve, and why a solve failed, in words. Both solve paths use them:
// the continuation (ContinuationDriver, LOCA) and the single static solve (StaticSolveDriver, Piro).
// The tests, a NOX Combo(OR) in this order:
//   1. FiniteValue: a NaN or infinite ||f|| fails the solve (an inadmissible element sets f to NaN);
//   2. optionally a test of the step-size method that may stop the solve first for a step correction
//      (StepControl::correctionTest: Contact Beta's Restart test);
//   3. the convergence test, whose converged state must also be acceptable: a state in which a slave
//      node passed through its master surface (contact tunnelling) fails the solve instead;
//   4. the iteration limit (IterationLimit: Maximum Iterations per solve, counted again after each
//      multiplier update of the augmented Lagrangian).
// When a solve fails, diagnose() names the reason for the one-line stop message: the test that failed,
// the element that made the residual NaN, the linear solver's failure (a singular stiffness and its free
// direction), the tunnelling node.
#include <cmath>
#include <functional>
#include <memory>
#include <string>

#include <NOX_StatusTest_Combo.H>
#include <NOX_StatusTest_FiniteValue.H>
#include <NOX_StatusTest_MaxIters.H>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

#include "model/ContactAugmentation.hpp"
#include "model/SolveDiagnostics.hpp"
#include "solvers/MessageText.hpp"
#include "solvers/StepControl.hpp"

namespace NOX::Abstract {
class Group;
}

namespace contessa::solvers {

/// Why an attempt (one Newton solve) failed.
struct SolveFailure {
  enum class Kind {
    None,                ///< it did not fail
    NonFiniteResidual,   ///< f is NaN or infinite (an inadmissible element, or bad data)
    StepCorrection,      ///< stopped for a step correction of the step-size method (not a failure of Newton)
    NewtonIterations,    ///< Maximum Iterations used up
    LinearSolver,        ///< the Newton direction could not be computed (e.g. a singular stiffness)
    Tunnelling,          ///< converged, but a slave node passed through its master surface
    Other                ///< an exception or NOX error
  };
  Kind kind = Kind::None;
  std::string reason;  ///< one line, e.g. "Newton did not converge in 20 iterations (last ||f|| = 3.2e-02)"
};

/// Converged only when `converged` says so AND the converged state is acceptable: `reject()` (called on
/// every rank at the same iterate, so it may communicate) returns why not, or "" to accept. A rejected
/// state fails the solve, so the continuation cuts the step back.
class AcceptedConvergenceTest : public NOX::StatusTest::Generic {
 public:
  /// `solveAgain(solver, converged)` (may be empty), asked at an accepted state (converged = true) and at
  /// every unconverged iterate after the first (false): true keeps the solve going at this load factor (the
  /// augmented Lagrangian's multipliers were updated and f computed again with them).
  AcceptedConvergenceTest(Teuchos::RCP<NOX::StatusTest::Generic> converged, std::function<std::string()> reject,
                          std::function<bool(const NOX::Solver::Generic&, bool)> solveAgain = {})
      : converged_(std::move(converged)), reject_(std::move(reject)), solveAgain_(std::move(solveAgain)) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType type) override;
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& os, int indent) const override;
  /// Why the last converged state was rejected ("" when it was not).
  const std::string& rejection() const { return rejection_; }

 private:
  Teuchos::RCP<NOX::StatusTest::Generic> converged_;
  std::function<std::string()> reject_;
  std::function<bool(const NOX::Solver::Generic&, bool)> solveAgain_;
  std::string rejection_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

/// Maximum Iterations of one Newton solve, counted from its start or from the last multiplier update of the
/// augmented Lagrangian (each update starts a new problem at the same load factor; NOX's MaxIters would
/// count the iterations of every update together).
class IterationLimit : public NOX::StatusTest::Generic {
 public:
  explicit IterationLimit(int maxIterations) : max_(maxIterations) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType type) override;
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& os, int indent) const override;
  /// The solve starts again from iteration `iteration` (a multiplier update there).
  void restartAt(int iteration) { start_ = iteration; }
  /// The iterations counted at the last check.
  int counted() const { return counted_; }

 private:
  int max_, start_ = 0, counted_ = 0;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

class NewtonStatusTests {
 public:
  /// `convergence` decides convergence. `diagnostics` says why a solve failed, `linearSolver` is the
  /// model's (its failures are read). `stepControl` (may be null: LOCA's methods and the single solve)
  /// adds its correction test before the convergence test, and is asked at a converged, tunnelling-free
  /// state whether the step is to be solved again with another size: a reason fails the solve as a step
  /// correction, not as a Newton failure.
  NewtonStatusTests(const model::SolveDiagnostics& diagnostics,
                    Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> linearSolver,
                    Teuchos::RCP<NOX::StatusTest::Generic> convergence, int maxIterations,
                    StepControl* stepControl = nullptr);
  // Its status tests call back into this object (a lambda holding `this`): a copy or a move would leave
  // them calling the original.
  NewtonStatusTests(const NewtonStatusTests&) = delete;
  NewtonStatusTests& operator=(const NewtonStatusTests&) = delete;

  Teuchos::RCP<NOX::StatusTest::Generic> test() const { return combo_; }
  /// The augmented Lagrangian (docs/theory-contact.md §15): at an accepted state, `augmentation` may update
  /// the contact multipliers; the solve then goes on at the same load factor from `group()` (the group the
  /// solver iterates on, whose f is computed again with the new multipliers), so an increment's Newton
  /// iterations include its augmentations and Contact Beta judges its final state. Both outlive the tests.
  void enableAugmentation(model::ContactAugmentation* augmentation, std::function<NOX::Abstract::Group&()> group) {
    augmentation_ = augmentation;
    group_ = std::move(group);
  }
  /// Multiplier updates in the solves so far.
  int augmentations() const { return augmentations_; }

  /// Call when a solve starts (remembers the linear solver's failure count).
  void startSolve();
  /// Why the solve that just ended failed; every rank calls it at the same point (it communicates).
  /// `noxOutput`: what NOX printed (an exception it caught), for the reasons the tests do not know.
  SolveFailure diagnose(const NOX::Solver::Generic& solver, const std::string& noxOutput) const;
  /// The linear solver's failure since startSolve() (kind None if it did not fail): also for the solves
  /// outside Newton, such as LOCA's tangent predictor. Every rank gets the same answer.
  SolveFailure linearSolverFailure() const;

 private:
  const model::SolveDiagnostics& diagnostics_;
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> linearSolver_;
  StepControl* stepControl_;
  Teuchos::RCP<NOX::StatusTest::FiniteValue> finite_;
  Teuchos::RCP<NOX::StatusTest::Generic> before_;
  Teuchos::RCP<AcceptedConvergenceTest> convergence_;
  Teuchos::RCP<IterationLimit> maxIters_;
  Teuchos::RCP<NOX::StatusTest::Combo> combo_;
  long linearFailuresAtStart_ = 0;
  long iterativeFailuresAtStart_ = 0;  ///< iterativeSolveLog().failures at startSolve()
  bool redoRequested_ = false;  ///< the last rejection was the step control's
  model::ContactAugmentation* augmentation_ = nullptr;
  std::function<NOX::Abstract::Group&()> group_;
  int augmentations_ = 0;
  double previousStep_ = HUGE_VAL;  ///< the last Newton step's largest component in this problem (early updates)
  /// At an accepted state (`converged`) or an unconverged iterate: updates the multipliers and recomputes f
  /// when the augmentation asks for it.
  bool augment(const NOX::Solver::Generic& solver, bool converged);
};

}  // namespace contessa::solvers
