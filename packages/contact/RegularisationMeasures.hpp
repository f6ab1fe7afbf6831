#pragma once
// How far the penalty regularisation is from the exact Kuhn–Tucker and Coulomb conditions at a converged
// state (issue 21, docs/theory-contact.md §14): the largest penetration, the largest elastic slip and the
// largest slip of an interface, and the test that says when they spoil the answer. A light header: the
// model and the output read it.
#include <algorithm>
#include <cmath>
#include <string>

namespace contessa::contact {

/// Maxima over the slave nodes of one interface (both passes of a two-pass interface) at the last commit.
struct RegularisationMeasures {
  /// Largest penetration −g_N over the nodes in contact: the exact condition (15) wants 0; the penalty
  /// law (16) needs |t_N|/ε_N.
  double penetration = 0.0;
  /// Largest elastic slip ‖t_T‖/ε_T over the nodes in frictional contact: the stretch of the stick spring
  /// of eq. (17), a relative tangential motion the exact Coulomb law (stick: ġ_T = 0) does not have. A
  /// slipping node has μ|t_N|/ε_T (Slip Tolerance × L_k with a slip tolerance).
  double elasticSlip = 0.0;
  /// Largest accumulated slip g_T of eq. (7) over the slave nodes: the relative tangential motion the run
  /// measures (elastic and frictional).
  double slip = 0.0;
  /// Largest displacement magnitude ‖u‖ of the interface's slave nodes: the contact's displacement scale.
  double displacementScale = 0.0;
  /// The frictional nodes that slip (status Slip with μ > 0) and the sum of their accumulated slips: the
  /// slip the interface measures is their mean (meanSlip).
  double slippingNodes = 0.0;
  double slipSum = 0.0;

  double meanSlip() const { return slippingNodes > 0.0 ? slipSum / slippingNodes : 0.0; }

  /// Maxima, and sums of the slipping nodes and their slips (several passes, several ranks).
  void include(const RegularisationMeasures& other) {
    penetration = std::max(penetration, other.penetration);
    elasticSlip = std::max(elasticSlip, other.elasticSlip);
    slip = std::max(slip, other.slip);
    displacementScale = std::max(displacementScale, other.displacementScale);
    slippingNodes += other.slippingNodes;
    slipSum += other.slipSum;
  }
};

/// The fraction of the measured quantity the regularisation may reach before the run says so.
constexpr double kRegularisationWarningFraction = 0.1;

/// Whether the elastic slip exceeds a tenth of the slip measured, the mean slip of the slipping nodes: a
/// node whose slip is below the elastic slip counts as sticking, so the slip zone loses the nodes of smaller
/// slip (docs/theory-contact.md §14). Judged only where some node slips: a sticking interface has no
/// frictional slip to compare with (its elastic slip is all its tangential motion).
inline bool elasticSlipSpoils(const RegularisationMeasures& m) {
  return m.slippingNodes > 0.0 && m.elasticSlip > kRegularisationWarningFraction * m.meanSlip();
}

/// Whether the penetration exceeds a tenth of the contact's displacement scale.
inline bool penetrationSpoils(const RegularisationMeasures& m) {
  return m.penetration > kRegularisationWarningFraction * m.displacementScale;
}

/// ‖t_T‖/ε_T of a node in frictional contact (`normOfTraction` = √(t_α ā^αβ t_β), eq. 19; `penalty` the
/// ε_T the return mapping used); 0 when no stick penalty acted.
inline double elasticSlipOf(double normOfTraction, double penalty) {
  return penalty > 0.0 ? normOfTraction / penalty : 0.0;
}

}  // namespace contessa::contact
