#include "solvers/JacobianCheckObserver.hpp"

#include <algorithm>

#include <LOCA_MultiContinuation_AbstractGroup.H>
#include <LOCA_MultiContinuation_ExtendedVector.H>
#include <NOX_Solver_Generic.H>
#include <NOX_Thyra_Vector.H>

#include "model/ContactMechanicsModel.hpp"
#include "model/JacobianCheck.hpp"

namespace contessa::solvers {

JacobianCheckObserver::JacobianCheckObserver(const model::ContactMechanicsModel& model, std::vector<int> increments,
                                             IncrementObserver& next, std::FILE* out, double plainSolveLoadFactor)
    : model_(model),
      increments_(std::move(increments)),
      next_(next),
      out_(out),
      plainSolveLoadFactor_(plainSolveLoadFactor),
      check_(std::make_unique<model::JacobianCheck>()) {}

JacobianCheckObserver::~JacobianCheckObserver() = default;

void JacobianCheckObserver::incrementConverged(const model::Vector& x, const IncrementReport& report) {
  next_.incrementConverged(x, report);
  increment_ = report.step + 1;
}

void JacobianCheckObserver::runPreIterate(const NOX::Solver::Generic& solver) {
  // The first iterate of a solve, before NOX evaluates anything at it.
  if (solver.getNumIterations() != 0 || increment_ < 1 || increment_ == lastChecked_) return;
  if (!increments_.empty() && std::find(increments_.begin(), increments_.end(), increment_) == increments_.end()) return;
  lastChecked_ = increment_;
  // LOCA's natural continuation solves for (x, λ) together: an extended vector; a LOCA group alone
  // carries λ as its parameter; a plain NOX group solves at a fixed load factor.
  const auto& group = solver.getSolutionGroup();
  const NOX::Abstract::Vector* x = &group.getX();
  double lambda = plainSolveLoadFactor_;
  if (const auto* extended = dynamic_cast<const LOCA::MultiContinuation::ExtendedVector*>(x)) {
    lambda = extended->getScalar(0);
    x = extended->getXVec().get();
  } else if (const auto* loca = dynamic_cast<const LOCA::MultiContinuation::AbstractGroup*>(&group)) {
    lambda = loca->getParam(0);
  }
  const auto& thyraX = dynamic_cast<const NOX::Thyra::Vector&>(*x).getThyraVector();
  const auto result = check_->check(model_, thyraX, lambda);
  ++checks_;
  if (model_.ownedDofMap()->getComm()->getRank() == 0 && out_ != nullptr) {
    std::fprintf(out_, "jacobian check, increment %d (load factor %.6g): %s (%ld residuals, %.1f s)\n", increment_,
                 lambda, model::JacobianCheck::describe(result, model_).c_str(), result.residualEvaluations,
                 result.seconds);
    std::fflush(out_);
  }
}

}  // namespace contessa::solvers
