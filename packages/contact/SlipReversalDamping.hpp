#pragma once
// Damping of two-state cycles in the slip direction during the Newton iterations of an increment.
#include "contact/ContactHistory.hpp"
#include "contact/NodeToFacetContact.hpp"

#include <cstddef>
#include <vector>

namespace contessa::contact {

/// A slipping node has no tangential stiffness along its slip (eq. 27 along the slip direction), so a
/// Newton step can carry it across its whole stick range into slip the other way, and the next step back:
/// the two-state cycle of nearly unloaded nodes (MOOSE's ping-pong, Code_Aster's "sliding forward/backward"
/// cycle, docs/theory-contact.md §5). This class watches each slave node's trial state from iterate to
/// iterate. When its slip direction reverses, the solution lies between the two states (in the stick range
/// or at its edge), and the node's tangent takes the secant stiffness of t_T1 between them,
/// Δt_T1/Δξ (SlipTangent::secantOf): regula falsi on the node's friction law, a step that lands between the
/// two states instead of across them. A further reversal narrows the bracket. The secant ends when the node
/// sticks (its consistent tangent is then the stick stiffness), or when it has slipped the same way for
/// `kReleaseIterates` iterates (it really slips: the consistent tangent restores quadratic convergence).
/// Only the tangent changes, never the residual: the converged answer is the same with or without it. (So
/// the secant is the derivative of no residual: the Jacobian check leaves it out, ContactInterfaceBase::
/// setConsistentTangents.)
///
/// `reversalsToDamp`: the reversals at consecutive iterates before the node's secant starts. Node-to-segment
/// damps every reversal (1). Mortar (3) damps a node once its slip has reversed at three iterates in a row,
/// A B A B, the two-state cycle repeating: one or two reversals are also the predictor's overshoot on an
/// oblique slide and Newton's correction of it (A B A, then on the same way), which a secant would slow from
/// quadratic to linear (the 3D Coulomb block, docs/verification-contact.md §9.5: damping the second reversal
/// in a row or within the increment did, 151 -> 155 Newton iterations and six pairs no longer quadratic).
///
/// State per increment: reset when the increment is committed or abandoned. The same evaluation repeated at
/// the same iterate (residual and Jacobian computed in separate calls) changes nothing.
class SlipReversalDamping {
 public:
  static constexpr int kReleaseIterates = 2;

  explicit SlipReversalDamping(std::size_t numNodes, int reversalsToDamp = 1)
      : nodes_(numNodes), reversalsToDamp_(reversalsToDamp) {}

  /// The slip tangent to use for `node` at the next evaluation.
  SlipTangent tangent(std::size_t node) const {
    const NodeState& n = nodes_[node];
    return n.secant > 0.0 ? SlipTangent::secantOf(n.secant) : SlipTangent::consistent();
  }

  /// Compares the node's new trial state with the one of the previous iterate (the committed state at the
  /// first iterate of an increment). Returns true when the slip direction has just reversed.
  template <int NXi>
  bool observe(std::size_t node, const ContactHistory<NXi>& previous, const ContactHistory<NXi>& current) {
    if (current == previous) return false;  // the same iterate evaluated again
    NodeState& n = nodes_[node];
    const bool bothSlip = previous.status == ContactStatus::Slip && current.status == ContactStatus::Slip &&
                          previous.segment == current.segment;
    // With two surface coordinates (3D) the tractions and the slip are compared in the parent coordinates:
    // reversed when the traction turns by more than 90°, the secant is Δt·Δξ/Δξ·Δξ along the slip.
    const Vector<NXi> dt = subtract(current.tangentialTraction, previous.tangentialTraction);
    const Vector<NXi> dxi = subtract(current.xi, previous.xi);
    const bool reversed = bothSlip && dot(previous.tangentialTraction, current.tangentialTraction) < 0.0;
    const double dtAlong = dot(dt, dxi);
    n.run = reversed && dtAlong > 0.0 ? n.run + 1 : 0;
    if (reversed && dtAlong > 0.0 && n.run < reversalsToDamp_) {
      ++reversals_;  // a reversal not (yet) a cycle: the consistent tangent
    } else if (reversed && dtAlong > 0.0) {
      // > 0: the traction follows the motion (one coordinate: Δt/Δξ, written so to keep 2D answers bit-identical)
      n.secant = NXi == 1 ? dt[0] / dxi[0] : dtAlong / dot(dxi, dxi);
      n.streak = 0;
      ++reversals_;
    } else if (current.status == ContactStatus::Slip && n.secant > 0.0 && ++n.streak >= kReleaseIterates) {
      n.secant = 0.0;
    } else if (current.status != ContactStatus::Slip) {
      n.secant = 0.0;
    }
    return reversed;
  }

  /// Reversals seen since the last reset (diagnostics).
  int reversals() const { return reversals_; }

  void reset() {
    nodes_.assign(nodes_.size(), NodeState{});
    reversals_ = 0;
  }

 private:
  struct NodeState {
    double secant = 0.0;  ///< secant stiffness Δt_T1/Δξ of the last reversal; 0 = consistent tangent
    int streak = 0;       ///< iterates slipping the same way since the last reversal
    int run = 0;          ///< reversals at consecutive iterates up to the last one observed
  };
  std::vector<NodeState> nodes_;
  int reversalsToDamp_;
  int reversals_ = 0;
};

}  // namespace contessa::contact
