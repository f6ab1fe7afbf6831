#pragma once
// `--check-jacobian`: the assembled Jacobian W = ∂f/∂x of the model evaluator (solids and contact
// together) against central differences of its residual, column by column, on any number of ranks.
// Works through the Thyra::ModelEvaluator interface (evalModel with x perturbed, and with W); of the
// model beyond it, it needs only to put its evaluation state back afterwards and to name who couples
// two DOFs. A debugging aid: 2 residual evaluations per unknown.
//
// Entry error, robust against tiny entries (docs/user-guide.md, "Checking the Jacobian"):
//   e_ij = |W_ij − D_ij| / max(|W_ij|, τ · max_k |W_ik|),   τ = rowFloor,
// D_ij = (f_i(x + h_j e_j) − f_i(x − h_j e_j)) / (2 h_j),   h_j = η · max(|x_j|, ‖x‖_∞, 1),  η = step,
// W is the derivative with every contact node's state held: its status (open, stick, slip, slip reversed),
// the master facet it is evaluated on, and where on it the node touches (its projection, an edge point or a
// vertex, which edge or vertex, past a free edge, blended over a valley edge). The facet and the contact point
// are HELD during the perturbed evaluations (ContactMechanicsModel::holdContactPoints: each slave node is
// evaluated on the facet and at the contact point of f(x), the facet extended past its edges), so D_ij is
// the derivative of the branch W is on. A node on a line of master nodes (a knife edge: a step of ±h_j of a
// master node tilts two coplanar faces into a ridge on one side and a valley on the other) is so compared
// like with like; before the hold such columns were differenced on one side or not compared (the 3D ring on
// a node line: 64 columns not compared, 71 one-sided; docs/verification-contact.md §9.4). (A node past a
// free edge by round-off only, its fade's weight exactly 1, is held unfaded: W is that branch's derivative to
// round-off, and the held facet's extension across an interior edge is no free edge.)
// The status follows the contact law and is not held: where it changes on one side of ±h_j (the residual's
// kink: a contact opening or closing, stick turning to slip), D_ij is the one-sided
// difference on the other side (second order, with a half step added there, which must keep the state
// too); where it changes on both sides, h_j shrinks by 1e-2 twice (τ grows as 1/h_j with it, as the noise
// does), and a column that still straddles kinks is not compared (counted and named in the report, by what
// changed: status, facet, contact point; with the hold only a status, or a held node's fade starting or
// ending past a free edge: its entries have no derivative to check at this state).
// Where the residual bends within h_j (h_j |f''| / 2 above 1e-4 of an entry's scale, from the second
// difference of the same residuals), the column is differenced again with h_j shrunk (up to twice, τ
// growing with it): when both agree to 1e-5 the longer step's differences stand, else the shorter's
// (counted in the report). A slipping 3D frictional node needs it: its slip direction turns by
// ε_T h_j / ‖t^trial‖, which is of order 1 when ‖t^trial‖ is a few μ|t_N| and ε_T h_j ≈ 1 (a wrong W
// is not hidden by it: the shorter step only measures f' more accurately).
// Norm-wise: ‖W − D‖_F / ‖W‖_F.
//
// check() compares the consistent tangent, which is Newton's W except at a slave node whose slip direction
// has just reversed: SlipReversalDamping gives it a secant stiffness along its slip (a Newton aid; the
// residual is unchanged), the derivative of no residual. Such nodes are counted in the report. (The Tet10
// Coulomb block's first iterate of increment 2 reverses node 20: its secant 9.5e4 against a consistent 0
// along the slip showed as W = 36.1 against FD = −119.4, an FD that held from h = 1e-6 down to 1e-10.)
#include <memory>
#include <string>

#include <Thyra_LinearOpBase.hpp>
#include <Thyra_VectorBase.hpp>

#include "model/ContactMechanicsModel.hpp"

namespace contessa::model {

struct JacobianComparison {
  double worstRelativeError = 0;  ///< max e_ij (infinite when a perturbed residual was not finite)
  GO row = -1, column = -1;       ///< global DOF ids of the worst entry
  double assembled = 0, finiteDifference = 0;  ///< W_ij and D_ij there
  double normwiseError = 0;       ///< ‖W − D‖_F / ‖W‖_F
  long residualEvaluations = 0;
  long nonSmoothColumns = 0;      ///< columns with a contact status change on both sides at every step tried
  GO firstNonSmoothColumn = -1;
  /// Of the columns not compared, those where some node's status (open, stick, slip, slip reversed), its
  /// master facet, or its contact point on the facet (projection, edge, vertex, past a free edge, blended:
  /// ContactPoint) changes. With the facet and contact point held only the status can (and the fade of a
  /// node held past a free edge).
  long nonSmoothFor[3] = {0, 0, 0};
  long oneSidedColumns = 0;       ///< columns differenced on one side: the other side changes a contact state
  long oneSidedFor[3] = {0, 0, 0};  ///< of those, the changes (status, facet, contact point) as above
  long retriedColumns = 0;        ///< columns differenced again at a shorter step because the residual bends within h
  long bentColumns = 0;           ///< of those, the ones whose differences changed: compared at the shorter step
  /// check(): slave nodes to which Newton's W at this iterate gives a secant slip tangent (their slip has
  /// just reversed: SlipReversalDamping); W is checked with their consistent tangents instead.
  long secantTangentNodes = 0;
  double seconds = 0;
};

class JacobianCheck {
 public:
  struct Options {
    double step = 1e-6;      ///< η: relative perturbation
    /// τ: entries below τ · (row maximum) are measured against it. A penalty row's residual carries
    /// round-off of about ε_N · 1e-16 · |X| (ε_N the penalty, |X| the coordinates), which central
    /// differences turn into noise of about 1e-16 |X| / h ≈ 1e-9 of its largest entry; with τ = 1e-4
    /// that noise shows as relative errors of a few 1e-6.
    double rowFloor = 1e-4;
  };
  JacobianCheck() = default;
  explicit JacobianCheck(Options options) : options_(options) {}

  /// Compares the model's own W at (x, λ) with central differences. Collective. Leaves the model's
  /// evaluation state (trial element and contact histories, the latest pass) exactly as it was, and
  /// verifies it for the contact history (throws std::logic_error otherwise).
  JacobianComparison check(const ContactMechanicsModel& model, const Thyra::VectorBase<double>& x, double lambda) const;
  /// Compares a given operator `W` (a Tpetra CrsMatrix over the model's spaces) with central
  /// differences of the model's residual at (x, λ). Collective; leaves the model's state as check() does.
  JacobianComparison compare(const ContactMechanicsModel& model, const Thyra::VectorBase<double>& x, double lambda,
                             const Thyra::LinearOpBase<double>& W) const;

  /// One line: "worst relative error 3.1e-09 at row node 41 y, column node 40 x (contact 'plate' slave
  /// node 41), W = ..., FD = ...; norm-wise 2.0e-11". Errors in 2 significant digits.
  static std::string describe(const JacobianComparison& result, const ContactMechanicsModel& model);

 private:
  Options options_;
};

}  // namespace contessa::model
