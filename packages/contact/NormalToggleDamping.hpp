#pragma once
// Damping of a slave node's open/closed cycle during the Newton iterations of an increment (the normal
// counterpart of SlipReversalDamping; docs/theory-contact.md §15 "The open/closed cycle").
#include <cstddef>
#include <vector>

namespace contessa::contact {

/// An open node has no normal stiffness (t_N = 0 for g_N ≥ −λ_N/ε_N, eq. 15.1), so a Newton step from an
/// open state sees only the structure and may carry the node deep into contact, and the step from there,
/// with the full ε_N, back out: a two-state cycle (measured on the frictional tube at ε_N = 1e9, a node at the
/// receding contact edge open at g_N = −λ_N/ε_N + 8e-13 mm and sticking at −3.1e-6 mm, ‖f‖ 6.5e-3 ↔ 5.9e3 N,
/// until the iteration limit). The solution lies between the two states. Once a node has changed between open
/// and closed at `kFlipsToDamp` consecutive iterates and is open, its tangent takes the secant stiffness of
/// the normal law between its last closed state and the open one,
///   k = t_N,closed / (g_N,closed − g_N,open)   (> 0; at most ε_N: the law is t_N = min(0, λ_N + ε_N g_N)),
/// added as k N Nᵀ (SlipTangent::normalStiffness): regula falsi on the node's normal law, a step that lands
/// between the two states instead of across them. A further cycle narrows the bracket. The secant ends when
/// the node closes (its consistent tangent is then ε_N) or stays open for `kReleaseIterates` iterates (it
/// really opens: an open node's tangent is 0, and a secant near ε_N would hold it in place). Only the tangent
/// changes, never the residual: a converged state is a solution of the same equations, an open node carries
/// no force. (The Jacobian check leaves the secant out, ContactInterfaceBase::setConsistentTangents.)
///
/// State per increment: reset when the increment is committed or abandoned. The same evaluation repeated at
/// the same iterate (`same`) changes nothing.
class NormalToggleDamping {
 public:
  /// Changes between open and closed at consecutive iterates (of one problem: one λ_N) before the secant
  /// starts: open, closed, open, closed, open — the cycle repeated. Measured on the frictional tube (fixed
  /// steps): with 3 the run at ε_N = 1e3 damps nodes of the contact edge that settle in three iterates and is
  /// cut back once (463 Newton iterations against 408); with 4 it damps none there and the cycles at 1e5 to
  /// 1e9 still end (docs/theory-contact.md §15).
  static constexpr int kFlipsToDamp = 4;
  static constexpr int kReleaseIterates = 2;

  explicit NormalToggleDamping(std::size_t numNodes) : nodes_(numNodes) {}

  /// The secant normal stiffness of `node` for its next evaluation while open (0: the consistent tangent).
  double stiffness(std::size_t node) const { return nodes_[node].secant; }

  /// Compares the node's state at the new iterate (`open`, its gap g_N and normal traction t_N) with the one
  /// of the previous iterate (`wasOpen`). `same`: the new iterate is the previous one evaluated again.
  /// `multiplier`: the λ_N the node is evaluated with; when it differs from the last observed one (an
  /// augmented Lagrangian update: the same iterate, another problem), the count starts anew — a change of
  /// state there is the update's, not a Newton step's. Returns true when a secant has just been set.
  bool observe(std::size_t node, bool wasOpen, bool open, double gap, double normalTraction, bool same,
               double multiplier = 0.0) {
    if (same) return false;
    NodeState& n = nodes_[node];
    if (multiplier != n.multiplier) {
      n = NodeState{};
      n.multiplier = multiplier;
    } else {
      n.flips = open != wasOpen ? n.flips + 1 : 0;
    }
    if (!open) {
      n.closedGap = gap;
      n.closedTraction = normalTraction;
      n.secant = 0.0;
      n.openIterates = 0;
      return false;
    }
    if (open != wasOpen && n.flips >= kFlipsToDamp && n.closedGap < gap && n.closedTraction < 0.0) {
      n.secant = n.closedTraction / (n.closedGap - gap);
      n.openIterates = 0;
      ++toggles_;
      return true;
    }
    if (n.secant > 0.0 && ++n.openIterates >= kReleaseIterates) n.secant = 0.0;
    return false;
  }

  /// Secants set since the last reset (diagnostics).
  int toggles() const { return toggles_; }

  void reset() {
    nodes_.assign(nodes_.size(), NodeState{});
    toggles_ = 0;
  }

 private:
  struct NodeState {
    double secant = 0.0;          ///< k of the last cycle; 0 = consistent tangent
    double closedGap = 0.0;       ///< g_N at the node's last closed iterate
    double closedTraction = 0.0;  ///< t_N there (< 0)
    int flips = 0;                ///< open/closed changes at consecutive iterates up to the last one observed
    int openIterates = 0;         ///< iterates open since the secant was set
    double multiplier = 0.0;      ///< λ_N of the last observation
  };
  std::vector<NodeState> nodes_;
  int toggles_ = 0;
};

}  // namespace contessa::contact
