#include "continuation/ContactBetaControl.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace contessa::continuation {

const std::vector<std::string>& quietGrowthNames() {
  static const std::vector<std::string> names = {"Max Growth Factor", "Newton Iterations"};
  return names;
}

QuietGrowth quietGrowthByName(const std::string& name) {
  const auto& names = quietGrowthNames();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) throw std::invalid_argument("unknown growth rule '" + name + "'");
  return static_cast<QuietGrowth>(it - names.begin());
}

ContactBetaControl::ContactBetaControl(const ContactBetaSettings& settings)
    : settings_(settings), correction_(settings.beta.nextContactFraction),
      appliedContactsPerStep_(settings.beta.contactsPerStep) {}

int ContactBetaControl::contactsPerStep(const std::vector<SlaveNodeIncrement>& nodes) const {
  if (settings_.beta.contactsPerStep != kAutomaticContactsPerStep) return settings_.beta.contactsPerStep;
  const bool frictional = std::any_of(nodes.begin(), nodes.end(), [](const auto& n) { return n.frictional; });
  return frictional ? kAutomaticContactsMinimum : automaticContactsPerStep(nodes.size());
}

AttemptPlan ContactBetaControl::plan(double base, double lambda) {
  if (base < settings_.minStep) {
    step_ = settings_.minStep;
    hitMinimumStep_ = true;
    return {false, step_, false};
  }
  double step = std::min(base, settings_.maxStep);
  // A sliver left for a last increment is taken now: the β check still guards this step.
  const double remaining = settings_.finalLoadFactor - lambda;
  if (remaining > step && remaining < 1.25 * step && remaining <= settings_.maxStep) step = remaining;
  step_ = plannedStep_ = step;
  startLambda_ = lambda;
  rechecks_ = 0;
  redos_ = 0;
  redoing_ = false;
  checkPending_ = settings_.mode == ContactBetaSettings::Mode::Restart;
  return {true, step_, checkPending_, false};
}

AttemptPlan ContactBetaControl::firstAttempt(double lambda) {
  beta_ = 1;
  carriedBeta_ = 1;
  afterFailure_ = false;
  return plan(settings_.initialStep, lambda);
}

AttemptPlan ContactBetaControl::afterConvergedIncrement(double lambda, const std::vector<SlaveNodeIncrement>& increment,
                                                        int newtonIterations) {
  double base = step_ * carriedBeta_;
  if (learning() && predictionStep_ > 0 && step_ > 0) {
    // The predicted β^k were fractions of predictionStep_; the increment took step_.
    std::vector<double> fractions = predictedFractions_;
    for (double& s : fractions) s *= predictionStep_ / step_;
    const double before = correction_.scale();
    correction_.observe(std::move(fractions), countEvents(increment, settings_.counted));
    // Restart mode carries the β measured at the last first iterate; it scales with c (β is homogeneous
    // in the β^k when an event, not a bound, determined it), so the next check need not restart for it.
    if (settings_.mode == ContactBetaSettings::Mode::Restart && lastBetaFromEvents_)
      base *= correction_.scale() / before;
  }
  predictionStep_ = 0;
  lastNewtonIterations_ = newtonIterations;
  beta_ = 1;
  carriedBeta_ = 1;
  afterFailure_ = false;
  return plan(base, lambda);
}

AttemptPlan ContactBetaControl::afterBetaRestart() {
  // eq. (10): Δt_cor = β Δt, solved once more without a new check (I_cor = 1).
  restartRequested_ = false;
  step_ *= beta_;
  if (redoing_) {  // a redo after a converged attempt: new contacts active from the start, no check
    redoing_ = false;
    checkPending_ = false;
    return {true, step_, false, true};
  }
  // A β far from 1 extrapolated the first iterate's gaps far beyond the step they were measured
  // with: the corrected step is checked once more at its own first iterate (eq. 11 re-linearised).
  ++rechecks_;
  checkPending_ = settings_.beta.nextContactFraction > 0 && rechecks_ <= settings_.maxCorrections &&
                  std::abs(std::log(beta_)) > std::log(2.0);
  plannedStep_ = step_;
  return {true, step_, checkPending_, true};
}

AttemptPlan ContactBetaControl::afterFailedAttempt(double lambda) {
  beta_ = 1;
  carriedBeta_ = 1;
  afterFailure_ = true;  // no growth right after a failure
  predictionStep_ = 0;
  return plan(step_ * settings_.failedStepFactor, lambda);
}

double ContactBetaControl::correctByPrediction(const std::vector<SlaveNodeIncrement>& predicted) {
  const BetaResult r = betaFor(predicted);
  recordPrediction(predicted, r);
  beta_ = r.beta;
  step_ *= beta_;
  return step_;
}

bool ContactBetaControl::restartAtFirstIterate(const std::vector<SlaveNodeIncrement>& firstIterate) {
  checkPending_ = false;
  const BetaResult r = betaFor(firstIterate);
  recordPrediction(firstIterate, r);
  if (!standsAsPlanned(r)) {
    beta_ = r.beta;
    restartRequested_ = true;
    return true;
  }
  carriedBeta_ = r.beta;
  justReleased_ = true;
  return false;
}

bool ContactBetaControl::standsAsPlanned(const BetaResult& r) const {
  const double f = settings_.beta.nextContactFraction;
  if (f <= 0 || r.fewCandidates || !r.fromEvents) return std::abs(r.beta - 1.0) <= settings_.restartTolerance;
  return r.placement >= 0.5 * f && r.placement < 0.5 * (1.0 + f);
}

std::string ContactBetaControl::redoAtConvergence(const std::vector<SlaveNodeIncrement>& converged) {
  const double f = settings_.beta.nextContactFraction;
  if (f <= 0 || redos_ >= settings_.maxCorrections || step_ <= 0) return "";  // f = 0: Table 1 as printed
  const int n = std::max(1, contactsPerStep(converged));
  appliedContactsPerStep_ = n;
  const int observed = countEvents(converged, settings_.counted);
  if (observed == n) return "";
  double beta = 1;
  if (observed < n) {
    // Fewer events than N_c: the nodes still heading for an event at the converged state give their
    // fractions of this step (eq. 11 between the commit and the converged state: > 1), now with the
    // stiffness of the contacts closed in it.
    if (afterFailure_) return "";
    std::vector<double> s = eventFractions(converged, settings_.counted, settings_.beta.touchingGap);
    std::sort(s.begin(), s.end());
    if (static_cast<int>(s.size()) <= n) return "";  // not N_c events ahead: the quiet growth decides
    beta = s[n - 1] + f * (s[n] - s[n - 1]);
  } else {
    // More events than N_c: the converged state only says they closed; their order is the predicted
    // one, rescaled so that the O-th predicted event falls where the step ended (EventRateCorrection).
    if (predictionStep_ <= 0) return "";
    std::vector<double> s = predictedFractions_;
    for (double& x : s) x *= predictionStep_ / step_;
    std::sort(s.begin(), s.end());
    const int m = static_cast<int>(s.size());
    const int unavoidable = static_cast<int>(std::upper_bound(s.begin(), s.end(), 0.0) - s.begin());
    if (m <= n || unavoidable >= observed || s[n - 1] <= 0) return "";
    const int o = std::min(observed, m);
    const double at = o < m ? s[o - 1] + f * (s[o] - s[o - 1]) : s[o - 1];
    beta = (s[n - 1] + f * (s[n] - s[n - 1])) / at;
  }
  const double maxGrowth = std::min({settings_.beta.maxGrowth, settings_.maxStep / step_,
                                     std::max(1.0, (settings_.finalLoadFactor - startLambda_) / step_)});
  beta = std::clamp(beta, std::max(settings_.beta.maxShrink, settings_.minStep / step_), std::max(1.0, maxGrowth));
  if (std::abs(beta - 1.0) < 0.02) return "";  // the bounds leave nothing to correct
  ++redos_;
  beta_ = beta;
  redoing_ = true;
  restartRequested_ = true;
  return std::to_string(observed) + " events instead of " + std::to_string(n) + ", step x " + std::to_string(beta);
}

void ContactBetaControl::recordPrediction(const std::vector<SlaveNodeIncrement>& nodes, const BetaResult& r) {
  predictedEvents_ = r.predictedContacts;
  appliedContactsPerStep_ = contactsPerStep(nodes);
  predictedFractions_ = eventFractions(nodes, settings_.counted, settings_.beta.touchingGap);
  predictionStep_ = plannedStep_;
  lastBetaFromEvents_ = r.fromEvents;
}

BetaResult ContactBetaControl::betaFor(const std::vector<SlaveNodeIncrement>& nodes) const {
  BetaOptions options = settings_.beta;
  options.contactsPerStep = contactsPerStep(nodes);
  options.eventRateScale = learning() ? correction_.scale() : 1.0;
  if (afterFailure_) options.maxGrowth = std::min(options.maxGrowth, 1.0);
  if (step_ > 0) {
    // No growth past the step bound, nor past the final load (the stepper clips there anyway).
    options.maxGrowth = std::min({options.maxGrowth, settings_.maxStep / step_,
                                  std::max(1.0, (settings_.finalLoadFactor - startLambda_) / step_)});
    options.maxShrink = std::max(options.maxShrink, settings_.minStep / step_);
  }
  BetaResult r = betaFromFractions(eventFractions(nodes, settings_.counted, settings_.beta.touchingGap), options);
  if (r.fewCandidates && settings_.quietGrowth == QuietGrowth::Newton && lastNewtonIterations_ > 0) {
    r.beta = std::clamp(newtonGrowth(), std::min(1.0, options.maxGrowth), options.maxGrowth);
    r.predictedContacts = static_cast<int>(std::upper_bound(r.candidates.begin(), r.candidates.end(), r.beta) -
                                           r.candidates.begin());
  }
  return r;
}

double ContactBetaControl::newtonGrowth() const {
  // §11.5: an increment that converged in fewer iterations than the target grows the next step by
  // their ratio (as LOCA's Adaptive control does), one that took more shrinks it.
  return static_cast<double>(settings_.targetNewtonIterations) / std::max(1, lastNewtonIterations_);
}

void ContactBetaControl::saveState(StateRecord& state) const {
  StateWriter fields(state);
  stateFields(*this, fields);
  fields("event_rate_scale", correction_.scale());
}

void ContactBetaControl::loadState(const StateRecord& state) {
  StateReader fields(state);
  stateFields(*this, fields);
  double scale = 1;
  fields("event_rate_scale", scale);
  correction_.restoreScale(scale);
}

}  // namespace contessa::continuation
