// The C¹-smoothed 2D master segment (HermiteLine4Facet, SmoothedMasterFacet.hpp; Master Smoothing = Hermite):
//  - the traits: Σ H_i = 1, the curve through its two ends, every derivative order against central
//    differences of the order below;
//  - C¹: two neighbouring segments meet with the same point and the same tangent dx̄/dξ;
//  - on nodes of a circle the curve lies within a small fraction of the chord's sagitta of the circle;
//  - the facets built from a side set's segments (neighbours; a free end's stand-in);
//  - the node-to-facet element's consistent tangent against central differences of its residual, in normal
//    contact, stick and slip, with the slip tolerance too;
//  - the reason for the smoothing (docs/verification-contact.md §8): under a slave node pressed into a master
//    whose nodes lie on a circle, a rotation of the master's nodes about the circle's centre turns the force
//    on a faceted master by the rotation angle (the follower stiffness −|F|/R) and hardly at all on the
//    smoothed one;
//  - the history carried across a shared node.
#include "ElementTestTools.hpp"
#include "contact/SmoothedMaster.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using cc::HermiteLine4Facet;
using Point = HermiteLine4Facet::Point;
using Nodes = std::array<Point, 4>;

namespace {

constexpr double kRadius = 0.75;

/// Node i of a polyline on the circle of radius R about the origin, below its centre, at the angle
/// −π/2 − (i − 1.5) Δθ: a master body (a slab) below the circle, pressed up against a slave inside it (a
/// die). The nodes run from right to left, so the master body lies on the left of x_a → x_b (Line2Facet's
/// convention) and the normal points towards the centre.
Point onCircle(double i, double dTheta) {
  const double theta = -M_PI / 2.0 - (i - 1.5) * dTheta;
  return {kRadius * std::cos(theta), kRadius * std::sin(theta)};
}

Nodes circleFacet(double dTheta, double first = 0.0) {
  Nodes x{};
  for (int i = 0; i < 4; ++i) x[i] = onCircle(first + i, dTheta);
  return x;
}

Point rotated(const Point& p, double angle) {
  return {std::cos(angle) * p[0] - std::sin(angle) * p[1], std::sin(angle) * p[0] + std::cos(angle) * p[1]};
}

}  // namespace

TEST(SmoothedMaster, ShapeFunctionsSumToOneAndInterpolateTheEnds) {
  for (double xi : {-1.0, -0.4, 0.3, 1.0}) {
    const auto h = HermiteLine4Facet::shapeFunctions({xi});
    EXPECT_NEAR(h[0] + h[1] + h[2] + h[3], 1.0, 1e-15);
  }
  const auto left = HermiteLine4Facet::shapeFunctions({-1.0}), right = HermiteLine4Facet::shapeFunctions({1.0});
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(left[i], i == 1 ? 1.0 : 0.0, 1e-15);
    EXPECT_NEAR(right[i], i == 2 ? 1.0 : 0.0, 1e-15);
  }
}

TEST(SmoothedMaster, DerivativesMatchCentralDifferences) {
  const double h = 1e-6;
  for (double xi : {-0.9, -0.2, 0.5}) {
    for (int k = 1; k <= 3; ++k) {
      const auto d = HermiteLine4Facet::derivative(xi, k);
      const auto plus = HermiteLine4Facet::derivative(xi + h, k - 1), minus = HermiteLine4Facet::derivative(xi - h, k - 1);
      for (int i = 0; i < 4; ++i) EXPECT_NEAR(d[i], (plus[i] - minus[i]) / (2 * h), 1e-7) << "order " << k << " node " << i;
    }
    // The traits' accessors are those derivatives.
    const auto d1 = HermiteLine4Facet::shapeDerivatives({xi});
    const auto d2 = HermiteLine4Facet::shapeSecondDerivatives({xi});
    const auto d3 = HermiteLine4Facet::shapeThirdDerivatives({xi});
    for (int i = 0; i < 4; ++i) {
      EXPECT_EQ(d1(i, 0), HermiteLine4Facet::derivative(xi, 1)[i]);
      EXPECT_EQ(d2[i](0, 0), HermiteLine4Facet::derivative(xi, 2)[i]);
      EXPECT_EQ(d3[i][0](0, 0), HermiteLine4Facet::derivative(xi, 3)[i]);
    }
  }
}

TEST(SmoothedMaster, NeighbouringSegmentsMeetWithTheSameTangent) {
  // Five nodes, uneven, on no particular curve: segments [0 1 2 3] and [1 2 3 4] share node 2.
  const std::array<Point, 5> p{{{0.0, 0.0}, {1.0, 0.3}, {1.7, 1.1}, {2.2, 2.4}, {3.5, 2.9}}};
  const Nodes first{p[0], p[1], p[2], p[3]}, second{p[1], p[2], p[3], p[4]};
  const auto end = cc::Projection<HermiteLine4Facet>::evaluateAt(Point{}, first, {1.0});
  const auto start = cc::Projection<HermiteLine4Facet>::evaluateAt(Point{}, second, {-1.0});
  for (int c = 0; c < 2; ++c) {
    EXPECT_NEAR(end.position[c], p[2][c], 1e-15);
    EXPECT_NEAR(start.position[c], p[2][c], 1e-15);
    EXPECT_NEAR(end.covariantBasis[0][c], start.covariantBasis[0][c], 1e-15);
    EXPECT_NEAR(end.covariantBasis[0][c], 0.25 * (p[3][c] - p[1][c]), 1e-15);  // dx̄/dξ = (x_n − x_p)/4
  }
  // The straight segment's normal jumps there by the polyline's kink; the smoothed one's does not.
  EXPECT_NEAR(cc::dot(end.normal, start.normal), 1.0, 1e-15);
}

TEST(SmoothedMaster, FollowsACircleMuchCloserThanItsChord) {
  const double dTheta = 0.15;  // the ironing slab's top under the die: 0.1 mm segments on R = 0.75 mm
  const auto x = circleFacet(dTheta);
  const double sagitta = kRadius * (1.0 - std::cos(dTheta / 2.0));
  double worst = 0.0;
  for (double xi = -1.0; xi <= 1.0; xi += 0.05) {
    const auto p = cc::Projection<HermiteLine4Facet>::evaluateAt(Point{}, x, {xi});
    worst = std::max(worst, std::abs(cc::norm(p.position) - kRadius));
  }
  std::printf("[ circle   ] chord sagitta %.3e, Hermite segment's largest radial error %.3e\n", sagitta, worst);
  EXPECT_LT(worst, 0.05 * sagitta);
}

TEST(SmoothedMaster, FacetsOfASideSetTakeTheirNeighbours) {
  // Segments of a polyline 10 → 11 → 12 → 13, in side-set order (not along the line).
  const std::vector<cc::GlobalIndex> segments{11, 12, 10, 11, 12, 13};
  const std::vector<cc::GlobalIndex> expected{10, 11, 12, 13, 10, 10, 11, 12, 11, 12, 13, 13};
  EXPECT_EQ(cc::hermiteMasterFacets(segments), expected);
}

// The element on the smoothed segment: its consistent tangent (NodeToFacetContact.hpp, with the cubic's third
// derivatives in the second variation of ξ̄) against central differences of its residual.
// Also on a free end's segment, whose missing neighbour is its end node (x_p = x_a: two element dofs that
// the assembly adds into the same node's).
TEST(SmoothedMaster, ConsistentTangentMatchesCentralDifferences) {
  const Nodes uneven{{{-0.1, 0.35}, {0.4, -0.05}, {1.3, 0.1}, {2.0, 0.6}}};  // uneven, curved
  const Nodes freeEnd{{{0.4, -0.05}, {0.4, -0.05}, {1.3, 0.1}, {2.0, 0.6}}};
  double worst = 0.0;
  for (const Nodes& facet : {uneven, freeEnd}) {
    for (const ct::Law& law : ct::kLaws) {
      const cc::NodeToFacetContact<HermiteLine4Facet> element(law.parameters);
      for (double xi : {-0.85, 0.1, 0.7}) {
        SCOPED_TRACE(std::string(law.name) + " at " + std::to_string(xi));
        const auto at = cc::Projection<HermiteLine4Facet>::evaluateAt(Point{}, facet, {xi});
        const cc::NodeToFacetGeometry<HermiteLine4Facet> g{cc::add(at.position, cc::scaled(-0.05, at.normal)), facet};
        const auto committed = ct::committedHistory<1>(3, {xi - 0.07}, {1.5});
        const auto r = element.evaluate(g, 3, committed);
        ASSERT_TRUE(r.projection.converged);
        EXPECT_NEAR(r.projection.xi[0], xi, 1e-11);
        EXPECT_NEAR(r.gap, -0.05, 1e-12);
        if (law.parameters.frictionCoefficient > 0.0) {
          EXPECT_EQ(r.status, law.parameters.frictionCoefficient > 1.0 ? ContactStatus::Stick : ContactStatus::Slip);
        }
        const auto fd = ct::finiteDifferenceTangent(element, g, 3, committed, 1e-6);
        worst = std::max(worst, ct::expectTangentClose(r.tangent, fd, 1e-6, std::string("Hermite ") + law.name));
      }
    }
  }
  std::printf("[ FD       ] Hermite segment: worst ‖K − K_FD‖/‖K_FD‖ = %.2e\n", worst);
}

TEST(SmoothedMaster, SlipToleranceTangentMatchesCentralDifferences) {
  struct Configuration {
    const char* name;
    double xi;
    double gap;
  };
  const Configuration configurations[] = {{"inside", 0.2, -0.01}, {"near_end", 0.9, -0.02}};
  const Nodes facet{{{-0.1, 0.35}, {0.4, -0.05}, {1.3, 0.1}, {2.0, 0.6}}};
  ct::checkSlipToleranceTangents<HermiteLine4Facet>(
      configurations,
      [&](const Configuration& c, double gap) {
        const auto at = cc::Projection<HermiteLine4Facet>::evaluateAt(Point{}, facet, {c.xi});
        const cc::NodeToFacetGeometry<HermiteLine4Facet> g{cc::add(at.position, cc::scaled(gap, at.normal)), facet};
        return std::make_pair(g, ct::committedHistory<1>(0, {c.xi - 0.3}, {0.0}));
      },
      1e-6, "Hermite");
}

// A slave node pressed into a master whose nodes lie on a circle (a slab's surface wrapped round a die);
// the master's nodes rotated by ω about the circle's centre, the slave node fixed. The force on the slave
// node turns with the facet's normal: by ω on a straight segment (the follower term −|F|/R of §8), by a
// small fraction of ω on the smoothed one, whose curve maps (nearly) onto itself under the rotation.
TEST(SmoothedMaster, RotatingTheMasterAboutItsCentreHardlyTurnsTheForce) {
  const double dTheta = 0.15, omega = 0.02;
  const cc::ContactLawParameters frictionless{1e3, 0.0, 0.0};
  const Point slave = cc::scaled(1.0 + 0.01 / kRadius, onCircle(1.3, dTheta));  // 0.01 into the master
  const auto turnOf = [&](auto facetTag, const auto& x, const auto& xRotated) {
    using F = decltype(facetTag);
    const cc::NodeToFacetContact<F> element(frictionless);
    const auto before = element.evaluate({slave, x}, 0, {}).slaveForce();
    const auto after = element.evaluate({slave, xRotated}, 0, {}).slaveForce();
    return std::atan2(before[0] * after[1] - before[1] * after[0], cc::dot(before, after));
  };
  const Nodes smooth = circleFacet(dTheta);
  Nodes smoothRotated{};
  for (int i = 0; i < 4; ++i) smoothRotated[i] = rotated(smooth[i], omega);
  const std::array<Point, 2> straight{smooth[1], smooth[2]};
  const std::array<Point, 2> straightRotated{smoothRotated[1], smoothRotated[2]};
  const double turnStraight = turnOf(cc::Line2Facet{}, straight, straightRotated);
  const double turnSmooth = turnOf(HermiteLine4Facet{}, smooth, smoothRotated);
  std::printf("[ rotation ] master rotated by %.3f: force turns by %.5f (straight), %.5f (Hermite)\n", omega,
              turnStraight, turnSmooth);
  EXPECT_NEAR(turnStraight, omega, 1e-12);
  EXPECT_LT(std::abs(turnSmooth), 0.05 * omega);
}

TEST(SmoothedMaster, HistoryCrossesASharedNodeContinuously) {
  const double dTheta = 0.15;
  cc::MasterFacetNodes<HermiteLine4Facet> from, to;
  from.id = 4;
  to.id = 5;
  from.nodes = {0, 1, 2, 3};
  to.nodes = {1, 2, 3, 4};
  from.x = circleFacet(dTheta, 0.0);
  to.x = circleFacet(dTheta, 1.0);
  const auto committed = ct::committedHistory<1>(4, {0.9}, {2.5});
  const auto moved = cc::transferHistory<HermiteLine4Facet>(committed, from, to);
  EXPECT_EQ(moved.segment, 5);
  EXPECT_NEAR(moved.xi[0], -1.1, 1e-12);  // the same point of the curve: 0.1 before the shared node
  EXPECT_NEAR(moved.tangentialTraction[0], 2.5, 1e-12);
  const auto a = cc::Projection<HermiteLine4Facet>::evaluateAt(Point{}, from.x, committed.xi).position;
  const auto b = cc::Projection<HermiteLine4Facet>::evaluateAt(Point{}, to.x, moved.xi).position;
  EXPECT_LT(cc::norm(cc::subtract(a, b)), 1e-3 * cc::norm(cc::subtract(from.x[2], from.x[1])));
}
