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

  bool isActive(double gap) const { return gap < 0.0; }
  /// t_N, eq. (16); 0 for an open node.
  double traction(double gap) const { return isActive(gap) ? penalty_ * gap : 0.0; }
  /// dt_N/dg_N: ε_N when active, 0 otherwise.
  double tractionDerivative(double gap) const { return isActive(gap) ? penalty_ : 0.0; }

  double penalty() const { return penalty_; }

 private:
  double penalty_;
};

}  // namespace contessa::contact
