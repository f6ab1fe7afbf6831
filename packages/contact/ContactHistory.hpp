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

  bool isInContact() const { return status != ContactStatus::Open; }

  friend bool operator==(const ContactHistory& a, const ContactHistory& b) {
    return a.segment == b.segment && a.xi == b.xi && a.tangentialTraction == b.tangentialTraction &&
           a.status == b.status && a.accumulatedSlip == b.accumulatedSlip;
  }
  friend bool operator!=(const ContactHistory& a, const ContactHistory& b) { return !(a == b); }
};

using ContactHistory2D = ContactHistory<1>;
using ContactHistory3D = ContactHistory<2>;

/// Committed and trial histories of all slave nodes of a contact pair.
template <int NXi>
class ContactHistoryStore {
 public:
  explicit ContactHistoryStore(std::size_t numSlaveNodes) : committed_(numSlaveNodes), trial_(numSlaveNodes) {}

  std::size_t size() const { return committed_.size(); }

  /// State at the last converged increment: the input of the element and of the return mapping.
  const ContactHistory<NXi>& committed(std::size_t node) const { return committed_[node]; }
  /// State at the current iterate (output of the element).
  const ContactHistory<NXi>& trial(std::size_t node) const { return trial_[node]; }
  void setTrial(std::size_t node, const ContactHistory<NXi>& history) { trial_[node] = history; }

  /// The increment converged: the trial state becomes the committed state (ξ_n, t_Tα,n, g_T updated).
  void commit() { committed_ = trial_; }
  /// A restarted run: the node's history as the restart file gives it, both copies.
  void restore(std::size_t node, const ContactHistory<NXi>& history) { committed_[node] = trial_[node] = history; }
  /// The increment is restarted or cut back: forget every trial update.
  void rollback() { trial_ = committed_; }

 private:
  std::vector<ContactHistory<NXi>> committed_;
  std::vector<ContactHistory<NXi>> trial_;
};

}  // namespace contessa::contact
