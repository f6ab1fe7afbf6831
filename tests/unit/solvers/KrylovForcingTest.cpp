// The Krylov tolerance of a Newton step (solvers/KrylovForcing.hpp): the deck's unless the linear residual
// it leaves could exceed a tenth of the Newton target, then a tenth of the target over ‖F_k‖, bounded at a
// hundredth of the deck's; and the step bookkeeping the iterative solver's monitor reads. The figures are
// the 3D punch's at 2·10^5 unknowns (bench/README.md, issue 23, seventh round): target 6.06 N, ‖F‖ 6.05e9 N
// at the second Newton iterate of the first increment, 4.12e4 N at the third.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "solvers/KrylovForcing.hpp"

namespace contessa::solvers {
namespace {

constexpr double kDeck = 1e-8;
constexpr double kTarget = 6.06;

TEST(KrylovForcing, StepWhoseLinearResidualStaysBelowATenthOfTheTargetKeepsTheDeckTolerance) {
  // 1e-8 · 4.12e4 = 4e-4 N, far below 0.606 N.
  EXPECT_EQ(newtonStepTolerance(kDeck, 4.12e4, kTarget), kDeck);
  // Exactly at the bound: kept.
  EXPECT_EQ(newtonStepTolerance(kDeck, kTargetFraction * kTarget / kDeck, kTarget), kDeck);
}

TEST(KrylovForcing, StepFarFromTheTargetAsksForATenthOfTheTargetOverItsResidual) {
  const double norm = 2.0e8;  // 1e-8 · 2e8 = 2 N > 0.606 N
  const double eta = newtonStepTolerance(kDeck, norm, kTarget);
  EXPECT_NEAR(eta, kTargetFraction * kTarget / norm, 1e-15 * eta);
  EXPECT_LT(eta, kDeck);
  EXPECT_GT(eta, kTightestFactor * kDeck);
  EXPECT_NEAR(eta * norm, 0.606, 1e-12);  // the linear residual it leaves, in N
}

TEST(KrylovForcing, TighteningIsBoundedAtAHundredthOfTheDeckTolerance) {
  // The punch's step 2: 0.606 / 6.05e9 = 1.0e-10, just above the bound; ten times the residual hits it.
  EXPECT_NEAR(newtonStepTolerance(kDeck, 6.05e9, kTarget), 0.606 / 6.05e9, 1e-22);
  EXPECT_EQ(newtonStepTolerance(kDeck, 6.05e10, kTarget), kTightestFactor * kDeck);
}

TEST(KrylovForcing, NeverLooserThanTheDeckAndTheDeckWhereNothingIsKnown) {
  EXPECT_EQ(newtonStepTolerance(1e-12, 6.05e10, kTarget), 1e-12);  // 0.06 N left: enough
  EXPECT_EQ(newtonStepTolerance(kDeck, 0.0, kTarget), kDeck);
  EXPECT_EQ(newtonStepTolerance(kDeck, std::numeric_limits<double>::quiet_NaN(), kTarget), kDeck);
  EXPECT_EQ(newtonStepTolerance(kDeck, std::numeric_limits<double>::infinity(), kTarget), kDeck);
  EXPECT_EQ(newtonStepTolerance(kDeck, 6.05e9, 0.0), kDeck);
}

TEST(KrylovForcing, OnlyTheNewtonStepsSolveIsTightenedAndTheFirstGivesTheRelativeTarget) {
  KrylovForcing forcing;
  forcing.term = ForcingTerm::NewtonTarget;
  forcing.absolute = 1e-6;
  forcing.relative = 1e-9;
  // Outside a Newton step (LOCA's predictor): the deck's, whatever the right-hand side.
  EXPECT_EQ(forcing.takeTolerance(kDeck, 6.06e9), kDeck);
  // The first step: its right-hand side is F_0, which sets the target max(1e-6, 1e-9 · 6.06e9) = 6.06.
  forcing.inStep = forcing.firstStep = true;
  EXPECT_NEAR(forcing.takeTolerance(kDeck, 6.06e9), kTightestFactor * kDeck, 1e-25);
  EXPECT_DOUBLE_EQ(forcing.target(), kTarget);
  // Consumed: a second solve in the same iterate gets the deck's.
  EXPECT_FALSE(forcing.inStep);
  EXPECT_EQ(forcing.takeTolerance(kDeck, 6.05e9), kDeck);
  // A later step keeps the first's target.
  forcing.inStep = true;
  EXPECT_NEAR(forcing.takeTolerance(kDeck, 2.0e8), 0.606 / 2.0e8, 1e-20);
  EXPECT_DOUBLE_EQ(forcing.target(), kTarget);
  forcing.inStep = true;
  EXPECT_EQ(forcing.takeTolerance(kDeck, 4.12e4), kDeck);
}

TEST(KrylovForcing, ConstantKeepsTheDeckToleranceForEveryStep) {
  KrylovForcing forcing;
  forcing.term = ForcingTerm::Constant;
  forcing.absolute = 1e-6;
  forcing.inStep = forcing.firstStep = true;
  EXPECT_EQ(forcing.takeTolerance(kDeck, 6.06e9), kDeck);
}

TEST(KrylovForcing, TheSingleSolvesAbsoluteTargetIgnoresTheFirstResidual) {
  KrylovForcing forcing;
  forcing.term = ForcingTerm::NewtonTarget;
  forcing.absolute = 1e-3;
  forcing.relative = 0.0;  // StaticSolveDriver: NormF(absolute) alone
  forcing.inStep = forcing.firstStep = true;
  EXPECT_NEAR(forcing.takeTolerance(kDeck, 2.0e4), 1e-4 / 2.0e4, 1e-20);
  EXPECT_EQ(forcing.target(), 1e-3);
}

}  // namespace
}  // namespace contessa::solvers
