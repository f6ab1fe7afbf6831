#pragma once
// Results of the model at a converged state, for output and for Contact Beta: element stresses, reactions
// over node sets, the contact nodal fields, counts and forces of the interfaces, and every slave node's
// change gathered over all ranks. Reads the assemblers; changes nothing.
#include <string>
#include <utility>
#include <vector>

#include "contact/ContactCounts.hpp"
#include "contact/RegularisationMeasures.hpp"
#include "continuation/ContactEvents.hpp"
#include "deck/ProblemDefinition.hpp"
#include "model/TpetraTypes.hpp"

namespace contessa::model {

class DofLayout;
class SolidAssembler;
class ContactAssembly;

/// Reaction force summed over a node set: Σ (f_int − f_ext) over its nodes, the force the supports
/// exert on the body (Abaqus RF convention). Per unit thickness in 2D.
struct NodeSetReaction {
  std::string nodeSet;
  std::vector<double> force;  ///< one entry per component
};

class PostProcessing {
 public:
  PostProcessing(const deck::ProblemDefinition& problem, const DofLayout& layout, const SolidAssembler& solids,
                 const ContactAssembly& contact);

  /// Columns: σ_xx σ_yy σ_zz σ_xy [σ_yz σ_xz] von Mises (axisymmetric: σ_zz is the hoop stress, stress_hoop).
  static std::vector<std::string> elementStressNames(int dimension, bool axisymmetric = false);
  /// One row per owned element at the overlapped displacement `u`.
  Teuchos::RCP<MultiVector> elementStresses(const double* u) const;
  /// The net nodal force (f_int + contact − λ f_ext, owned) summed over each of the deck's reaction node
  /// sets and all ranks.
  std::vector<NodeSetReaction> reactions(const Vector& netForce) const;

  static std::vector<std::string> contactFieldNames();
  /// contact_pressure, contact_gap, contact_status, contact_slip per owned node at the last commit (0 off
  /// the slave surfaces; gap NaN where no master facet is in reach).
  Teuchos::RCP<MultiVector> contactNodalFields() const;
  /// Sums over all ranks and interfaces, at the last commit.
  contact::ContactCounts contactCounts() const;
  /// Force the master exerts on the slave body, per interface (both passes of a two-pass interface summed
  /// under the interface name), summed over ranks: one component per space dimension.
  std::vector<std::pair<std::string, std::vector<double>>> contactForces() const;
  /// Largest penetration, elastic slip and slip per interface (both passes of a two-pass interface under
  /// its name) at the last commit, and the largest displacement magnitude of its slave nodes in the
  /// owned solution `x`: maxima over ranks, the same on every rank.
  std::vector<std::pair<std::string, contact::RegularisationMeasures>> contactRegularisation(const Vector& x) const;

  /// Every slave node (all ranks, all interfaces, the same order on every rank) for Contact Beta: the last
  /// commit against the latest evaluation, against the state at the overlapped displacement `u` and λ, or
  /// over the last converged increment.
  std::vector<continuation::SlaveNodeIncrement> trialIncrement() const;
  std::vector<continuation::SlaveNodeIncrement> incrementAt(const double* u, double loadFactor) const;
  std::vector<continuation::SlaveNodeIncrement> committedIncrement() const;

 private:
  const deck::ProblemDefinition& problem_;
  const DofLayout& layout_;
  const SolidAssembler& solids_;
  const ContactAssembly& contact_;
};

}  // namespace contessa::model
