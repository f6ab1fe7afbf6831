// Step-size method registry: one row per method (name, description, its parameters, its factory).
#include "solvers/StepSizeMethods.hpp"

#include <memory>
#include <stdexcept>


#include "common/Registry.hpp"
#include "deck/ParameterValidation.hpp"
#include "solvers/ContactBetaStepControl.hpp"

namespace contessa::solvers {
namespace {

using Teuchos::ParameterList;

// ---- Constant (LOCA's): a fixed Δλ, cut back on failure and recovering towards the initial step.
void constantParameters(ParameterList& step) {
  deck::setBounded(step, "Successful Step Increase Factor", 1.26, 1.0, 100.0,
                   "Δλ multiplier after a successful increment (Constant recovers towards the initial step)");
}

// ---- Adaptive (LOCA's): Δλ grows after increments that took few Newton iterations.
void adaptiveParameters(ParameterList& step) {
  deck::setBounded(step, "Aggressiveness", 0.5, 0.0, 1.0, "Adaptive only: how fast Δλ grows after easy increments");
}

// ---- Contact Beta (Contessa's): the paper's load-step regulation, eq. (10)–(13), Table 1; its parameters
// and hooks are ContactBetaStepControl's.
std::unique_ptr<StepControl> createContactBeta(const StepControlContext& context) {
  return std::make_unique<ContactBetaStepControl>(context);
}

const Registry<StepSizeMethod>& registry() {
  static const Registry<StepSizeMethod> rows(
      "step-size method",
      {
          {"Constant", "fixed Δλ, cut back on failure", constantParameters, {}},
          {"Adaptive", "LOCA's iteration-count control", adaptiveParameters, {}},
          {"Contact Beta", "N_c contacts per increment (eq. 10-13)", ContactBetaStepControl::addParameters,
           createContactBeta},
      });
  return rows;
}

}  // namespace

const std::vector<StepSizeMethod>& stepSizeMethodRegistry() { return registry().rows(); }

const StepSizeMethod& stepSizeMethod(const std::string& name) {
  if (const StepSizeMethod* method = registry().find(name)) return *method;
  throw std::logic_error("step-size method '" + name + "' is not registered");
}

std::unique_ptr<StepControl> createStepControl(const StepControlContext& context) {
  const StepSizeMethod& method = stepSizeMethod(context.stepSize.get<std::string>("Method"));
  return method.create ? method.create(context) : std::make_unique<StepControl>();
}

continuation::CountedEvents countedEvents(const ParameterList& stepSize) {
  return ContactBetaStepControl::countedEvents(stepSize);
}

std::vector<std::string> stepSizeMethods() { return registry().names(); }

void addStepSizeParameters(ParameterList& step) {
  std::string doc;
  for (const auto& m : stepSizeMethodRegistry()) doc += (doc.empty() ? "" : "; ") + m.name + ": " + m.doc;
  deck::setChoice(step, "Method", "Constant", stepSizeMethods(), doc);
  // Read by every method.
  deck::setPositive(step, "Initial Step Size", 0.1, "Δλ of the first increment");
  deck::setPositive(step, "Min Step Size", 1e-6, "Smallest Δλ before the run gives up");
  deck::setPositive(step, "Max Step Size", 1.0, "Largest Δλ");
  deck::setBounded(step, "Failed Step Reduction Factor", 0.5, 1e-3, 0.999, "Δλ multiplier after a failed increment");
  for (const auto& m : stepSizeMethodRegistry())
    if (m.addParameters != nullptr) m.addParameters(step);
}

}  // namespace contessa::solvers
