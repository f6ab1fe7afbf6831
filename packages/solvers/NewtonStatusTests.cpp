#include "solvers/NewtonStatusTests.hpp"

#include <cstdio>

#include <NOX_Abstract_Group.H>
#include <NOX_Solver_Generic.H>

#include "solvers/IterativeSolveMonitor.hpp"
#include "solvers/MumpsSolver.hpp"

namespace contessa::solvers {

using Teuchos::RCP;
using Teuchos::rcp;

std::string shortNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

std::string loadFactorText(double lambda) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", lambda);
  return text;
}

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

const MumpsFailures* mumpsFailures(const model::ContactMechanicsModel& model) {
  const auto* mumps = dynamic_cast<const MumpsLinearOpWithSolveFactory*>(model.get_W_factory().get());
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
  if (status_ != NOX::StatusTest::Converged) return status_;
  rejection_ = reject_();
  if (!rejection_.empty()) status_ = NOX::StatusTest::Failed;
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

NewtonStatusTests::NewtonStatusTests(const model::ContactMechanicsModel& model, RCP<NOX::StatusTest::Generic> convergence,
                                     int maxIterations, RCP<NOX::StatusTest::Generic> beforeConvergence,
                                     std::function<std::string()> redoStep)
    : model_(model),
      finite_(rcp(new NOX::StatusTest::FiniteValue())),
      before_(std::move(beforeConvergence)),
      // A converged state in which a body has passed through another is no answer: the increment fails
      // and is cut back (theory-contact.md §12).
      convergence_(rcp(new AcceptedConvergenceTest(std::move(convergence),
                                                   [this] {
                                                     redoRequested_ = false;
                                                     std::string why = model_.contactTunnelling();
                                                     if (why.empty() && redoStep_) {
                                                       why = redoStep_();
                                                       redoRequested_ = !why.empty();
                                                     }
                                                     return why;
                                                   }))),
      maxIters_(rcp(new NOX::StatusTest::MaxIters(maxIterations))),
      combo_(rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR))),
      redoStep_(std::move(redoStep)) {
  combo_->addStatusTest(finite_);
  if (!before_.is_null()) combo_->addStatusTest(before_);
  combo_->addStatusTest(convergence_);
  combo_->addStatusTest(maxIters_);
}

void NewtonStatusTests::startSolve() {
  const MumpsFailures* failures = mumpsFailures(model_);
  linearFailuresAtStart_ = failures != nullptr ? failures->count : 0;
  iterativeFailuresAtStart_ = iterativeSolveLog().failures;
}

SolveFailure NewtonStatusTests::diagnose(const NOX::Solver::Generic& solver, const std::string& noxOutput) const {
  using Kind = SolveFailure::Kind;
  if (solver.getStatus() == NOX::StatusTest::Converged) return {};
  if (convergence_->getStatus() == NOX::StatusTest::Failed && redoRequested_)
    return {Kind::ContactBetaRestart, "stopped for a Contact Beta step correction: " + convergence_->rejection()};
  if (convergence_->getStatus() == NOX::StatusTest::Failed)
    return {Kind::Tunnelling, "contact tunnelling: " + convergence_->rejection() +
                                  " (the increment is too large for the contact to follow)"};
  if (finite_->getStatus() == NOX::StatusTest::Failed) {
    const std::string element = model_.inadmissibleElement();
    return {Kind::NonFiniteResidual,
            element.empty() ? std::string("the residual is not finite (NaN or infinite)") : "the residual is not finite: " + element};
  }
  if (!before_.is_null() && before_->getStatus() == NOX::StatusTest::Failed)
    return {Kind::ContactBetaRestart, "stopped for a Contact Beta step correction"};
  if (maxIters_->getStatus() == NOX::StatusTest::Failed) {
    const int n = solver.getNumIterations();
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
  const MumpsFailures* failures = mumpsFailures(model_);
  if (failures == nullptr || failures->count == linearFailuresAtStart_) return {};
  if (failures->nullPivots > 0)
    return {SolveFailure::Kind::LinearSolver,
            "the stiffness matrix is singular: " + model_.describeFreeMotion(failures->nullSpace) +
                (failures->nullPivots > static_cast<int>(failures->nullSpace.size())
                     ? " (and " + std::to_string(failures->nullPivots - static_cast<int>(failures->nullSpace.size())) +
                           " more null pivots)"
                     : std::string()) +
                (model_.hasContact() ? " (add a support; an open contact holds nothing, so a body held by contact "
                                       "alone must touch it from the start)"
                                     : " (add a support: a Dirichlet condition that holds it)")};
  return {SolveFailure::Kind::LinearSolver,
          "the MUMPS factorization failed (INFOG(1) = " + std::to_string(failures->info) + ")"};
}

}  // namespace contessa::solvers
