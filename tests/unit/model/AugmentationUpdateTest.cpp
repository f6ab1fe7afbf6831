// The augmented Lagrangian's update (docs/theory-contact.md §15): what the update loop counts as a violation
// (a positive gap held by λ_N as well as a penetration), the penalty growth rule (model::grownPenalty), and
// the grown penalties as interface state (applied to the next evaluation, kept by a commit, undone by a
// cut-back).
#include "InterfaceTestTools.hpp"
#include "model/ContactAugmentation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cc = contessa::contact;
namespace ct = contessa::contact::testing;
using contessa::model::grownPenalty;

namespace {

// Three slave nodes on y = 0 (L_k = 1) under a rigid line at y = 0.5 − λ (it touches them at λ = 0.5);
// frictionless, ε_N = 1e6, Penetration Tolerance 1e-3.
std::unique_ptr<cc::ContactInterfaceBase> pressedPlate() {
  auto spec = ct::threeNodesUnderRigidLine({{-10.0, 0.5}, {10.0, 0.5}}, {0.0, -1.0});
  spec.law.enforcement = cc::ContactLawParameters::Enforcement::AugmentedLagrangian;
  spec.law.penetrationTolerance = 1e-3;
  spec.law.elasticSlipTolerance = 1e-4;
  spec.law.maxAugmentations = 10;
  return cc::makeContactInterface(spec, {1, 1, 1});
}

const auto kNoSink = [](const cc::GlobalIndex*, int, const double*, const double*, const double*) {};

}  // namespace

TEST(AugmentationViolation, APositiveGapHeldByTheMultiplierCountsAsAPenetrationDoes) {
  const auto plate = pressedPlate();
  plate->evaluate(ct::threeNodesOnXAxis, 0.52, true, kNoSink);  // g_N = −0.02
  EXPECT_NEAR(plate->trialViolation().penetration, 0.02, 1e-12);
  plate->augment(true);  // λ_N = −ε_N · 0.02 = −2e4: in contact while g_N < 0.02
  // The line moves back to y = 0.005: every node is at g_N = +0.005 and still pressed, t_N = −2e4 + 5e3.
  plate->evaluate(ct::threeNodesOnXAxis, 0.495, true, kNoSink);
  plate->commit();
  ASSERT_EQ(plate->committedStates()[1].status, cc::ContactStatus::Slip);  // frictionless: closed
  EXPECT_NEAR(plate->committedStates()[1].pressure, 1.5e4, 1e-6);
  // g_N t_N = 0 is violated by 0.005 L: five times the tolerance (the loop once saw no violation here).
  plate->evaluate(ct::threeNodesOnXAxis, 0.495, true, kNoSink);
  EXPECT_NEAR(plate->trialViolation().penetration, 0.005, 1e-12);
}

TEST(PenaltyGrowth, GrowsToAThirtiethOfTheToleranceAtMostThirtyfoldUnlessTheLastUpdateQuarteredIt) {
  const double first = HUGE_VAL;  // no update yet in the increment
  EXPECT_EQ(grownPenalty(1.0, 3e-3, 1e-3, first), 30.0);     // 3e-3 / (1e-3 / 30) = 90, bounded by 30
  // From a growth of 0.5 (below the deck's: only to see the factor unbounded): 1.2e-3 / (1e-3 / 30) = 36.
  EXPECT_NEAR(grownPenalty(0.5, 1.2e-3, 1e-3, first), 18.0, 1e-12);
  EXPECT_EQ(grownPenalty(4.0, 0.9e-3, 1e-3, first), 4.0);    // within the tolerance: no update, no growth
  EXPECT_EQ(grownPenalty(0.1, 2e-3, 1e-3, 1e-2), 0.1);       // the last update quartered it: Uzawa suffices
  EXPECT_NEAR(grownPenalty(0.1, 3e-3, 1e-3, 1e-2), 9.0, 1e-12);  // reduced to 0.3 only: grows
  EXPECT_EQ(grownPenalty(4.0, 3e-3, 0.0, first), 4.0);       // no tolerance: nothing to grow for
  EXPECT_EQ(grownPenalty(50.0, 3e-3, 1e-3, first), 50.0);    // never shrinks (a restart's growth above the bound)
}

TEST(PenaltyGrowth, TheGrownPenaltyIsStateKeptByACommitAndUndoneByACutBack) {
  const auto plate = pressedPlate();
  plate->evaluate(ct::threeNodesOnXAxis, 0.52, true, kNoSink);
  plate->commit();
  EXPECT_NEAR(plate->committedStates()[1].pressure, 2e4, 1e-6);  // ε_N · 0.02
  plate->setPenaltyGrowth(10.0);
  EXPECT_EQ(plate->spec().law.normalPenalty, 1e7);
  plate->evaluate(ct::threeNodesOnXAxis, 0.52, true, kNoSink);
  plate->rollback();  // a cut-back: the deck's penalty again
  EXPECT_EQ(plate->penaltyGrowth(), 1.0);
  EXPECT_EQ(plate->spec().law.normalPenalty, 1e6);
  plate->evaluate(ct::threeNodesOnXAxis, 0.52, true, kNoSink);
  plate->commit();
  EXPECT_NEAR(plate->committedStates()[1].pressure, 2e4, 1e-6);
  plate->setPenaltyGrowth(10.0);
  plate->evaluate(ct::threeNodesOnXAxis, 0.52, true, kNoSink);
  plate->commit();
  EXPECT_NEAR(plate->committedStates()[1].pressure, 2e5, 1e-5);
  plate->rollback();  // kept by the commit
  EXPECT_EQ(plate->penaltyGrowth(), 10.0);
  plate->restorePenaltyGrowth(3.0);  // a restart: committed too
  plate->setPenaltyGrowth(30.0);
  plate->rollback();
  EXPECT_EQ(plate->spec().law.normalPenalty, 3e6);
}
