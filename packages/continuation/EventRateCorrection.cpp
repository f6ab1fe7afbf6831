#include "continuation/EventRateCorrection.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <cmath>

namespace contessa::continuation {

bool EventRateCorrection::observe(std::vector<double> s, int observed) {
  std::sort(s.begin(), s.end());
  const std::size_t n = s.size();
  const std::size_t o = static_cast<std::size_t>(std::max(0, observed));
  const std::size_t unavoidable =
      static_cast<std::size_t>(std::upper_bound(s.begin(), s.end(), 0.0) - s.begin());
  // Fewer events than predicted at β^k = 0 (events of any step): the prediction was wrong in kind, not
  // in rate; nothing to learn about c.
  if (o < unavoidable) return false;
  const double inf = std::numeric_limits<double>::infinity();
  const std::size_t last = std::min(o, n);  // the last predicted event that happened (1-based; 0: none)
  const double below = last >= 1 ? s[last - 1] : 0.0;
  const double hi = below > 0 ? 1.0 / below : inf;   // c s_O ≤ 1
  const double lo = o < n ? 1.0 / s[o] : 0.0;        // c s_{O+1} > 1
  if (scale_ > lo && scale_ <= hi) return false;     // consistent: keep
  double c = hi;
  if (o < n) c = 1.0 / (below + nextFraction_ * (s[o] - below));
  c = std::clamp(c, minScale_, maxScale_);
  const bool changed = c != scale_;
  scale_ = c;
  return changed;
}

}  // namespace contessa::continuation
