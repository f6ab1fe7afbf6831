#pragma once
// The learned correction of eq. (11): the ratio c of the actual to the predicted event fractions β^k,
// learned from the events that did happen in the last converged increments
// (docs/theory-load-stepping.md §2.2).
#include <vector>

namespace contessa::continuation {

/// Eq. (11) extrapolates each node's gap (or Coulomb indicator) linearly from t to the trial state, and
/// the trial state knows nothing of the events inside the step: in Restart mode the first iterate has
/// the new contacts frozen, in Predictor mode the prediction extrapolates the last increment. When
/// several nodes close in one step, each closure holds the surface back and its neighbours close later
/// than predicted (on the tube, N_c = 4 and 8 gave 3 and 5 closures per increment). This class models
/// the bias as one factor, actual β^k ≈ c × predicted β^k, and learns c from each converged increment:
/// with the predicted fractions s_1 ≤ s_2 ≤ … of the step it took and O events observed, c is
/// consistent when c s_O ≤ 1 < c s_{O+1} (exactly the O first predicted events fit in the step). A
/// consistent c is kept (no drift while the control delivers N_c); an inconsistent one is replaced by
/// the c that puts the step taken at the Next Contact Fraction f between the O-th and (O+1)-th scaled
/// events, i.e. the c with which eq. (13) with f would have chosen this very step for N_c = O:
///   c = 1 / (s_O + f (s_{O+1} − s_O))      (s_0 = 0; only the bound c = 1/s_n when O ≥ n events).
/// c stays within [minScale, maxScale].
class EventRateCorrection {
 public:
  explicit EventRateCorrection(double nextFraction, double minScale = 0.25, double maxScale = 4.0)
      : nextFraction_(nextFraction), minScale_(minScale), maxScale_(maxScale) {}

  /// c: multiply every predicted β^k by it (BetaOptions::eventRateScale).
  double scale() const { return scale_; }
  /// A restarted run: c as it was learned.
  void restoreScale(double scale) { scale_ = scale; }

  /// An increment converged. `predicted`: the unscaled β^k of the counted events predicted for it,
  /// as fractions of the step it finally took (any order); `observed`: the counted events that happened.
  /// Returns true when c changed.
  bool observe(std::vector<double> predicted, int observed);

 private:
  double nextFraction_, minScale_, maxScale_;
  double scale_ = 1.0;
};

}  // namespace contessa::continuation
