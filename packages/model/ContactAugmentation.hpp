#pragma once
// What the Newton solve of an increment needs of the augmented Lagrangian (docs/theory-contact.md §15): at an
// iterate, whether the contact multipliers are to be updated and the same load factor solved again (Uzawa).
// No Trilinos; of the contact package only the law's parameters (the growth's bound).
#include <algorithm>
#include <cmath>

#include "contact/ContactLawParameters.hpp"

namespace contessa::model {

/// Penalty growth in the method of multipliers (Bertsekas 1982, *Constrained optimization and Lagrange
/// multiplier methods*, §2.2; docs/theory-contact.md eq. 15.5): at a multiplier update whose gap `violation`
/// (over L) exceeds its `tolerance`, the normal penalty grows unless the increment's last update
/// (`lastViolation`, +∞ before the first) has reduced it to a quarter — by the factor that would have left a
/// thirtieth of the tolerance with the penalty alone (a penetration goes as 1/ε_N), to at most 30 times the
/// deck's value. Returns the new factor over the deck's penalty (`growth` the current one; never smaller).
/// As any violation above the tolerance asks for 30 or more, the first growth reaches the bound: in effect
/// the penalty grows once, by 30, at the first update the run needs.
constexpr double kGrowthReduction = 0.25;
/// A thirtieth: after the growth the grown penalty alone carries the load still to come until the next
/// update, and the answer follows the mean penetration; with a tenth the tube's plate force at ε_N = 1e3 is
/// 1.2e-5 to 1.7e-5 off, with a thirtieth 4e-6 to 6e-6, as with the updates of every increment before.
constexpr double kGrowthTarget = 1.0 / 30.0;
/// The bound: 100 or 1000 times the deck's penalty left the stick patch test with tolerances of 1e-12
/// unsolvable (3D: Newton stalls at ‖f‖ 3.7e-10 at the initial state), 30 solves it (theory §15).
constexpr double kMaxGrowth = contact::ContactLawParameters::kMaxPenaltyGrowth;
inline double grownPenalty(double growth, double violation, double tolerance, double lastViolation) {
  const bool converging = violation <= kGrowthReduction * lastViolation && lastViolation < HUGE_VAL;
  if (!(tolerance > 0.0) || !(violation > tolerance) || converging) return growth;
  return std::max(growth, std::min(kMaxGrowth, growth * violation / (kGrowthTarget * tolerance)));
}

/// The Newton iterate at which an update is asked for.
struct AugmentationPoint {
  bool converged = true;  ///< the solve's convergence test holds there
  /// Otherwise (an early update, §15 "Updates before convergence"): the iterate's remaining displacement
  /// error, estimated from its last Newton steps (largest component).
  double errorEstimate = 0.0;
};

class ContactAugmentation {
 public:
  virtual ~ContactAugmentation() = default;
  /// Collective, at a Newton iterate of an increment. True (on every rank): some interface with
  /// Enforcement = Augmented Lagrangian misses its Penetration or Elastic Slip Tolerance and has updates
  /// left in this increment; its multipliers now hold the iterate's tractions, and the residual is to be
  /// computed again (the state is no answer yet). At an unconverged iterate, only when its gaps are known to
  /// a tenth of every augmented interface's tolerances (the error estimate below that). False: go on (accept
  /// a converged iterate).
  virtual bool augmentContact(const AugmentationPoint& at) = 0;
  /// Whether some interface has Enforcement = Augmented Lagrangian (the same on every rank).
  virtual bool hasAugmentedContact() const = 0;
};

}  // namespace contessa::model
