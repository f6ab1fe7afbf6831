#include "solvers/ContactBetaStepSize.hpp"

#include <algorithm>
#include <cmath>

#include <LOCA_MultiContinuation_AbstractStrategy.H>
#include <LOCA_MultiContinuation_ExtendedVector.H>
#include <NOX_Solver_Generic.H>
#include <NOX_Thyra_Vector.H>
#include <Thyra_TpetraThyraWrappers.hpp>

namespace contessa::solvers {

namespace {

std::vector<continuation::GapChange> toGapChanges(const std::vector<contact::SlaveGapChange>& gaps) {
  std::vector<continuation::GapChange> out;
  out.reserve(gaps.size());
  for (const auto& g : gaps) out.push_back({g.committedGap, g.trialGap, g.inContactAtCommit});
  return out;
}

}  // namespace

continuation::BetaResult currentBeta(const ContactBetaState& state, const std::vector<contact::SlaveGapChange>& gaps) {
  auto options = state.options;
  if (state.afterFailure) options.maxGrowth = std::min(options.maxGrowth, 1.0);
  if (state.stepSize > 0) {
    // No growth past the step bound, nor past the final load (the stepper clips there anyway).
    options.maxGrowth = std::min({options.maxGrowth, state.maxStep / state.stepSize,
                                  std::max(1.0, (state.finalLoadFactor - state.startLoadFactor) / state.stepSize)});
    options.maxShrink = std::max(options.maxShrink, state.minStep / state.stepSize);
  }
  return continuation::computeBeta(toGapChanges(gaps), options);
}

ContactBetaState contactBetaState(const Teuchos::ParameterList& p) {
  ContactBetaState state;
  state.mode = p.get<std::string>("Mode") == "Predictor" ? ContactBetaState::Mode::Predictor : ContactBetaState::Mode::Restart;
  state.options.contactsPerStep = p.get<int>("Contacts Per Step");
  state.options.maxGrowth = p.get<double>("Max Growth Factor");
  state.options.maxShrink = p.get<double>("Max Shrink Factor");
  state.restartTolerance = p.get<double>("Restart Tolerance");
  state.options.nextContactFraction = p.get<double>("Next Contact Fraction");
  return state;
}

NOX::StatusTest::StatusType ContactBetaRestartTest::checkStatus(const NOX::Solver::Generic& solver,
                                                                NOX::StatusTest::CheckType) {
  status_ = NOX::StatusTest::Unconverged;
  state_.justUnfrozen = false;
  // Table 1: β is determined at the first iteration (i = 1) of an uncorrected attempt (I_cor = 0).
  // That iterate was computed with the contact set of time t (new contacts frozen), so a node about to
  // close shows the penetration it would reach without contact: ^{t+Δt} g_N of eq. (11).
  if (!state_.checkThisAttempt || solver.getNumIterations() != 1) return status_;
  state_.checkThisAttempt = false;
  const auto result = currentBeta(state_, model_.contactGapChanges());
  state_.predictedContacts = result.predictedContacts;
  if (std::abs(result.beta - 1.0) > state_.restartTolerance) {
    state_.beta = result.beta;
    state_.restartRequested = true;
    status_ = NOX::StatusTest::Failed;  // LOCA restarts the increment; the strategy applies β
    return status_;
  }
  // The step stands (the measured β seeds the next increment's step): contact is enforced from here
  // on, and the residual of this iterate is recomputed with it before the convergence tests see it.
  state_.carriedBeta = result.beta;
  state_.justUnfrozen = true;
  model_.setNewContactsFrozen(false);
  auto& group = const_cast<NOX::Abstract::Group&>(solver.getSolutionGroup());
  const auto x = group.getX().clone(NOX::DeepCopy);
  group.setX(*x);
  group.computeF();
  return status_;
}

std::ostream& ContactBetaRestartTest::print(std::ostream& os, int indent) const {
  for (int i = 0; i < indent; ++i) os << ' ';
  os << status_ << "Contact Beta restart: beta = " << state_.beta << " (" << state_.predictedContacts
     << " nodes predicted to close, N_c = " << state_.options.contactsPerStep << ")\n";
  return os;
}

ContactBetaStepSize::ContactBetaStepSize(const Teuchos::ParameterList& p, const model::ContactMechanicsModel& model,
                                         ContactBetaState& state)
    : model_(model),
      state_(state),
      initial_(p.get<double>("Initial Step Size")),
      min_(p.get<double>("Min Step Size")),
      max_(p.get<double>("Max Step Size")),
      failedFactor_(p.get<double>("Failed Step Reduction Factor")) {}

double ContactBetaStepSize::predictedBeta(LOCA::MultiContinuation::AbstractStrategy& curGroup,
                                          const LOCA::MultiContinuation::ExtendedVector& predictor, double stepSize) {
  // LOCA's predictor is (dx/ds, dλ/ds); natural continuation steps in λ: x(λ + Δλ) ≈ x + Δλ dx/dλ.
  const double dlds = predictor.getScalar(0);
  const auto& current = dynamic_cast<const LOCA::MultiContinuation::ExtendedVector&>(curGroup.getX());
  auto xPredicted = current.getXVec()->clone(NOX::DeepCopy);
  if (dlds != 0.0) xPredicted->update(stepSize / dlds, *predictor.getXVec(), 1.0);
  const double lambda = current.getScalar(0) + stepSize;
  const auto& thyra = dynamic_cast<const NOX::Thyra::Vector&>(*xPredicted);
  const auto x = Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>::getConstTpetraVector(
      Teuchos::rcpFromRef(thyra.getThyraVector()));
  const auto result = currentBeta(state_, model_.contactGapChangesAt(*x, lambda));
  state_.predictedContacts = result.predictedContacts;
  return result.beta;
}

NOX::Abstract::Group::ReturnType ContactBetaStepSize::computeStepSize(
    LOCA::MultiContinuation::AbstractStrategy& curGroup, const LOCA::MultiContinuation::ExtendedVector& predictor,
    const NOX::Solver::Generic&, const LOCA::Abstract::Iterator::StepStatus& stepStatus,
    const LOCA::Abstract::Iterator&, double& stepSize) {
  const double requestedBeta = state_.beta;
  const double carriedBeta = state_.carriedBeta;
  state_.carriedBeta = 1.0;
  state_.beta = 1.0;
  state_.afterFailure = false;
  model_.setNewContactsFrozen(false);
  if (first_) {
    first_ = false;
    stepSize = initial_;
  } else if (stepStatus == LOCA::Abstract::Iterator::Unsuccessful) {
    if (state_.restartRequested) {
      // eq. (10): Δt_cor = β Δt, then the increment is solved once more without a new check (I_cor = 1).
      state_.restartRequested = false;
      state_.beta = requestedBeta;
      stepSize *= state_.beta;
      state_.checkThisAttempt = false;
      previous_ = stepSize;
      return NOX::Abstract::Group::Ok;
    }
    stepSize *= failedFactor_;  // a genuine Newton failure: cut back, and check β again
    state_.afterFailure = true;
  } else {
    // After a converged increment the base step is the one just accepted (β-corrected), times the β
    // measured in it when that was too close to 1 to restart for.
    stepSize = (previous_ > 0 ? previous_ : stepSize) * carriedBeta;
  }
  if (stepSize < min_) {
    stepSize = min_;
    state_.hitMinimumStep = true;
    return NOX::Abstract::Group::Failed;
  }
  stepSize = std::min(stepSize, max_);
  // A sliver left for a last increment is taken now: the β check below still guards this step.
  const double remaining = state_.finalLoadFactor - curGroup.getContinuationParameter();
  if (remaining > stepSize && remaining < 1.25 * stepSize && remaining <= max_) stepSize = remaining;
  state_.stepSize = stepSize;
  state_.startLoadFactor = curGroup.getContinuationParameter();
  state_.minStep = min_;
  state_.maxStep = max_;
  if (state_.mode == ContactBetaState::Mode::Predictor) {
    state_.beta = predictedBeta(curGroup, predictor, stepSize);
    stepSize *= state_.beta;
  } else {
    state_.checkThisAttempt = true;
    model_.setNewContactsFrozen(true);
  }
  previous_ = stepSize;
  return NOX::Abstract::Group::Ok;
}

}  // namespace contessa::solvers
