// ContactBetaControl (docs/theory-load-stepping.md §11): the step of each attempt, the restart by the
// predicted count, the re-solve of a converged increment with other than N_c events, and the quiet
// growth. Nodes are built so that the arithmetic is exact (dyadic gaps closing by exactly 1).
#include "continuation/ContactBetaControl.hpp"
#include "ClosingNodes.hpp"

#include <gtest/gtest.h>

#include "common/Error.hpp"
#include "common/StateRecord.hpp"

#include <vector>

namespace cb = contessa::continuation;
using cb::NodeStatus;
using cb::testing::closingAt;
using cb::testing::nodesAt;

namespace {

cb::ContactBetaSettings settings(int nc, double f = 0.5) {
  cb::ContactBetaSettings s;
  s.beta.contactsPerStep = nc;
  s.beta.nextContactFraction = f;
  s.beta.maxGrowth = 8;
  s.initialStep = 0.125;
  s.maxStep = 1;
  return s;
}

// The same in the predictor mode (the step corrected by the predicted events and re-solved at convergence).
cb::ContactBetaSettings predictorSettings(int nc) {
  cb::ContactBetaSettings s = settings(nc);
  s.mode = cb::ContactBetaSettings::Mode::Predictor;
  return s;
}

}  // namespace

TEST(ContactBetaControl, RestartsWhenThePlannedStepTakesAnotherCount) {
  cb::ContactBetaControl control(settings(2));
  const auto plan = control.firstAttempt(0.0);
  EXPECT_TRUE(plan.checkFirstIterate);
  EXPECT_EQ(plan.step, 0.125);
  // β^k = 0.25, 0.5, 0.75: the planned step (β = 1) takes 3 events, N_c = 2 → restart with
  // β = 0.5 + 0.5 (0.75 − 0.5) = 0.625.
  EXPECT_TRUE(control.restartAtFirstIterate(nodesAt({0.25, 0.5, 0.75})));
  EXPECT_EQ(control.beta(), 0.625);
  const auto corrected = control.afterBetaRestart();
  EXPECT_EQ(corrected.step, 0.125 * 0.625);
  EXPECT_TRUE(corrected.corrected);
  EXPECT_FALSE(corrected.checkFirstIterate);  // |log 0.625| < log 2: no re-check
}

TEST(ContactBetaControl, KeepsAStepThatTakesExactlyNcWithAMargin) {
  cb::ContactBetaControl control(settings(2));
  control.firstAttempt(0.0);
  // β^k = 0.25, 0.875, 1.125: β = 0.875 + 0.5 × 0.25 = 1 exactly; placement of 1 = 0.5, in [0.25, 0.75).
  EXPECT_FALSE(control.restartAtFirstIterate(nodesAt({0.25, 0.875, 1.125})));
  // β^k = 0.25, 0.5, 1.0625: 2 events at β = 1, but 1 lies at (1 − 0.5)/0.5625 = 0.89 of the way to
  // the third: too close, restart.
  control.firstAttempt(0.0);
  EXPECT_TRUE(control.restartAtFirstIterate(nodesAt({0.25, 0.5, 1.0625})));
}

TEST(ContactBetaControl, AFarCorrectionIsCheckedAgain) {
  cb::ContactBetaControl control(settings(1));
  control.firstAttempt(0.0);
  // β^k = 4, 6: β = 4 + 0.5 × 2 = 5 (> 2): the corrected step is checked at its own first iterate.
  EXPECT_TRUE(control.restartAtFirstIterate(nodesAt({4.0, 6.0})));
  EXPECT_EQ(control.beta(), 5.0);
  const auto again = control.afterBetaRestart();
  EXPECT_EQ(again.step, 0.625);
  EXPECT_TRUE(again.checkFirstIterate);
}

TEST(ContactBetaControl, PaperModeRestartsOnceByTheTolerance) {
  cb::ContactBetaControl control(settings(1, 0.0));  // f = 0: eq. (13) as printed, Table 1
  control.firstAttempt(0.0);
  // β = β^1 = 4: restart, and the corrected step is not checked again (I_cor = 1).
  EXPECT_TRUE(control.restartAtFirstIterate(nodesAt({4.0, 6.0})));
  EXPECT_EQ(control.beta(), 4.0);
  EXPECT_FALSE(control.afterBetaRestart().checkFirstIterate);
  // Nor is a converged increment re-solved.
  EXPECT_EQ(control.redoAtConvergence(nodesAt({0.5, 0.75, 0.875})), "");
}

TEST(ContactBetaControl, AConvergedIncrementWithTooFewEventsIsSolvedAgainLarger) {
  cb::ContactBetaControl control(predictorSettings(2));
  control.firstAttempt(0.0);
  // Converged: one node closed (g 0.5 → −0.5), two still approach with β^k = 2 and 4 of this step.
  // N_c = 2: the second event is at 2, the third at 4 → β = 2 + 0.5 × 2 = 3.
  const std::string why = control.redoAtConvergence(nodesAt({0.5, 2.0, 4.0}));
  EXPECT_NE(why, "");
  EXPECT_EQ(control.beta(), 3.0);
  EXPECT_TRUE(control.restartRequested());
  const auto redo = control.afterBetaRestart();
  EXPECT_EQ(redo.step, 0.375);
  EXPECT_TRUE(redo.corrected);
  // Exactly N_c: accepted.
  EXPECT_EQ(control.redoAtConvergence(nodesAt({0.5, 0.75, 4.0})), "");
}

TEST(ContactBetaControl, AConvergedIncrementWithTooManyEventsIsSolvedAgainSmaller) {
  cb::ContactBetaControl control(predictorSettings(1));
  control.firstAttempt(0.0);
  // Predicted β^k = 0.25, 0.5, 0.75, 1.5 for the planned step: β = 0.25 + 0.5 × 0.25 = 0.375.
  EXPECT_EQ(control.correctByPrediction(nodesAt({0.25, 0.5, 0.75, 1.5})), 0.125 * 0.375);
  // In that step (the predicted fractions become 2/3, 4/3, 2, 4) three nodes closed instead of one.
  // Rescaled so that the step ends half way between the 3rd and 4th predicted: at = 2 + 0.5 × 2 = 3;
  // wanted half way between the 1st and 2nd: 2/3 + 0.5 × 2/3 = 1 → β = 1/3.
  const std::string why = control.redoAtConvergence(nodesAt({0.5, 0.5, 0.5, 8.0}));
  EXPECT_NE(why, "");
  EXPECT_DOUBLE_EQ(control.beta(), 1.0 / 3.0);
}

TEST(ContactBetaControl, CorrectionsAreBoundedPerIncrement) {
  cb::ContactBetaSettings s = predictorSettings(2);
  s.maxCorrections = 1;
  cb::ContactBetaControl control(s);
  control.firstAttempt(0.0);
  EXPECT_NE(control.redoAtConvergence(nodesAt({0.5, 2.0, 4.0})), "");
  control.afterBetaRestart();
  EXPECT_EQ(control.redoAtConvergence(nodesAt({0.5, 2.0, 4.0})), "");  // the one correction is used
}

TEST(ContactBetaControl, QuietGrowthByNewtonIterations) {
  cb::ContactBetaSettings s = settings(2);
  s.quietGrowth = cb::QuietGrowth::Newton;
  s.targetNewtonIterations = 6;
  cb::ContactBetaControl control(s);
  control.firstAttempt(0.0);
  control.afterConvergedIncrement(0.125, {}, 3);  // 3 iterations: half the target
  // One candidate only (≤ N_c): β = 6 / 3 = 2 instead of Max Growth Factor 8.
  EXPECT_EQ(control.betaFor(nodesAt({5.0})).beta, 2.0);
  s.quietGrowth = cb::QuietGrowth::Cap;
  cb::ContactBetaControl capped(s);
  capped.firstAttempt(0.0);
  capped.afterConvergedIncrement(0.125, {}, 3);
  // To the cap, here the final load: (1 − 0.125) / 0.125 = 7 < Max Growth Factor 8.
  EXPECT_EQ(capped.betaFor(nodesAt({5.0})).beta, 7.0);
}

// Checkpoint and restart: a control restored from another's saved state decides every later attempt as
// the original does (the learned event rate, the carried β, the counters), and a state without one of
// its fields is refused naming it.
TEST(ContactBetaControl, ARestoredStateDecidesAsTheOriginal) {
  const auto stateOf = [](const cb::ContactBetaControl& control) {
    contessa::StateRecord r;
    control.saveState(r);
    return r;
  };
  cb::ContactBetaControl original(settings(2));
  original.firstAttempt(0.0);
  original.restartAtFirstIterate(nodesAt({0.25, 0.5, 0.75}));
  original.afterBetaRestart();
  // A converged increment with 3 events where 2 were predicted: the event rate is learned.
  original.afterConvergedIncrement(0.078125, nodesAt({0.25, 0.5, 0.75}), 5);
  const auto state = stateOf(original);

  cb::ContactBetaControl restored(settings(2));
  restored.loadState(state);
  EXPECT_EQ(state.firstUnread(), "");
  EXPECT_TRUE(contessa::sameState(stateOf(restored), state));
  EXPECT_EQ(restored.eventRateScale(), original.eventRateScale());
  EXPECT_NE(original.eventRateScale(), 1.0);  // learned: the restore has something to restore
  EXPECT_EQ(restored.beta(), original.beta());
  for (const auto& nodes : {nodesAt({0.5, 0.625, 2.0}), nodesAt({0.25, 0.375, 0.5, 4.0})}) {
    EXPECT_EQ(restored.restartAtFirstIterate(nodes), original.restartAtFirstIterate(nodes));
    EXPECT_EQ(restored.beta(), original.beta());
    const auto a = original.afterBetaRestart(), b = restored.afterBetaRestart();
    EXPECT_EQ(a.step, b.step);
    EXPECT_EQ(a.checkFirstIterate, b.checkFirstIterate);
    const auto c = original.afterConvergedIncrement(0.25, nodes, 4), d = restored.afterConvergedIncrement(0.25, nodes, 4);
    EXPECT_EQ(c.step, d.step);
    EXPECT_TRUE(contessa::sameState(stateOf(original), stateOf(restored)));
  }
  contessa::StateRecord withoutBeta;
  for (const auto& [name, field] : state.fields())
    if (name != "carried_beta") withoutBeta.putField(name, field);
  try {
    restored.loadState(withoutBeta);
    ADD_FAILURE() << "a state without carried_beta was loaded";
  } catch (const contessa::InputError& e) {
    EXPECT_STREQ(e.what(), "state: carried_beta: missing (this Contessa needs it)");
  }
}
