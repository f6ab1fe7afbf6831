#pragma once
// What the Newton solve of an increment needs of the augmented Lagrangian (docs/theory-contact.md §15): at a
// converged iterate, whether the contact multipliers are to be updated and the same load factor solved
// again (Uzawa). No Trilinos, no contact types.
namespace contessa::model {

class ContactAugmentation {
 public:
  virtual ~ContactAugmentation() = default;
  /// Collective, at a converged Newton iterate of an increment. True (on every rank): some interface with
  /// Enforcement = Augmented Lagrangian misses its Penetration or Elastic Slip Tolerance and has updates
  /// left in this increment; its multipliers now hold the iterate's tractions, and the residual is to be
  /// computed again (the state is no answer yet). False: accept the iterate.
  virtual bool augmentContact() = 0;
  /// Whether some interface has Enforcement = Augmented Lagrangian (the same on every rank).
  virtual bool hasAugmentedContact() const = 0;
};

}  // namespace contessa::model
