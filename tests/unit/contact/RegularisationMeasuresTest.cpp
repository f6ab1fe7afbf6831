// Issue 21, point 3: the largest penetration, elastic slip and slip an interface reports at its commit, and
// the test that says when they spoil the answer (contact/RegularisationMeasures.hpp).
#include <gtest/gtest.h>

#include "InterfaceTestTools.hpp"

namespace cc = contessa::contact;
namespace ct = contessa::contact::testing;

namespace {

// Three slave nodes at y = 0 (x = 0, 1, 2) under a rigid line at y = 0.5 (body above), 20 long, that moves
// by λ (mx, −1): it touches the nodes at λ = 0.5.
cc::ContactInterfaceSpec plate(double mx) {
  auto spec = ct::threeNodesUnderRigidLine({{-10.0, 0.5}, {10.0, 0.5}}, {mx, -1.0});
  spec.law.frictionCoefficient = 0.3;
  spec.law.slipTolerance = 0.01;  // stick radius 0.01 × L = 0.01
  return spec;
}

constexpr auto slave = ct::threeNodesOnXAxis;

// The measures `spec`'s interface commits at λ after a first commit at λ = 0, with a trial state beyond it
// (λ = 0.9) rolled back: a trial state leaves no trace.
cc::RegularisationMeasures after(const cc::ContactInterfaceSpec& spec, double lambda) {
  const auto interface = cc::makeContactInterface(spec, {1, 1, 1});
  const auto sink = [](const cc::GlobalIndex*, int, const double*, const double*, const double*) {};
  interface->evaluate(slave, 0.0, true, sink);
  interface->commit();
  interface->evaluate(slave, lambda, true, sink);
  interface->commit();
  interface->evaluate(slave, 0.9, true, sink);
  interface->rollback();
  return interface->committedRegularisation();
}

// What the frictional plate's nodes report: the three maxima (to 1e-12), how many slip and whether the
// elastic slip spoils the answer.
struct Expected {
  double penetration, elasticSlip, slip, slippingNodes;
  bool elasticSlipSpoils;
};

void expectMeasures(const cc::RegularisationMeasures& m, const Expected& e) {
  EXPECT_NEAR(m.penetration, e.penetration, 1e-12);
  EXPECT_NEAR(m.elasticSlip, e.elasticSlip, 1e-12);
  EXPECT_NEAR(m.slip, e.slip, 1e-12);
  EXPECT_EQ(m.slippingNodes, e.slippingNodes);
  EXPECT_EQ(cc::elasticSlipSpoils(m), e.elasticSlipSpoils);
}

}  // namespace

TEST(RegularisationMeasures, StickingNodesReportTheirSpringStretch) {
  // λ = 0.51: 0.01 of penetration; the line moved 0.5 × 0.01 along x since it touched: all three stick
  // with that relative motion as their elastic slip (t_T = ε_T × 0.005, ε_T = μ|t_N|/0.01); no slip to
  // compare it with, so it does not spoil.
  expectMeasures(after(plate(0.5), 0.51), {0.01, 0.005, 0.005, 0.0, false});
}

TEST(RegularisationMeasures, SlippingNodesReportTheStickRadius) {
  // mx = 3: a relative motion of 0.03 since the touch, beyond the stick radius 0.01: all three slip, with
  // the elastic slip μ|t_N|/ε_T = 0.01 and a slip of 0.03 (a third: the run would warn).
  const auto m = after(plate(3.0), 0.51);
  expectMeasures(m, {0.01, 0.01, 0.03, 3.0, true});
  EXPECT_NEAR(m.meanSlip(), 0.03, 1e-12);
}

TEST(RegularisationMeasures, FrictionlessInterfacesHaveNoElasticSlip) {
  auto spec = plate(3.0);
  spec.law.frictionCoefficient = 0.0;
  const auto m = after(spec, 0.52);
  EXPECT_NEAR(m.penetration, 0.02, 1e-12);
  EXPECT_EQ(m.elasticSlip, 0.0);
  EXPECT_EQ(m.slippingNodes, 0.0);  // frictionless "slip" is free sliding, not measured slip
}

TEST(RegularisationMeasures, CriteriaAreATenth) {
  cc::RegularisationMeasures m;
  m.penetration = 0.011;
  m.displacementScale = 0.1;
  EXPECT_TRUE(cc::penetrationSpoils(m));
  m.penetration = 0.009;
  EXPECT_FALSE(cc::penetrationSpoils(m));
  m.slippingNodes = 2;
  m.slipSum = 0.2;  // mean 0.1
  m.elasticSlip = 0.0099;
  EXPECT_FALSE(cc::elasticSlipSpoils(m));
  m.elasticSlip = 0.0101;
  EXPECT_TRUE(cc::elasticSlipSpoils(m));
}

TEST(RegularisationMeasures, IncludeTakesMaximaAndSumsTheSlippingNodes) {
  cc::RegularisationMeasures a, b;
  a.penetration = 1;
  a.elasticSlip = 3;
  a.slippingNodes = 1;
  a.slipSum = 2;
  b.penetration = 2;
  b.slip = 5;
  b.displacementScale = 7;
  b.slippingNodes = 3;
  b.slipSum = 6;
  a.include(b);
  EXPECT_EQ(a.penetration, 2);
  EXPECT_EQ(a.elasticSlip, 3);
  EXPECT_EQ(a.slip, 5);
  EXPECT_EQ(a.displacementScale, 7);
  EXPECT_EQ(a.meanSlip(), 2.0);
}
