#pragma once
// The model's load steps (issue 19 §2; continuation::LoadSchedule, made from the deck by
// deck::loadScheduleOf): what the continuation driver sees of them (LoadStepping, a light interface like
// IncrementalState).
#include <string>

#include "deck/LoadStepDefinitions.hpp"

namespace contessa::model {

class LoadStepping {
 public:
  virtual ~LoadStepping() = default;
  virtual int numLoadSteps() const = 0;
  /// From now on the load factor λ the model is evaluated at is step `step`'s own λ_s ∈ [0, 1] (0-based;
  /// step 0 at first).
  virtual void setLoadStep(int step) = 0;
  virtual int loadStep() const = 0;
};

using deck::dirichletKey;
using deck::frictionKey;
using deck::loadKey;
using deck::loadScheduleOf;
using deck::motionKey;

}  // namespace contessa::model
