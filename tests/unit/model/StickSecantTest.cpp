// The augmented Lagrangian's secant update of a sticking node's tangential multiplier (contact::stickSecantFactor,
// docs/theory-contact.md §15, "The stick multipliers' secant"): on a node held by a linear structure,
// t_T = F − K ā Δξ, the secant of two updates finds the multiplier that leaves no motion in one step, whatever
// the stick penalty did between them; it keeps the multiplier inside the Coulomb cone and falls back to Uzawa's
// step (factor 1) where the motion changed by less than the Newton noise or the measured stiffness is not positive.
#include "contact/ContactInterface.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace cc = contessa::contact;

namespace {

// The node at equilibrium with multiplier λ and stick penalty ε: K m = F − t, t = λ + ε m, so m = (F − λ)/(K + ε).
template <int N>
cc::StickUpdate<N> held(const cc::Vector<N>& force, double stiffness, const cc::Vector<N>& multiplier, double penalty) {
  const cc::Vector<N> motion = cc::scaled(1.0 / (stiffness + penalty), cc::subtract(force, multiplier));
  return {cc::add(multiplier, cc::scaled(penalty, motion)), motion};
}

template <int N>
double norm(const cc::Vector<N>& v, const cc::Matrix<N, N>& inverseMetric) {
  return std::sqrt(cc::dot(v, cc::multiply(inverseMetric, v)));
}

// Two Uzawa updates (λ ← t) with penalties ε0, ε1, then the secant's: the result against F.
template <int N>
cc::Vector<N> secantAfterTwoUpdates(const cc::Vector<N>& force, double stiffness, double e0, double e1,
                                    const cc::Matrix<N, N>& inverseMetric, double cone, double* factor) {
  const cc::Vector<N> l0{};
  const auto u0 = held<N>(force, stiffness, l0, e0);
  const cc::Vector<N> l1 = u0.traction;  // Uzawa, eq. (15.3)
  const auto u1 = held<N>(force, stiffness, l1, e1);
  *factor = cc::stickSecantFactor(u0, u1, l1, e1, inverseMetric, cone, 1e-12, HUGE_VAL);
  return cc::add(l1, cc::scaled(*factor, cc::subtract(u1.traction, l1)));
}

TEST(StickSecant, OneStepToTheMultiplierWithoutMotionIn2D) {
  // K = 100 against ε_T = 0.5: Uzawa's rate K/(K + ε) = 0.995 per update.
  const cc::Matrix<1, 1> inverseMetric{{{4.0}}};  // ā = 1/4: a facet of length 1, ξ in [−1, 1]
  const cc::Vector<1> force{0.3};
  double factor = 0;
  const auto l = secantAfterTwoUpdates<1>(force, 100.0, 0.5, 0.5, inverseMetric, 1e3, &factor);
  EXPECT_NEAR(l[0], force[0], 1e-12);
  EXPECT_NEAR(factor, 1.0 + 100.0 / 0.5, 1e-9);
  // The motion that multiplier leaves: none.
  EXPECT_NEAR(norm<1>(held<1>(force, 100.0, l, 0.5).motion, inverseMetric), 0.0, 1e-15);
}

TEST(StickSecant, OneStepIn3DWithAStickPenaltyThatChangedBetweenTheUpdates) {
  // A sheared face (non-diagonal metric); ε_T follows λ_N, which the first update changed threefold.
  const cc::Matrix<2, 2> metric{{{1.0, 0.3, 0.3, 0.5}}};
  const cc::Matrix<2, 2> inverseMetric = cc::inverse(metric);
  const cc::Vector<2> force{0.2, -0.1};
  double factor = 0;
  const auto l = secantAfterTwoUpdates<2>(force, 80.0, 0.2, 0.6, inverseMetric, 1e3, &factor);
  EXPECT_NEAR(l[0], force[0], 1e-12);
  EXPECT_NEAR(l[1], force[1], 1e-12);
  EXPECT_NEAR(factor, 1.0 + 80.0 / 0.6, 1e-9);
}

TEST(StickSecant, StopsOnTheCoulombCone) {
  // The multiplier without motion, F, lies outside the cone μ|λ_N| = 0.25: the node is to slip; the step
  // ends on the cone, along Uzawa's direction.
  const cc::Matrix<2, 2> inverseMetric = cc::inverse(cc::Matrix<2, 2>{{{1.0, 0.3, 0.3, 0.5}}});
  const cc::Vector<2> force{0.4, 0.1};
  ASSERT_GT(norm<2>(force, inverseMetric), 0.25);
  double factor = 0;
  const auto l = secantAfterTwoUpdates<2>(force, 80.0, 0.5, 0.5, inverseMetric, 0.25, &factor);
  EXPECT_NEAR(norm<2>(l, inverseMetric), 0.25, 1e-12);
  EXPECT_GT(factor, 1.0);
  EXPECT_LT(factor, 1.0 + 80.0 / 0.5);
}

TEST(StickSecant, FadesToUzawasStepBelowTheNoiseWithoutAJump) {
  const cc::Matrix<1, 1> inverseMetric{{{1.0}}};
  const cc::Vector<1> multiplier{0.1};
  const double noise = 1e-8;
  // A stiffness K = 100 read over a motion change c: K̃ = K c²/(c² + n²), the factor 1 + K̃/ε (ε = 1).
  const auto factorAt = [&](double change) {
    const cc::StickUpdate<1> a{{0.2}, {1e-3}}, b{{0.2 + 100.0 * change}, {1e-3 - change}};
    return cc::stickSecantFactor(a, b, multiplier, 1.0, inverseMetric, 1e3, noise, HUGE_VAL);
  };
  EXPECT_NEAR(factorAt(noise), 1.0 + 50.0, 1e-6);               // half the secant's step at c = n
  EXPECT_NEAR(factorAt(1e-3 * noise), 1.0 + 100.0 * 1e-6, 1e-9);  // (c/n)² of it far below
  EXPECT_NEAR(factorAt(1e3 * noise), 1.0 + 100.0, 1e-3);         // all of it far above
  // No jump anywhere between: over c from n/100 to 100 n in steps of 0.1 %, the factor moves by less than
  // 0.2 % of the full step between neighbours (a threshold would jump by the full step).
  double last = factorAt(1e-2 * noise);
  for (double c = 1e-2 * noise; c < 1e2 * noise; c *= 1.001) {
    const double f = factorAt(c);
    EXPECT_LT(std::abs(f - last), 0.002 * 100.0) << "at c = " << c;
    last = f;
  }
  // The traction fell with the motion: no positive stiffness holds the node, Uzawa's step.
  const cc::StickUpdate<1> c{{0.2}, {1e-3}}, d{{0.15}, {5e-4}};
  EXPECT_EQ(cc::stickSecantFactor(c, d, multiplier, 1.0, inverseMetric, 1e3, noise, 1e6), 1.0);
}

TEST(StickSecant, SaturatesSmoothlyAtItsBound) {
  const cc::Matrix<1, 1> inverseMetric{{{1.0}}};
  const cc::Vector<1> multiplier{0.1};
  const cc::StickUpdate<1> e{{0.2}, {1e-3}}, f{{0.25}, {5e-4}};  // K = 100
  // g = 100: f = 1 + 100/(1 + 100/19) with a bound of 20, below it; without a bound 101.
  EXPECT_NEAR(cc::stickSecantFactor(e, f, multiplier, 1.0, inverseMetric, 1e3, 0.0, 20.0), 1.0 + 100.0 / (1.0 + 100.0 / 19.0),
              1e-12);
  EXPECT_LT(cc::stickSecantFactor(e, f, multiplier, 1.0, inverseMetric, 1e3, 0.0, 20.0), 20.0);
  EXPECT_NEAR(cc::stickSecantFactor(e, f, multiplier, 1.0, inverseMetric, 1e3, 0.0, HUGE_VAL), 101.0, 1e-9);
}

TEST(StickSecant, TheSameFactorInAnyUnitSystem) {
  // mm/N against m/N: lengths (motions, the noise) x 1e-3, forces kept, the stick penalty (force/length) x 1e3;
  // the metric of a facet 1e-3 times as long goes as 1e-6, its inverse as 1e6.
  const cc::Matrix<2, 2> metric{{{1.0, 0.3, 0.3, 0.5}}};
  const cc::Matrix<2, 2> metricSI{{{1e-6, 0.3e-6, 0.3e-6, 0.5e-6}}};
  const cc::Vector<2> multiplier{0.05, 0.01};
  // Covariant traction components t_α = t · a_α scale with the facet's length, the motion ā_αβ Δξ^β with its square.
  const cc::StickUpdate<2> a{{0.12, -0.03}, {2e-3, -1e-3}}, b{{0.15, -0.05}, {1.2e-3, -0.4e-3}};
  const cc::StickUpdate<2> aSI{{0.12e-3, -0.03e-3}, {2e-9, -1e-9}}, bSI{{0.15e-3, -0.05e-3}, {1.2e-9, -0.4e-9}};
  const cc::Vector<2> multiplierSI{0.05e-3, 0.01e-3};
  // The cone radius μ|λ_N| is a force: the same in both. 100: the secant's factor; 0.3: the cone's.
  for (double cone : {100.0, 0.3}) {
    for (double noise : {0.0, 3e-4, 3e-3}) {
      const double mm = cc::stickSecantFactor(a, b, multiplier, 2.0, cc::inverse(metric), cone, noise, 1000.0);
      const double m = cc::stickSecantFactor(aSI, bSI, multiplierSI, 2.0e3, cc::inverse(metricSI), cone, noise * 1e-3, 1000.0);
      EXPECT_GT(mm, 1.0);
      EXPECT_NEAR(m, mm, 1e-12 * mm) << "noise " << noise << ", cone " << cone;
    }
  }
}

}  // namespace
