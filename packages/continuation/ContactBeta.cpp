#include "continuation/ContactBeta.hpp"

#include <algorithm>
#include <cmath>

namespace contessa::continuation {

int automaticContactsPerStep(std::size_t slaveNodes) {
  const double share = std::ceil(kAutomaticContactsShare * static_cast<double>(slaveNodes));
  return std::max(kAutomaticContactsMinimum, static_cast<int>(share));
}

double closureFraction(const GapChange& change, double touchingGap) {
  if (change.inContactAtStart || !std::isfinite(change.gapStart)) return -1;
  if (change.gapStart <= touchingGap) return 0;  // touching: closes at once if it closes at all
  if (!std::isfinite(change.gapEnd)) return -1;
  const double closing = change.gapStart - change.gapEnd;  // denominator of eq. (11)
  if (!(closing > 0)) return -1;                           // moving away, or parallel to the master
  return change.gapStart / closing;                        // eq. (11); = 1 for an exact hit at t + Δt
}

BetaResult computeBeta(const std::vector<GapChange>& changes, const BetaOptions& options) {
  std::vector<double> fractions;
  for (const auto& c : changes) {
    const double b = closureFraction(c, options.touchingGap);
    if (b >= 0) fractions.push_back(b);
  }
  return betaFromFractions(std::move(fractions), options);
}

BetaResult betaFromFractions(std::vector<double> fractions, const BetaOptions& options) {
  BetaResult result;
  result.candidates = std::move(fractions);
  for (double& b : result.candidates) b *= options.eventRateScale;
  std::sort(result.candidates.begin(), result.candidates.end());  // eq. (12)
  std::size_t nc = static_cast<std::size_t>(std::max(1, options.contactsPerStep));
  if (options.nextContactFraction > 0) {  // unavoidable events beyond N_c: take them, and nothing more
    const auto unavoidable = static_cast<std::size_t>(
        std::upper_bound(result.candidates.begin(), result.candidates.end(), 0.0) - result.candidates.begin());
    nc = std::max(nc, unavoidable);
  }
  double beta = options.maxGrowth;
  result.fewCandidates = result.candidates.size() <= nc;
  if (!result.fewCandidates) {
    const double below = result.candidates[nc - 1], above = result.candidates[nc];
    beta = below + options.nextContactFraction * (above - below);
    // Where the planned step (β = 1) falls between event N_c and event N_c + 1.
    result.placement = above > below ? (1.0 - below) / (above - below) : (1.0 < below ? -1.0 : 2.0);
  }
  result.beta = std::clamp(beta, options.maxShrink, options.maxGrowth);
  result.fromEvents = !result.fewCandidates && result.beta == beta;
  result.predictedContacts = static_cast<int>(
      std::upper_bound(result.candidates.begin(), result.candidates.end(), result.beta) - result.candidates.begin());
  return result;
}

}  // namespace contessa::continuation
