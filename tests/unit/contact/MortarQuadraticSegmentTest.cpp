// The 2D mortar kernel on 3-node segments (MortarQuadraticSegment): the flat pieces' weighted gaps against
// their closed form (a uniform gap gives g A_a, the nodal lengths the chords' halves; the gradient the
// consistent load L/6, 2L/3, L/6), the exact first and second derivatives of the weighted gaps and slips
// against central differences, and a rigid master's derivatives along its motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact/MortarInterface.hpp"
#include "contact/MortarQuadraticSegment.hpp"
#include "MortarTestTools.hpp"

namespace contessa::contact {
namespace {

constexpr int kC = kQuadraticSegmentPairCoordinates;

MortarFacetPairShape shapeOf(int slaveNodes, int masterNodes, double l0, double l1) {
  MortarFacetPairShape s;
  s.slaveNodes = slaveNodes;
  s.masterNodes = masterNodes;
  s.slavePieceAreas[0] = l0;
  s.slavePieceAreas[1] = l1;
  return s;
}

// A straight slave Line3 on top of a body below, x from 1 to 0 (its normal, the right of node 0 → node 1,
// points up), mid-edge node at 0.5; a straight master Line3 above at height `gap` from x = left to right
// (normal down), mid-edge node in its middle.
QuadraticSegmentPairCoordinates<double> flatPair(double left, double right, double gap) {
  return {1.0, 0.0, 0.0, 0.0, 0.5, 0.0, left, gap, right, gap, 0.5 * (left + right), gap};
}

TEST(MortarQuadraticSegment, AUniformGapGivesTheGapTimesTheHatLengthsAndTheConsistentLoads) {
  const double gap = -0.01;
  const MortarQuadraticSegmentDerivatives d = quadraticSegmentPairDerivatives(flatPair(-0.5, 1.7, gap), shapeOf(3, 3, 0.5, 0.5));
  ASSERT_TRUE(d.overlaps);
  const double lengths[3] = {0.25, 0.25, 0.5};
  double load[3] = {0, 0, 0};  // −Σ_a ∂g̃_a/∂y_b (n_m points down): the nodal loads of a uniform unit pressure
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(d.mortarLength[a], lengths[a], 1e-15) << a;
    EXPECT_NEAR(d.weightedGap[a], gap * lengths[a], 1e-16) << a;
    for (int b = 0; b < 3; ++b) load[b] -= d.gradient[a][2 * b + 1];
  }
  EXPECT_NEAR(load[0], 1.0 / 6.0, 1e-14);
  EXPECT_NEAR(load[1], 1.0 / 6.0, 1e-14);
  EXPECT_NEAR(load[2], 2.0 / 3.0, 1e-14);
}

// A curved, tilted pair clipped inside both segments: slave Line3 (mid-edge node off the chord) against a
// master Line3, both curved; the slave's pieces' reference lengths other than their current ones.
QuadraticSegmentPairCoordinates<double> curvedPair() {
  return {1.05, 0.02, -0.03, -0.05, 0.52, 0.04, -0.2, -0.01, 1.3, 0.06, 0.58, 0.015};
}
QuadraticSegmentPairCommitted curvedCommitted() {
  return {1.0, 0.01, -0.06, -0.055, 0.49, 0.03, -0.17, -0.01, 1.33, 0.055, 0.6, 0.01};
}

// Central differences of the values' gap (or slip) and of the derivatives' gradients against the exact
// gradient and Hessian, for slave and master node counts (3, 3), (3, 2) and (2, 3).
void expectDerivativesAreCentralDifferences(int slaveNodes, int masterNodes, bool slip) {
  const auto x = curvedPair();
  const MortarFacetPairShape shape = shapeOf(slaveNodes, masterNodes, 0.55, 0.6);
  const QuadraticSegmentPairCommitted then = curvedCommitted();
  const QuadraticSegmentPairCommitted* committed = slip ? &then : nullptr;
  const MortarQuadraticSegmentDerivatives d = quadraticSegmentPairDerivatives(x, shape, committed);
  ASSERT_TRUE(d.overlaps);
  const auto value = [&](const QuadraticSegmentPairCoordinates<double>& y, int a) {
    const auto g = quadraticSegmentPairGaps(y, shape, committed);
    return slip ? g.weightedSlip[a] : g.weightedGap[a];
  };
  const double h = 1e-6;
  for (int a = 0; a < slaveNodes; ++a) {
    const auto& gradient = slip ? d.slipGradient[a] : d.gradient[a];
    const auto& hessian = slip ? d.slipHessian[a] : d.hessian[a];
    EXPECT_DOUBLE_EQ(slip ? d.weightedSlip[a] : d.weightedGap[a], value(x, a));
    double scale = 0, gradientError = 0, hessianScale = 0, hessianError = 0;
    for (int j = 0; j < kC; ++j) {
      auto plus = x, minus = x;
      plus[j] += h;
      minus[j] -= h;
      scale = std::max(scale, std::abs(gradient[j]));
      gradientError = std::max(gradientError, std::abs((value(plus, a) - value(minus, a)) / (2 * h) - gradient[j]));
      const auto dp = quadraticSegmentPairDerivatives(plus, shape, committed);
      const auto dm = quadraticSegmentPairDerivatives(minus, shape, committed);
      for (int i = 0; i < kC; ++i) {
        const double fd = ((slip ? dp.slipGradient[a][i] : dp.gradient[a][i]) - (slip ? dm.slipGradient[a][i] : dm.gradient[a][i])) / (2 * h);
        hessianScale = std::max(hessianScale, std::abs(hessian[i * kC + j]));
        hessianError = std::max(hessianError, std::abs(fd - hessian[i * kC + j]));
        EXPECT_NEAR(hessian[i * kC + j], hessian[j * kC + i], 1e-12) << "a Hessian is symmetric";
      }
    }
    EXPECT_GT(scale, 1e-3);
    EXPECT_GT(hessianScale, 1e-3);
    EXPECT_LT(gradientError, 1e-8 * std::max(scale, 1.0)) << "slave node " << a;
    EXPECT_LT(hessianError, 1e-7 * std::max(hessianScale, 1.0)) << "slave node " << a;
  }
}

TEST(MortarQuadraticSegment, WeightedGapsAreDifferentiatedTwiceExactly) {
  expectDerivativesAreCentralDifferences(3, 3, false);
  expectDerivativesAreCentralDifferences(3, 2, false);
  expectDerivativesAreCentralDifferences(2, 3, false);
}

TEST(MortarQuadraticSegment, WeightedSlipIncrementsAreDifferentiatedTwiceExactly) {
  expectDerivativesAreCentralDifferences(3, 3, true);
  expectDerivativesAreCentralDifferences(3, 2, true);
}

TEST(MortarQuadraticSegment, ARigidMastersDerivativesAreTheFullOnesAlongItsMotion) {
  // A Line2 rigid master (slots 3 and 4) moving by `motion`: entry 6 holds the derivatives along it.
  const auto x = curvedPair();
  const MortarFacetPairShape shape = shapeOf(3, 2, 0.55, 0.6);
  const double motion[6] = {0.3, -0.7, 0.3, -0.7, 0.0, 0.0};
  const auto full = quadraticSegmentPairDerivatives(x, shape);
  const auto along = quadraticSegmentPairDerivatives(x, shape, nullptr, motion);
  for (int a = 0; a < 3; ++a) {
    double expected = 0;
    for (int b = 0; b < 6; ++b) expected += full.gradient[a][6 + b] * motion[b];
    EXPECT_NEAR(along.gradient[a][6], expected, 1e-13);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(along.gradient[a][i], full.gradient[a][i], 1e-14);
  }
}

// An interface of 2 slave Line3 segments (x from 1 to 0 on y = 0: nodes 0, 1 corners at x = 1, 0.5, 2 the
// mid-edge node at 0.75; 1, 3 corners at 0.5, 0; 4 at 0.25) against 3 master Line3 segments below, from
// x = 0 to 1 (corners 5–8 at x = 0, 1/3, 2/3, 1; mid-edge nodes 9–11): neither mesh refines the other, and
// the master's middle mid-edge node is level with the slave's middle corner.
constexpr double kPenalty = 1e6;
ContactInterfaceSpec line3Spec(double friction) {
  ContactInterfaceSpec spec;
  spec.name = "line3";
  spec.dimension = 2;
  spec.mortar = true;
  spec.slaveNodes = {0, 1, 2, 3, 4};
  spec.slaveFacets = {0, 1, 2, 1, 3, 4};
  spec.slaveFacetNodes = 3;
  spec.slaveFacetMeasures = {0.25, 0.25, 0.25, 0.25};
  spec.slaveAreas = {0.125, 0.25, 0.25, 0.125, 0.25};
  spec.slaveFacetLengths = {0.5, 0.5, 0.5, 0.5, 0.5};
  spec.law.normalPenalty = kPenalty;
  spec.law.frictionCoefficient = friction;
  spec.law.tangentialPenalty = friction > 0 ? kPenalty : 0.0;
  spec.masterFacets = {5, 6, 9, 6, 7, 10, 7, 8, 11};
  spec.masterFacetNodes = 3;
  return spec;
}
std::vector<double> line3Coordinates(double penetration, double stretch) {
  std::vector<double> x = {1, 0, 0.5, 0, 0.75, 0, 0, 0, 0.25, 0};
  for (double m : {0.0, 1.0 / 3, 2.0 / 3, 1.0, 1.0 / 6, 0.5, 5.0 / 6}) x.insert(x.end(), {m, -penetration});
  for (std::size_t i = 0; i < x.size(); i += 2) x[i] *= stretch;
  return x;
}

TEST(MortarInterfaceLine3, AUniformPenetrationGivesTheSamePressureAtCornersAndMidEdgeNodes) {
  // The patch test at the interface: a uniform penetration d of stretched, non-matching Line3 segments
  // gives p = ε_N d at every slave node, and the consistent loads L/6, 2L/3, L/6 per slave segment, no
  // tangential force.
  const double d = 1.1e-6;
  auto interface = makeMortarInterface(line3Spec(0.0), std::vector<char>(5, 1));
  const auto a = testing::assemble<2>(*interface, line3Coordinates(d, 1.0 + 4.3e-4), 0.0);
  for (const auto& s : a.states) EXPECT_NEAR(s.pressure, kPenalty * d, 1e-12 * kPenalty * d);
  const double p = kPenalty * d, load[5] = {p / 12, p / 6, p / 3, p / 12, p / 3};  // L = 0.5
  for (int node = 0; node < 5; ++node) {
    EXPECT_NEAR(a.residual[2 * node + 1], load[node], 1e-12 * p) << node;  // −(−p ∇g̃): pushes the slave up
    EXPECT_NEAR(a.residual[2 * node], 0.0, 1e-15 * p) << node;
  }
  for (int node = 5; node < 12; ++node) EXPECT_NEAR(a.residual[2 * node], 0.0, 1e-15 * p) << node;
}

// The Line3 interface tilted and curved (mid-edge nodes off their chords), every slave node closed; a
// deformable Line3 master or a rigid Line2 one moving by (0.1, −0.02) per unit load factor. Penalties 10³.
std::unique_ptr<ContactInterfaceBase> unevenInterface(bool rigidMaster, double friction) {
  ContactInterfaceSpec spec = line3Spec(friction);
  spec.law.normalPenalty = 1e3;
  if (friction > 0) spec.law.tangentialPenalty = 1e3;
  if (rigidMaster) {
    spec.masterFacets.clear();
    spec.masterFacetNodes = 0;
    spec.rigidMaster = true;
    spec.rigidSurface.points = {-0.2, -0.03, 0.6, -0.036, 1.2, -0.027};
    spec.rigidSurface.facets = {0, 1, 1, 2};
    spec.rigidSurface.motion = {0.1, -0.02};
  }
  return makeMortarInterface(spec, std::vector<char>(5, 1));
}
std::vector<double> unevenLine3(bool rigidMaster) {
  std::vector<double> x = {1.02, 0.01, 0.49, -0.005, 0.76, 0.012, 0.01, 0.0, 0.26, -0.008};
  if (!rigidMaster)
    x.insert(x.end(), {-0.1, -0.031, 0.34, -0.026, 0.65, -0.034, 1.1, -0.03, 0.12, -0.027, 0.5, -0.032, 0.88, -0.029});
  return x;
}
// The uneven state with the slave slid along x by `slide` (more at larger x) and the master back a little.
std::vector<double> slidLine3(bool rigidMaster, double slide) {
  auto x = unevenLine3(rigidMaster);
  for (std::size_t node = 0; node < x.size() / 2; ++node) x[2 * node] += node < 5 ? slide * (1.0 + 0.1 * node) : -0.2 * slide;
  return x;
}

// The trial evaluation at x and λ after committing the uneven state at λ = 0.3.
testing::Assembled trialAt(bool rigidMaster, double friction, const std::vector<double>& x, double lambda) {
  auto interface = unevenInterface(rigidMaster, friction);
  testing::assemble<2>(*interface, unevenLine3(rigidMaster), 0.3);
  return testing::assemble<2>(*interface, x, lambda);
}

void expectTangentIsTheCentralDifference(bool rigidMaster, double friction, double slide, ContactStatus expected) {
  const auto x = slidLine3(rigidMaster, slide);
  const double lambda = 0.3 + 0.5 * slide;
  const testing::Assembled a = trialAt(rigidMaster, friction, x, lambda);
  for (const auto& st : a.states) EXPECT_EQ(st.status, expected);
  double scale = 0;
  const double error = testing::tangentCentralDifferenceError(
      a.tangent, x, [&](const std::vector<double>& y) { return trialAt(rigidMaster, friction, y, lambda).residual; }, &scale);
  EXPECT_GT(scale, 100.0);
  EXPECT_LT(error, 1e-6 * scale);
  if (friction > 0) {
    double tangential = 0;
    for (int node = 0; node < 5; ++node) tangential = std::max(tangential, std::abs(a.residual[2 * node]));
    EXPECT_GT(tangential, 1e-3) << "a tangential force";
  }
  if (!rigidMaster) return;
  double dScale = 0;
  const double dError = testing::loadDerivativeCentralDifferenceError(
      a.dLambda, lambda, [&](double mu) { return trialAt(true, friction, x, mu).residual; }, &dScale);
  EXPECT_GT(dScale, 1.0);
  EXPECT_LT(dError, 1e-6 * dScale);
}

TEST(MortarInterfaceLine3, TangentIsTheCentralDifferenceOfTheResidual) {
  expectTangentIsTheCentralDifference(false, 0.0, 0.0, ContactStatus::Slip);  // frictionless: reported as slip
  expectTangentIsTheCentralDifference(true, 0.0, 0.0, ContactStatus::Slip);
}

TEST(MortarInterfaceLine3, FrictionalTangentInStickAndSlipIsTheCentralDifferenceOfTheResidual) {
  for (const bool rigid : {false, true}) {
    expectTangentIsTheCentralDifference(rigid, 0.3, 1e-4, ContactStatus::Stick);
    expectTangentIsTheCentralDifference(rigid, 0.3, 0.05, ContactStatus::Slip);
  }
}

TEST(MortarInterfaceLine3, ASlidingPatchCarriesCoulombsForce) {
  // Uniform penetration d, the slave slid by 0.05 along +x: every node slips, the tangential force on the
  // slave is −μ times the normal force.
  const double d = 1e-3, mu = 0.3;
  auto interface = makeMortarInterface(line3Spec(mu), std::vector<char>(5, 1));
  auto x = line3Coordinates(d, 1.0);
  for (int node = 5; node < 12; ++node) x[2 * node] = 1.4 * x[2 * node] - 0.2;  // the master over [−0.2, 1.2]
  testing::assemble<2>(*interface, x, 0.0);
  for (int node = 0; node < 5; ++node) x[2 * node] += 0.05;
  const auto a = testing::assemble<2>(*interface, x, 0.0);
  for (const auto& st : a.states) EXPECT_EQ(st.status, ContactStatus::Slip);
  const auto& force = interface->committedSlaveForce();
  EXPECT_NEAR(force[1], -kPenalty * d, 1e-9 * kPenalty * d);  // p over the slave's length 1
  EXPECT_NEAR(force[0], -mu * kPenalty * d, 1e-9 * kPenalty * d);
}

}  // namespace
}  // namespace contessa::contact
