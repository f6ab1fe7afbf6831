#include "solvers/ContactBetaStepSize.hpp"

#include <cmath>
#include <stdexcept>

#include <LOCA_MultiContinuation_AbstractStrategy.H>
#include <LOCA_MultiContinuation_ExtendedVector.H>
#include <NOX_Solver_Generic.H>
#include <NOX_Thyra_Vector.H>

namespace contessa::solvers {

using continuation::ContactBetaSettings;

NOX::StatusTest::StatusType ContactBetaRestartTest::checkStatus(const NOX::Solver::Generic& solver,
                                                                NOX::StatusTest::CheckType) {
  // The first iterate of a checked attempt is decided before the status tests (iterateSet): a check still
  // pending here means the solver no longer calls its observers where LOCA 13.2's NOX does.
  if (solver.getNumIterations() == 1 && control_.control().checkPending())
    throw std::logic_error("Contact Beta: the first iterate reached the status tests unchecked (NOX observer order)");
  status_ = control_.firstIterateRejected() ? NOX::StatusTest::Failed : NOX::StatusTest::Unconverged;
  return status_;
}

std::ostream& ContactBetaRestartTest::print(std::ostream& os, int indent) const {
  const auto& control = control_.control();
  for (int i = 0; i < indent; ++i) os << ' ';
  os << status_ << "Contact Beta restart: beta = " << control.beta() << " (" << control.predictedEvents()
     << " events predicted, N_c = " << control.appliedContactsPerStep() << ")\n";
  return os;
}

std::vector<continuation::SlaveNodeIncrement> ContactBetaStepSize::predictedNodes(
    LOCA::MultiContinuation::AbstractStrategy& curGroup, const LOCA::MultiContinuation::ExtendedVector& predictor,
    double stepSize) const {
  // LOCA's predictor is (dx/ds, dλ/ds); natural continuation steps in λ: x(λ + Δλ) ≈ x + Δλ dx/dλ.
  const double dlds = predictor.getScalar(0);
  const auto& current = dynamic_cast<const LOCA::MultiContinuation::ExtendedVector&>(curGroup.getX());
  auto xPredicted = current.getXVec()->clone(NOX::DeepCopy);
  if (dlds != 0.0) xPredicted->update(stepSize / dlds, *predictor.getXVec(), 1.0);
  const double lambda = current.getScalar(0) + stepSize;
  const auto& thyra = dynamic_cast<const NOX::Thyra::Vector&>(*xPredicted);
  return events_.trialIncrementAt(thyra.getThyraVector(), lambda);
}

NOX::Abstract::Group::ReturnType ContactBetaStepSize::computeStepSize(
    LOCA::MultiContinuation::AbstractStrategy& curGroup, const LOCA::MultiContinuation::ExtendedVector& predictor,
    const NOX::Solver::Generic& solver, const LOCA::Abstract::Iterator::StepStatus& stepStatus,
    const LOCA::Abstract::Iterator&, double& stepSize) {
  events_.freezeNewContacts(false);
  const double lambda = curGroup.getContinuationParameter();
  continuation::AttemptPlan plan;
  if (first_) {
    first_ = false;
    plan = control_.firstAttempt(lambda);
  } else if (stepStatus == LOCA::Abstract::Iterator::Unsuccessful) {
    plan = control_.restartRequested() ? control_.afterBetaRestart() : control_.afterFailedAttempt(lambda);
  } else {
    plan = control_.afterConvergedIncrement(lambda, events_.committedIncrement(), solver.getNumIterations());
  }
  stepSize = plan.step;
  if (!plan.ok) return NOX::Abstract::Group::Failed;
  if (control_.settings().mode == ContactBetaSettings::Mode::Predictor && !plan.corrected)
    stepSize = control_.correctByPrediction(predictedNodes(curGroup, predictor, stepSize));
  if (plan.checkFirstIterate) events_.freezeNewContacts(true);
  previous_ = stepSize;
  return NOX::Abstract::Group::Ok;
}

void ContactBetaStepSize::saveState(StateRecord& state) const {
  StateWriter fields(state);
  stateFields(*this, fields);
  control_.saveState(state.child("contact_beta"));
}

void ContactBetaStepSize::loadState(const StateRecord& state) {
  control_.loadState(state.child("contact_beta"));
  StateReader fields(state);
  stateFields(*this, fields);
}

}  // namespace contessa::solvers
