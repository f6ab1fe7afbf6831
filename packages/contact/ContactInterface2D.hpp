#pragma once
// Coupling of one 2D contact interface: which slave nodes touch which master segments, their contact
// forces and tangents handed to the assembler, and the committed/trial contact history. Detection
// (BoundingBoxTree + SegmentSelector2D) and resolution (NodeToFacetContact) are used as they are;
// this class only organises them over an interface. Pure C++: the model turns the global DOF ids it
// receives into Tpetra entries.
#include <array>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "contact/ContactHistory.hpp"
#include "contact/ContactLawParameters.hpp"
#include "contact/NodeToFacetContact.hpp"
#include "contact/SegmentSelector2D.hpp"
#include "contact/SlipReversalDamping.hpp"

namespace contessa::contact {

using GlobalIndex = long long;

/// A rigid master surface: a polyline whose points move rigidly by λ · motion. The rigid body lies to
/// the LEFT of the direction of traversal, so its outward normal is on the right (Line2Facet).
struct RigidSurface2D {
  std::vector<Vector<2>> points;  ///< reference positions, in order
  Vector<2> motion{};             ///< displacement of every point at load factor 1
};

/// Everything that defines an interface, in mesh terms.
struct ContactInterfaceSpec2D {
  std::string name;
  std::vector<GlobalIndex> slaveNodes;  ///< mesh nodes, sorted
  std::vector<double> slaveAreas;       ///< tributary length of each slave node (reference), unit thickness
  std::vector<double> slaveFacetLengths;  ///< mean length of the slave sides at each node (slip tolerance's L_k)
  /// Deformable master: mesh node pairs, ordered so the master body's outward normal is on the right.
  std::vector<std::array<GlobalIndex, 2>> masterSegments;
  bool rigidMaster = false;
  RigidSurface2D rigidSurface;  ///< when rigidMaster
  ContactLawParameters law;
};

/// State of one slave node for output (at the last converged increment).
struct SlaveNodeState {
  double pressure = 0;  ///< contact pressure −t_N ≥ 0 (force per unit area), eq. (16)
  double gap = 0;       ///< g_N, eq. (4); +∞ when no master segment is in reach
  ContactStatus status = ContactStatus::Open;
  double slip = 0;      ///< accumulated slip g_T, eq. (7)
};

/// An owned slave node over the increment: the last commit against a trial state, for the load-step
/// correction of eq. (11) and its events (continuation::SlaveNodeIncrement documents each field).
struct SlaveNodeChange {
  double committedGap = std::numeric_limits<double>::infinity();  ///< g_N at the commit; +∞: no master
  double trialGap = std::numeric_limits<double>::infinity();
  ContactStatus committedStatus = ContactStatus::Open, trialStatus = ContactStatus::Open;
  /// Coulomb indicator f (eq. 19) of the committed tractions along the trial slip direction, and
  /// f^trial (eq. 21); NaN unless in contact in both states with μ > 0.
  double committedIndicator = std::numeric_limits<double>::quiet_NaN();
  double trialIndicator = std::numeric_limits<double>::quiet_NaN();
  bool slipReversed = false;  ///< slipping in both states, in opposite directions
};

struct ContactCounts {
  int active = 0, newlyActive = 0, stick = 0, slip = 0;
};

/// A slave node that passed through the master surface in the current increment (tunnelling).
struct TunnellingNode {
  std::size_t slave = 0;   ///< index into ContactInterfaceSpec2D::slaveNodes
  GlobalIndex node = -1;   ///< its mesh node
  int segment = -1;        ///< the master segment it went through
  double time = 0;         ///< where along the increment, 0 (committed) … 1 (trial)
};

class ContactInterface2D {
 public:
  /// `evaluatesSlave[i]`: this rank evaluates slave node i (its owner does, so each contribution is
  /// assembled once).
  ContactInterface2D(ContactInterfaceSpec2D spec, std::vector<char> evaluatesSlave);

  /// Current position of a mesh node (reference + displacement).
  using NodePosition = std::function<Vector<2>(GlobalIndex node)>;
  /// One contact element: global DOF ids (node·2 + c; −1 for a rigid master's DOFs, which are not
  /// unknowns), the residual r_c and tangent ∂r_c/∂u (row-major), and ∂r_c/∂λ (rigid master motion).
  using Sink = std::function<void(const GlobalIndex* dofs, int numDofs, const double* residual,
                                  const double* tangent, const double* dResidualdLambda)>;

  /// Evaluates every slave node this rank owns at the current positions and load factor. With
  /// `updateTrial`, stores the trial history (Newton iterations); without, leaves it alone (reactions).
  void evaluate(const NodePosition& position, double loadFactor, bool updateTrial, const Sink& sink);

  /// The owned slave nodes: the last commit against the latest trial evaluation.
  std::vector<SlaveNodeChange> trialChanges() const;
  /// The owned slave nodes at the given positions and load factor against the last commit (contact
  /// evaluated with every node free to close, no force assembled, no history stored: a look ahead at a
  /// predicted state).
  std::vector<SlaveNodeChange> changesAt(const NodePosition& position, double loadFactor) const;
  /// The owned slave nodes over the last converged increment: its start against its end.
  std::vector<SlaveNodeChange> committedIncrement() const;

  /// While frozen, nodes open at the last commit carry no force (their gaps are still measured): the
  /// first Newton iterate then shows where the body goes without new contacts (eq. 11 of Contact Beta).
  void setNewContactsFrozen(bool frozen) { frozen_ = frozen; }

  /// Slave nodes of this rank that crossed a master segment, from its front to its back, between the
  /// last commit and the latest trial evaluation and are not in contact now (no master in reach, or a
  /// positive gap on another segment): the penalty never saw them (theory-contact.md §12). A node in
  /// contact now is ordinary penalty penetration, whatever it crossed. Each node's straight path is
  /// tested against each segment's straight motion (SweptCrossing) among the candidates of a tree of
  /// swept boxes, so the check costs O((n + m) log m).
  std::vector<TunnellingNode> tunnellingNodes() const;

  /// The increment converged: trial → committed (and the master positions the history refers to).
  void commit();
  /// The increment is abandoned: back to the committed state.
  void rollback();

  const ContactInterfaceSpec2D& spec() const { return spec_; }
  const std::vector<char>& evaluatesSlave() const { return evaluatesSlave_; }
  /// Output of the owned slave nodes at the last commit.
  const std::vector<SlaveNodeState>& committedStates() const { return committedOutput_; }
  /// Counts over owned slave nodes at the last commit (new = open at the commit before).
  ContactCounts committedCounts() const { return committedCounts_; }
  /// Total force the master exerts on the owned slave nodes at the last commit (per unit thickness).
  Vector<2> committedSlaveForce() const { return committedForce_; }

 private:
  std::vector<MasterSegment2D> masterSegments(const NodePosition& position, double loadFactor) const;
  /// Slave node k against its commit: `result` is its contact evaluation with `committed` (its committed
  /// history on the evaluated segment), or null when it was not evaluated (no master, or frozen).
  SlaveNodeChange changeOf(std::size_t k, double gap, const NodeToFacetResult<Line2Facet>* result,
                           const ContactHistory<1>& committed) const;
  /// Slave node k with nothing changed since the commit.
  SlaveNodeChange unchanged(std::size_t k) const;
  std::vector<SlaveNodeChange> owned(const std::vector<SlaveNodeChange>& all) const;

  ContactInterfaceSpec2D spec_;
  std::vector<char> evaluatesSlave_;
  NodeToFacetContact<Line2Facet> element_;
  SegmentSelector2D selector_;
  ContactHistoryStore<1> history_;
  SlipReversalDamping damping_;  ///< tangent of nodes whose slip direction flips between iterates
  std::vector<MasterSegment2D> committedMaster_;  ///< master positions of the committed configuration
  std::vector<MasterSegment2D> lastSegments_;     ///< master positions of the latest trial evaluation
  std::vector<Vector<2>> committedSlave_;         ///< slave positions of the committed configuration
  std::vector<Vector<2>> lastSlave_;              ///< slave positions of the latest trial evaluation
  std::vector<SlaveNodeState> trialOutput_, committedOutput_;
  std::vector<SlaveNodeChange> trialChanges_, committedIncrement_;  ///< per slave node (owned ones set)
  Vector<2> trialForce_{}, committedForce_{};
  ContactCounts committedCounts_;
  bool frozen_ = false;
};

}  // namespace contessa::contact
