#include "solvers/ContactBetaStepControl.hpp"

#include <NOX_Abstract_Group.H>
#include <NOX_Abstract_Vector.H>
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "common/ParameterTable.hpp"
#include "deck/ParameterValidation.hpp"
#include "solvers/ContactBetaStepSize.hpp"
#include "solvers/MessageText.hpp"

namespace contessa::solvers {

using continuation::ContactBetaSettings;
using Teuchos::ParameterList;

namespace {

using Settings = ContactBetaSettings;

const std::vector<std::string>& modeNames() {
  static const std::vector<std::string> names = {"Restart", "Predictor"};  // the order of Settings::Mode
  return names;
}

// A range [min, max] (deck::setBounded) for a row's declare.
ParameterTable<Settings>::Declare<double> bounded(double min, double max) {
  return [=](ParameterList& p, const std::string& name, double value, const std::string& doc) {
    deck::setBounded(p, name, value, min, max, doc);
  };
}

// Contact Beta's parameters, each declared once with the default of ContactBetaSettings and read into it.
const ParameterTable<Settings>& table() {
  const Settings d;  // the defaults
  static const auto rows =
      ParameterTable<Settings>()
          .declared("Contacts Per Step", [](Settings& s) -> int& { return s.beta.contactsPerStep; }, d.beta.contactsPerStep,
                    "Contact Beta: N_c, the number of slave nodes allowed to come into contact per increment (eq. 13); "
                    "0 (the default) = automatic: 2 (the paper's) when an interface has friction (its answer depends on "
                    "the path), otherwise max(2, half the slave nodes of all interfaces), the fewest Newton "
                    "iterations measured (docs/theory-load-stepping.md §11.7) ([0, inf])",
                    [](ParameterList& p, const std::string& name, int value, const std::string& doc) {
                      auto atLeastZero = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>());
                      atLeastZero->setMin(continuation::kAutomaticContactsPerStep);
                      p.set(name, value, doc, atLeastZero);
                    })
          .enumChoice("Mode", &Settings::mode, d.mode, modeNames(),
                      "Contact Beta: Restart = the paper's Table 1 (β at the first Newton iteration, one restart); "
                      "Predictor = β from the predicted state before the solve (no restart)")
          .declared("Max Growth Factor", [](Settings& s) -> double& { return s.beta.maxGrowth; }, d.beta.maxGrowth,
                    "Contact Beta: largest β (growth of Δλ per increment)", bounded(1.0, 1e3))
          .declared("Max Shrink Factor", [](Settings& s) -> double& { return s.beta.maxShrink; }, d.beta.maxShrink,
                    "Contact Beta: smallest β (shrink of Δλ per increment)", bounded(1e-6, 1.0))
          .declared("Restart Tolerance", &Settings::restartTolerance, d.restartTolerance,
                    "Contact Beta, Restart: no restart when |β − 1| is below this. Applies with Next Contact Fraction "
                    "= 0 (the paper), when fewer candidates than Contacts Per Step approach, or when a step bound sets "
                    "β; otherwise the step stands when it ends between the predicted N_c-th and next event "
                    "(docs/theory-load-stepping.md §11)",
                    bounded(0.0, 1.0))
          .declared("Next Contact Fraction", [](Settings& s) -> double& { return s.beta.nextContactFraction; },
                    d.beta.nextContactFraction,
                    "Contact Beta: β between β^{N_c} (0 = eq. 13 as printed) and β^{N_c+1} (closing N_c nodes, not "
                    "N_c + 1)",
                    bounded(0.0, 0.999))
          .enumChoice("Counted Events", &Settings::counted, d.counted, continuation::countedEventsNames(),
                      "Contact Beta: the status changes limited to N_c per increment (history column new_events): "
                      "Closures (the paper) or All Status Changes (closures, openings, stick/slip changes, slip "
                      "reversals)")
          .value("Learn Event Rate", &Settings::learnEventRate, d.learnEventRate,
                 "Contact Beta: correct the β^k of eq. (11) by the ratio of actual to predicted event fractions "
                 "learned from the last increments (not with Next Contact Fraction = 0: eq. 13 as printed)")
          .enumChoice("Growth Without Events", &Settings::quietGrowth, d.quietGrowth, continuation::quietGrowthNames(),
                      "Contact Beta: how the step grows while at most N_c events lie ahead: to Max Growth Factor, or "
                      "by the Newton iterations of the last increment (towards Target Newton Iterations)")
          .declared("Max Corrections Per Increment", &Settings::maxCorrections, d.maxCorrections,
                    "Contact Beta (f > 0): beyond the paper's one restart, how often per increment a restarted step "
                    "with β far from 1 is checked again at its first iterate, and how often a converged increment "
                    "with other than N_c counted events is solved again with a corrected step; 0 = Table 1 as "
                    "printed ([0, 10])",
                    [](ParameterList& p, const std::string& name, int value, const std::string& doc) {
                      p.set(name, value, doc, Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>(0, 10)));
                    })
          .count("Target Newton Iterations", &Settings::targetNewtonIterations, d.targetNewtonIterations,
                 "Contact Beta with Growth Without Events = Newton Iterations: the iterations an increment aims at");
  return rows;
}

}  // namespace

void ContactBetaStepControl::addParameters(ParameterList& step) { table().publishInto(step); }

continuation::CountedEvents ContactBetaStepControl::countedEvents(const ParameterList& stepSize) {
  return table().read(stepSize).counted;
}

ContactBetaSettings ContactBetaStepControl::settings(const ParameterList& p, double finalLoadFactor) {
  ContactBetaSettings s = table().read(p);
  // Read by every method (StepSizeMethods.cpp declares them).
  s.initialStep = p.get<double>("Initial Step Size");
  s.minStep = p.get<double>("Min Step Size");
  s.maxStep = p.get<double>("Max Step Size");
  s.failedStepFactor = p.get<double>("Failed Step Reduction Factor");
  s.finalLoadFactor = finalLoadFactor;
  return s;
}

ContactBetaStepControl::ContactBetaStepControl(const StepControlContext& context)
    : events_(context.events), control_(settings(context.stepSize, context.finalLoadFactor)) {}

Teuchos::RCP<LOCA::StepSize::AbstractStrategy> ContactBetaStepControl::createStrategy() {
  return Teuchos::rcp(new ContactBetaStepSize(events_, control_));
}

Teuchos::RCP<NOX::StatusTest::Generic> ContactBetaStepControl::correctionTest() {
  if (control_.settings().mode != ContactBetaSettings::Mode::Restart) return Teuchos::null;
  return Teuchos::rcp(new ContactBetaRestartTest(*this));
}

void ContactBetaStepControl::startIterate() {
  control_.nextIterate();
  firstIterateRejected_ = false;
}

void ContactBetaStepControl::iterateSet(const std::function<NOX::Abstract::Group&()>& iterate, int iteration) {
  // Table 1: β is determined at the first iteration (i = 1) of an uncorrected attempt (I_cor = 0).
  // That iterate was computed with the contact set of time t (new contacts frozen), so a node about to
  // close shows the penetration it would reach without contact: ^{t+Δt} g_N of eq. (11). Its residual is
  // the one the solver computes next (computed here first, then kept by the group).
  if (!control_.checkPending() || iteration != 1) return;
  NOX::Abstract::Group& group = iterate();
  if (group.computeF() != NOX::Abstract::Group::Ok) return;  // the solver fails the solve
  if (control_.restartAtFirstIterate(events_.trialIncrement())) {
    firstIterateRejected_ = true;  // the restart test fails the solve; LOCA restarts the increment with β
    return;
  }
  // The step stands (the measured β seeds the next increment's step): contact is enforced from here on,
  // and the residual of this iterate is computed again with it before the convergence tests see it.
  events_.freezeNewContacts(false);
  const auto x = group.getX().clone(NOX::DeepCopy);
  group.setX(*x);
  group.computeF();
}

bool ContactBetaStepControl::mayConverge() const { return !events_.newContactsFrozen(); }

std::string ContactBetaStepControl::redoAtConvergence() {
  return control_.redoAtConvergence(events_.trialIncrement());
}

std::string ContactBetaStepControl::stopReason() const {
  if (!control_.hitMinimumStep()) return "";
  return "Contact Beta asked for a step below Min Step Size = " + shortNumber(control_.settings().minStep) +
         " to let only " + std::to_string(control_.appliedContactsPerStep()) + " contacts close per increment";
}

std::string ContactBetaStepControl::choiceMade() const {
  if (control_.settings().beta.contactsPerStep != continuation::kAutomaticContactsPerStep) return "";
  const int n = control_.appliedContactsPerStep();
  if (n <= 0) return "";  // no decision was taken (no slave nodes, or no increment)
  return "Contact Beta: Contacts Per Step not given, automatic N_c = " + std::to_string(n) +
         " (2 with friction, otherwise half the slave nodes; docs/theory-load-stepping.md §11.7)";
}

}  // namespace contessa::solvers
