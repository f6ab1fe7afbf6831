#pragma once
// The deck's boundary conditions on the DOF layout: Dirichlet rows with their values ū at λ = 1, the
// dead external forces f_ext at λ = 1 (nodal forces, and the tractions and body forces of Problem/Loads),
// the springs to ground (Problem/Loads, Type Spring), and the follower loads (ExternalLoads, which the
// model's assembly pass calls). They turn the assembled forces into the residual of the model,
// f = f_int + r_c − λ f_p(x) − λ f_ext + K_s u on free rows and u − λ ū on prescribed rows, and its ∂/∂λ.
// A spring is a support: its force −K_s u is the reaction of its node set (reactions: f_int − λ f_ext
// with the follower loads in the assembled forces, the springs not).
#include <memory>
#include <vector>

#include "deck/ProblemDefinition.hpp"
#include "model/DofLayout.hpp"
#include "model/ExternalLoads.hpp"

namespace contessa::model {

class BoundaryConditions {
 public:
  /// Throws InputError when two conditions prescribe the same DOF differently.
  BoundaryConditions(const deck::ProblemDefinition& problem, const DofLayout& layout);

  ~BoundaryConditions();

  /// f = force − λ f_ext + K_s x on free rows, x − λ ū on prescribed rows (owned vectors).
  void residual(const Vector& force, const Vector& x, double lambda, Vector& f) const;
  /// d = ∂force/∂λ − f_ext on free rows (a rigid master moves with λ), −ū on prescribed rows.
  void dResidualdLambda(const Vector& dForcedLambda, Vector& d) const;

  /// Owned local rows with a Dirichlet condition (rows of the identity in the Jacobian).
  const std::vector<LO>& prescribedRows() const { return prescribedRows_; }
  /// Dead f_ext at λ = 1 (owned): nodal forces, tractions, body forces.
  const Vector& externalForce() const { return *externalForce_; }
  /// The loads on sets; the model's assembly pass assembles their follower part.
  const ExternalLoads& loads() const { return *loads_; }
  /// Adds each spring's stiffness k to its diagonal entry (owned rows, overlapped numbering) through
  /// `add(dof, k)`, e.g. into the Jacobian's scatter.
  template <class Add>
  void addSpringStiffness(Add&& add) const {
    for (std::size_t k = 0; k < springOverlapDofs_.size(); ++k) add(springOverlapDofs_[k], springStiffness_[k]);
  }

 private:
  std::vector<LO> prescribedRows_;        ///< owned local rows with a Dirichlet condition
  std::vector<double> prescribedValues_;  ///< ū at λ = 1, per prescribed row
  Teuchos::RCP<Vector> externalForce_;
  std::unique_ptr<ExternalLoads> loads_;
  // Springs to ground, one entry per owned DOF with a spring (stiffnesses of several sets summed).
  std::vector<LO> springRows_;            ///< owned local rows
  std::vector<LO> springOverlapDofs_;     ///< the same DOFs, overlapped local numbering
  std::vector<double> springStiffness_;
};

}  // namespace contessa::model
