// The load-step correction β of the reference paper, section 2.1 (eq. 10–13, Table 1):
// closureFraction (β^k, eq. 11) and computeBeta (eq. 12, 13 and Contessa's nextContactFraction).
// Every expected value is worked out by hand in the comments. Most gaps are chosen so that
// g_t − g_{t+Δt} is exactly 1 (or another power of two) in binary floating point, which makes
// β^k = g_t exactly and lets the tests compare with EXPECT_EQ / EXPECT_DOUBLE_EQ.
#include "continuation/ContactBeta.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace cb = contessa::continuation;

namespace {

constexpr double kTouching = 1e-10;  // the default BetaOptions::touchingGap
const double kInf = std::numeric_limits<double>::infinity();
const double kNaN = std::numeric_limits<double>::quiet_NaN();

cb::GapChange gap(double start, double end, bool inContact = false) { return {start, end, inContact}; }

/// A node with β^k = b exactly: g_t = b, g_{t+Δt} = b − 1 (closing by exactly 1 over Δt). b is a
/// dyadic fraction in every use, so b − 1 and b / 1 are exact.
cb::GapChange closingAt(double b) { return gap(b, b - 1.0); }

/// BetaOptions' members in their declared order, the event-rate scale at its default.
cb::BetaOptions options(int nc, double fraction, double maxGrowth = 2.0, double maxShrink = 0.05) {
  return {nc, maxGrowth, maxShrink, fraction, kTouching};
}

/// Four candidates out of order, β^k = 0.75, 0.25, 1.5, 0.5, and three nodes that are not candidates
/// (in contact at the start, moving away, no master in reach). Sorted (eq. 12): 0.25, 0.5, 0.75, 1.5.
std::vector<cb::GapChange> fourCandidates() {
  return {closingAt(0.75), gap(0.2, -0.3, /*inContact=*/true), closingAt(0.25), gap(0.2, 0.3),
          closingAt(1.5),  gap(kInf, kInf),                    closingAt(0.5)};
}

bool notCandidate(double betaK) { return betaK < 0; }

}  // namespace

// ---------------------------------------------------------------------------------------------------
// closureFraction: β^k of eq. (11)
// ---------------------------------------------------------------------------------------------------

TEST(ClosureFraction, Eq11Value) {
  // β^k = g_t / (g_t − g_{t+Δt})
  EXPECT_EQ(cb::closureFraction(gap(0.75, -0.25), kTouching), 0.75);  // 0.75 / 1: closes at 3/4 of Δt
  EXPECT_EQ(cb::closureFraction(gap(2.0, -6.0), kTouching), 0.25);    // 2 / 8
  EXPECT_EQ(cb::closureFraction(gap(1.0, 0.5), kTouching), 2.0);      // 1 / 0.5: still open, closes at 2Δt
  EXPECT_EQ(cb::closureFraction(gap(0.5, -1.5), kTouching), 0.25);    // 0.5 / 2
  // Not exact in binary: 0.3 / (0.3 − 0.1) = 1.5 to a few ulp.
  EXPECT_DOUBLE_EQ(cb::closureFraction(gap(0.3, 0.1), kTouching), 1.5);
  // Millimetre-sized gaps as in the tube deck: 0.8 / (0.8 + 1.2) = 0.4.
  EXPECT_DOUBLE_EQ(cb::closureFraction(gap(0.8, -1.2), kTouching), 0.4);
}

TEST(ClosureFraction, ExactHitAtEndOfStepIsOne) {
  // g_{t+Δt} = 0: the node touches exactly at t + Δt, β^k = g_t / g_t = 1 exactly.
  EXPECT_EQ(cb::closureFraction(gap(0.37, 0.0), kTouching), 1.0);
  EXPECT_EQ(cb::closureFraction(gap(1e-3, 0.0), kTouching), 1.0);
  EXPECT_EQ(cb::closureFraction(gap(123.456, 0.0), kTouching), 1.0);
}

TEST(ClosureFraction, MovingAwayOrParallelIsNotACandidate) {
  // g_t − g_{t+Δt} ≤ 0: the node does not approach the master.
  EXPECT_PRED1(notCandidate, cb::closureFraction(gap(0.5, 0.7), kTouching));   // moving away
  EXPECT_PRED1(notCandidate, cb::closureFraction(gap(0.5, 0.5), kTouching));   // parallel (exactly)
  EXPECT_PRED1(notCandidate, cb::closureFraction(gap(1e-3, 10.0), kTouching)); // far away
}

TEST(ClosureFraction, NodeInContactAtStartIsNotACandidate) {
  // Already active at t: it does not "come into contact" in this increment, whatever its gaps.
  EXPECT_PRED1(notCandidate, cb::closureFraction(gap(0.5, -0.5, true), kTouching));
  EXPECT_PRED1(notCandidate, cb::closureFraction(gap(-1e-3, -2e-3, true), kTouching));  // penetrating
  EXPECT_PRED1(notCandidate, cb::closureFraction(gap(0.0, -1.0, true), kTouching));     // touching
}

TEST(ClosureFraction, TouchingNodeIsZero) {
  // g_t ≤ touchingGap: β^k = 0 (it closes at once if it closes at all).
  EXPECT_EQ(cb::closureFraction(gap(0.0, -0.5), kTouching), 0.0);
  EXPECT_EQ(cb::closureFraction(gap(1e-11, -0.5), kTouching), 0.0);
  EXPECT_EQ(cb::closureFraction(gap(1e-10, -0.5), kTouching), 0.0);   // the bound itself (≤)
  EXPECT_EQ(cb::closureFraction(gap(-1e-4, -2e-4), kTouching), 0.0);  // slightly penetrating, not yet active
  // Just above the bound it is an ordinary candidate: 2e-10 / (2e-10 + 2e-10) = 0.5 exactly.
  EXPECT_EQ(cb::closureFraction(gap(2e-10, -2e-10), kTouching), 0.5);
  // The bound is the argument: with touchingGap = 0.02 a gap of 0.01 is touching; with 0.001 it is
  // not: 0.01 / (0.01 + 0.01) = 0.5.
  EXPECT_EQ(cb::closureFraction(gap(0.01, -0.01), 0.02), 0.0);
  EXPECT_DOUBLE_EQ(cb::closureFraction(gap(0.01, -0.01), 0.001), 0.5);
  // Documented contract (header: "0 for a touching node (g_t ≤ touchingGap)"): the end gap is not
  // looked at, so a touching node counts as 0 even when it moves away or its end gap is unknown.
  EXPECT_EQ(cb::closureFraction(gap(0.0, 0.5), kTouching), 0.0);
  EXPECT_EQ(cb::closureFraction(gap(0.0, kInf), kTouching), 0.0);
}

TEST(ClosureFraction, NoMasterInReachIsNotACandidate) {
  // +∞ gaps mean no master segment in reach (GapChange::gapStart).
  EXPECT_PRED1(notCandidate, cb::closureFraction(gap(kInf, kInf), kTouching));
  EXPECT_PRED1(notCandidate, cb::closureFraction(gap(kInf, 0.5), kTouching));   // in reach only at the end
  EXPECT_PRED1(notCandidate, cb::closureFraction(gap(kInf, -0.5), kTouching));
  EXPECT_PRED1(notCandidate, cb::closureFraction(gap(0.5, kInf), kTouching));   // out of reach at the end
}

TEST(ClosureFraction, NaNGapsAreNotCandidates) {
  EXPECT_PRED1(notCandidate, cb::closureFraction(gap(kNaN, 0.5), kTouching));
  EXPECT_PRED1(notCandidate, cb::closureFraction(gap(kNaN, -0.5), kTouching));
  EXPECT_PRED1(notCandidate, cb::closureFraction(gap(0.5, kNaN), kTouching));
  EXPECT_PRED1(notCandidate, cb::closureFraction(gap(kNaN, kNaN), kTouching));
}

TEST(ClosureFraction, NeverNaNAndNeverNegativeForACandidate) {
  // Over a grid of awkward values the result is either "not a candidate" (< 0) or a finite β^k ≥ 0.
  const std::vector<double> values = {kNaN, kInf, -kInf, 0.0, -0.0, kTouching, 2 * kTouching, -1.0,
                                      1e-300, 1e300, 0.5, 1.0, -1e300};
  for (double start : values)
    for (double end : values)
      for (bool inContact : {false, true}) {
        const double b = cb::closureFraction(gap(start, end, inContact), kTouching);
        EXPECT_FALSE(std::isnan(b)) << "g_t = " << start << ", g_end = " << end;
        if (b >= 0) {
          EXPECT_TRUE(std::isfinite(b)) << "g_t = " << start << ", g_end = " << end;
        }
        if (inContact) {
          EXPECT_LT(b, 0) << "g_t = " << start << ", g_end = " << end;
        }
      }
}

// ---------------------------------------------------------------------------------------------------
// computeBeta: eq. (12) sorting, eq. (13) and the nextContactFraction interpolation
// ---------------------------------------------------------------------------------------------------

TEST(ComputeBeta, SortsCandidatesAscendingEq12) {
  const auto r = cb::computeBeta(fourCandidates(), options(1, 0.0));
  EXPECT_EQ(r.candidates, (std::vector<double>{0.25, 0.5, 0.75, 1.5}));  // non-candidates dropped
}

TEST(ComputeBeta, SortsByClosureFractionNotByGap) {
  // The larger gap can close first when it approaches faster:
  //   a: 0.4 / (0.4 + 0.4) = 0.5    b: 0.1 / (0.1 − 0) = 1    c: 0.05 / (0.05 + 0.15) = 0.25
  //   d: 0.9 / (0.9 − 0.6) = 3 (to a few ulp)
  const auto r = cb::computeBeta({gap(0.1, 0.0), gap(0.9, 0.6), gap(0.4, -0.4), gap(0.05, -0.15)}, options(1, 0.0));
  ASSERT_EQ(r.candidates.size(), 4u);
  EXPECT_DOUBLE_EQ(r.candidates[0], 0.25);
  EXPECT_DOUBLE_EQ(r.candidates[1], 0.5);
  EXPECT_DOUBLE_EQ(r.candidates[2], 1.0);
  EXPECT_DOUBLE_EQ(r.candidates[3], 3.0);
}

TEST(ComputeBeta, Eq13AsPrintedIsBetaNc) {
  // nextContactFraction = 0: β = β^{N_c} of the sorted 0.25, 0.5, 0.75, 1.5. Node N_c sits exactly
  // at zero gap at βΔt and counts as predicted (β^k ≤ β): N_c predicted contacts.
  for (const auto& [nc, expected] : std::vector<std::pair<int, double>>{{1, 0.25}, {2, 0.5}, {3, 0.75}}) {
    const auto r = cb::computeBeta(fourCandidates(), options(nc, 0.0));
    EXPECT_EQ(r.beta, expected) << "N_c = " << nc;
    EXPECT_EQ(r.predictedContacts, nc) << "N_c = " << nc;
  }
}

TEST(ComputeBeta, NextContactFractionInterpolatesTowardsNodeNcPlusOne) {
  // f = 0.9: β = β^{N_c} + 0.9 (β^{N_c+1} − β^{N_c})
  //   N_c = 1: 0.25 + 0.9 × 0.25 = 0.475
  //   N_c = 2: 0.5  + 0.9 × 0.25 = 0.725
  //   N_c = 3: 0.75 + 0.9 × 0.75 = 1.425   (β > 1: the step grows)
  for (const auto& [nc, expected] : std::vector<std::pair<int, double>>{{1, 0.475}, {2, 0.725}, {3, 1.425}}) {
    const auto r = cb::computeBeta(fourCandidates(), options(nc, 0.9));
    EXPECT_DOUBLE_EQ(r.beta, expected) << "N_c = " << nc;
    EXPECT_EQ(r.predictedContacts, nc) << "N_c = " << nc;  // node N_c + 1 stays open
  }
  // f = 0.5: N_c = 2: 0.5 + 0.5 × 0.25 = 0.625 (exact).
  EXPECT_EQ(cb::computeBeta(fourCandidates(), options(2, 0.5)).beta, 0.625);
  // f = 0.999 (the deck's upper bound): 0.25 + 0.999 × 0.25 = 0.49975 < 0.5, node 2 still open.
  const auto r = cb::computeBeta(fourCandidates(), options(1, 0.999));
  EXPECT_DOUBLE_EQ(r.beta, 0.49975);
  EXPECT_EQ(r.predictedContacts, 1);
}

TEST(ComputeBeta, ExactlyNcCandidatesGrowsToTheCap) {
  // Four candidates, N_c = 4: there is no node N_c + 1 to stop before: β = maxGrowth = 2, and all
  // four (β^k ≤ 1.5 ≤ 2) are predicted to close.
  auto r = cb::computeBeta(fourCandidates(), options(4, 0.9));
  EXPECT_EQ(r.beta, 2.0);
  EXPECT_EQ(r.predictedContacts, 4);
  // Same with eq. (13) (f = 0): the cap, not β^{N_c} = 1.5.
  r = cb::computeBeta(fourCandidates(), options(4, 0.0));
  EXPECT_EQ(r.beta, 2.0);
  // With a cap of 1.2 the node at 1.5 is beyond it: 3 predicted.
  r = cb::computeBeta(fourCandidates(), options(4, 0.9, 1.2));
  EXPECT_EQ(r.beta, 1.2);
  EXPECT_EQ(r.predictedContacts, 3);
}

TEST(ComputeBeta, MoreThanCandidatesGrowsToTheCap) {
  // N_c = 5 and 10 > 4 candidates: β = maxGrowth.
  for (int nc : {5, 10}) {
    const auto r = cb::computeBeta(fourCandidates(), options(nc, 0.9, 3.0));
    EXPECT_EQ(r.beta, 3.0) << "N_c = " << nc;
    EXPECT_EQ(r.predictedContacts, 4) << "N_c = " << nc;
  }
  // One candidate at β^k = 4 beyond the cap of 2, N_c = 2: β = 2, nothing predicted to close.
  const auto r = cb::computeBeta({closingAt(4.0)}, options(2, 0.9));
  EXPECT_EQ(r.beta, 2.0);
  EXPECT_EQ(r.predictedContacts, 0);
}

TEST(ComputeBeta, ClampsToMaxShrink) {
  // β^k = 1/64, 1/32, 1/16 (exact). N_c = 1, f = 0: β^1 = 0.015625 < maxShrink = 0.05 → 0.05.
  // Then 1/64 and 1/32 (0.03125) are ≤ 0.05: 2 predicted contacts, more than N_c (the floor wins).
  const std::vector<cb::GapChange> tiny = {closingAt(1.0 / 16), closingAt(1.0 / 64), closingAt(1.0 / 32)};
  auto r = cb::computeBeta(tiny, options(1, 0.0));
  EXPECT_EQ(r.beta, 0.05);
  EXPECT_EQ(r.predictedContacts, 2);
  // f = 0.9: 1/64 + 0.9 / 64 = 0.0296875, still < 0.05.
  r = cb::computeBeta(tiny, options(1, 0.9));
  EXPECT_EQ(r.beta, 0.05);
  // A larger floor: maxShrink = 0.5 on 0.25, 0.5, 0.75, 1.5 with N_c = 1, f = 0 → 0.5, and the node at
  // exactly 0.5 is predicted too (≤): 2.
  r = cb::computeBeta(fourCandidates(), options(1, 0.0, 2.0, 0.5));
  EXPECT_EQ(r.beta, 0.5);
  EXPECT_EQ(r.predictedContacts, 2);
}

TEST(ComputeBeta, ClampsToMaxGrowth) {
  // β^k = 4, 8. N_c = 1, f = 0: 4 > maxGrowth = 2 → 2, nothing closes in 2Δt.
  const std::vector<cb::GapChange> far = {closingAt(8.0), closingAt(4.0)};
  auto r = cb::computeBeta(far, options(1, 0.0));
  EXPECT_EQ(r.beta, 2.0);
  EXPECT_EQ(r.predictedContacts, 0);
  // f = 0.9: 4 + 0.9 × 4 = 7.6 → 2.
  r = cb::computeBeta(far, options(1, 0.9));
  EXPECT_EQ(r.beta, 2.0);
  // maxGrowth = 10 leaves 7.6 alone: node 1 closes, node 2 (at 8) does not.
  r = cb::computeBeta(far, options(1, 0.9, 10.0));
  EXPECT_DOUBLE_EQ(r.beta, 7.6);
  EXPECT_EQ(r.predictedContacts, 1);
}

TEST(ComputeBeta, TouchingNodesTakeAPlace) {
  // A touching node (β^k = 0) and two closing at 0.5 and 0.75.
  const std::vector<cb::GapChange> g = {closingAt(0.75), gap(0.0, -1.0), closingAt(0.5)};
  // N_c = 1, f = 0: β = β^1 = 0 → maxShrink 0.05; only the touching node closes.
  auto r = cb::computeBeta(g, options(1, 0.0));
  EXPECT_EQ(r.candidates, (std::vector<double>{0.0, 0.5, 0.75}));
  EXPECT_EQ(r.beta, 0.05);
  EXPECT_EQ(r.predictedContacts, 1);
  // N_c = 1, f = 0.9: 0 + 0.9 × 0.5 = 0.45.
  r = cb::computeBeta(g, options(1, 0.9));
  EXPECT_DOUBLE_EQ(r.beta, 0.45);
  EXPECT_EQ(r.predictedContacts, 1);
  // N_c = 2, f = 0: β = β^2 = 0.5, the touching node and the one at 0.5.
  r = cb::computeBeta(g, options(2, 0.0));
  EXPECT_EQ(r.beta, 0.5);
  EXPECT_EQ(r.predictedContacts, 2);
}

TEST(ComputeBeta, TiedNodesCloseTogether) {
  // Two nodes at β^k = 0.5 and one at 0.75, N_c = 1: β = 0.5 + f × 0 = 0.5 for any f, and both tied
  // nodes are predicted (no step size can separate them): 2 > N_c.
  const std::vector<cb::GapChange> g = {closingAt(0.5), closingAt(0.75), closingAt(0.5)};
  for (double f : {0.0, 0.9}) {
    const auto r = cb::computeBeta(g, options(1, f));
    EXPECT_EQ(r.beta, 0.5) << "f = " << f;
    EXPECT_EQ(r.predictedContacts, 2) << "f = " << f;
  }
}

TEST(ComputeBeta, PredictedContactsCountsCandidatesUpToBeta) {
  // β^k = 0.25, 0.5, 0.75, 1.5 and N_c = 2, f = 0.9: β = 0.725 → 0.25 and 0.5 predicted: 2.
  // N_c = 3, f = 0.9, maxGrowth = 1.0: 1.425 → 1.0 → 0.25, 0.5, 0.75: 3.
  // N_c = 3, f = 0.9, maxGrowth = 0.6: 1.425 → 0.6 → 0.25, 0.5: 2 (< N_c: the cap forbids more).
  EXPECT_EQ(cb::computeBeta(fourCandidates(), options(2, 0.9)).predictedContacts, 2);
  auto r = cb::computeBeta(fourCandidates(), options(3, 0.9, 1.0));
  EXPECT_EQ(r.beta, 1.0);
  EXPECT_EQ(r.predictedContacts, 3);
  r = cb::computeBeta(fourCandidates(), options(3, 0.9, 0.6, 0.05));
  EXPECT_EQ(r.beta, 0.6);
  EXPECT_EQ(r.predictedContacts, 2);
}

TEST(ComputeBeta, EmptyInputGrowsToTheCap) {
  auto r = cb::computeBeta({}, options(2, 0.9));
  EXPECT_EQ(r.beta, 2.0);
  EXPECT_TRUE(r.candidates.empty());
  EXPECT_EQ(r.predictedContacts, 0);
  // maxGrowth = 1: the step stays as it is.
  EXPECT_EQ(cb::computeBeta({}, options(2, 0.9, 1.0)).beta, 1.0);
  // Only non-candidates (in contact, moving away, parallel, out of reach): the same as empty.
  r = cb::computeBeta({gap(0.1, -0.1, true), gap(0.1, 0.2), gap(0.1, 0.1), gap(kInf, kInf), gap(0.1, kInf)},
                      options(1, 0.9, 5.0));
  EXPECT_EQ(r.beta, 5.0);
  EXPECT_TRUE(r.candidates.empty());
  EXPECT_EQ(r.predictedContacts, 0);
}

TEST(ComputeBeta, NaNGapsAreIgnored) {
  // NaN gaps are dropped; β comes from the two valid nodes 0.25 and 0.5: N_c = 1, f = 0.9 → 0.475.
  const std::vector<cb::GapChange> g = {gap(kNaN, kNaN), closingAt(0.5), gap(0.5, kNaN), gap(kNaN, -1.0),
                                        closingAt(0.25)};
  auto r = cb::computeBeta(g, options(1, 0.9));
  EXPECT_EQ(r.candidates, (std::vector<double>{0.25, 0.5}));
  EXPECT_DOUBLE_EQ(r.beta, 0.475);
  EXPECT_EQ(r.predictedContacts, 1);
  // Only NaN: like empty, β = maxGrowth, never NaN.
  r = cb::computeBeta({gap(kNaN, kNaN), gap(kNaN, 0.0), gap(1.0, kNaN)}, options(1, 0.9));
  EXPECT_EQ(r.beta, 2.0);
  EXPECT_EQ(r.predictedContacts, 0);
}

TEST(ComputeBeta, DefaultOptions) {
  // The defaults of BetaOptions: N_c automatic (ContactBetaControl resolves it from the slave nodes,
  // AutomaticContactsTest), f = 0.9, β in [0.05, 2], touchingGap = 1e-10.
  cb::BetaOptions defaults;
  EXPECT_EQ(defaults.contactsPerStep, cb::kAutomaticContactsPerStep);
  defaults.contactsPerStep = 2;
  EXPECT_EQ(defaults.nextContactFraction, 0.9);
  EXPECT_EQ(defaults.maxGrowth, 2.0);
  EXPECT_EQ(defaults.maxShrink, 0.05);
  EXPECT_EQ(defaults.touchingGap, 1e-10);
  // 0.25, 0.5, 0.75, 1.5 with the defaults and N_c = 2: 0.5 + 0.9 × 0.25 = 0.725.
  EXPECT_DOUBLE_EQ(cb::computeBeta(fourCandidates(), defaults).beta, 0.725);
}
