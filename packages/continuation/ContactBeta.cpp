#include "continuation/ContactBeta.hpp"

#include <algorithm>
#include <cmath>

namespace contessa::continuation {

double closureFraction(const GapChange& change, double touchingGap) {
  if (change.inContactAtStart || !std::isfinite(change.gapStart)) return -1;
  if (change.gapStart <= touchingGap) return 0;  // touching: closes at once if it closes at all
  if (!std::isfinite(change.gapEnd)) return -1;
  const double closing = change.gapStart - change.gapEnd;  // denominator of eq. (11)
  if (!(closing > 0)) return -1;                           // moving away, or parallel to the master
  return change.gapStart / closing;                        // eq. (11); = 1 for an exact hit at t + Δt
}

BetaResult computeBeta(const std::vector<GapChange>& changes, const BetaOptions& options) {
  BetaResult result;
  for (const auto& c : changes) {
    const double b = closureFraction(c, options.touchingGap);
    if (b >= 0) result.candidates.push_back(b);
  }
  std::sort(result.candidates.begin(), result.candidates.end());  // eq. (12)
  const std::size_t nc = static_cast<std::size_t>(std::max(1, options.contactsPerStep));
  double beta = options.maxGrowth;
  if (result.candidates.size() > nc)
    beta = result.candidates[nc - 1] + options.nextContactFraction * (result.candidates[nc] - result.candidates[nc - 1]);
  result.beta = std::clamp(beta, options.maxShrink, options.maxGrowth);
  result.predictedContacts = static_cast<int>(
      std::upper_bound(result.candidates.begin(), result.candidates.end(), result.beta) - result.candidates.begin());
  return result;
}

}  // namespace contessa::continuation
