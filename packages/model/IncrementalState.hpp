#pragma once
// What an incremental solver needs of the path-dependent state of a model (element internal variables,
// contact history): keep the state of a converged increment, or go back to the last one kept when an
// increment is abandoned. No Trilinos, no contact types.
namespace contessa::model {

class IncrementalState {
 public:
  virtual ~IncrementalState() = default;
  /// The increment converged: its trial state becomes the committed one.
  virtual void commitState() = 0;
  /// The increment is abandoned: back to the committed state.
  virtual void rollbackState() = 0;
  /// The load factor of the latest evaluation (the target of an abandoned increment).
  virtual double lastLoadFactor() const = 0;
};

}  // namespace contessa::model
