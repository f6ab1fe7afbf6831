#pragma once
// Damping of two-state cycles in the slip direction during the Newton iterations of an increment.
#include "contact/ContactHistory.hpp"
#include "contact/NodeToSegmentContact2D.hpp"

#include <cstddef>
#include <vector>

namespace contessa::contact {

/// A slipping node has no tangential stiffness along its slip (eq. 27 with one surface coordinate), so a
/// Newton step can carry it across its whole stick range into slip the other way, and the next step back:
/// the two-state cycle of nearly unloaded nodes (MOOSE's ping-pong, Code_Aster's "sliding forward/backward"
/// cycle, docs/theory-contact.md §5). This class watches each slave node's trial state from iterate to
/// iterate; when its slip direction reverses, the node's tangent takes the stick stiffness
/// (SlipTangent::StickStiffness) until it sticks or keeps its direction for one iterate, then the
/// consistent tangent again (quadratic convergence at the end). Only the tangent changes, never the
/// residual: the converged answer is the same with or without damping.
///
/// State per Newton iterate: reset when the increment is committed or abandoned. The same evaluation
/// repeated at the same iterate (residual and Jacobian computed in separate calls) changes nothing.
class SlipReversalDamping {
 public:
  explicit SlipReversalDamping(std::size_t numNodes) : damped_(numNodes, 0) {}

  /// The slip tangent to use for `node` at the next evaluation.
  SlipTangent tangent(std::size_t node) const {
    return damped_[node] ? SlipTangent::StickStiffness : SlipTangent::Consistent;
  }

  /// Compares the node's new trial state with the one of the previous iterate (the committed state at the
  /// first iterate of an increment). Returns true when the slip direction has just reversed.
  bool observe(std::size_t node, const ContactHistory<1>& previous, const ContactHistory<1>& current) {
    if (current == previous) return false;  // the same iterate evaluated again
    const bool reversed = previous.status == ContactStatus::Slip && current.status == ContactStatus::Slip &&
                          previous.segment == current.segment &&
                          previous.tangentialTraction[0] * current.tangentialTraction[0] < 0.0;
    if (reversed) ++reversals_;
    if (reversed) damped_[node] = 1;
    else if (current.status != ContactStatus::Slip) damped_[node] = 0;
    return reversed;
  }

  /// Reversals seen since the last reset (diagnostics).
  int reversals() const { return reversals_; }

  void reset() {
    damped_.assign(damped_.size(), 0);
    reversals_ = 0;
  }

 private:
  std::vector<char> damped_;
  int reversals_ = 0;
};

}  // namespace contessa::contact
