// Friction from the first touch (issue 19, point 4): a slave node open at the last commit that closes
// during the increment takes as stick reference the point where its straight path relative to the master,
// from (ξ_0, g_N,0) at the commit to (ξ̄, g_N) now, crossed the facet (CommittedApproach). Its traction
// against the closed form, its independence of where along that path the increment started, and its
// consistent tangent (with the new ∂τ/∂g_N terms) against central differences of the residual, 2D and 3D,
// stick and slip, at the facet's projection and at a vertex.
#include "ElementTestTools.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using cc::CommittedApproach;
using cc::ContactPoint;

namespace {

// ε_N = 1e3, ε_T = 5e2; stick with μ = 100, slip with μ = 0.2.
const cc::ContactLawParameters kStick{1e3, 5e2, 100.0};
const cc::ContactLawParameters kSlip{1e3, 5e2, 0.2};

/// 2D: slave node at ξ on the segment (1, 0) → (−1, 0) (ā_11 = 1, n̄ = +y), at signed distance `gap`.
cc::NodeToFacetGeometry<cc::Line2Facet> segmentSlaveAt(double xi, double gap,
                                                        Vector<2> x1 = {1.0, 0.0}, Vector<2> x2 = {-1.0, 0.0}) {
  const std::array<Vector<2>, 2> segment{x1, x2};
  const auto p = cc::SegmentProjection2D::evaluateAt({0.0, 0.0}, segment, {xi});
  return {cc::add(p.position, cc::scaled(gap, p.normal)), segment};
}

/// 3D: slave node at ξ on a warped face (b̄_12 ≠ 0), at signed distance `gap` along n̄(ξ).
const std::array<Vector<3>, 4> kWarped{{{0.0, 0.0, 0.0}, {2.0, 0.1, 0.4}, {2.2, 2.0, -0.1}, {-0.1, 1.9, 0.3}}};
cc::NodeToFacetGeometry<cc::Quad4Facet> faceSlaveAt(Vector<2> xi, double gap) {
  const auto p = cc::FaceProjection3D::evaluateAt({0.0, 0.0, 0.0}, kWarped, xi);
  return {cc::add(p.position, cc::scaled(gap, p.normal)), kWarped};
}

template <class Facet>
double checkTangent(const cc::NodeToFacetContact<Facet>& element, const cc::NodeToFacetGeometry<Facet>& g,
                    const CommittedApproach<Facet::kSurfaceDim>& approach, ContactStatus expected,
                    const std::string& what, const ContactPoint& point = ContactPoint::projection()) {
  const cc::ContactHistory<Facet::kSurfaceDim> open{};  // committed: open
  const auto r = element.evaluate(g, 3, open, 0.0, cc::SlipTangent::consistent(), point, approach);
  EXPECT_EQ(r.status, expected) << what;
  EXPECT_NE(r.tangentialTraction, Vector<Facet::kSurfaceDim>{}) << what;
  return ct::expectTangentClose(
      r.tangent, ct::finiteDifferenceTangent(element, g, 3, open, ct::kFdStep, 0.0, point, approach), ct::kFdTolerance, what);
}

// checkTangent in stick and in slip at each of `configurations` (name, geometry g, approach); the worst.
template <class Facet, class Configurations>
double worstInStickAndSlip(const Configurations& configurations, const std::string& dimension) {
  double worst = 0.0;
  for (const auto& c : configurations) {
    worst = std::max(worst, checkTangent(cc::NodeToFacetContact<Facet>(kStick), c.g, c.approach, ContactStatus::Stick,
                                         dimension + " stick " + c.name));
    worst = std::max(worst, checkTangent(cc::NodeToFacetContact<Facet>(kSlip), c.g, c.approach, ContactStatus::Slip,
                                         dimension + " slip " + c.name));
  }
  return worst;
}

}  // namespace

// Committed at ξ_0 = 0.1, g_N,0 = 0.02; now at ξ̄ = 0.4, g_N = −0.01: it touched at τ = 0.02/0.03 = 2/3,
// at ξ = 0.3, so Δξ = 0.1 and, in stick, t_T = ε_T ā_11 Δξ = 50; in slip t_T = μ|t_N| = 0.2 · 10 = 2.
TEST(FirstTouch, TractionFromThePointWhereTheNodeTouched) {
  const auto g = segmentSlaveAt(0.4, -0.01);
  const auto approach = CommittedApproach<1>::at(0.02, {0.1});
  const cc::ContactHistory<1> open{};
  const auto stick = cc::NodeToFacetContact<cc::Line2Facet>(kStick).evaluate(
      g, 3, open, 0.0, cc::SlipTangent::consistent(), ContactPoint::projection(), approach);
  EXPECT_EQ(stick.status, ContactStatus::Stick);
  EXPECT_NEAR(stick.tangentialTraction[0], 50.0, 1e-9);
  EXPECT_NEAR(stick.trial.xi[0], 0.4, 1e-12);  // the next increment's reference: the converged ξ̄
  EXPECT_NEAR(stick.trial.accumulatedSlip, 0.1, 1e-12);
  const auto slip = cc::NodeToFacetContact<cc::Line2Facet>(kSlip).evaluate(
      g, 3, open, 0.0, cc::SlipTangent::consistent(), ContactPoint::projection(), approach);
  EXPECT_EQ(slip.status, ContactStatus::Slip);
  EXPECT_NEAR(slip.tangentialTraction[0], 2.0, 1e-9);
  // The force on the slave node opposes its motion (x = −ξ on this segment: the node moved to −x).
  EXPECT_GT(stick.slaveForce()[0], 0.0);
  // Without an approach (no committed state) the former rule: no traction in this increment.
  const auto unknown = cc::NodeToFacetContact<cc::Line2Facet>(kStick).evaluate(g, 3, open);
  EXPECT_EQ(unknown.tangentialTraction[0], 0.0);
}

// The same straight path started at three points (as increments of different size would): the node
// touches at ξ = 0.3 in each, so the traction is the same; a node touching at the commit (g_N,0 = 0) is
// referred to its committed point.
TEST(FirstTouch, TractionDoesNotDependOnWhereTheIncrementStarted) {
  const cc::NodeToFacetContact<cc::Line2Facet> element(kStick);
  const auto g = segmentSlaveAt(0.4, -0.01);
  const cc::ContactHistory<1> open{};
  // Points of the line through (ξ, g) = (0.3, 0) and (0.4, −0.01): ξ = 0.3 − 10 g.
  for (double g0 : {0.0, 0.001, 0.02, 0.5}) {
    const auto approach = CommittedApproach<1>::at(g0, {0.3 - 10.0 * g0});
    const auto r = element.evaluate(g, 3, open, 0.0, cc::SlipTangent::consistent(), ContactPoint::projection(), approach);
    EXPECT_NEAR(r.tangentialTraction[0], 50.0, 1e-9) << "g_N,0 = " << g0;
  }
}

TEST(FirstTouch, Line2TangentMatchesCentralDifferences) {
  const struct {
    const char* name;
    cc::NodeToFacetGeometry<cc::Line2Facet> g;
    CommittedApproach<1> approach;
  } configurations[] = {
      {"horizontal", segmentSlaveAt(0.4, -0.01), CommittedApproach<1>::at(0.02, {0.1})},
      {"inclined_stretched", segmentSlaveAt(-0.3, -0.06, {2.3, 0.9}, {-0.5, -0.6}), CommittedApproach<1>::at(0.05, {-0.6})},
      {"touching_at_commit", segmentSlaveAt(0.7, -0.05, {1.2, 0.2}, {-1.1, -0.1}), CommittedApproach<1>::at(0.0, {0.2})},
      {"far_approach", segmentSlaveAt(0.05, -0.04), CommittedApproach<1>::at(0.9, {-0.8})},
  };
  const double worst = worstInStickAndSlip<cc::Line2Facet>(configurations, "2D");
  // The slip tolerance's pressure-dependent ε_T (s L = 4: stick; 0.005: slip).
  cc::ContactLawParameters tolerance = kStick;
  tolerance.tangentialPenalty = 0.0;
  tolerance.slipTolerance = 0.005;
  const auto g = segmentSlaveAt(0.4, -0.01);
  const cc::NodeToFacetContact<cc::Line2Facet> element(tolerance);
  const cc::ContactHistory<1> open{};
  const auto approach = CommittedApproach<1>::at(0.02, {0.1});
  const auto r = element.evaluate(g, 3, open, 1.0, cc::SlipTangent::consistent(), ContactPoint::projection(), approach);
  const auto fd = ct::finiteDifferenceTangent(element, g, 3, open, ct::kFdStep, 1.0, ContactPoint::projection(), approach);
  EXPECT_LT(ct::relativeDifference(r.tangent, fd), ct::kFdTolerance);
  std::printf("[ FD       ] worst relative error %.2e\n", worst);
}

TEST(FirstTouch, Quad4TangentMatchesCentralDifferences) {
  const struct {
    const char* name;
    cc::NodeToFacetGeometry<cc::Quad4Facet> g;
    CommittedApproach<2> approach;
  } configurations[] = {
      {"warped", faceSlaveAt({-0.3, 0.4}, -0.06), CommittedApproach<2>::at(0.03, {-0.45, 0.2})},
      {"warped_corner", faceSlaveAt({0.93, -0.95}, -0.05), CommittedApproach<2>::at(0.2, {0.6, -0.7})},
      {"touching_at_commit", faceSlaveAt({0.1, 0.2}, -0.04), CommittedApproach<2>::at(0.0, {0.0, 0.25})},
  };
  const double worst = worstInStickAndSlip<cc::Quad4Facet>(configurations, "3D");
  std::printf("[ FD       ] worst relative error %.2e\n", worst);
}

// At a vertex (ContactPoint): τ follows the vertex gap g_N = −‖x^k − x_v‖ and its operator N_b.
TEST(FirstTouch, AtAVertexTangentMatchesCentralDifferences) {
  cc::NodeToFacetGeometry<cc::Line2Facet> g;
  g.slave = {-0.03, -0.05};
  g.master = {{{2.0, 0.0}, {0.0, 0.0}}};
  const auto vertex = ContactPoint::vertex(1, -1.0);
  const auto approach = CommittedApproach<1>::at(0.04, {1.2});
  checkTangent(cc::NodeToFacetContact<cc::Line2Facet>(kStick), g, approach, ContactStatus::Stick, "2D vertex stick", vertex);
  checkTangent(cc::NodeToFacetContact<cc::Line2Facet>(kSlip), g, approach, ContactStatus::Slip, "2D vertex slip", vertex);
}
