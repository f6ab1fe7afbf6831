// Contact Beta's events beyond the paper (ContactEvents.hpp): the status change of a slave node over an
// increment and the fraction β^k of the step at which it happens, for every kind: closure (eq. 11),
// opening (g_N crosses zero), stick → slip and slip reversal (the Coulomb indicator f of eq. 19 crosses
// zero), slip → stick (at the start of any step). Values worked out by hand in the comments; the
// numbers are dyadic so the divisions are exact.
#include "continuation/ContactEvents.hpp"
#include "continuation/EventRateCorrection.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace cb = contessa::continuation;
using cb::CountedEvents;
using cb::NodeStatus;

namespace {

constexpr double kTouching = 1e-10;

cb::SlaveNodeIncrement node(double g0, double g1, NodeStatus s0, NodeStatus s1, double f0 = std::numeric_limits<double>::quiet_NaN(),
                            double f1 = std::numeric_limits<double>::quiet_NaN(), bool reversed = false) {
  return {g0, g1, s0, s1, f0, f1, reversed};  // SlaveNodeIncrement's members in their declared order
}

double fraction(const cb::SlaveNodeIncrement& n, CountedEvents rule = CountedEvents::AllStatusChanges) {
  return cb::eventFraction(n, rule, kTouching);
}

}  // namespace

TEST(ContactEvents, ClosureIsEquation11UnderBothRules) {
  // g_t = 0.75, g = −0.25: β^k = 0.75 / (0.75 + 0.25) = 0.75.
  const auto n = node(0.75, -0.25, NodeStatus::Open, NodeStatus::Stick);
  EXPECT_EQ(fraction(n, CountedEvents::Closures), 0.75);
  EXPECT_EQ(fraction(n), 0.75);
  EXPECT_EQ(cb::statusChange(n), cb::EventKind::Closure);
  // Beyond the step: g_t = 1, g = 0.5 → β^k = 1 / 0.5 = 2.
  EXPECT_EQ(fraction(node(1.0, 0.5, NodeStatus::Open, NodeStatus::Open)), 2.0);
}

TEST(ContactEvents, OpeningCrossesZeroGap) {
  // In contact with g_t = −0.25, separating to g = 0.75: g crosses 0 at 0.25 / 1 = 0.25 of the step.
  const auto n = node(-0.25, 0.75, NodeStatus::Stick, NodeStatus::Open);
  EXPECT_EQ(fraction(n), 0.25);
  EXPECT_EQ(cb::statusChange(n), cb::EventKind::Opening);
  // Closures only: an opening is no event.
  EXPECT_LT(fraction(n, CountedEvents::Closures), 0.0);
  EXPECT_EQ(cb::countEvents({n}, CountedEvents::Closures), 0);
  EXPECT_EQ(cb::countEvents({n}, CountedEvents::AllStatusChanges), 1);
  // Pressed harder: no opening ahead.
  EXPECT_LT(fraction(node(-0.25, -0.5, NodeStatus::Slip, NodeStatus::Slip)), 0.0);
  // No pressure left at t (g_t = 0): opens in any step.
  EXPECT_EQ(fraction(node(0.0, 0.5, NodeStatus::Slip, NodeStatus::Open)), 0.0);
  // A tiny penetration still carries pressure: −1e-12 → 1e-12 crosses at one half.
  EXPECT_DOUBLE_EQ(fraction(node(-1e-12, 1e-12, NodeStatus::Stick, NodeStatus::Stick)), 0.5);
}

TEST(ContactEvents, StickToSlipCrossesTheCoulombCone) {
  // Stick at t with f_t = −0.75 (inside the cone), trial f = 0.25: f crosses 0 at 0.75 / 1.
  const auto n = node(-1.0, -1.0, NodeStatus::Stick, NodeStatus::Slip, -0.75, 0.25);
  EXPECT_EQ(fraction(n), 0.75);
  EXPECT_EQ(cb::statusChange(n), cb::EventKind::StickToSlip);
  // On the cone at t: slips in any step.
  EXPECT_EQ(fraction(node(-1.0, -1.0, NodeStatus::Stick, NodeStatus::Slip, 0.0, 0.5)), 0.0);
  // Moving away from the cone: no event.
  EXPECT_LT(fraction(node(-1.0, -1.0, NodeStatus::Stick, NodeStatus::Stick, -0.5, -0.75)), 0.0);
  // Beyond the step: f_t = −0.5, trial −0.25 → 0.5 / 0.25 = 2.
  EXPECT_EQ(fraction(node(-1.0, -1.0, NodeStatus::Stick, NodeStatus::Stick, -0.5, -0.25)), 2.0);
}

TEST(ContactEvents, SlipToStickIsUnavoidable) {
  // A slipping node on the cone that sticks in the trial state does so at the start of any step.
  const auto n = node(-1.0, -1.0, NodeStatus::Slip, NodeStatus::Stick, 0.0, -0.5);
  EXPECT_EQ(fraction(n), 0.0);
  EXPECT_EQ(cb::statusChange(n), cb::EventKind::SlipToStick);
  // Still slipping the same way (f_t = 0 along the slip): no event ahead.
  EXPECT_LT(fraction(node(-1.0, -1.0, NodeStatus::Slip, NodeStatus::Slip, 0.0, 0.25)), 0.0);
}

TEST(ContactEvents, SlipReversalCrossesTheOtherSideOfTheCone) {
  // Slipping at t, driven the other way: along the trial direction f_t = −‖t_T‖ − μ|t_N| = −1.5;
  // trial f = 0.5: crosses 0 at 1.5 / 2 = 0.75 of the step.
  const auto n = node(-1.0, -1.0, NodeStatus::Slip, NodeStatus::Slip, -1.5, 0.5, true);
  EXPECT_EQ(fraction(n), 0.75);
  EXPECT_EQ(cb::statusChange(n), cb::EventKind::SlipReversal);
  EXPECT_EQ(cb::countEvents({n}, CountedEvents::AllStatusChanges), 1);
  EXPECT_EQ(cb::countEvents({n}, CountedEvents::Closures), 0);
}

TEST(ContactEvents, AContactNodeTakesItsEarliestEvent) {
  // Opening at 0.5 (g −0.5 → 0.5) and stick → slip at 0.25 (f −0.25 → 0.75): 0.25.
  EXPECT_EQ(fraction(node(-0.5, 0.5, NodeStatus::Stick, NodeStatus::Open, -0.25, 0.75)), 0.25);
  // Frictionless (NaN indicators): the opening alone.
  EXPECT_EQ(fraction(node(-0.5, 0.5, NodeStatus::Stick, NodeStatus::Open)), 0.5);
}

TEST(ContactEvents, FractionsListOnlyNodesHeadingForCountedEvents) {
  const std::vector<cb::SlaveNodeIncrement> nodes = {
      node(0.75, -0.25, NodeStatus::Open, NodeStatus::Stick),           // closure 0.75
      node(-0.25, 0.75, NodeStatus::Stick, NodeStatus::Open),           // opening 0.25
      node(1.0, 2.0, NodeStatus::Open, NodeStatus::Open),               // receding: none
      node(std::numeric_limits<double>::infinity(), 1.0, NodeStatus::Open, NodeStatus::Open)};  // no master
  EXPECT_EQ(cb::eventFractions(nodes, CountedEvents::Closures, kTouching), (std::vector<double>{0.75}));
  EXPECT_EQ(cb::eventFractions(nodes, CountedEvents::AllStatusChanges, kTouching), (std::vector<double>{0.75, 0.25}));
}

TEST(ContactEvents, DeckNames) {
  EXPECT_EQ(cb::countedEventsByName("Closures"), CountedEvents::Closures);
  EXPECT_EQ(cb::countedEventsByName("All Status Changes"), CountedEvents::AllStatusChanges);
  EXPECT_THROW(cb::countedEventsByName("closures"), std::invalid_argument);
}

TEST(EventRateCorrection, LearnsTheRatioAndKeepsAConsistentOne) {
  // Predicted fractions 0.25, 0.5, 0.75, 1.0 of the step taken; 2 events observed. c = 1 predicted 4:
  // inconsistent. With f = 0.5 the new c puts the step half way between the 2nd and 3rd:
  // c = 1 / (0.5 + 0.5 (0.75 − 0.5)) = 1 / 0.625 = 1.6.
  cb::EventRateCorrection c(0.5);
  EXPECT_TRUE(c.observe({1.0, 0.25, 0.75, 0.5}, 2));
  EXPECT_DOUBLE_EQ(c.scale(), 1.6);
  // Consistent now (1.6 × 0.5 = 0.8 ≤ 1 < 1.6 × 0.75 = 1.2): kept.
  EXPECT_FALSE(c.observe({0.25, 0.5, 0.75, 1.0}, 2));
  EXPECT_DOUBLE_EQ(c.scale(), 1.6);
  // Bounded: 1 observed of fractions 0.01, 0.02 → c = 1 / (0.01 + 0.5 × 0.01) ≈ 67, clamped to 4.
  EXPECT_TRUE(c.observe({0.01, 0.02}, 1));
  EXPECT_EQ(c.scale(), 4.0);
}
