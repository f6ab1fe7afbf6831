// Automatic N_c (issue 23, point 4; docs/theory-load-stepping.md §11.7): without Contacts Per Step in the
// deck, Contact Beta lets max(2, ⌈share × slave nodes⌉) nodes close per increment, and the paper's 2 when
// an interface has friction; an explicit N_c is used exactly as given. Nodes are built so that the
// arithmetic is exact (dyadic gaps closing by exactly 1).
#include <gtest/gtest.h>

#include <vector>

#include "continuation/ContactBetaControl.hpp"
#include "ClosingNodes.hpp"

namespace cb = contessa::continuation;
using cb::NodeStatus;
using cb::testing::closingAt;
using cb::testing::nodesAt;

namespace {

/// Nine slave nodes (automatic N_c = ⌈9/2⌉ = 5): five close within the planned step (β^k 0.25 … 0.875),
/// the sixth at 1.125.
std::vector<cb::SlaveNodeIncrement> nineNodes() { return nodesAt({0.25, 0.5, 0.625, 0.75, 0.875, 1.125, 2, 3, 4}); }

/// `n` open slave nodes with no master in reach (no event ahead).
std::vector<cb::SlaveNodeIncrement> farNodes(std::size_t n) { return std::vector<cb::SlaveNodeIncrement>(n); }

/// The same nodes on a frictional interface.
std::vector<cb::SlaveNodeIncrement> frictional(std::vector<cb::SlaveNodeIncrement> nodes) {
  for (auto& n : nodes) n.frictional = true;
  return nodes;
}

cb::ContactBetaSettings settings(int nc) {
  cb::ContactBetaSettings s;
  s.beta.contactsPerStep = nc;
  s.beta.nextContactFraction = 0.5;
  s.beta.maxGrowth = 8;
  s.initialStep = 0.125;
  s.maxStep = 1;
  return s;
}

}  // namespace

TEST(AutomaticContacts, IsTheDecksDefault) {
  EXPECT_EQ(cb::BetaOptions().contactsPerStep, cb::kAutomaticContactsPerStep);
  EXPECT_EQ(cb::ContactBetaSettings().beta.contactsPerStep, cb::kAutomaticContactsPerStep);
  EXPECT_EQ(cb::kAutomaticContactsPerStep, 0);  // no valid N_c: it cannot be mistaken for one
}

TEST(AutomaticContacts, HalfTheSlaveNodesNeverBelowThePapersTwo) {
  EXPECT_EQ(cb::kAutomaticContactsShare, 0.5);
  EXPECT_EQ(cb::automaticContactsPerStep(0), 2);
  EXPECT_EQ(cb::automaticContactsPerStep(1), 2);
  EXPECT_EQ(cb::automaticContactsPerStep(4), 2);
  EXPECT_EQ(cb::automaticContactsPerStep(5), 3);  // ⌈5/2⌉
  EXPECT_EQ(cb::automaticContactsPerStep(9), 5);
  EXPECT_EQ(cb::automaticContactsPerStep(102), 51);  // the tube's outer side
  EXPECT_EQ(cb::automaticContactsPerStep(441), 221);
  // Monotone in the number of nodes, and never more than there are (past the minimum).
  for (std::size_t n = 1; n < 2000; ++n) {
    EXPECT_LE(cb::automaticContactsPerStep(n - 1), cb::automaticContactsPerStep(n));
    if (n >= 2) {
      EXPECT_LE(cb::automaticContactsPerStep(n), static_cast<int>(n));
    }
  }
}

TEST(AutomaticContacts, TheControlResolvesItForTheNodesItIsGiven) {
  const cb::ContactBetaControl automatic(settings(cb::kAutomaticContactsPerStep));
  EXPECT_EQ(automatic.contactsPerStep(farNodes(9)), 5);
  EXPECT_EQ(automatic.contactsPerStep(farNodes(102)), 51);
  EXPECT_EQ(automatic.appliedContactsPerStep(), 0);  // nothing decided yet
  // An explicit N_c is used as given, whatever the number of nodes, with or without friction.
  for (int nc : {1, 2, 3, 16}) {
    const cb::ContactBetaControl fixed(settings(nc));
    EXPECT_EQ(fixed.contactsPerStep(farNodes(9)), nc);
    EXPECT_EQ(fixed.contactsPerStep(farNodes(100000)), nc);
    EXPECT_EQ(fixed.contactsPerStep(frictional(farNodes(102))), nc);
    EXPECT_EQ(fixed.appliedContactsPerStep(), nc);
  }
}

TEST(AutomaticContacts, TheFirstIterateCheckUsesTheResolvedCount) {
  // Automatic N_c = 5: the planned step takes the five events up to 0.875 and stops before 1.125:
  // β = 0.875 + 0.5 (1.125 − 0.875) = 1, the step stands (placement 0.5).
  cb::ContactBetaControl automatic(settings(cb::kAutomaticContactsPerStep));
  automatic.firstAttempt(0.0);
  EXPECT_FALSE(automatic.restartAtFirstIterate(nineNodes()));
  EXPECT_EQ(automatic.appliedContactsPerStep(), 5);
  EXPECT_EQ(automatic.betaFor(nineNodes()).beta, 1.0);
  // N_c = 2 given: the same nodes make it restart with β = 0.5 + 0.5 (0.625 − 0.5) = 0.5625.
  cb::ContactBetaControl two(settings(2));
  two.firstAttempt(0.0);
  EXPECT_TRUE(two.restartAtFirstIterate(nineNodes()));
  EXPECT_EQ(two.beta(), 0.5625);
  EXPECT_EQ(two.appliedContactsPerStep(), 2);
}

TEST(AutomaticContacts, FrictionKeepsThePapersTwo) {
  // The frictional answer depends on the path: automatic N_c is 2 as soon as one node is frictional
  // (one frictional interface among frictionless ones), whatever the number of nodes.
  const cb::ContactBetaControl automatic(settings(cb::kAutomaticContactsPerStep));
  EXPECT_EQ(cb::kAutomaticContactsMinimum, 2);
  EXPECT_EQ(automatic.contactsPerStep(frictional(farNodes(102))), 2);
  auto mixed = farNodes(300);
  mixed[299].frictional = true;
  EXPECT_EQ(automatic.contactsPerStep(mixed), 2);
  // The first-iterate check then restarts as N_c = 2 given does.
  cb::ContactBetaControl control(settings(cb::kAutomaticContactsPerStep));
  control.firstAttempt(0.0);
  EXPECT_TRUE(control.restartAtFirstIterate(frictional(nineNodes())));
  EXPECT_EQ(control.beta(), 0.5625);
  EXPECT_EQ(control.appliedContactsPerStep(), 2);
}

TEST(AutomaticContacts, AConvergedIncrementIsCountedAgainstTheResolvedCount) {
  // Predictor mode: β from the predicted state, then the converged increment's events are counted.
  cb::ContactBetaSettings s = settings(cb::kAutomaticContactsPerStep);
  s.mode = cb::ContactBetaSettings::Mode::Predictor;
  cb::ContactBetaControl automatic(s);
  automatic.firstAttempt(0.0);
  EXPECT_EQ(automatic.correctByPrediction(nineNodes()), 0.125);  // β = 1 for N_c = 5
  EXPECT_EQ(automatic.redoAtConvergence(nineNodes()), "");     // five closed = N_c: accepted
  s.beta.contactsPerStep = 2;
  cb::ContactBetaControl two(s);
  two.firstAttempt(0.0);
  EXPECT_EQ(two.correctByPrediction(nineNodes()), 0.125 * 0.5625);
  // Five closed in it instead of two: solved again, smaller.
  EXPECT_NE(two.redoAtConvergence(nineNodes()), "");
  EXPECT_LT(two.beta(), 1.0);
}

TEST(AutomaticContacts, FewNodesGrowLikeAnExplicitCount) {
  // Two approaching nodes: automatic N_c = 2 (the minimum) equals N_c = 2 given, so β is the growth
  // cap in both (at most N_c candidates ahead).
  const auto nodes = nodesAt({1.5, 3.0});
  cb::ContactBetaControl automatic(settings(cb::kAutomaticContactsPerStep)), two(settings(2));
  automatic.firstAttempt(0.0);
  two.firstAttempt(0.0);
  const auto a = automatic.betaFor(nodes), b = two.betaFor(nodes);
  EXPECT_TRUE(a.fewCandidates);
  EXPECT_EQ(a.beta, b.beta);
  EXPECT_EQ(a.beta, 8.0);  // Max Growth Factor 8 = Max Step Size / step
}
