#pragma once
// Coupling of one contact interface: which slave nodes touch which master facets, their contact forces and
// tangents handed to the assembler, and the committed/trial contact history. One path for 2D and 3D: the
// model holds ContactInterfaceBase pointers, made by makeContactInterface for the mesh dimension
// (ContactInterface<Line2Facet>, node-to-segment; ContactInterface<Quad4Facet>, node-to-face; both defined
// and instantiated in ContactInterface.cpp). Detection (BoundingBoxTree + FacetSelector), the master
// surface (MasterSurface: deformable or rigid), history transfer and resolution (NodeToFacetContact) are
// used as they are; this class only organises them over an interface. Pure C++: the model turns the global
// DOF ids it receives into Tpetra entries.
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "common/StateRecord.hpp"
#include "contact/ContactCounts.hpp"
#include "contact/ContactHistory.hpp"
#include "contact/InterfaceSpec.hpp"
#include "contact/RegularisationMeasures.hpp"

namespace contessa::contact {

/// State of one slave node for output (at the last converged increment).
struct SlaveNodeState {
  double pressure = 0;  ///< contact pressure −t_N ≥ 0 (force per unit area), eq. (16)
  double gap = 0;       ///< g_N, eq. (4); +∞ when no master facet is in reach
  ContactStatus status = ContactStatus::Open;
  double slip = 0;      ///< accumulated slip g_T, eq. (7)
  /// ‖t_T‖/ε_T, the stretch of the stick spring (RegularisationMeasures); not in the restart file (a
  /// restarted run shows it from its first increment on).
  double elasticSlip = 0;
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
  int trialFacet = -1;        ///< the master facet the trial state was evaluated on (−1: none)
  /// Where on trialFacet the trial state touches (ContactPoint): its kind as an int (0 the projection,
  /// 1 a vertex, 2 an edge point, 3 the projection past a free edge, faded) and the vertex's or the edge's
  /// nodes, local in the facet (−1: none).
  int trialContactKind = 0;
  int trialContactNodes[2] = {-1, -1};
  bool frictional = false;  ///< its interface has μ > 0 (automatic Contact Beta N_c keeps the paper's 2)
};

/// Augmented Lagrangian: the owned slave nodes' largest violations at the latest trial evaluation, each
/// over the slave facet length L_k of its node (the tolerances' unit, ContactLawParameters).
struct AugmentationViolation {
  /// max |g_N|/L_k over the nodes in contact: a penetration −g_N, or a positive gap g_N at which λ_N < 0
  /// still holds the node (eq. 15.1: λ_N + ε_N g_N < 0), both violations of g_N t_N = 0 (eq. 15)
  double penetration = 0;
  double elasticSlip = 0;  ///< max ‖t_T − λ_T‖/(ε_T L_k) over the sticking nodes
};


/// Augmented Lagrangian with friction: a sticking node at an Uzawa update, its stick traction t_T = λ_T + ε_T ā Δξ
/// and its relative motion since it stuck, ā Δξ (covariant, on the node's facet; eq. 15.2).
template <int NXi>
struct StickUpdate {
  Vector<NXi> traction{};
  Vector<NXi> motion{};
};

/// The factor f of the update λ_T ← λ_T + f (t_T − λ_T) of a node that sticks at two successive updates on
/// the same facet (docs/theory-contact.md §15, "The stick multipliers' secant", eq. 15.6–15.7). The plain
/// update (15.3) is f = 1 and shrinks the motion by the node's Uzawa rate K/(K + ε_T) only, near 1 where the
/// pressure and with it ε_T = μ|λ_N|/(s L_k) are small. The structure holds the node with t_T = F − K m
/// (m = ā Δξ its motion since it stuck, F the force it would carry at rest, K its tangential stiffness
/// there), so the multiplier that leaves no motion is λ_T* = t_T + K m, f = 1 + K/ε_T. K is measured from the
/// last two updates, whatever ε_T did between them (it follows λ_N), by a regularised secant
///     K̃ = max(0, −⟨Δt_T, Δm⟩) / (⟨Δm, Δm⟩ + n²)        (ā^αβ inner products, n = `noise`),
/// the secant's K weighted by ⟨Δm, Δm⟩/(⟨Δm, Δm⟩ + n²): a motion change at the Newton error n an update may
/// read gives half the step, a smaller one none. The factor saturates smoothly at `maxFactor`,
///     f = 1 + g/(1 + g/(maxFactor − 1)),   g = K̃/ε_T,
/// and stops on the Coulomb cone ‖λ_T‖ ≤ `coneRadius` = μ|λ_N| (past it the node slips). Every step is a
/// continuous function of the updates with no threshold, and K̃/ε_T is a ratio of like quantities, so that
/// neither round-off, nor the rank count, nor the unit system can switch a node between Uzawa's step and
/// the secant's (the thresholds of the first version did: theory §15).
template <int NXi>
double stickSecantFactor(const StickUpdate<NXi>& previous, const StickUpdate<NXi>& current, const Vector<NXi>& multiplier,
                         double stickPenalty, const Matrix<NXi, NXi>& inverseMetric, double coneRadius, double noise,
                         double maxFactor) {
  const auto inner = [&](const Vector<NXi>& a, const Vector<NXi>& b) { return dot(a, multiply(inverseMetric, b)); };
  const Vector<NXi> motionChange = subtract(current.motion, previous.motion);
  const double regularised = inner(motionChange, motionChange) + noise * noise;
  if (!(stickPenalty > 0.0) || !(regularised > 0.0)) return 1.0;
  const double stiffness =
      std::max(0.0, -inner(subtract(current.traction, previous.traction), motionChange)) / regularised;
  const double stretch = stiffness / stickPenalty;
  const double factor = 1.0 + stretch / (1.0 + stretch / (maxFactor - 1.0));
  // ‖λ + f d‖² = R² on the line, d = t_T − λ_T: a f² + b f + q = 0, q ≤ 0 when λ is inside the cone. Its
  // larger root, with the discriminant kept from going negative, is continuous across q = 0 too (a λ that a
  // step left on the cone may lie a round-off outside it).
  const Vector<NXi> d = subtract(current.traction, multiplier);
  const double a = inner(d, d);
  const double b = 2.0 * inner(multiplier, d);
  const double q = inner(multiplier, multiplier) - coneRadius * coneRadius;
  if (!(a > 0.0)) return 1.0;
  const double onCone = (-b + std::sqrt(std::max(0.0, b * b - 4.0 * a * q))) / (2.0 * a);
  return std::max(1.0, std::min(factor, onCone));
}

/// Augmented Lagrangian, the multiplier predictor (docs/theory-contact.md eq. 15.8): a slave node's converged
/// tractions' change per unit load factor over the last increment, `known` only where the node stuck on one
/// facet at both its ends.
template <int NXi>
struct TractionRate {
  bool known = false;
  double normal = 0.0;       ///< d t_N / dλ
  Vector<NXi> tangential{};  ///< d t_Tα / dλ (covariant, on the node's facet)
};

/// A slave node that passed through the master surface in the current increment (tunnelling).
struct TunnellingNode {
  std::size_t slave = 0;  ///< index into ContactInterfaceSpec::slaveNodes
  GlobalIndex node = -1;  ///< its mesh node
  int facet = -1;         ///< the master facet it went through
  double time = 0;        ///< where along the increment, 0 (committed) … 1 (trial)
};

/// The restart fields of a slave node's change over the last increment and of its output, which the
/// node-to-facet and the mortar interfaces both keep (their saveCommittedSlaves / restoreSlaves: const parts
/// when saving, copies to put back when loading).
template <class Change, class Fields>
void slaveChangeFields(Change& c, Fields& field) {
  field("committed_gap", c.committedGap, StateValues::AnyDouble);  // +inf: no master in reach
  field("trial_gap", c.trialGap, StateValues::AnyDouble);
  field("committed_status", c.committedStatus);
  field("trial_status", c.trialStatus);
  field("committed_indicator", c.committedIndicator, StateValues::AnyDouble);  // NaN unless in frictional contact
  field("trial_indicator", c.trialIndicator, StateValues::AnyDouble);
  field("slip_reversed", c.slipReversed);
}
template <class Output, class Fields>
void slaveOutputFields(Output& o, Fields& field) {
  field("pressure", o.pressure);
  field("gap", o.gap, StateValues::AnyDouble);
  field("output_status", o.status);
  field("output_slip", o.slip);
}

/// One interface as the model sees it, whatever the dimension.
class ContactInterfaceBase {
 public:
  /// Current position of a mesh node (reference + displacement): writes spec().dimension values to x.
  using NodePosition = std::function<void(GlobalIndex node, double* x)>;
  /// One contact element: global DOF ids (node·dim + c; −1 for a rigid master's DOFs, which are not
  /// unknowns), the residual r_c and tangent ∂r_c/∂u (row-major), and ∂r_c/∂λ (a moving rigid master).
  using Sink = std::function<void(const GlobalIndex* dofs, int numDofs, const double* residual,
                                  const double* tangent, const double* dResidualdLambda)>;

  virtual ~ContactInterfaceBase() = default;
  /// A copy with the same state (saved and put back around the finite-difference Jacobian check).
  virtual std::unique_ptr<ContactInterfaceBase> clone() const = 0;

  /// Evaluates every slave node this rank owns at the current positions and load factor. With
  /// `updateTrial`, stores the trial history (Newton iterations); without, leaves it alone (reactions).
  virtual void evaluate(const NodePosition& position, double loadFactor, bool updateTrial, const Sink& sink) = 0;
  /// The owned slave nodes at the given positions and load factor against the last commit (contact
  /// evaluated with every node free to close, no force assembled, no history stored: a look ahead at a
  /// predicted state). The same search as evaluate's (the tree's candidates), O((n + m) log m).
  virtual std::vector<SlaveNodeChange> changesAt(const NodePosition& position, double loadFactor) const = 0;
  /// Slave nodes of this rank that crossed a master facet, from its front to its back, between the last
  /// commit and the latest trial evaluation and are not in contact now (no master in reach, or a positive
  /// gap on another facet): the penalty never saw them (theory-contact.md §12). A node in contact now is
  /// ordinary penalty penetration, whatever it crossed. Each node's straight path is tested against each
  /// facet's straight motion (SweptCrossing) among the candidates of a tree of swept boxes, so the check
  /// costs O((n + m) log m).
  virtual std::vector<TunnellingNode> tunnellingNodes() const = 0;
  /// Load steps (continuation::LoadSchedule): a rigid master's points at X + offset + a · motion, a the
  /// load factor evaluate() is given; nothing for a deformable master.
  virtual void setRigidMotion(const std::vector<double>& offset, const std::vector<double>& motion) = 0;
  /// Load steps: the Coulomb coefficient μ of the evaluations from now on (InputError if the law cannot
  /// take it).
  virtual void setFrictionCoefficient(double mu) = 0;
  /// The increment converged: trial → committed (and the master positions the history refers to).
  virtual void commit() = 0;
  /// The increment is abandoned: back to the committed state (the multipliers too).
  virtual void rollback() = 0;
  /// While `consistent`, every node's tangent is the derivative of its residual: the secant slip
  /// stiffness that SlipReversalDamping gives a node whose slip direction has just reversed (a Newton aid
  /// that changes the tangent, never the residual) is left out of the stiffness, while the damping still
  /// watches the iterates. The Jacobian check's W (JacobianCheck): its differences of the residual measure
  /// the consistent tangent only. Nothing for an interface without such secants.
  virtual void setConsistentTangents(bool /*consistent*/) {}
  /// Slave nodes of this rank to which the latest trial evaluation gave a secant slip tangent (with
  /// consistent tangents: would have given one).
  virtual int secantTangentNodes() const { return 0; }
  /// Augmented Lagrangian (spec().law.isAugmented()): the multipliers take the tractions of the latest
  /// trial evaluation (the Uzawa update, docs/theory-contact.md eq. 15.3), within the increment. Nothing for
  /// an interface without multipliers. `atEquilibrium`: that evaluation is of a converged Newton iterate (not
  /// an early update's, §15 "Updates before convergence"); only there may a sticking node's multiplier take
  /// the secant's step (eq. 15.7), which reads the iterate as an equilibrium of the structure.
  virtual void augment(bool atEquilibrium) { (void)atEquilibrium; }
  /// Augmented Lagrangian, the multiplier predictor (docs/theory-contact.md eq. 15.8), before commit(): each
  /// node's traction rate over the converging increment, whose load factor changed by `loadChange` (NaN:
  /// unknown, no rate), where the node stuck at both of its ends on one facet.
  virtual void measureTractionRates(double loadChange) { (void)loadChange; }
  /// At an attempt's first evaluation, `loadChange` past the last commit: each node with a measured rate gets
  /// the multipliers its tractions extrapolate to (as an update: undone by a cut-back).
  virtual void predictMultipliers(double loadChange) { (void)loadChange; }
  /// The owned slave nodes' violations at the latest trial evaluation (for the augmentation test).
  AugmentationViolation trialViolation() const;
  /// Augmented Lagrangian: the normal penalty from now on is the deck's times `growth` ≥ 1 (penalty growth,
  /// docs/theory-contact.md eq. 15.5); the multipliers are left as they are, so call it only where the problem
  /// changes anyway (with an update). State like the multipliers: kept by a commit, undone by a cut-back.
  void setPenaltyGrowth(double growth);
  double penaltyGrowth() const { return growth_; }
  /// A restarted run: the growth of the restart file's increment (committed too).
  void restorePenaltyGrowth(double growth) {
    setPenaltyGrowth(growth);
    committedGrowth_ = growth;
  }

  // The restart file's state of the committed configuration, by name (docs/architecture.md, "Checkpoint
  // and restart"; common/StateRecord.hpp).
  /// Rows of the table "slaves" (id: slave node index) for the owned slave nodes: history (facet, ξ, t_T,
  /// status, slip), the change over the last increment (Contact Beta reads it), the output and the
  /// committed position.
  virtual void saveCommittedSlaves(StateRecord& table) const = 0;
  /// Reads and checks every row (every rank judges the whole table alike) and puts the owned slave nodes'
  /// rows back as their committed and trial state; InputError naming a field that is missing, of another
  /// shape or not finite, or a missing row.
  virtual void restoreSlaves(const StateRecord& table) = 0;
  /// The table "master" (id: the facet's position): the master facets' committed positions (the same on
  /// every rank).
  virtual void saveCommittedMaster(StateRecord& table) const = 0;
  virtual void restoreMaster(const StateRecord& table) = 0;

  /// The owned slave nodes: the last commit against the latest trial evaluation.
  std::vector<SlaveNodeChange> trialChanges() const { return owned(trialChanges_); }
  /// The owned slave nodes over the last converged increment: its start against its end.
  std::vector<SlaveNodeChange> committedIncrement() const { return owned(committedIncrement_); }
  /// While frozen, nodes open at the last commit carry no force (their gaps are still measured): the
  /// first Newton iterate then shows where the body goes without new contacts (eq. 11 of Contact Beta).
  void setNewContactsFrozen(bool frozen) { frozen_ = frozen; }

  const ContactInterfaceSpec& spec() const { return spec_; }
  const std::vector<char>& evaluatesSlave() const { return evaluatesSlave_; }
  /// Output of the owned slave nodes at the last commit.
  const std::vector<SlaveNodeState>& committedStates() const { return committedOutput_; }
  /// Counts over owned slave nodes at the last commit (new = open at the commit before).
  ContactCounts committedCounts() const { return committedCounts_; }
  /// Total force the master exerts on the owned slave nodes at the last commit (spec().dimension
  /// components; per unit thickness in 2D).
  const std::vector<double>& committedSlaveForce() const { return committedForce_; }
  /// Largest penetration, elastic slip and slip over the owned slave nodes at the last commit (the
  /// displacement scale is the model's to fill in: the interface does not know the reference positions).
  RegularisationMeasures committedRegularisation() const;

 protected:
  /// Reads a restart table of slave-node rows (saveCommittedSlaves): for each row checks its id against
  /// the interface, positions `rows` at it and calls read(k); then fails naming the first slave node
  /// this rank evaluates that has no row. read(k) reads the row's fields and keeps them if
  /// evaluatesSlave()[k].
  void readSlaveRows(const StateRecord& table, StateTableReader& rows,
                     const std::function<void(std::size_t)>& read) const;
  /// `evaluatesSlave[i]`: this rank evaluates slave node i (its owner does, so each contribution is
  /// assembled once).
  ContactInterfaceBase(ContactInterfaceSpec spec, std::vector<char> evaluatesSlave);

  std::vector<SlaveNodeChange> owned(const std::vector<SlaveNodeChange>& all) const;
  /// spec_.law has changed its normal penalty (penalty growth): the element is to be built again.
  virtual void lawChanged() {}
  /// The growth of the increment is kept (commit) or forgotten (rollback).
  void commitPenaltyGrowth() { committedGrowth_ = growth_; }
  void rollbackPenaltyGrowth() { setPenaltyGrowth(committedGrowth_); }

  ContactInterfaceSpec spec_;
  std::vector<char> evaluatesSlave_;
  std::vector<SlaveNodeState> trialOutput_, committedOutput_;
  std::vector<SlaveNodeChange> trialChanges_, committedIncrement_;  ///< per slave node (owned ones set)
  std::vector<double> trialForce_, committedForce_;
  ContactCounts committedCounts_;
  bool frozen_ = false;

 private:
  double deckNormalPenalty_ = 0.0;  ///< spec_.law's before any growth
  double growth_ = 1.0, committedGrowth_ = 1.0;
};

/// The interface of spec.dimension (2: Line2Facet segments, 3: Quad4Facet faces).
std::unique_ptr<ContactInterfaceBase> makeContactInterface(ContactInterfaceSpec spec, std::vector<char> evaluatesSlave);

}  // namespace contessa::contact
