#pragma once
// The deck's boundary conditions on the DOF layout: Dirichlet rows with their values ū, the dead
// external forces f_ext (nodal forces, and the tractions and body forces of Problem/Loads), the springs
// to ground (Problem/Loads, Type Spring), and the follower loads (ExternalLoads, which the model's
// assembly pass calls). In a load step (continuation::LoadSchedule) ū = ū_0 + a Δū and f_ext = f_0 +
// a Δf, a = a(λ) the step's amplitude; without load steps ū_0 = f_0 = 0, a = λ and Δū, Δf the deck's
// values. They turn the assembled forces into the residual of the model,
// f = f_int + r_c − f_p(x) − f_ext + K_s u on free rows and u − ū on prescribed rows, and its ∂/∂λ.
// A spring is a support: its force −K_s u is the reaction of its node set (reactions: f_int − λ f_ext
// with the follower loads in the assembled forces, the springs not).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "continuation/LoadSchedule.hpp"
#include "deck/ProblemDefinition.hpp"
#include "model/DofLayout.hpp"
#include "model/ExternalLoads.hpp"

namespace contessa::model {

class BoundaryConditions {
 public:
  /// Throws InputError when two conditions prescribe the same DOF differently.
  BoundaryConditions(const deck::ProblemDefinition& problem, const DofLayout& layout);

  ~BoundaryConditions();

  /// The values of load step `step` of `schedule` (start and change of every condition and load).
  void setLoadStep(const continuation::LoadSchedule& schedule, int step);

  /// f = force − f_ext + K_s x on free rows, x − ū on prescribed rows (owned vectors), at amplitude a.
  void residual(const Vector& force, const Vector& x, double a, Vector& f) const;
  /// d = ∂force/∂λ − a' Δf on free rows (a rigid master moves with λ), −a' Δū on prescribed rows.
  void dResidualdLambda(const Vector& dForcedLambda, double slope, Vector& d) const;
  /// v −= f_ext at amplitude a (dead loads and nodal forces; owned).
  void subtractExternalForce(double a, Vector& v) const;

  /// Owned local rows with a Dirichlet condition (rows of the identity in the Jacobian).
  const std::vector<LO>& prescribedRows() const { return prescribedRows_; }
  /// The loads on sets; the model's assembly pass assembles their follower part.
  const ExternalLoads& loads() const { return *loads_; }
  /// Adds each spring's stiffness k to its diagonal entry (owned rows, overlapped numbering) through
  /// `add(dof, k)`, e.g. into the Jacobian's scatter.
  template <class Add>
  void addSpringStiffness(Add&& add) const {
    for (std::size_t k = 0; k < springOverlapDofs_.size(); ++k) add(springOverlapDofs_[k], springStiffness_[k]);
  }

 private:
  /// Dead f_ext of the values `value(name)` of the loads and nodal forces (owned).
  Teuchos::RCP<Vector> deadForce(const std::function<std::vector<double>(const std::string&)>& value,
                                 bool change) const;

  const deck::ProblemDefinition& problem_;
  const DofLayout& layout_;
  std::vector<LO> prescribedRows_;        ///< owned local rows with a Dirichlet condition
  std::vector<std::string> prescribedBy_;  ///< the condition of each prescribed row
  std::vector<double> prescribedStart_, prescribedChange_;  ///< ū_0 and Δū per prescribed row
  Teuchos::RCP<Vector> startForce_, changeForce_;           ///< f_0 and Δf
  bool hasStartForce_ = false;
  std::unique_ptr<ExternalLoads> loads_;
  // Springs to ground, one entry per owned DOF with a spring (stiffnesses of several sets summed).
  std::vector<LO> springRows_;            ///< owned local rows
  std::vector<LO> springOverlapDofs_;     ///< the same DOFs, overlapped local numbering
  std::vector<double> springStiffness_;
};

}  // namespace contessa::model
