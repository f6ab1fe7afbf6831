#pragma once
// Contact state of one slave node, and its two copies: committed (last converged increment) and trial
// (current Newton iterate). Friction is path dependent, so the return mapping of eq. (20)–(23) always
// starts from the committed copy; a restarted or cut-back increment (the β restart of Table 1) rolls
// the trial copy back.
#include "contact/SmallMatrix.hpp"

#include <cstddef>
#include <vector>

namespace contessa::contact {

/// The codes are those of the Exodus variable contact_status.
enum class ContactStatus : int { Open = 0, Stick = 1, Slip = 2 };

/// History of one slave node on a master facet with NXi surface coordinates (1 in 2D, 2 in 3D).
template <int NXi>
struct ContactHistory {
  int segment = -1;                   ///< master segment (2D) / face (3D) id the node projects on
  Vector<NXi> xi{};                   ///< ξ^α of the contact point (committed copy: last converged state)
  Vector<NXi> tangentialTraction{};   ///< t_Tα, covariant components, eq. (14), (22)
  ContactStatus status = ContactStatus::Open;
  double accumulatedSlip = 0.0;       ///< g_T, eq. (7)
  /// Augmented Lagrangian (ContactLawParameters::Enforcement), zero with the penalty law. In the committed
  /// copy: the multipliers λ_N ≤ 0 and λ_Tα (covariant, on `segment`) the element uses, eq. (15.1)–(15.2)
  /// of docs/theory-contact.md; in the trial copy: the tractions t_N and t_Tα the next update takes.
  double normalMultiplier = 0.0;
  Vector<NXi> tangentialMultiplier{};

  bool isInContact() const { return status != ContactStatus::Open; }

  friend bool operator==(const ContactHistory& a, const ContactHistory& b) {
    return a.segment == b.segment && a.xi == b.xi && a.tangentialTraction == b.tangentialTraction &&
           a.status == b.status && a.accumulatedSlip == b.accumulatedSlip &&
           a.normalMultiplier == b.normalMultiplier && a.tangentialMultiplier == b.tangentialMultiplier;
  }
  friend bool operator!=(const ContactHistory& a, const ContactHistory& b) { return !(a == b); }
};

using ContactHistory2D = ContactHistory<1>;
using ContactHistory3D = ContactHistory<2>;

/// Committed and trial histories of all slave nodes of a contact pair.
template <int NXi>
class ContactHistoryStore {
 public:
  explicit ContactHistoryStore(std::size_t numSlaveNodes)
      : committed_(numSlaveNodes), trial_(numSlaveNodes), atCommit_(numSlaveNodes) {}

  std::size_t size() const { return committed_.size(); }

  /// State at the last converged increment: the input of the element and of the return mapping.
  const ContactHistory<NXi>& committed(std::size_t node) const { return committed_[node]; }
  /// State at the current iterate (output of the element).
  const ContactHistory<NXi>& trial(std::size_t node) const { return trial_[node]; }
  void setTrial(std::size_t node, const ContactHistory<NXi>& history) { trial_[node] = history; }

  /// The increment converged: the trial state becomes the committed state (ξ_n, t_Tα,n, g_T updated). The
  /// augmented Lagrangian's multipliers are carried so that the converged state stays one: λ_N is the one
  /// the increment used (t_N = λ_N + ε_N g_N unchanged; 0 for a node that opened), λ_T the trial's (the
  /// converged t_T, the stick reference moving to ξ_{n+1}, where the trial of eq. 15.2 is λ_T; a sticking
  /// node's trial history carries its kept reference and λ_T instead, eq. 15.4, ContactInterface). The next
  /// increment then starts from an equilibrium, as the continuation's predictor assumes.
  void commit() {
    for (std::size_t i = 0; i < committed_.size(); ++i) {
      const double normal = trial_[i].isInContact() ? committed_[i].normalMultiplier : 0.0;
      committed_[i] = trial_[i];
      committed_[i].normalMultiplier = normal;
    }
    trial_ = committed_;
    atCommit_ = committed_;
  }
  /// A restarted run: the node's history as the restart file gives it, both copies.
  void restore(std::size_t node, const ContactHistory<NXi>& history) {
    committed_[node] = trial_[node] = atCommit_[node] = history;
  }
  /// The increment is restarted or cut back: forget every trial update and every multiplier update.
  void rollback() {
    committed_ = atCommit_;
    trial_ = committed_;
  }
  /// Uzawa update of the augmented Lagrangian within the increment: each node's multipliers become the
  /// tractions of the latest trial state (λ ← ⟨λ + ε g⟩, docs/theory-contact.md eq. 15.3); the rest of
  /// the committed state stays (the stick reference ξ_n in particular).
  void augment() {
    for (std::size_t i = 0; i < committed_.size(); ++i) {
      committed_[i].normalMultiplier = trial_[i].normalMultiplier;
      committed_[i].tangentialMultiplier = trial_[i].tangentialMultiplier;
    }
  }
  /// The multiplier predictor at an increment's start (docs/theory-contact.md eq. 15.8): the node's multipliers
  /// for this attempt, like an update (a cut-back restores the commit's; the next attempt predicts again).
  void predict(std::size_t node, double normalMultiplier, const Vector<NXi>& tangentialMultiplier) {
    committed_[node].normalMultiplier = normalMultiplier;
    committed_[node].tangentialMultiplier = tangentialMultiplier;
  }

 private:
  std::vector<ContactHistory<NXi>> committed_;
  std::vector<ContactHistory<NXi>> trial_;
  std::vector<ContactHistory<NXi>> atCommit_;  ///< committed_ before this increment's multiplier updates
};

}  // namespace contessa::contact
