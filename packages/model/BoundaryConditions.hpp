#pragma once
// The deck's boundary conditions on the DOF layout: Dirichlet rows with their values ū at λ = 1, and the
// external nodal forces f_ext at λ = 1. They turn the assembled forces into the residual of the model,
// f = f_int + r_c − λ f_ext on free rows and u − λ ū on prescribed rows, and its ∂/∂λ.
#include <vector>

#include "deck/ProblemDefinition.hpp"
#include "model/DofLayout.hpp"

namespace contessa::model {

class BoundaryConditions {
 public:
  /// Throws InputError when two conditions prescribe the same DOF differently.
  BoundaryConditions(const deck::ProblemDefinition& problem, const DofLayout& layout);

  /// f = force − λ f_ext on free rows, x − λ ū on prescribed rows (owned vectors).
  void residual(const Vector& force, const Vector& x, double lambda, Vector& f) const;
  /// d = ∂force/∂λ − f_ext on free rows (a rigid master moves with λ), −ū on prescribed rows.
  void dResidualdLambda(const Vector& dForcedLambda, Vector& d) const;

  /// Owned local rows with a Dirichlet condition (rows of the identity in the Jacobian).
  const std::vector<LO>& prescribedRows() const { return prescribedRows_; }
  /// f_ext at λ = 1 (owned).
  const Vector& externalForce() const { return *externalForce_; }

 private:
  std::vector<LO> prescribedRows_;        ///< owned local rows with a Dirichlet condition
  std::vector<double> prescribedValues_;  ///< ū at λ = 1, per prescribed row
  Teuchos::RCP<Vector> externalForce_;
};

}  // namespace contessa::model
