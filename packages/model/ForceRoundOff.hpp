#pragma once
// The round-off level of the elements' internal forces: the out-of-balance force that rounding alone leaves
// at an exact equilibrium, below which no Newton iteration can push ‖f_free‖ (docs/theory-load-stepping.md
// §7, "The force-scaled test's round-off floor"). No Trilinos.
//
// A solid kernel forms F = I + GRAD u (Kinematics.hpp) and the strain from F − I. Each diagonal entry of F
// is 1 + ∂u_c/∂X_c rounded to within ε of 1, whatever the strain: the strain carries an absolute error of
// about ε along each axis, the stress one of about ε C, however small the deformation is. At a strain of
// 1e-9 that is 1e-7 of the stress and of the force scale F = ‖f_int‖, so a force-relative bound of
// 1e-10 F cannot be met (and a Newton step taken from that noise spoils an exact answer:
// roller_hydrostatic). An element's forces under a rounding ε of its stretch along axis c are ε times its
// forces under a unit stretch along c, the displacement d_c e_c with d_c = X_c − X̄^e_c (X̄^e the
// element's mean position; the radius X_r itself for r in an axisymmetric mesh, whose hoop stretch
// 1 + u_r / R is rounded relative to 1 too). These roundings are independent from element to element and
// from axis to axis, so they add in squares:
//
//     r_i² = Σ_e Σ_c (ε Σ_{j of axis c} K^e_ij d_j)²,
//
// K^e the element's stiffness at the reference state: the floor only matters where strains are tiny (below
// about 1e-6, where ε C is above 1e-10 of the stress), and there the stiffness is the reference one. An
// element's |f_e| would be no measure of it: it scales with the strain, the rounding of F does not.
#include <vector>

namespace contessa::model {

class ForceRoundOff {
 public:
  /// `reference`: the reference coordinate of each overlapped DOF (its node's X in the DOF's component;
  /// DOFs of no element may hold anything). Element DOFs are node-major (node · dimension + component).
  ForceRoundOff(std::vector<double> reference, int dimension, bool axisymmetric);

  /// Adds element e's terms to the rows of its DOFs: `dofs` (overlapped numbering), `stiffness` row-major n × n.
  void addElement(const int* dofs, int n, const double* stiffness);

  /// r_i² of every overlapped DOF, this rank's elements only (a node shared by ranks sums their parts).
  const std::vector<double>& squaredLevels() const { return squaredLevels_; }

 private:
  std::vector<double> reference_, squaredLevels_, stretch_;
  int dimension_;
  bool axisymmetric_;
};

}  // namespace contessa::model
