#pragma once
// What a step-size method adds to the continuation beyond LOCA's stepping: its LOCA strategy, Newton
// status tests, a veto on convergence, its words in the increment reports and the stop message. The
// driver (ContinuationDriver) asks these hooks and knows no method by name; a method's registry row
// (StepSizeMethods.cpp) builds its control. LOCA's own methods (Constant, Adaptive) add nothing: the
// defaults below. What a method keeps in a restart file is its strategy's (ResumableStepSize).
#include <functional>
#include <memory>
#include <string>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace LOCA::StepSize {
class AbstractStrategy;
}
namespace NOX {
namespace Abstract {
class Group;
}
namespace StatusTest {
class Generic;
}
}  // namespace NOX
namespace contessa::continuation {
class ContactEventSource;
}

namespace contessa::solvers {

/// What a step-size method's control is built from: the validated Step Size list, the stepper's Max Value
/// and the model's slave nodes.
struct StepControlContext {
  const Teuchos::ParameterList& stepSize;
  double finalLoadFactor;
  continuation::ContactEventSource& events;
};

class StepControl {
 public:
  virtual ~StepControl() = default;

  /// The LOCA strategy of a method Contessa adds (StepSizeFactory); null: LOCA builds its own by name.
  virtual Teuchos::RCP<LOCA::StepSize::AbstractStrategy> createStrategy() { return Teuchos::null; }

  // ---- The Newton solve of an attempt (NewtonStatusTests, ResidualTest).
  /// A test checked before the convergence test, which may stop the solve for a step correction; null:
  /// none.
  virtual Teuchos::RCP<NOX::StatusTest::Generic> correctionTest() { return Teuchos::null; }
  /// A Newton iteration starts (before its status tests).
  virtual void startIterate() {}
  /// The solver has set the iterate `iteration` (x after the line search) in its group, `group()`; its
  /// status tests come next. A method may change what the model evaluates here and compute f again (the
  /// only place where it may: the status tests only test).
  virtual void iterateSet(const std::function<NOX::Abstract::Group&()>& /*group*/, int /*iteration*/) {}
  /// False vetoes convergence at this iterate.
  virtual bool mayConverge() const { return true; }
  /// False disables the update test at this iterate (its Newton update was computed for another residual).
  virtual bool updateMeaningful() const { return true; }
  /// At a converged, tunnelling-free state: "" accepts it; otherwise why the step is to be solved again
  /// with another size (a correction, not a Newton failure).
  virtual std::string redoAtConvergence() { return ""; }
  /// How a solve stopped for a correction is named in the stop reason, e.g. "a Contact Beta step correction".
  virtual std::string correctionName() const { return "a step correction"; }

  // ---- Reports.
  /// The step correction factor applied to the current increment (1: none), for the history.
  virtual double correctionFactor() const { return 1.0; }
  /// The last failed attempt was stopped for a correction (not a Newton failure).
  virtual bool correctionRequested() const { return false; }
  /// When the continuation stopped without a failed attempt: the method's own reason in words (e.g. a step
  /// below Min Step Size asked for by the method), or "".
  virtual std::string stopReason() const { return ""; }
  /// What the method chose by itself and the log should say once at the run's end (e.g. an automatic
  /// setting's value), or "".
  virtual std::string choiceMade() const { return ""; }
};

}  // namespace contessa::solvers
