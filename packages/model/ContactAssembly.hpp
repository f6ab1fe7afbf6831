#pragma once
// The contact part of the residual and tangent: drives the contact interfaces (one
// contact::ContactInterfaceBase per interface and pass, whatever the dimension) over the slave nodes this
// rank owns, adds their forces and ∂r_c/∂λ to the overlapped force arrays, and their tangents to the
// Jacobian through StiffnessScatter (positions cached per coupling). It reserves the contact couplings of
// the graph (contact::reserveCouplings: around the reference configuration at set-up), notices, agreed on
// every rank, a pairing outside them, and reserves them again around the current configuration for the
// model's graph rebuild. Holds the interfaces' committed and trial contact history.
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "contact/ContactInterface.hpp"
#include "contact/CouplingReservation.hpp"
#include "continuation/LoadSchedule.hpp"
#include "deck/ProblemDefinition.hpp"
#include "model/ContactAugmentation.hpp"
#include "common/StateRecord.hpp"
#include "model/DofLayout.hpp"
#include "model/StiffnessScatter.hpp"

namespace contessa::model {

class ContactAssembly {
 public:
  using Interfaces = std::vector<std::unique_ptr<contact::ContactInterfaceBase>>;

  /// One interface per spec of `problem`; each slave node is evaluated by the rank that owns it (in its
  /// part of the mesh). Positions come from the contact surfaces' replicated reference coordinates
  /// (problem.contactNodes), which `layout`'s overlap holds.
  ContactAssembly(const deck::ProblemDefinition& problem, const DofLayout& layout);

  /// The nodes of every contact surface (slave nodes and deformable master nodes): every rank holds
  /// them (DofLayout's replicated nodes).
  static std::vector<mesh::GlobalIndex> surfaceNodes(const std::vector<contact::ContactInterfaceSpec>& specs);

  /// Adds to `rows` (per overlapped row, its columns) the couplings reserved for contact (by the reach
  /// rule of contact::CouplingReservation, around the reference configuration until reserveAround).
  void addReservedCouplings(std::vector<std::vector<LO>>& rows) const;

  /// Adds every owned slave node's contact force and ∂r_c/∂λ at the overlapped displacement `u` and load
  /// factor λ to `force` and `dForcedLambda` (overlapped arrays); with `scatter`, its tangent. With
  /// `updateTrial`, stores the trial history. Collective with `scatter`: returns false on every rank when
  /// a slave node (of any rank) met a master facet outside the reserved couplings — their tangents are
  /// then incomplete, and the caller reserves again (reserveAround), rebuilds the graph and assembles
  /// again; throws std::logic_error when a reserved coupling is missing from the graph (a defect).
  /// In a load step (setLoadStep) `lambda` is the step's amplitude a, and ∂r_c/∂λ is scaled by its slope
  /// a' (the rigid masters move with a).
  bool assemble(const double* u, double lambda, bool updateTrial, double* force, double* dForcedLambda,
                StiffnessScatter* scatter, double slope = 1.0);
  /// Load step `step` of `schedule`: each rigid master's motion (X + start + a · change) and friction
  /// coefficient (start + a · change: set before every evaluation where the step changes it).
  void setLoadStep(const continuation::LoadSchedule& schedule, int step);
  /// After assemble() returned false: the first pairing outside the reservation (the same words on every
  /// rank), e.g. "contact interface 'strip': slave node 80 met a master facet beyond the reserved reach 0.5".
  const std::string& outsideReservation() const { return outside_; }
  /// Collective, after assemble() returned false: reserves the couplings of the interfaces that met a
  /// pairing outside their reservation again, around the current configuration (reference + overlapped
  /// displacement `u`), by the same reach rule. Every pairing the last pass made is then reserved.
  void reserveAround(const double* u);

  /// The owned slave nodes at the overlapped displacement `u` and load factor λ against the last commit
  /// (no force, no history stored).
  std::vector<contact::SlaveNodeChange> changesAt(const double* u, double lambda) const;
  /// The owned slave nodes: the last commit against the latest trial evaluation.
  std::vector<contact::SlaveNodeChange> trialChanges() const;
  /// The owned slave nodes over the last converged increment.
  std::vector<contact::SlaveNodeChange> committedIncrement() const;

  void commit();
  void rollback();
  /// Collective, at a Newton iterate: the Uzawa update of every augmented-Lagrangian interface that misses
  /// a tolerance (the largest violation over all ranks) and has updates left in the increment; true when
  /// one was updated. At an unconverged iterate nothing is updated unless the Newton update is below a
  /// tenth of every augmented interface's tolerance lengths (earlyUpdateBound). At a converged one, an
  /// interface out of updates and still outside a tolerance is accepted, and rank 0 says so once per
  /// interface (`lambda`: the load factor, for that line).
  bool augment(double lambda, const AugmentationPoint& at);
  /// This rank's part of the committed contact state, a group "interface_<i>" per interface: its slave
  /// nodes (table "slaves"; rank `writer` also the table "master").
  void saveState(StateRecord& contact, bool writer) const;
  /// The committed contact state from a restart file's group "contact" (this rank's slave nodes, the masters).
  void restore(const StateRecord& contact);
  /// Contact Beta, Restart mode: nodes open at the last commit carry no force while frozen.
  void setNewContactsFrozen(bool frozen);
  bool newContactsFrozen() const { return frozen_; }

  /// Collective: slave nodes that passed through their master surface between the last commit and the
  /// latest evaluation and are not in contact now, in words (ContactMechanicsModel::contactTunnelling).
  std::string tunnelling() const;

  /// Every interface's tangents the consistent ones while `consistent` (ContactInterfaceBase::
  /// setConsistentTangents: no slip-reversal secants), for the Jacobian check.
  void setConsistentTangents(bool consistent);
  /// The owned slave nodes (every interface) to which the latest trial evaluation gave, or with consistent
  /// tangents would have given, a secant slip tangent.
  int secantTangentNodes() const;

  bool empty() const { return interfaces_.empty(); }
  const Interfaces& interfaces() const { return interfaces_; }
  /// Copies of the interfaces with their state, and putting them back (the Jacobian check's evaluations
  /// must leave no trace).
  Interfaces saveState() const;
  void restoreState(const Interfaces& saved);

 private:
  /// A mortar interface's couplings: each owned slave node's weighted-gap support, every node with every other.
  void addMortarCouplings(const contact::ContactInterfaceSpec& spec, const std::vector<char>& evaluates,
                          const contact::CouplingReservation& reservation, std::vector<std::vector<LO>>& rows) const;
  /// A node-to-facet interface's couplings across master edges (its valley blends; frictionless or penalty).
  void addAcrossEdgeCouplings(const contact::ContactInterfaceSpec& spec, std::vector<std::vector<LO>>& rows) const;
  /// Current position of a mesh node: reference + overlapped displacement.
  contact::ContactInterfaceBase::NodePosition positions(const double* u) const;
  /// The owned slave nodes' changes of every interface, in interface order.
  template <class Changes>
  std::vector<contact::SlaveNodeChange> collect(const Changes& changesOf) const;

  const DofLayout& layout_;
  mesh::GlobalIndex numGlobalNodes_;
  std::vector<double> referenceX_;  ///< per overlapped DOF: the reference coordinate (surface nodes; else 0)
  Interfaces interfaces_;
  std::vector<contact::CouplingReservation> reservations_;  ///< per interface: the couplings the graph holds
  std::vector<int> outsideByInterface_;  ///< per interface: the last stiffness pass met a pairing outside (all ranks)
  std::string outside_;                  ///< the first of them, in words
  bool frozen_ = false;
  std::vector<int> augmentations_;  ///< per interface: multiplier updates in the current increment
  /// Per interface: the gap violation (over L) at its last update in the increment (+∞ before the first),
  /// which decides penalty growth (grownPenalty).
  std::vector<double> lastViolation_;
  std::vector<char> augmentationWarned_;
  /// The largest Newton update at which an unconverged iterate's violations are trusted for an update.
  double earlyUpdateBound() const;
  /// Rank 0, once per interface: interface i stopped short of a tolerance (`violation`: its penetration
  /// and elastic slip over L).
  void warnShortOfTolerance(std::size_t i, const double violation[2], double lambda);  ///< per interface: the run has said it stopped short of a tolerance
  /// The multiplier predictor (docs/theory-contact.md eq. 15.8): the load factor (the step's amplitude) of the
  /// last commit (NaN: none yet in load step `predictorStep_`) and of the latest trial evaluation; whether the
  /// attempt's first evaluation at its own load factor is still to come.
  double committedAmplitude_ = std::numeric_limits<double>::quiet_NaN();
  double latestAmplitude_ = std::numeric_limits<double>::quiet_NaN();
  int predictorStep_ = 0;
  bool predictionPending_ = false;
  /// At a trial evaluation at amplitude `a`: the interfaces predict their multipliers if it is the attempt's
  /// first at a load factor other than the commit's.
  void predictMultipliers(double a);
  std::vector<double> frictionStart_, frictionChange_;  ///< per interface, of the current load step
  /// Sets each interface's friction coefficient at amplitude a where the load step changes it.
  void frictionAt(double a) const;
};

}  // namespace contessa::model
