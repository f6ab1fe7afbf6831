#include "solvers/NewtonStatusTests.hpp"

#include <NOX_Abstract_Group.H>
#include <NOX_Abstract_Vector.H>
#include <NOX_Solver_Generic.H>
#include <NOX_Solver_LineSearchBased.H>

#include <cmath>

#include "solvers/IterativeSolveMonitor.hpp"
#include "solvers/MumpsSolver.hpp"

namespace contessa::solvers {

using Teuchos::RCP;
using Teuchos::rcp;

namespace {

// The message of an exception NOX caught during the solve ("Catch Throws During Solve"), on one line.
std::string caughtException(const std::string& noxOutput) {
  const std::string marker = "caught exception during solver iteration:";
  const auto at = noxOutput.find(marker);
  if (at == std::string::npos) return "";
  std::string what = noxOutput.substr(at + marker.size());
  what = what.substr(0, what.find("Setting solver status to Failed"));
  std::string line;
  for (char c : what) {
    if (c == '\n' || c == '\t') c = ' ';
    if (c == ' ' && (line.empty() || line.back() == ' ')) continue;
    line += c;
  }
  while (!line.empty() && line.back() == ' ') line.pop_back();
  if (line.size() > 300) line = line.substr(0, 300) + "...";
  return line;
}

const MumpsFailures* mumpsFailures(const Thyra::LinearOpWithSolveFactoryBase<double>* linearSolver) {
  const auto* mumps = dynamic_cast<const MumpsLinearOpWithSolveFactory*>(linearSolver);
  return mumps != nullptr ? &mumps->failures() : nullptr;
}

}  // namespace

NOX::StatusTest::StatusType AcceptedConvergenceTest::checkStatus(const NOX::Solver::Generic& solver,
                                                                 NOX::StatusTest::CheckType type) {
  if (type == NOX::StatusTest::None) {
    status_ = NOX::StatusTest::Unevaluated;
    return status_;
  }
  status_ = converged_->checkStatus(solver, type);
  if (status_ == NOX::StatusTest::Unconverged && solveAgain_ && solver.getNumIterations() > 0) {
    solveAgain_(solver, false);  // an early multiplier update (the solve goes on either way)
    return status_;
  }
  if (status_ != NOX::StatusTest::Converged) return status_;
  rejection_ = reject_();
  if (!rejection_.empty())
    status_ = NOX::StatusTest::Failed;
  else if (solveAgain_ && solveAgain_(solver, true))
    status_ = NOX::StatusTest::Unconverged;
  return status_;
}

std::ostream& AcceptedConvergenceTest::print(std::ostream& os, int indent) const {
  converged_->print(os, indent);
  if (!rejection_.empty()) {
    for (int i = 0; i < indent; ++i) os << ' ';
    os << status_ << "converged state rejected: " << rejection_ << "\n";
  }
  return os;
}

NOX::StatusTest::StatusType IterationLimit::checkStatus(const NOX::Solver::Generic& solver, NOX::StatusTest::CheckType) {
  if (solver.getNumIterations() == 0) start_ = 0;  // a new solve
  counted_ = solver.getNumIterations() - start_;
  status_ = counted_ >= max_ ? NOX::StatusTest::Failed : NOX::StatusTest::Unconverged;
  return status_;
}

std::ostream& IterationLimit::print(std::ostream& os, int indent) const {
  for (int i = 0; i < indent; ++i) os << ' ';
  os << status_ << "Newton iterations = " << counted_ << " < " << max_ << " (since the start or the last multiplier update)\n";
  return os;
}

NewtonStatusTests::NewtonStatusTests(const model::SolveDiagnostics& diagnostics,
                                     RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> linearSolver,
                                     RCP<NOX::StatusTest::Generic> convergence, int maxIterations,
                                     StepControl* stepControl)
    : diagnostics_(diagnostics),
      linearSolver_(std::move(linearSolver)),
      stepControl_(stepControl),
      finite_(rcp(new NOX::StatusTest::FiniteValue())),
      before_(stepControl != nullptr ? stepControl->correctionTest() : Teuchos::null),
      // A converged state in which a body has passed through another is no answer: the increment fails
      // and is cut back (theory-contact.md §12).
      convergence_(rcp(new AcceptedConvergenceTest(std::move(convergence),
                                                   [this] {
                                                     redoRequested_ = false;
                                                     std::string why = diagnostics_.contactTunnelling();
                                                     if (why.empty() && stepControl_ != nullptr) {
                                                       why = stepControl_->redoAtConvergence();
                                                       redoRequested_ = !why.empty();
                                                     }
                                                     return why;
                                                   },
                                                   [this](const NOX::Solver::Generic& solver, bool converged) {
                                                     return augment(solver, converged);
                                                   }))),
      maxIters_(rcp(new IterationLimit(maxIterations))),
      combo_(rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR))) {
  combo_->addStatusTest(finite_);
  if (!before_.is_null()) combo_->addStatusTest(before_);
  combo_->addStatusTest(convergence_);
  combo_->addStatusTest(maxIters_);
}

namespace {

// The largest displacement component of the Newton step that led to the solver's iterate: the full
// direction, not the step a line search shortened (as ResidualTest's update test).
double newtonStep(const NOX::Solver::Generic& solver) {
  auto dx = solver.getSolutionGroup().getX().clone(NOX::DeepCopy);
  dx->update(-1.0, solver.getPreviousSolutionGroup().getX(), 1.0);
  const auto* lineSearch = dynamic_cast<const NOX::Solver::LineSearchBased*>(&solver);
  const double step = lineSearch != nullptr ? lineSearch->getStepSize() : 1.0;
  return step > 0 ? dx->norm(NOX::Abstract::Vector::MaxNorm) / step : HUGE_VAL;
}

}  // namespace

bool NewtonStatusTests::augment(const NOX::Solver::Generic& solver, bool converged) {
  if (augmentation_ == nullptr) return false;
  model::AugmentationPoint at;
  if (!converged) {
    // Early updates only where the iterate is the solve's own (not while Contact Beta holds new contacts
    // back or has just changed what is evaluated).
    if (!augmentation_->hasAugmentedContact()) return false;
    if (stepControl_ != nullptr && (!stepControl_->mayConverge() || !stepControl_->updateMeaningful())) {
      // This iterate's step belongs to another problem than the next one (new contacts held back, or just
      // released): the contraction is measured again from the next two steps.
      previousStep_ = HUGE_VAL;
      return false;
    }
    // The iterate's remaining error, estimated from the contraction ρ of its last two Newton steps
    // (ρ/(1 − ρ) times the last step: a linear rate's geometric tail, and at a quadratic rate more than
    // the next step). None before two steps of the same problem.
    const double step = newtonStep(solver), previous = previousStep_;
    previousStep_ = step;
    const double rate = step / previous;
    if (!std::isfinite(previous) || !(rate < 0.5)) return false;
    at.converged = false;
    at.errorEstimate = rate / (1.0 - rate) * step;
  }
  if (!augmentation_->augmentContact(at)) return false;
  ++augmentations_;
  previousStep_ = HUGE_VAL;  // the next step is the new problem's first
  maxIters_->restartAt(solver.getNumIterations());
  // The one status test that changes the group: the iterate is the start of a new problem at the same load
  // factor (new multipliers), so its f is computed again before the next Newton direction. The group's f
  // and Jacobian are invalidated as a step control's iterateSet hook does it (StepControl.hpp).
  NOX::Abstract::Group& group = group_();
  const auto x = group.getX().clone(NOX::DeepCopy);
  group.setX(*x);
  group.computeF();
  return true;
}

void NewtonStatusTests::startSolve() {
  previousStep_ = HUGE_VAL;
  const MumpsFailures* failures = mumpsFailures(linearSolver_.get());
  linearFailuresAtStart_ = failures != nullptr ? failures->count : 0;
  iterativeFailuresAtStart_ = iterativeSolveLog().failures;
}

SolveFailure NewtonStatusTests::diagnose(const NOX::Solver::Generic& solver, const std::string& noxOutput) const {
  using Kind = SolveFailure::Kind;
  if (solver.getStatus() == NOX::StatusTest::Converged) return {};
  if (convergence_->getStatus() == NOX::StatusTest::Failed && redoRequested_)
    return {Kind::StepCorrection, "stopped for " + stepControl_->correctionName() + ": " + convergence_->rejection()};
  if (convergence_->getStatus() == NOX::StatusTest::Failed)
    return {Kind::Tunnelling, "contact tunnelling: " + convergence_->rejection() +
                                  " (the increment is too large for the contact to follow)"};
  if (finite_->getStatus() == NOX::StatusTest::Failed) {
    const std::string cause = diagnostics_.nonFiniteResidualCause();
    return {Kind::NonFiniteResidual,
            cause.empty() ? std::string("the residual is not finite (NaN or infinite)") : "the residual is not finite: " + cause};
  }
  if (!before_.is_null() && before_->getStatus() == NOX::StatusTest::Failed)
    return {Kind::StepCorrection, "stopped for " + stepControl_->correctionName()};
  if (maxIters_->getStatus() == NOX::StatusTest::Failed) {
    const int n = maxIters_->counted();
    return {Kind::NewtonIterations, "Newton did not converge in " + std::to_string(n) + (n == 1 ? " iteration" : " iterations") +
                                        " (last ||f|| = " + shortNumber(solver.getSolutionGroup().getNormF()) + ")"};
  }
  // No test failed: the iteration itself stopped, in the linear solve or with an exception.
  if (auto linear = linearSolverFailure(); linear.kind != Kind::None) return linear;
  const std::string caught = caughtException(noxOutput);
  return {Kind::Other, caught.empty() ? std::string("the Newton iteration stopped (the linear solve failed)")
                                      : "the Newton iteration stopped: " + caught};
}

SolveFailure NewtonStatusTests::linearSolverFailure() const {
  if (iterativeSolveLog().failures != iterativeFailuresAtStart_)
    return {SolveFailure::Kind::LinearSolver, iterativeSolveLog().lastFailure};
  const MumpsFailures* failures = mumpsFailures(linearSolver_.get());
  if (failures == nullptr || failures->count == linearFailuresAtStart_) return {};
  if (failures->nullPivots > 0)
    return {SolveFailure::Kind::LinearSolver,
            "the stiffness matrix is singular: " + diagnostics_.describeFreeMotion(failures->nullSpace) +
                (failures->nullPivots > static_cast<int>(failures->nullSpace.size())
                     ? " (and " + std::to_string(failures->nullPivots - static_cast<int>(failures->nullSpace.size())) +
                           " more null pivots)"
                     : std::string()) +
                (diagnostics_.hasContact() ? " (add a support; an open contact holds nothing, so a body held by contact "
                                       "alone must touch it from the start)"
                                     : " (add a support: a Dirichlet condition that holds it)")};
  return {SolveFailure::Kind::LinearSolver,
          "the MUMPS factorization failed (INFOG(1) = " + std::to_string(failures->info) + ")"};
}

}  // namespace contessa::solvers
