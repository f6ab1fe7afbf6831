// The augmented Lagrangian's secant update of a sticking node's tangential multiplier (contact::stickSecantFactor,
// docs/theory-contact.md §15, "The stick multipliers' secant"): on a node held by a linear structure,
// t_T = F − K ā Δξ, the secant of two updates finds the multiplier that leaves no motion in one step, whatever
// the stick penalty did between them; it keeps the multiplier inside the Coulomb cone and falls back to Uzawa's
// step (factor 1) where the motion changed by less than the Newton noise or the measured stiffness is not positive.
#include "contact/ContactInterface.hpp"

#include <gtest/gtest.h>

#include <cmath>

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
  *factor = cc::stickSecantFactor(u0, u1, l1, e1, inverseMetric, cone, 1e-12, 1e6);
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

TEST(StickSecant, UzawasStepWhereTheSecantCannotBeTrusted) {
  const cc::Matrix<1, 1> inverseMetric{{{1.0}}};
  const cc::Vector<1> multiplier{0.1};
  // The motion changed by 1e-9, below the noise 1e-8 the update may read.
  const cc::StickUpdate<1> a{{0.2}, {1e-3}}, b{{0.25}, {1e-3 - 1e-9}};
  EXPECT_EQ(cc::stickSecantFactor(a, b, multiplier, 1.0, inverseMetric, 1e3, 1e-8, 1e6), 1.0);
  // The traction fell with the motion: no positive stiffness holds the node.
  const cc::StickUpdate<1> c{{0.2}, {1e-3}}, d{{0.15}, {5e-4}};
  EXPECT_EQ(cc::stickSecantFactor(c, d, multiplier, 1.0, inverseMetric, 1e3, 1e-8, 1e6), 1.0);
  // A positive stiffness, but the factor bounded.
  const cc::StickUpdate<1> e{{0.2}, {1e-3}}, f{{0.25}, {5e-4}};  // K = 100
  EXPECT_EQ(cc::stickSecantFactor(e, f, multiplier, 1.0, inverseMetric, 1e3, 1e-8, 20.0), 20.0);
  EXPECT_NEAR(cc::stickSecantFactor(e, f, multiplier, 1.0, inverseMetric, 1e3, 1e-8, 1e6), 101.0, 1e-9);
}

}  // namespace
