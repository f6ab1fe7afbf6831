// The load steps' schedule (continuation/LoadSchedule.hpp): values and ∂/∂λ_s at a step's load factor,
// the amplitude's interpolation and slope, values held by steps that do not name them, the friction
// coefficient that is not ramped from zero, and a run without steps (v = λ v_deck bit for bit). Every
// expected value is worked out by hand in the comments (binary-exact fractions where possible).
#include "continuation/LoadSchedule.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace cb = contessa::continuation;
using V = std::vector<double>;

namespace {

// press (0.5 of its period, amplitude table) then slide: the ironing pattern of the user guide.
cb::LoadSchedule pressThenSlide() {
  cb::LoadSchedule s;
  s.addQuantity("Dirichlet Conditions/press", {-1.0});
  s.addQuantity("Dirichlet Conditions/shear", {0.0});
  s.addQuantity("Contact/die/Motion", {0.0, -2.0});
  s.addQuantity("Contact/die/Friction Coefficient", {0.25}, false);
  cb::ScheduledStep press;
  press.name = "press";
  press.timePeriod = 0.5;
  press.amplitude = cb::Amplitude({0.0, 0.5, 1.0}, {0.0, 0.75, 1.0});
  cb::ScheduledStep slide;
  slide.name = "slide";
  slide.endValues["Dirichlet Conditions/shear"] = {4.0};
  slide.endValues["Contact/die/Motion"] = {8.0, -2.0};
  slide.endValues["Contact/die/Friction Coefficient"] = {0.5};
  s.addStep(press);
  s.addStep(slide);
  return s;
}

}  // namespace

TEST(Amplitude, RampIsTheIdentityBitForBit) {
  const cb::Amplitude ramp;
  for (double t : {0.0, 0.1, 1.0 / 3.0, 0.7, 1.0}) {
    EXPECT_EQ(ramp.value(t), t);
    EXPECT_EQ(ramp.slope(t), 1.0);
  }
}

TEST(Amplitude, TableInterpolatesPiecewiseLinearly) {
  const cb::Amplitude a({0.0, 0.5, 1.0}, {0.0, 0.75, 1.0});
  EXPECT_EQ(a.value(0.0), 0.0);
  EXPECT_EQ(a.value(0.25), 0.375);  // half of the first segment: 0.75 / 2
  EXPECT_EQ(a.value(0.5), 0.75);
  EXPECT_EQ(a.value(0.75), 0.875);  // 0.75 + 0.5·0.25
  EXPECT_EQ(a.value(1.0), 1.0);
  EXPECT_EQ(a.slope(0.25), 1.5);   // 0.75 / 0.5
  EXPECT_EQ(a.slope(0.5), 0.5);    // at a breakpoint: the segment that starts there, 0.25 / 0.5
  EXPECT_EQ(a.slope(1.0), 0.5);    // at the end: the last segment's
}

TEST(Amplitude, SlopeMatchesCentralDifferences) {
  const cb::Amplitude a({0.0, 0.2, 0.6, 1.0}, {0.0, 0.1, 0.9, 1.0});
  const double h = 1e-6;
  for (double t : {0.1, 0.3, 0.55, 0.8}) EXPECT_NEAR(a.slope(t), (a.value(t + h) - a.value(t - h)) / (2 * h), 1e-8) << t;
}

TEST(Amplitude, RefusesBadTables) {
  EXPECT_THROW(cb::Amplitude({0.0, 1.0}, {0.0}), std::invalid_argument);              // lengths differ
  EXPECT_THROW(cb::Amplitude({0.0, 0.6, 0.6, 1.0}, {0, 1, 1, 1}), std::invalid_argument);  // not increasing
  EXPECT_THROW(cb::Amplitude({0.1, 1.0}, {0.0, 1.0}), std::invalid_argument);        // not from 0
  EXPECT_THROW(cb::Amplitude({0.0, 1.5}, {0.0, 1.0}), std::invalid_argument);        // not to 1
}

TEST(LoadSchedule, WithoutStepsIsTheProportionalLoadFactor) {
  cb::LoadSchedule s;
  s.addQuantity("Dirichlet Conditions/pull", {0.3});
  s.addQuantity("Contact/plate/Friction Coefficient", {0.2}, false);
  ASSERT_EQ(s.numSteps(), 1);
  for (double lambda : {0.0, 0.1, 0.7, 1.0}) {
    EXPECT_EQ(s.value(0, "Dirichlet Conditions/pull", lambda)[0], lambda * 0.3);  // bit for bit
    EXPECT_EQ(s.derivative(0, "Dirichlet Conditions/pull", lambda)[0], 0.3);
    EXPECT_EQ(s.value(0, "Contact/plate/Friction Coefficient", lambda)[0], 0.2);  // held, not ramped
    EXPECT_EQ(s.derivative(0, "Contact/plate/Friction Coefficient", lambda)[0], 0.0);
    EXPECT_EQ(s.time(0, lambda), lambda);
  }
  EXPECT_FALSE(s.changes(0, "Contact/plate/Friction Coefficient"));
}

TEST(LoadSchedule, FirstStepRampsTheDeckValuesWithItsAmplitude) {
  const auto s = pressThenSlide();
  ASSERT_EQ(s.numSteps(), 2);
  EXPECT_EQ(s.stepName(0), "press");
  // λ = 0.25: A = 0.375, press = −0.375, motion (0, −0.75); A' = 1.5: ∂/∂λ = (−1.5), (0, −3).
  EXPECT_EQ(s.value(0, "Dirichlet Conditions/press", 0.25), V{-0.375});
  EXPECT_EQ(s.derivative(0, "Dirichlet Conditions/press", 0.25), V{-1.5});
  EXPECT_EQ(s.value(0, "Contact/die/Motion", 0.25), (V{0.0, -0.75}));
  EXPECT_EQ(s.derivative(0, "Contact/die/Motion", 0.25), (V{0.0, -3.0}));
  EXPECT_EQ(s.value(0, "Dirichlet Conditions/shear", 0.25), V{0.0});
  // Friction holds the deck's 0.25 through the press.
  EXPECT_EQ(s.value(0, "Contact/die/Friction Coefficient", 0.25), V{0.25});
  EXPECT_EQ(s.value(0, "Contact/die/Friction Coefficient", 1.0), V{0.25});
}

TEST(LoadSchedule, SecondStepStartsAtTheFirstStepsEndAndHoldsWhatItDoesNotName) {
  const auto s = pressThenSlide();
  // The press is held (−1) with zero derivative; shear 0 → 4 and motion (0, −2) → (8, −2) on a ramp.
  EXPECT_EQ(s.start(1, "Dirichlet Conditions/press"), V{-1.0});
  EXPECT_EQ(s.value(1, "Dirichlet Conditions/press", 0.5), V{-1.0});
  EXPECT_EQ(s.derivative(1, "Dirichlet Conditions/press", 0.5), V{0.0});
  EXPECT_FALSE(s.changes(1, "Dirichlet Conditions/press"));
  EXPECT_EQ(s.value(1, "Dirichlet Conditions/shear", 0.25), V{1.0});
  EXPECT_EQ(s.derivative(1, "Dirichlet Conditions/shear", 0.25), V{4.0});
  EXPECT_EQ(s.value(1, "Contact/die/Motion", 0.5), (V{4.0, -2.0}));
  EXPECT_EQ(s.derivative(1, "Contact/die/Motion", 0.5), (V{8.0, 0.0}));
  // Friction ramps from the previous end value 0.25 to 0.5: 0.375 half-way.
  EXPECT_EQ(s.value(1, "Contact/die/Friction Coefficient", 0.5), V{0.375});
  EXPECT_EQ(s.derivative(1, "Contact/die/Friction Coefficient", 0.5), V{0.25});
  // Continuity at the boundary: step 2 at λ = 0 is step 1 at λ = 1.
  for (const char* key : {"Dirichlet Conditions/press", "Dirichlet Conditions/shear", "Contact/die/Motion",
                          "Contact/die/Friction Coefficient"})
    EXPECT_EQ(s.value(1, key, 0.0), s.value(0, key, 1.0)) << key;
}

TEST(LoadSchedule, TimeRunsOnAcrossSteps) {
  const auto s = pressThenSlide();
  EXPECT_EQ(s.startTime(0), 0.0);
  EXPECT_EQ(s.time(0, 1.0), 0.5);
  EXPECT_EQ(s.startTime(1), 0.5);
  EXPECT_EQ(s.time(1, 0.25), 0.75);  // 0.5 + 0.25·1: A-independent
}

TEST(LoadSchedule, ValueDerivativeMatchesCentralDifferences) {
  const auto s = pressThenSlide();
  const double h = 1e-7;
  for (int step : {0, 1})
    for (double lambda : {0.2, 0.6, 0.9}) {
      const auto d = s.derivative(step, "Contact/die/Motion", lambda);
      const auto plus = s.value(step, "Contact/die/Motion", lambda + h);
      const auto minus = s.value(step, "Contact/die/Motion", lambda - h);
      for (std::size_t c = 0; c < d.size(); ++c) EXPECT_NEAR(d[c], (plus[c] - minus[c]) / (2 * h), 1e-6);
    }
}

TEST(LoadSchedule, RefusesUnknownQuantitiesAndWrongSizes) {
  cb::LoadSchedule s;
  s.addQuantity("Loads/gravity", {0.0, -9.81});
  cb::ScheduledStep bad;
  bad.name = "bad";
  bad.endValues["Loads/wind"] = {1.0, 0.0};
  EXPECT_THROW(s.addStep(bad), std::invalid_argument);
  bad.endValues.clear();
  bad.endValues["Loads/gravity"] = {1.0};
  EXPECT_THROW(s.addStep(bad), std::invalid_argument);
}
