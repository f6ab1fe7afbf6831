#pragma once
// The step-size control of Contact Beta (the reference paper's section 2.1, Table 1, with Contessa's
// additions, docs/theory-load-stepping.md): which Δλ each attempt gets, when the first iterate asks
// for a restart, what is learned from a converged increment. Pure C++ with named operations; the LOCA
// strategy and the NOX status test (solvers/ContactBetaStepSize) only relay LOCA's calls to it.
#include <string>
#include <vector>

#include "common/StateRecord.hpp"
#include "continuation/ContactBeta.hpp"
#include "continuation/ContactEvents.hpp"
#include "continuation/EventRateCorrection.hpp"

namespace contessa::continuation {

/// How the step grows while at most N_c events lie ahead (β has no event to aim at).
enum class QuietGrowth {
  Cap,     ///< β = Max Growth Factor (the paper: "β > 1 grows the step when the user's step is too small")
  Newton,  ///< by the Newton iterations of the last increment (docs/theory-load-stepping.md §11.5)
};
/// Deck names, in the order of the enum: "Max Growth Factor", "Newton Iterations".
const std::vector<std::string>& quietGrowthNames();
QuietGrowth quietGrowthByName(const std::string& name);

struct ContactBetaSettings {
  enum class Mode { Restart, Predictor };
  Mode mode = Mode::Restart;
  BetaOptions beta;  ///< N_c, growth and shrink caps, f (its eventRateScale is learned, not set)
  CountedEvents counted = CountedEvents::Closures;
  bool learnEventRate = true;  ///< EventRateCorrection; never with f = 0 (eq. 13 as printed)
  double restartTolerance = 0.1;
  double initialStep = 0.1, minStep = 1e-6, maxStep = 1.0, failedStepFactor = 0.5;
  double finalLoadFactor = 1.0;  ///< the stepper's Max Value
  QuietGrowth quietGrowth = QuietGrowth::Cap;
  int targetNewtonIterations = 6;  ///< QuietGrowth::Newton: the iterations an increment aims at
  /// Beyond the paper's one restart per increment: first-iterate re-checks of a restarted step whose β
  /// was far from 1, and re-solves of converged attempts with other than N_c events (redoAtConvergence),
  /// each at most this many per increment. 0: Table 1 as printed.
  int maxCorrections = 3;
};

/// The step of one attempt.
struct AttemptPlan {
  bool ok = true;                  ///< false: the step fell below Min Step Size (the run stops)
  double step = 0;                 ///< Δλ
  bool checkFirstIterate = false;  ///< Restart, I_cor = 0: freeze new contacts, check β at the first iterate
  bool corrected = false;          ///< a β-corrected step (restart or redo): no Predictor-mode β on top
};

class ContactBetaControl {
 public:
  explicit ContactBetaControl(const ContactBetaSettings& settings);

  // ---- Before every attempt (LOCA's computeStepSize); λ is the load factor the attempt starts from.
  AttemptPlan firstAttempt(double lambda);
  /// The last attempt converged: `increment` is every slave node's committed change over it (start
  /// against end), `newtonIterations` its Newton iterations. Learns c, then plans the next increment.
  AttemptPlan afterConvergedIncrement(double lambda, const std::vector<SlaveNodeIncrement>& increment,
                                      int newtonIterations);
  /// The last attempt was stopped for a β correction (a first-iterate restart or a converged-state
  /// re-solve): eq. (10), Δt_cor = β Δt. Unchecked (I_cor = 1), except a first-iterate restart with β far
  /// from 1, which is checked again at its own first iterate (§11.3).
  AttemptPlan afterBetaRestart();
  /// The last attempt's Newton solve failed: cut back; β may not grow this attempt.
  AttemptPlan afterFailedAttempt(double lambda);

  /// Predictor mode: β from the slave nodes at the state predicted for the planned step; returns the
  /// step to take (β × planned).
  double correctByPrediction(const std::vector<SlaveNodeIncrement>& predicted);

  /// Restart mode, at the first Newton iterate of a checked attempt (Table 1, i = 1, I_cor = 0).
  /// True: the step does not stand as planned (standsAsPlanned: with Next Contact Fraction > 0 it must end
  /// between the predicted N_c-th and next event, otherwise |β − 1| ≤ Restart Tolerance); stop and restart
  /// with β. False: the step stands, its β is carried to the next increment, and new contacts are to be
  /// switched on.
  bool restartAtFirstIterate(const std::vector<SlaveNodeIncrement>& firstIterate);
  /// At a converged state of the current attempt (every slave node against the commit): "" accepts it;
  /// otherwise it brought other than N_c counted events and the step is to be solved again with
  /// Δλ × β (the reason, for the log). At most `maxCorrections` per increment; never with f = 0.
  std::string redoAtConvergence(const std::vector<SlaveNodeIncrement>& converged);
  /// Every Newton iterate: the release of new contacts concerns only the iterate it happened at.
  void nextIterate() { justReleased_ = false; }

  // ---- Checkpoint and restart: everything the next decisions depend on, by name (stateFields, below the
  // members), and putting it back; loadState throws InputError naming a field that is missing, of
  // another shape or not finite.
  void saveState(StateRecord& state) const;
  void loadState(const StateRecord& state);

  // ---- Queries.
  const ContactBetaSettings& settings() const { return settings_; }
  bool checkPending() const { return checkPending_; }
  bool restartRequested() const { return restartRequested_; }
  /// New contacts were switched on at this iterate: its Newton update was computed without them.
  bool newContactsJustReleased() const { return justReleased_; }
  bool hitMinimumStep() const { return hitMinimumStep_; }
  /// N_c for decisions over these slave nodes (all of them, every interface): the deck's Contacts Per
  /// Step, or with kAutomaticContactsPerStep the paper's 2 when any of them is frictional, otherwise
  /// automaticContactsPerStep(nodes.size()).
  int contactsPerStep(const std::vector<SlaveNodeIncrement>& nodes) const;
  /// N_c of the last decision (the deck's before any; 0 while automatic and undecided), for messages.
  int appliedContactsPerStep() const { return appliedContactsPerStep_; }
  double beta() const { return beta_; }  ///< β applied to this increment (1 = none), for the history
  int predictedEvents() const { return predictedEvents_; }
  double eventRateScale() const { return correction_.scale(); }

  /// β for the given node states at the current planned step: eq. (11)–(13) with the learned scale,
  /// within the step bounds (βΔλ in [Min, Max Step Size], no growth past Max Value, none right after a
  /// failure), the growth with few events by settings().quietGrowth.
  BetaResult betaFor(const std::vector<SlaveNodeIncrement>& nodes) const;

 private:
  AttemptPlan plan(double base, double lambda);
  bool standsAsPlanned(const BetaResult& result) const;
  void recordPrediction(const std::vector<SlaveNodeIncrement>& nodes, const BetaResult& result);
  double newtonGrowth() const;
  bool learning() const { return settings_.learnEventRate && settings_.beta.nextContactFraction > 0; }

  ContactBetaSettings settings_;
  EventRateCorrection correction_;
  double step_ = 0;             ///< Δλ of the current attempt (β-corrected once decided)
  double plannedStep_ = 0;      ///< Δλ the current attempt was planned (and checked) with
  double startLambda_ = 0;      ///< λ at the start of the current attempt
  double beta_ = 1;             ///< β applied to the current increment
  double carriedBeta_ = 1;      ///< Restart: β measured within the tolerance, for the next increment's step
  bool afterFailure_ = false, checkPending_ = false, restartRequested_ = false, justReleased_ = false;
  bool hitMinimumStep_ = false;
  bool lastBetaFromEvents_ = false;  ///< the last β was set by an event, not by a bound
  int predictedEvents_ = 0;
  int rechecks_ = 0;  ///< restarts of the current increment
  int redos_ = 0;     ///< redoAtConvergence corrections of the current increment
  bool redoing_ = false;
  int lastNewtonIterations_ = 0;
  int appliedContactsPerStep_ = 0;  ///< not checkpointed: derived again from the nodes at every decision
  std::vector<double> predictedFractions_;  ///< unscaled β^k of the last check / prediction
  double predictionStep_ = 0;               ///< the Δλ they refer to (0: none recorded)

  /// The members above a restart keeps (the learned event-rate scale too, through correction_).
  template <class Self, class Fields>
  static void stateFields(Self& self, Fields& field) {
    field("step", self.step_);
    field("planned_step", self.plannedStep_);
    field("start_lambda", self.startLambda_);
    field("beta", self.beta_);
    field("carried_beta", self.carriedBeta_);
    field("after_failure", self.afterFailure_);
    field("check_pending", self.checkPending_);
    field("restart_requested", self.restartRequested_);
    field("just_released", self.justReleased_);
    field("hit_minimum_step", self.hitMinimumStep_);
    field("last_beta_from_events", self.lastBetaFromEvents_);
    field("predicted_events", self.predictedEvents_);
    field("rechecks", self.rechecks_);
    field("redos", self.redos_);
    field("redoing", self.redoing_);
    field("last_newton_iterations", self.lastNewtonIterations_);
    // A fraction may overflow to +inf (a node closing by a subnormal distance): a value, not damage.
    field("predicted_fractions", self.predictedFractions_, StateValues::AnyDouble);
    field("prediction_step", self.predictionStep_);
  }
};

}  // namespace contessa::continuation
