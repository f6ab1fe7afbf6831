#include "solvers/ContactBetaStepControl.hpp"

#include <NOX_Abstract_Group.H>
#include <NOX_Abstract_Vector.H>
#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "deck/ParameterValidation.hpp"
#include "solvers/ContactBetaStepSize.hpp"
#include "solvers/MessageText.hpp"

namespace contessa::solvers {

using continuation::ContactBetaSettings;
using Teuchos::ParameterList;

namespace {

// The parameter names, each written once: addParameters declares them, settings reads them.
const char* const kContactsPerStep = "Contacts Per Step";
const char* const kMode = "Mode";
const char* const kMaxGrowth = "Max Growth Factor";
const char* const kMaxShrink = "Max Shrink Factor";
const char* const kRestartTolerance = "Restart Tolerance";
const char* const kNextContactFraction = "Next Contact Fraction";
const char* const kCountedEvents = "Counted Events";
const char* const kLearnEventRate = "Learn Event Rate";
const char* const kGrowthWithoutEvents = "Growth Without Events";
const char* const kMaxCorrections = "Max Corrections Per Increment";
const char* const kTargetNewtonIterations = "Target Newton Iterations";

const std::vector<std::string>& modeNames() {
  static const std::vector<std::string> names = {"Restart", "Predictor"};  // the order of Settings::Mode
  return names;
}

template <class Enum>
const std::string& nameOf(const std::vector<std::string>& names, Enum value) {
  return names.at(static_cast<std::size_t>(value));
}

/// Declares a choice among `names` (listed in the order of Enum's values) whose default is `value`.
template <class Enum>
void setEnumChoice(ParameterList& step, const char* key, const std::vector<std::string>& names, Enum value,
                   const std::string& doc) {
  deck::setChoice(step, key, nameOf(names, value), names, doc);
}

}  // namespace

void ContactBetaStepControl::addParameters(ParameterList& step) {
  const ContactBetaSettings d;  // the defaults
  deck::setPositiveInt(step, kContactsPerStep, d.beta.contactsPerStep,
                       "Contact Beta: N_c, the number of slave nodes allowed to come into contact per increment (eq. 13)");
  setEnumChoice(step, kMode, modeNames(), d.mode,
                "Contact Beta: Restart = the paper's Table 1 (β at the first Newton iteration, one restart); "
                "Predictor = β from the predicted state before the solve (no restart)");
  deck::setBounded(step, kMaxGrowth, d.beta.maxGrowth, 1.0, 1e3, "Contact Beta: largest β (growth of Δλ per increment)");
  deck::setBounded(step, kMaxShrink, d.beta.maxShrink, 1e-6, 1.0, "Contact Beta: smallest β (shrink of Δλ per increment)");
  deck::setBounded(step, kRestartTolerance, d.restartTolerance, 0.0, 1.0,
                   "Contact Beta, Restart: no restart when |β − 1| is below this. Applies with Next Contact Fraction = 0 (the paper), "
                   "when fewer candidates than Contacts Per Step approach, or when a step bound sets β; otherwise the step "
                   "stands when it ends between the predicted N_c-th and next event (docs/theory-load-stepping.md §11)");
  deck::setBounded(step, kNextContactFraction, d.beta.nextContactFraction, 0.0, 0.999,
                   "Contact Beta: β between β^{N_c} (0 = eq. 13 as printed) and β^{N_c+1} (closing N_c nodes, not N_c + 1)");
  setEnumChoice(step, kCountedEvents, continuation::countedEventsNames(), d.counted,
                "Contact Beta: the status changes limited to N_c per increment (history column new_events): "
                "Closures (the paper) or All Status Changes (closures, openings, stick/slip changes, slip reversals)");
  step.set(kLearnEventRate, d.learnEventRate,
           "Contact Beta: correct the β^k of eq. (11) by the ratio of actual to predicted event fractions learned "
           "from the last increments (not with Next Contact Fraction = 0: eq. 13 as printed)");
  setEnumChoice(step, kGrowthWithoutEvents, continuation::quietGrowthNames(), d.quietGrowth,
                "Contact Beta: how the step grows while at most N_c events lie ahead: to Max Growth Factor, or by "
                "the Newton iterations of the last increment (towards Target Newton Iterations)");
  step.set(kMaxCorrections, d.maxCorrections,
           "Contact Beta (f > 0): beyond the paper's one restart, how often per increment a restarted step with β "
           "far from 1 is checked again at its first iterate, and how often a converged increment with other than "
           "N_c counted events is solved again with a corrected step; 0 = Table 1 as printed ([0, 10])",
           Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>(0, 10)));
  deck::setPositiveInt(step, kTargetNewtonIterations, d.targetNewtonIterations,
                       "Contact Beta with Growth Without Events = Newton Iterations: the iterations an increment aims at");
}

ContactBetaSettings ContactBetaStepControl::settings(const ParameterList& p, double finalLoadFactor) {
  ContactBetaSettings s;
  s.mode = p.get<std::string>(kMode) == nameOf(modeNames(), ContactBetaSettings::Mode::Predictor)
               ? ContactBetaSettings::Mode::Predictor
               : ContactBetaSettings::Mode::Restart;
  s.beta.contactsPerStep = p.get<int>(kContactsPerStep);
  s.beta.maxGrowth = p.get<double>(kMaxGrowth);
  s.beta.maxShrink = p.get<double>(kMaxShrink);
  s.beta.nextContactFraction = p.get<double>(kNextContactFraction);
  s.counted = continuation::countedEventsByName(p.get<std::string>(kCountedEvents));
  s.learnEventRate = p.get<bool>(kLearnEventRate);
  s.quietGrowth = continuation::quietGrowthByName(p.get<std::string>(kGrowthWithoutEvents));
  s.targetNewtonIterations = p.get<int>(kTargetNewtonIterations);
  s.maxCorrections = p.get<int>(kMaxCorrections);
  s.restartTolerance = p.get<double>(kRestartTolerance);
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
         " to let only " + std::to_string(control_.settings().beta.contactsPerStep) + " contacts close per increment";
}

}  // namespace contessa::solvers
