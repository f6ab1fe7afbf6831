#pragma once
// What the Newton solve of an increment needs of the augmented Lagrangian (docs/theory-contact.md §15): at an
// iterate, whether the contact multipliers are to be updated and the same load factor solved again (Uzawa).
// No Trilinos, no contact types.
namespace contessa::model {

/// The Newton iterate at which an update is asked for.
struct AugmentationPoint {
  bool converged = true;  ///< the solve's convergence test holds there
  /// Otherwise (an early update, §15 "Updates before convergence"): the iterate's remaining displacement
  /// error, estimated from its last Newton steps (largest component).
  double errorEstimate = 0.0;
};

class ContactAugmentation {
 public:
  virtual ~ContactAugmentation() = default;
  /// Collective, at a Newton iterate of an increment. True (on every rank): some interface with
  /// Enforcement = Augmented Lagrangian misses its Penetration or Elastic Slip Tolerance and has updates
  /// left in this increment; its multipliers now hold the iterate's tractions, and the residual is to be
  /// computed again (the state is no answer yet). At an unconverged iterate, only when its gaps are known to
  /// a tenth of every augmented interface's tolerances (the error estimate below that). False: go on (accept
  /// a converged iterate).
  virtual bool augmentContact(const AugmentationPoint& at) = 0;
  /// Whether some interface has Enforcement = Augmented Lagrangian (the same on every rank).
  virtual bool hasAugmentedContact() const = 0;
};

}  // namespace contessa::model
