#pragma once
// The 2D node-to-segment penalty contact element with Coulomb friction: one slave node k and the two
// nodes of its master segment, 6 dofs ordered [x_k, y_k, x_1, y_1, x_2, y_2]. It returns the contact
// residual and its consistent tangent for the current positions x = X + u and the committed history.
#include "contact/ContactLawParameters.hpp"
#include "contact/CoulombReturnMapping.hpp"
#include "contact/PenaltyNormalLaw.hpp"
#include "contact/Projection.hpp"

namespace contessa::contact {

/// Current positions of the slave node and of the master segment's nodes 1 → 2 (see Line2Facet for
/// the orientation that makes n̄ the outward normal of the master body).
struct NodeToSegmentGeometry2D {
  Vector<2> slave{};
  std::array<Vector<2>, 2> master{};
};

/// Which tangent to build. Consistent is the exact derivative of the residual (quadratic Newton);
/// PaperMainTerms keeps only eq. (24)–(26), for comparison and verification.
enum class TangentTerms { Consistent, PaperMainTerms };

/// The tangential stiffness ∂t_T1/∂ξ̄ of a slipping node in the tangent. Consistent: eq. (27), zero along the
/// slip with one surface coordinate. Secant: a given stiffness instead, for a node whose slip direction
/// flips between Newton iterates (SlipReversalDamping): the secant of t_T1 between the two states of the
/// cycle, so the step lands between them, in the stick range, instead of jumping across it. The residual,
/// hence the converged answer, is the same either way.
struct SlipTangent {
  bool secant = false;
  double stiffness = 0.0;  ///< ∂t_T1/∂ξ̄ used when `secant` (at most the stick stiffness ε_T ā_11)

  static SlipTangent consistent() { return {}; }
  static SlipTangent secantOf(double stiffness) { return {true, stiffness}; }
};

struct NodeToSegmentResult2D {
  static constexpr int kDofs = 6;

  ProjectionResult<Line2Facet> projection{};   ///< ξ̄, ā_1, ā_11, n̄, g_N on the segment (unclamped)
  ContactStatus status = ContactStatus::Open;  ///< Open, Stick or Slip at this iterate
  double normalTraction = 0.0;                 ///< t_N = ε_N g_N, eq. (16)
  double tangentialTraction = 0.0;             ///< t_T1, covariant, eq. (22)
  ReturnMappingResult<1> friction{};           ///< trial state of eq. (20)–(23), when evaluated
  Vector<kDofs> residual{};                    ///< r_c = t_N ∂g_N/∂u + t_T1 ∂ξ̄/∂u
  Matrix<kDofs, kDofs> tangent{};              ///< K_c = ∂r_c/∂u
  ContactHistory<1> trial{};                   ///< trial history to store for this slave node

  /// Force exerted by the contact on the slave node, −r_c[0..1]; along +n̄ when penetrating.
  Vector<2> slaveForce() const { return {-residual[0], -residual[1]}; }
};

/// Node-to-segment contact element, 2D.
///
/// Residual (virtual work of the contact tractions, eq. (14) with the point-wise tractions of
/// eq. (16) and (22)):
///   r_c = t_N ∂g_N/∂u + t_T1 ∂ξ̄/∂u,     ∂g_N/∂u = N  (eq. 26),   ∂ξ̄/∂u = D^1 + g_N ā^11 N̄_1,
/// where, with H_i = H_i(ξ̄), D^1 = ā^11 T_1 and
///   N   = [ n̄;  −H_1 n̄;  −H_2 n̄ ]          T_1   = [ ā_1; −H_1 ā_1; −H_2 ā_1 ]     (eq. 26)
///   N̄_1 = [ 0;  H_1,1 n̄;  H_2,1 n̄ ]         T̄_1   = [ 0;   H_1,1 ā_1; H_2,1 ā_1 ]
/// (N̄_1·δu = n̄·δā_1 and T̄_1·δu = ā_1·δā_1 = ½ δā_11: the motion of the master nodes rotates and
/// stretches the segment.) It is added to the internal forces: R(u) = f_int + r_c − f_ext, K = ∂R/∂u.
/// Since t_N < 0 in contact, the force on the slave node, −r_c = ε_N|g_N| n̄ + …, pushes it out.
///
/// History: the element reads the committed history of the node on THIS segment (after a segment
/// change, first map it with transferHistory2D) and returns the trial history. A node whose committed
/// status is Open is a first contact: its stick reference point is the current ξ̄ and it carries no
/// tangential traction in this increment (friction starts from the first converged contact point).
class NodeToSegmentContact2D {
 public:
  static constexpr int kDofs = 6;

  explicit NodeToSegmentContact2D(const ContactLawParameters& parameters,
                                  TangentTerms terms = TangentTerms::Consistent);

  /// Residual, tangent and trial history for the current positions `x` on master segment `segment`.
  /// `facetLength` is L_k, the mean length of the slave sides at the node (reference configuration): the
  /// length the slip tolerance refers to (ε_T = μ|t_N|/(s L_k), ContactLawParameters); unused when s = 0.
  NodeToSegmentResult2D evaluate(const NodeToSegmentGeometry2D& x, int segment, const ContactHistory<1>& committed,
                                 double facetLength = 0.0, SlipTangent slipTangent = SlipTangent::consistent()) const;

  const ContactLawParameters& parameters() const { return parameters_; }

 private:
  ContactLawParameters parameters_;
  TangentTerms terms_;
  PenaltyNormalLaw normalLaw_;
  CoulombReturnMapping<1> returnMapping_;
};

}  // namespace contessa::contact
