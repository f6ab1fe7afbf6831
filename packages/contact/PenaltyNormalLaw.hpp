#pragma once
// Normal part of the contact law: penalty regularisation of the Kuhn–Tucker conditions (15).
#include "common/Error.hpp"

#include <string>

namespace contessa::contact {

/// eq. (16): t_N = ε_N g_N, active only for a penetrating node, g_N < 0 (eq. 6).
///
/// Sign convention: g_N < 0 gives t_N < 0, a compressive normal traction, consistent with t̄_N ≤ 0 of
/// eq. (15). The force this traction exerts on the slave node is −t_N n̄ = ε_N |g_N| n̄, along the
/// master's outward normal: it pushes the slave node out of the master body (see NodeToFacetContact).
class PenaltyNormalLaw {
 public:
  explicit PenaltyNormalLaw(double normalPenalty) : penalty_(normalPenalty) {
    requireInput(normalPenalty > 0.0,
                 "contact: the normal penalty epsilon_N must be > 0, got " + std::to_string(normalPenalty));
  }

  /// `multiplier` λ_N ≤ 0 is the augmented Lagrangian's (0: the penalty law). The augmented traction is
  /// that of Simo & Laursen (1992), eq. (4.5) in the sign convention here (compression < 0):
  ///   t_N = min(0, λ_N + ε_N g_N),
  /// which is eq. (16) for λ_N = 0. A node with λ_N < 0 is active while g_N < −λ_N/ε_N (possibly > 0).
  bool isActive(double gap, double multiplier = 0.0) const { return multiplier + penalty_ * gap < 0.0; }
  /// t_N, eq. (16) (or its augmented form); 0 for an open node.
  double traction(double gap, double multiplier = 0.0) const {
    return isActive(gap, multiplier) ? multiplier + penalty_ * gap : 0.0;
  }
  /// dt_N/dg_N: ε_N when active, 0 otherwise.
  double tractionDerivative(double gap, double multiplier = 0.0) const {
    return isActive(gap, multiplier) ? penalty_ : 0.0;
  }

  double penalty() const { return penalty_; }

 private:
  double penalty_;
};

}  // namespace contessa::contact
