#pragma once
// The absolute bound of the Newton residual test (ResidualTest): either the deck's Absolute Residual
// Tolerance, in the deck's force unit, or — when the deck does not set one — Force-Scaled Residual
// Tolerance times the force scale F of the state being judged,
//
//     ‖f‖₂ ≤ c · F,   F = ‖f_int‖₂ over every DOF (model/ForceScale.hpp),
//
// which at equilibrium is the 2-norm of the external loads on the free DOFs, the contact forces at the
// contact nodes and the reactions at the prescribed DOFs together. ‖f‖ and F are nodal forces of the same
// mesh, so the test is independent of the unit of force (a deck in MPa and the same deck in Pa take the
// same iterations) and of the rank count (both are global 2-norms). This is the force-relative test of
// Abaqus (R_max ≤ 5·10⁻³ q̃, q̃ the time-averaged nodal force) and of Code_Aster's RESI_GLOB_RELA (relative
// to the external and reaction forces), measured on the judged state itself so that a restarted run
// judges every state as the uninterrupted run did. A state that carries no force (F = 0) has no absolute
// bound: the relative and update tests decide there.
//
// The force-scaled bound has a floor: the round-off level φ of the out-of-balance force (the elements'
// rounding at the state's positions, model/ForceRoundOff.hpp), at most kLooseFraction · F,
//
//     ‖f_free‖₂ ≤ max(c · F, min(φ, kLooseFraction · F)),
//
// so that a state whose displacements are a tiny fraction of its coordinates (strains below about 1e-6,
// where φ exceeds 1e-10 F) converges at the round-off its forces are computed with, instead of iterating
// on that noise (docs/theory-load-stepping.md §7). A deck's absolute tolerance has no floor: it decides as
// the deck says. No NOX: unit-tested on its own.
#include <algorithm>
#include <string>

#include <Teuchos_ParameterList.hpp>

namespace contessa::solvers {

class ResidualTolerance {
 public:
  /// The default of Piro/NOX/Status Tests/Force-Scaled Residual Tolerance (docs/verification.md, "Newton
  /// tolerance and the force scale", for the measurement).
  static constexpr double kDefaultFactor = 1e-10;
  /// A state accepted by an absolute bound above this fraction of its force scale, with ‖f‖ above it too,
  /// is said once in the log: the answer may be far from converged.
  static constexpr double kLooseFraction = 1e-6;

  static ResidualTolerance absolute(double tolerance) { return {false, tolerance}; }
  static ResidualTolerance forceScaled(double factor) { return {true, factor}; }
  /// From the validated Piro/NOX/Status Tests: the absolute rule when it holds Absolute Residual Tolerance
  /// (validatePiro leaves it there only when the deck gives it), else the force-scaled one.
  static ResidualTolerance fromDeck(const Teuchos::ParameterList& statusTests);

  bool isForceScaled() const { return scaled_; }
  /// The bound on ‖f‖₂ at a state of force scale `forceScale` (≥ 0), without its floor.
  double boundAt(double forceScale) const { return scaled_ ? value_ * forceScale : value_; }
  /// The floor of the force-scaled bound at a state of force scale `forceScale` whose out-of-balance force
  /// is rounded to about `roundOff` (model/ForceScale.hpp): min(roundOff, kLooseFraction · F); 0 under the
  /// deck's absolute tolerance.
  double floorAt(double forceScale, double roundOff) const {
    return scaled_ ? std::min(roundOff, kLooseFraction * forceScale) : 0.0;
  }
  /// Whether accepting ‖f‖₂ ≤ boundAt(F) is loose against F (bound > kLooseFraction · F).
  bool looseAt(double forceScale) const { return boundAt(forceScale) > kLooseFraction * forceScale; }
  /// The rule in words, for the log, e.g. "||f|| <= 1e-10 * F (F = ||f_int||, ...)".
  std::string describe() const;

 private:
  ResidualTolerance(bool scaled, double value) : scaled_(scaled), value_(value) {}
  bool scaled_;
  double value_;
};

/// What the Newton tests saw of the force scale during a run: the log's last line about it and the
/// warning said once (kept by the driver, filled by ResidualTest).
struct ResidualToleranceRecord {
  double lastForceScale = 0;    ///< F at the last converged state
  double largestForceScale = 0; ///< the largest F of a converged state
  double lastBound = 0;         ///< the absolute bound applied there (its floor, when that was above c · F)
  std::string warning;          ///< the first loose acceptance, in words ("" when none)
  int floorAcceptances = 0;     ///< states the round-off floor accepted (‖f_free‖ above c · F, below the floor)
  std::string floorNote;        ///< the first of them, in words ("" when none)
  /// Notes a state the residual test accepted with `norm` under `bound` (F = `forceScale`); `byAbsolute`:
  /// the absolute bound decided (not the relative test); `byFloor`: its round-off floor did (`norm` above
  /// c · F). The first loose one (rule.looseAt(F) and ‖f‖ above kLooseFraction · F) sets `warning`; the
  /// first by the floor sets `floorNote`.
  void accepted(const ResidualTolerance& rule, double forceScale, double norm, double bound, bool byAbsolute,
                bool byFloor = false);
  /// What the floor decided over the run, for the log ("" when it never did).
  std::string floorSummary() const;
};

}  // namespace contessa::solvers
