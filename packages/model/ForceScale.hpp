#pragma once
// The size of the forces a state carries and of its out-of-balance force, for a Newton test that is relative
// to them instead of to the deck's force unit (solvers/ResidualTolerance.hpp). No Trilinos.
namespace contessa::model {

class ForceScale {
 public:
  virtual ~ForceScale() = default;
  /// ‖f_int‖₂, the 2-norm over every DOF of the elements' internal forces (summed over the ranks that share
  /// a node) at the latest evaluation of the residual: at equilibrium the external loads on the free DOFs
  /// (dead and follower loads, minus the springs' forces), the contact forces at the contact nodes and the
  /// reactions at the prescribed DOFs, in the deck's force unit. The same on every rank (a global norm).
  virtual double forceScale() const = 0;
  /// ‖f‖₂ over the free DOFs at the latest residual evaluation: the out-of-balance force alone. The
  /// prescribed rows of f hold x − ū, a displacement, whose round-off (about 1e-17 at coordinates of order 1)
  /// would otherwise set a floor in length units under a force residual that scales with the unit of force.
  /// Infinite while a prescribed row does not hold (|x − ū| above 1e-10 of the largest |x|): the state is
  /// then no candidate for a force-relative test (a solve from rest under a prescribed displacement has
  /// f_int = 0 and f_free = 0 at its first iterate).
  virtual double outOfBalanceNorm() const = 0;
  /// The largest |X| of the mesh's reference coordinates over every rank, in the deck's length unit: the
  /// scale of the positions x = X + u whose round-off sets a floor under the Newton update (0: none known).
  virtual double lengthScale() const { return 0.0; }
  /// The round-off level of outOfBalanceNorm() at the latest residual evaluation: ‖r‖₂ over the free DOFs of
  /// the elements' rounding r (ForceRoundOff.hpp: ε times their forces under unit stretches, in squares),
  /// the out-of-balance force that rounding alone leaves at an exact equilibrium, in the deck's force unit.
  /// The same on every rank (0: none known).
  virtual double forceRoundOff() const { return 0.0; }
};

}  // namespace contessa::model
