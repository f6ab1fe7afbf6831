// Step-size method registry: one row per method (name, description, its parameters, its factory).
#include "solvers/StepSizeMethods.hpp"

#include <stdexcept>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "common/Registry.hpp"
#include "continuation/ContactBetaControl.hpp"
#include "deck/ParameterValidation.hpp"
#include "solvers/ContactBetaStepSize.hpp"

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

// ---- Contact Beta (Contessa's): the paper's load-step regulation, eq. (10)–(13), Table 1.
void contactBetaParameters(ParameterList& step) {
  deck::setPositiveInt(step, "Contacts Per Step", 2,
                       "Contact Beta: N_c, the number of slave nodes allowed to come into contact per increment (eq. 13)");
  deck::setChoice(step, "Mode", "Restart", {"Restart", "Predictor"},
                  "Contact Beta: Restart = the paper's Table 1 (β at the first Newton iteration, one restart); "
                  "Predictor = β from the predicted state before the solve (no restart)");
  deck::setBounded(step, "Max Growth Factor", 2.0, 1.0, 1e3, "Contact Beta: largest β (growth of Δλ per increment)");
  deck::setBounded(step, "Max Shrink Factor", 0.05, 1e-6, 1.0, "Contact Beta: smallest β (shrink of Δλ per increment)");
  deck::setBounded(step, "Restart Tolerance", 0.1, 0.0, 1.0, "Contact Beta, Restart: no restart when |β − 1| is below this. Applies with Next Contact Fraction = 0 (the paper), "
                  "when fewer candidates than Contacts Per Step approach, or when a step bound sets β; otherwise the step "
                  "stands when it ends between the predicted N_c-th and next event (docs/theory-load-stepping.md §11)");
  deck::setBounded(step, "Next Contact Fraction", 0.9, 0.0, 0.999,
                   "Contact Beta: β between β^{N_c} (0 = eq. 13 as printed) and β^{N_c+1} (closing N_c nodes, not N_c + 1)");
  deck::setChoice(step, "Counted Events", "Closures", continuation::countedEventsNames(),
                  "Contact Beta: the status changes limited to N_c per increment (history column new_events): "
                  "Closures (the paper) or All Status Changes (closures, openings, stick/slip changes, slip reversals)");
  step.set("Learn Event Rate", true,
           "Contact Beta: correct the β^k of eq. (11) by the ratio of actual to predicted event fractions learned "
           "from the last increments (not with Next Contact Fraction = 0: eq. 13 as printed)");
  deck::setChoice(step, "Growth Without Events", "Max Growth Factor", continuation::quietGrowthNames(),
                  "Contact Beta: how the step grows while at most N_c events lie ahead: to Max Growth Factor, or by "
                  "the Newton iterations of the last increment (towards Target Newton Iterations)");
  step.set("Max Corrections Per Increment", 3,
           "Contact Beta (f > 0): beyond the paper's one restart, how often per increment a restarted step with β "
           "far from 1 is checked again at its first iterate, and how often a converged increment with other than "
           "N_c counted events is solved again with a corrected step; 0 = Table 1 as printed ([0, 10])",
           Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>(0, 10)));
  deck::setPositiveInt(step, "Target Newton Iterations", 6,
                       "Contact Beta with Growth Without Events = Newton Iterations: the iterations an increment aims at");
}

Teuchos::RCP<LOCA::StepSize::AbstractStrategy> createContactBeta(const StepSizeContext& context) {
  return Teuchos::rcp(new ContactBetaStepSize(context.events, context.contactBeta));
}

const Registry<StepSizeMethod>& registry() {
  static const Registry<StepSizeMethod> rows(
      "step-size method",
      {
          {"Constant", "fixed Δλ, cut back on failure", constantParameters, {}, false},
          {"Adaptive", "LOCA's iteration-count control", adaptiveParameters, {}, false},
          {"Contact Beta", "N_c contacts per increment (eq. 10-13)", contactBetaParameters, createContactBeta, true},
      });
  return rows;
}

}  // namespace

const std::vector<StepSizeMethod>& stepSizeMethodRegistry() { return registry().rows(); }

const StepSizeMethod& stepSizeMethod(const std::string& name) {
  if (const StepSizeMethod* method = registry().find(name)) return *method;
  throw std::logic_error("step-size method '" + name + "' is not registered");
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
