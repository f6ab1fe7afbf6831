#pragma once
// What the solve drivers (ContinuationDriver, solveStatic) see of the model: the Thyra model evaluator
// and the small interfaces it implements (path-dependent state, contact events for the step-size
// methods, diagnostics of a failed solve). No concrete model type: the app makes the view with
// SolverModel::of(model) from a model that implements all of them (model::ContactMechanicsModel).
#include <Teuchos_RCP.hpp>
#include <Thyra_ModelEvaluator.hpp>

#include "continuation/ContactEventSource.hpp"
#include "model/ContactAugmentation.hpp"
#include "model/ForceScale.hpp"
#include "model/IncrementalState.hpp"
#include "model/LoadStepping.hpp"
#include "model/SolveDiagnostics.hpp"

namespace contessa::solvers {

struct SolverModel {
  Teuchos::RCP<Thyra::ModelEvaluator<double>> evaluator;
  model::IncrementalState* state = nullptr;
  continuation::ContactEventSource* events = nullptr;
  const model::SolveDiagnostics* diagnostics = nullptr;
  model::LoadStepping* loadStepping = nullptr;  ///< the load steps (continuation::LoadSchedule)
  int dimension = 0;  ///< displacement components per node (the restart file's node table)
  model::ContactAugmentation* augmentation = nullptr;  ///< the augmented Lagrangian's multiplier updates
  const model::ForceScale* forces = nullptr;  ///< the force scale of the Newton test (ResidualTolerance)

  template <class Model>
  static SolverModel of(const Teuchos::RCP<Model>& model) {
    return {model, model.get(), model.get(), model.get(), model.get(), model->dimension(), model.get(), model.get()};
  }
};

}  // namespace contessa::solvers
