#include "solvers/ContactBetaStepSize.hpp"

#include <cmath>
#include <stdexcept>

#include <LOCA_MultiContinuation_AbstractStrategy.H>
#include <LOCA_MultiContinuation_ExtendedVector.H>
#include <NOX_Solver_Generic.H>
#include <NOX_Thyra_Vector.H>

namespace contessa::solvers {

using continuation::ContactBetaSettings;

ContactBetaSettings contactBetaSettings(const Teuchos::ParameterList& p, double finalLoadFactor) {
  ContactBetaSettings s;
  s.mode = p.get<std::string>("Mode") == "Predictor" ? ContactBetaSettings::Mode::Predictor
                                                      : ContactBetaSettings::Mode::Restart;
  s.beta.contactsPerStep = p.get<int>("Contacts Per Step");
  s.beta.maxGrowth = p.get<double>("Max Growth Factor");
  s.beta.maxShrink = p.get<double>("Max Shrink Factor");
  s.beta.nextContactFraction = p.get<double>("Next Contact Fraction");
  s.counted = continuation::countedEventsByName(p.get<std::string>("Counted Events"));
  s.learnEventRate = p.get<bool>("Learn Event Rate");
  s.quietGrowth = continuation::quietGrowthByName(p.get<std::string>("Growth Without Events"));
  s.targetNewtonIterations = p.get<int>("Target Newton Iterations");
  s.maxCorrections = p.get<int>("Max Corrections Per Increment");
  s.restartTolerance = p.get<double>("Restart Tolerance");
  s.initialStep = p.get<double>("Initial Step Size");
  s.minStep = p.get<double>("Min Step Size");
  s.maxStep = p.get<double>("Max Step Size");
  s.failedStepFactor = p.get<double>("Failed Step Reduction Factor");
  s.finalLoadFactor = finalLoadFactor;
  return s;
}

NOX::StatusTest::StatusType ContactBetaRestartTest::checkStatus(const NOX::Solver::Generic& solver,
                                                                NOX::StatusTest::CheckType) {
  status_ = NOX::StatusTest::Unconverged;
  control_.nextIterate();
  // Table 1: β is determined at the first iteration (i = 1) of an uncorrected attempt (I_cor = 0).
  // That iterate was computed with the contact set of time t (new contacts frozen), so a node about to
  // close shows the penetration it would reach without contact: ^{t+Δt} g_N of eq. (11).
  if (!control_.checkPending() || solver.getNumIterations() != 1) return status_;
  if (control_.restartAtFirstIterate(events_.trialIncrement())) {
    status_ = NOX::StatusTest::Failed;  // LOCA restarts the increment; the strategy applies β
    return status_;
  }
  // The step stands (the measured β seeds the next increment's step): contact is enforced from here
  // on, and the residual of this iterate is recomputed with it before the convergence tests see it.
  events_.freezeNewContacts(false);
  auto& group = const_cast<NOX::Abstract::Group&>(solver.getSolutionGroup());
  const auto x = group.getX().clone(NOX::DeepCopy);
  group.setX(*x);
  group.computeF();
  return status_;
}

std::ostream& ContactBetaRestartTest::print(std::ostream& os, int indent) const {
  for (int i = 0; i < indent; ++i) os << ' ';
  os << status_ << "Contact Beta restart: beta = " << control_.beta() << " (" << control_.predictedEvents()
     << " events predicted, N_c = " << control_.settings().beta.contactsPerStep << ")\n";
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
