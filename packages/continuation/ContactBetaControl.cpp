#include "continuation/ContactBetaControl.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <cstdio>
#include <cstdlib>
static const bool kTrace = std::getenv("CONTESSA_BETA_TRACE") != nullptr;  // TRACE

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
    : settings_(settings), correction_(settings.beta.nextContactFraction) {}

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
  checkPending_ = settings_.mode == ContactBetaSettings::Mode::Restart;
  return {true, step_, checkPending_};
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
    if (kTrace) {  // TRACE
      std::vector<double> f = fractions; std::sort(f.begin(), f.end());
      std::fprintf(stderr, "TRACE learn: step %.5f observed %d c %.4f; s:", step_, countEvents(increment, settings_.counted), correction_.scale());
      for (std::size_t i = 0; i < f.size() && i < 14; ++i) std::fprintf(stderr, " %.3f", f[i]);
      std::fprintf(stderr, "\n");
    }
    correction_.observe(std::move(fractions), countEvents(increment, settings_.counted));
    if (kTrace) std::fprintf(stderr, "TRACE   -> c %.4f\n", correction_.scale());  // TRACE
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
  checkPending_ = false;
  step_ *= beta_;
  return {true, step_, false};
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
  if (std::abs(r.beta - 1.0) > settings_.restartTolerance) {
    beta_ = r.beta;
    restartRequested_ = true;
    return true;
  }
  carriedBeta_ = r.beta;
  justReleased_ = true;
  return false;
}

void ContactBetaControl::recordPrediction(const std::vector<SlaveNodeIncrement>& nodes, const BetaResult& r) {
  predictedEvents_ = r.predictedContacts;
  predictedFractions_ = eventFractions(nodes, settings_.counted, settings_.beta.touchingGap);
  predictionStep_ = plannedStep_;
  lastBetaFromEvents_ = r.fromEvents;
}

BetaResult ContactBetaControl::betaFor(const std::vector<SlaveNodeIncrement>& nodes) const {
  BetaOptions options = settings_.beta;
  options.eventRateScale = learning() ? correction_.scale() : 1.0;
  if (afterFailure_) options.maxGrowth = std::min(options.maxGrowth, 1.0);
  if (step_ > 0) {
    // No growth past the step bound, nor past the final load (the stepper clips there anyway).
    options.maxGrowth = std::min({options.maxGrowth, settings_.maxStep / step_,
                                  std::max(1.0, (settings_.finalLoadFactor - startLambda_) / step_)});
    options.maxShrink = std::max(options.maxShrink, settings_.minStep / step_);
  }
  BetaResult r = betaFromFractions(eventFractions(nodes, settings_.counted, settings_.beta.touchingGap), options);
  if (kTrace) {  // TRACE
    std::fprintf(stderr, "TRACE beta: step %.5f c %.4f beta %.4f pred %d few %d; cand:", step_, options.eventRateScale, r.beta, r.predictedContacts, (int)r.fewCandidates);
    for (std::size_t i = 0; i < r.candidates.size() && i < 14; ++i) std::fprintf(stderr, " %.3f", r.candidates[i]);
    std::fprintf(stderr, "\n");
  }
  if (r.fewCandidates && settings_.quietGrowth == QuietGrowth::Newton && lastNewtonIterations_ > 0) {
    r.beta = std::clamp(newtonGrowth(), std::min(1.0, options.maxGrowth), options.maxGrowth);
    r.predictedContacts = static_cast<int>(std::upper_bound(r.candidates.begin(), r.candidates.end(), r.beta) -
                                           r.candidates.begin());
  }
  return r;
}

double ContactBetaControl::newtonGrowth() const {
  // Placeholder, decided in §5.1: grow as the last increment's Newton iterations allow.
  return static_cast<double>(settings_.targetNewtonIterations) / std::max(1, lastNewtonIterations_);
}

}  // namespace contessa::continuation
