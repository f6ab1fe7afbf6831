// The 2D mortar kernels (MortarSegment) and interface (MortarInterface): the weighted gaps of a non-matching
// pair against their closed form, their exact first and second derivatives against central differences,
// and the interface's residual, tangent and ∂r/∂λ against central differences of its residual.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "contact/MortarDual.hpp"
#include "contact/MortarInterface.hpp"
#include "contact/MortarSegment.hpp"
#include "MortarTestTools.hpp"

namespace contessa::contact {
namespace {

// A slave segment on top of a body below (traversed right to left: its normal, the right of the direction,
// points up) under a master segment above (traversed left to right: its normal points down).
SegmentPairCoordinates<double> flatPair(double masterLeft, double masterRight, double gap) {
  return {1.0, 0.0, 0.0, 0.0, masterLeft, gap, masterRight, gap};
}

TEST(MortarSegment, WeightedGapsOfAFlatPartialOverlapAreTheGapTimesTheMortarLengths) {
  // Master over x ∈ [0.3, 2]: it covers ξ ∈ [0, 0.7] of the slave segment (ξ = 1 − x), so
  // ∫ N_0 = ∫_0^0.7 (1 − ξ) dξ = 0.455 and ∫ N_1 = ∫_0^0.7 ξ dξ = 0.245.
  const double gap = -0.01;
  const MortarPairGaps<double> g = segmentPairGaps(flatPair(0.3, 2.0, gap), 1.0);
  ASSERT_TRUE(g.overlaps);
  EXPECT_NEAR(g.mortarLength[0], 0.455, 1e-14);
  EXPECT_NEAR(g.mortarLength[1], 0.245, 1e-14);
  EXPECT_NEAR(g.weightedGap[0], gap * 0.455, 1e-15);
  EXPECT_NEAR(g.weightedGap[1], gap * 0.245, 1e-15);
}

TEST(MortarSegment, PairsThatDoNotFaceOrOverlapOrLieFarAwayCountNothing) {
  EXPECT_FALSE(segmentPairGaps(flatPair(1.5, 2.0, 0.0), 1.0).overlaps);    // beside the slave segment
  EXPECT_FALSE(segmentPairGaps(flatPair(2.0, -1.0, 0.0), 1.0).overlaps);   // turned away: normal up, like the slave's
  EXPECT_FALSE(segmentPairGaps(flatPair(0.0, 1.0, -3.0), 1.0).overlaps);   // far behind: another side of the body
  EXPECT_FALSE(segmentPairGaps(flatPair(0.0, 1.0, 3.0), 1.0).overlaps);    // far in front
  EXPECT_TRUE(segmentPairGaps(flatPair(0.0, 1.0, 0.5), 1.0).overlaps);
}

TEST(MortarSegment, AMasterEndFlushWithASlaveEndWithinRoundOffClipsAtTheSlaveEnd) {
  // Penetration g under a master from x = δ to 2 (the slave's end ξ = 1 is x = 0). Clipped at the master's
  // end ξ_b = 1 − x_m0, g̃_1 owes that end's motion along the line the edge term g N_1(ξ_b) ∂ξ_b/∂x_m0 =
  // −g (1 − δ); snapped to the
  // slave's end (δ below kMortarSnap), it owes nothing: flush edges give one answer, not two by round-off.
  const double gap = -0.01;
  const MortarPairDerivatives apart = segmentPairDerivatives(flatPair(1e-6, 2.0, gap), 1.0);
  EXPECT_NEAR(apart.gradient[1][4], -gap * (1.0 - 1e-6), 1e-12);
  const MortarPairDerivatives flush = segmentPairDerivatives(flatPair(1e-13, 2.0, gap), 1.0);
  EXPECT_EQ(flush.gradient[1][4], 0.0);
  EXPECT_NEAR(flush.mortarLength[1], 0.5, 1e-15);
}

// A tilted, curved-looking pair clipped at one slave end and one master end, with a slave node beyond each
// end (a curved slave surface: the averaged nodal normals differ from the segment's).
// Its slave segment's reference length (here other than its current one: a stretched segment).
constexpr double kTiltedLength = 1.2;
SegmentPairCoordinates<double> tiltedPair() {
  return {1.1, 0.05, -0.02, -0.07, 0.35, -0.03, 1.6, 0.12, 2.0, 0.3, -1.0, -0.35};
}
// The neighbour segments continue the slave surface: stored as (y_0, s_0) and (s_1, y_1).
MortarSlaveNeighbours tiltedNeighbours() { return {{1, 1}}; }

// Committed positions of the tilted pair's four nodes: the slave moved right and up, the master left.
SegmentPairCommitted tiltedCommitted() { return {1.05, 0.04, -0.08, -0.075, 0.38, -0.03, 1.63, 0.115}; }

// Which weighted quantity a derivative test reads: the gap or (friction) the slip increment.
double quantity(const MortarPairGaps<double>& g, int a, bool slip) { return slip ? g.weightedSlip[a] : g.weightedGap[a]; }

void expectDerivativesAreCentralDifferences(const MortarSlaveNeighbours& neighbours, bool slip = false) {
  constexpr int m = kMortarPairCoordinates;
  const auto x = tiltedPair();
  const SegmentPairCommitted then = tiltedCommitted();
  const SegmentPairCommitted* committed = slip ? &then : nullptr;
  const MortarPairDerivatives d = segmentPairDerivatives(x, kTiltedLength, neighbours, committed);
  ASSERT_TRUE(d.overlaps);
  const MortarPairGaps<double> plain = segmentPairGaps(x, kTiltedLength, neighbours, committed);
  const auto& gradient = slip ? d.slipGradient : d.gradient;
  const auto& hessian = slip ? d.slipHessian : d.hessian;
  const double h = 1e-6;
  for (int a = 0; a < 2; ++a) {
    EXPECT_DOUBLE_EQ(slip ? d.weightedSlip[a] : d.weightedGap[a], quantity(plain, a, slip));
    double scale = 0, gradientError = 0, hessianScale = 0, hessianError = 0;
    for (int j = 0; j < m; ++j) {
      auto plus = x, minus = x;
      plus[j] += h;
      minus[j] -= h;
      const double fd = (quantity(segmentPairGaps(plus, kTiltedLength, neighbours, committed), a, slip) -
                         quantity(segmentPairGaps(minus, kTiltedLength, neighbours, committed), a, slip)) / (2 * h);
      scale = std::max(scale, std::abs(gradient[a][j]));
      gradientError = std::max(gradientError, std::abs(fd - gradient[a][j]));
      const MortarPairDerivatives dp = segmentPairDerivatives(plus, kTiltedLength, neighbours, committed),
                                  dm = segmentPairDerivatives(minus, kTiltedLength, neighbours, committed);
      for (int i = 0; i < m; ++i) {
        const auto& gp = slip ? dp.slipGradient : dp.gradient;
        const auto& gm = slip ? dm.slipGradient : dm.gradient;
        const double fdHessian = (gp[a][i] - gm[a][i]) / (2 * h);
        hessianScale = std::max(hessianScale, std::abs(hessian[a][i * m + j]));
        hessianError = std::max(hessianError, std::abs(fdHessian - hessian[a][i * m + j]));
        EXPECT_NEAR(hessian[a][i * m + j], hessian[a][j * m + i], 1e-12) << "a Hessian is symmetric";
      }
    }
    EXPECT_GT(scale, 0.1);
    EXPECT_GT(hessianScale, 0.1);
    EXPECT_LT(gradientError, 1e-8 * scale) << "slave node " << a;
    EXPECT_LT(hessianError, 1e-7 * hessianScale) << "slave node " << a;
  }
}

TEST(MortarSegment, GradientAndHessianAreTheCentralDifferencesOfTheWeightedGaps) {
  expectDerivativesAreCentralDifferences({});
}

TEST(MortarSegment, WeightedSlipIncrementsAreDifferentiatedTwiceExactly) {
  expectDerivativesAreCentralDifferences(tiltedNeighbours(), true);
}

// A function of three variables with every operation the kernels use (sums, products, quotients, square
// roots, constants on either side), in any number type.
template <class T>
T mixedFunction(const T& a, const T& b, const T& c) {
  using std::sqrt;
  const T q = (a * b - 0.5) / (c + 2.0);
  return sqrt(1.0 + a * a * c) * q - 3.0 / (b * b + 1.0) + (1.0 - c) * (a / 4.0) - (2.0 - q);
}

TEST(MortarDual, HessianDualCarriesTheNestedDualsGradientAndHessian) {
  // HessianDual (symmetric storage, the chain rule once per operation) against Dual<Dual<double, 3>, 3>
  // (nested forward mode): the same value and gradient, the Hessian to round-off, and a symmetric Hessian.
  const double x[3] = {0.7, -1.3, 0.4};
  using Nested = Dual<Dual<double, 3>, 3>;
  const Nested n = mixedFunction(secondOrderVariable<3>(x[0], 0), secondOrderVariable<3>(x[1], 1),
                                 secondOrderVariable<3>(x[2], 2));
  const HessianDual<3> h = mixedFunction(hessianVariable<3>(x[0], 0), hessianVariable<3>(x[1], 1),
                                         hessianVariable<3>(x[2], 2));
  // The value and gradient rounded alike (the residual −p ∇g̃ the same to the bit).
  EXPECT_EQ(h.v, n.v.v);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(h.gradient(i), n.d[i].v) << i;
    EXPECT_NEAR(h.gradient(i), n.v.d[i], 1e-14) << i;
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(h.hessian(i, j), n.d[i].d[j], 1e-13) << i << ", " << j;
      EXPECT_EQ(h.hessian(i, j), h.hessian(j, i));
    }
  }
  double scale = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) scale = std::max(scale, std::abs(n.d[i].d[j]));
  EXPECT_GT(scale, 0.5) << "a function with curvature";
}

// The rigid master's coordinates (entries 4–7) moving by `motion`: the derivatives along the motion, in
// entry 4, are the full derivatives contracted with the motion; the slave entries are unchanged.
void expectDerivativesAlongTheMotionAreTheFullOnesContracted(bool slip) {
  constexpr int m = kMortarPairCoordinates;
  const auto x = tiltedPair();
  const SegmentPairCommitted then = tiltedCommitted();
  const SegmentPairCommitted* committed = slip ? &then : nullptr;
  const double motion[4] = {0.3, -0.7, 0.3, -0.7};
  const MortarPairDerivatives full = segmentPairDerivatives(x, kTiltedLength, tiltedNeighbours(), committed);
  const MortarPairDerivatives along = segmentPairDerivatives(x, kTiltedLength, tiltedNeighbours(), committed, motion);
  ASSERT_TRUE(along.overlaps);
  const auto contract = [&](const std::array<double, m * m>& h, int i) {  // Σ_b H[i][4 + b] motion_b
    double sum = 0;
    for (int b = 0; b < 4; ++b) sum += h[i * m + 4 + b] * motion[b];
    return sum;
  };
  for (int a = 0; a < 2; ++a) {
    const auto& g = slip ? full.slipGradient[a] : full.gradient[a];
    const auto& h = slip ? full.slipHessian[a] : full.hessian[a];
    const auto& ga = slip ? along.slipGradient[a] : along.gradient[a];
    const auto& ha = slip ? along.slipHessian[a] : along.hessian[a];
    EXPECT_EQ(slip ? along.weightedSlip[a] : along.weightedGap[a], slip ? full.weightedSlip[a] : full.weightedGap[a]);
    double gradientAlong = 0, curvatureAlong = 0, scale = 0;
    for (int b = 0; b < 4; ++b) {
      gradientAlong += g[4 + b] * motion[b];
      curvatureAlong += contract(h, 4 + b) * motion[b];
    }
    for (int i = 0; i < m * m; ++i) scale = std::max(scale, std::abs(h[i]));
    EXPECT_NEAR(ga[4], gradientAlong, 1e-13);
    EXPECT_GT(std::abs(gradientAlong), 1e-3) << "the motion moves the gap";
    EXPECT_NEAR(ha[4 * m + 4], curvatureAlong, 1e-13 * scale);
    for (int b = 1; b < 4; ++b) EXPECT_EQ(ga[4 + b], 0.0);
    for (int i = 0; i < m; ++i) {
      const bool master = i >= 4 && i < 8;
      if (!master) {
        EXPECT_NEAR(ga[i], g[i], 1e-14);
        EXPECT_NEAR(ha[i * m + 4], contract(h, i), 1e-13 * scale) << i;
        EXPECT_NEAR(ha[4 * m + i], contract(h, i), 1e-13 * scale) << i;
      }
      for (int j = 0; j < m; ++j) {
        if (!master && !(j >= 4 && j < 8)) {
          EXPECT_NEAR(ha[i * m + j], h[i * m + j], 1e-13 * scale) << i << ", " << j;
        }
      }
    }
  }
}

TEST(MortarSegment, ARigidMasterIsDifferentiatedAlongItsMotion) {
  expectDerivativesAlongTheMotionAreTheFullOnesContracted(false);
  expectDerivativesAlongTheMotionAreTheFullOnesContracted(true);
}

TEST(MortarSegment, ARigidSlideGivesTheSlipTimesTheMortarLengths) {
  // The slave slid by 0.02 along +x under a fixed master (whose tangent t_m is +x): Δũ_a = 0.02 ∫ N_a.
  const double gap = -0.01, slide = 0.02;
  const SegmentPairCommitted then{1.0 - slide, 0.0, -slide, 0.0, 0.3, gap, 2.0, gap};
  const MortarPairGaps<double> g = segmentPairGaps(flatPair(0.3, 2.0, gap), 1.0, {}, &then);
  ASSERT_TRUE(g.overlaps);
  EXPECT_NEAR(g.weightedSlip[0], slide * 0.455, 1e-15);
  EXPECT_NEAR(g.weightedSlip[1], slide * 0.245, 1e-15);
  // The master moving with the slave: no relative slip.
  const SegmentPairCommitted together{1.0 - slide, 0.0, -slide, 0.0, 0.3 - slide, gap, 2.0 - slide, gap};
  const MortarPairGaps<double> none = segmentPairGaps(flatPair(0.3, 2.0, gap), 1.0, {}, &together);
  EXPECT_NEAR(none.weightedSlip[0], 0.0, 1e-16);
  EXPECT_NEAR(none.weightedSlip[1], 0.0, 1e-16);
}

TEST(MortarSegment, WithAveragedNodalNormalsTheNeighbourSlaveNodesAreDifferentiatedToo) {
  expectDerivativesAreCentralDifferences(tiltedNeighbours());
  // The neighbours turn the nodal normals, hence move the clip point at the master's end, and the weighted
  // gaps owe them g(ξ_clip) N_a(ξ_clip) ∂ξ_clip/∂y: not zero with a gap of 0.2 at the clip point.
  auto x = tiltedPair();
  x[5] += 0.2;
  x[7] += 0.2;
  const MortarPairDerivatives d = segmentPairDerivatives(x, kTiltedLength, tiltedNeighbours());
  ASSERT_TRUE(d.overlaps);
  double neighbourScale = 0;
  for (int i = 8; i < kMortarPairCoordinates; ++i) neighbourScale = std::max(neighbourScale, std::abs(d.gradient[0][i]));
  EXPECT_GT(neighbourScale, 1e-3) << "zero without the neighbours";
}

TEST(MortarSegment, AMasterNodeOnTheInterpolatedNormalAtXiClipsTheSlaveSegmentAtXi) {
  // Slave segment (0, 0) → (−1, 0) (normal up) between a neighbour (1, −0.3) beyond node 0 (stored
  // (y_0, s_0)) and (−2, −0.2) beyond node 1 (stored (s_1, y_1)): the nodal normals tilt right and left.
  // A master node on the interpolated normal n(0.3) = 0.7 n_0 + 0.3 n_1 through the slave point ξ = 0.3
  // is seen at ξ = 0.3: the master segment from it to the right covers ξ ∈ [0, 0.3].
  const auto unit = [](double x, double y) { const double l = std::hypot(x, y); return std::array<double, 2>{x / l, y / l}; };
  const auto n0u = unit(0.3, 1.0), n1u = unit(-0.2, 1.0);
  const auto n0 = unit(n0u[0], 1.0 + n0u[1]), n1 = unit(n1u[0], 1.0 + n1u[1]);
  const double xi = 0.3, t = 0.05;
  const double mx = -xi + t * (0.7 * n0[0] + 0.3 * n1[0]), my = t * (0.7 * n0[1] + 0.3 * n1[1]);
  const SegmentPairCoordinates<double> x{0, 0, -1, 0, mx, my, 2.0, 0.06, 1.0, -0.3, -2.0, -0.2};
  const MortarPairGaps<double> g = segmentPairGaps(x, 1.0, {{1, 1}});
  ASSERT_TRUE(g.overlaps);
  EXPECT_NEAR(g.mortarLength[0] + g.mortarLength[1], xi, 1e-13);
  // With the segment's own normal (0, 1) the same node is seen straight below it, at ξ = −m_x ≠ 0.3.
  const MortarPairGaps<double> plain = segmentPairGaps(x, 1.0);
  EXPECT_NEAR(plain.mortarLength[0] + plain.mortarLength[1], -mx, 1e-13);
  EXPECT_GT(std::abs(mx + xi), 1e-3);
  // The gap is measured along the master's normal: the master line y = my + (x − mx)(0.06 − my)/(2 − mx)
  // above the slave line y = 0, whatever the normals; g̃_0 + g̃_1 = ∫_0^0.3 g dξ.
  const double slope = (0.06 - my) / (2.0 - mx), cosine = 1.0 / std::hypot(1.0, slope);
  const auto gapAtX = [&](double px) { return (my + (px - mx) * slope) * cosine; };  // below the line: open
  const double exact = 0.5 * xi * (gapAtX(0.0) + gapAtX(-xi));  // affine in ξ: the trapezoid is exact
  EXPECT_NEAR(g.weightedGap[0] + g.weightedGap[1], exact, 1e-14);
}

// A non-matching interface: 3 slave segments on y = 0 (x ∈ [0, 3]) under 2 master segments (x ∈ [−0.2, 3.2]).
// Nodes 0–3 slave (right to left along the slave surface), 4–6 master (left to right), DOFs node·2 + c.
constexpr double kPenalty = 1e3;

ContactInterfaceSpec patchSpec(bool rigidMaster) {
  ContactInterfaceSpec spec;
  spec.name = "patch";
  spec.dimension = 2;
  spec.mortar = true;
  spec.slaveNodes = {0, 1, 2, 3};
  spec.slaveFacets = {0, 1, 1, 2, 2, 3};
  spec.slaveFacetMeasures = {1.0, 1.0, 1.0};
  spec.slaveAreas = {0.5, 1.0, 1.0, 0.5};
  spec.slaveFacetLengths = {1.0, 1.0, 1.0, 1.0};
  spec.law.normalPenalty = kPenalty;
  if (rigidMaster) {
    spec.rigidMaster = true;
    spec.rigidSurface.points = {-0.2, -0.03, 1.5, -0.03, 3.2, -0.03};
    spec.rigidSurface.facets = {0, 1, 1, 2};
    spec.rigidSurface.motion = {0.1, -0.02};
  } else {
    spec.masterFacets = {4, 5, 5, 6};
  }
  return spec;
}

std::vector<double> patchCoordinates(double penetration) {
  // Slave nodes at x = 3, 2, 1, 0 on y = 0; master nodes at x = −0.2, 1.5, 3.2 on y = −penetration.
  return {3, 0, 2, 0, 1, 0, 0, 0, -0.2, -penetration, 1.5, -penetration, 3.2, -penetration};
}

using testing::Assembled;

Assembled assemble(ContactInterfaceBase& interface, const std::vector<double>& x, double lambda) {
  return testing::assemble<2>(interface, x, lambda);
}

std::unique_ptr<ContactInterfaceBase> patchInterface(bool rigidMaster) {
  return makeMortarInterface(patchSpec(rigidMaster), std::vector<char>(4, 1));
}

TEST(MortarInterface, NonMatchingFlatPenetrationGivesTheSamePressureAtEverySlaveNode) {
  // The contact patch test at the interface: a uniform penetration d over non-matching segments gives
  // p = ε_N d at every slave node, the end nodes included, and the master takes the opposite force.
  const double d = 1e-3;
  auto interface = patchInterface(false);
  const Assembled a = assemble(*interface, patchCoordinates(d), 0.0);
  for (const auto& s : a.states) {
    EXPECT_EQ(s.status, ContactStatus::Slip);
    EXPECT_NEAR(s.pressure, kPenalty * d, 1e-12 * kPenalty * d);
  }
  double slaveForce = 0, masterForce = 0;
  for (int node = 0; node < 7; ++node) (node < 4 ? slaveForce : masterForce) -= a.residual[2 * node + 1];
  EXPECT_NEAR(slaveForce, -kPenalty * d * 3.0, 1e-12);  // pressure × slave length 3, pushing the slave down
  EXPECT_NEAR(masterForce, kPenalty * d * 3.0, 1e-12);
  EXPECT_NEAR(interface->committedSlaveForce()[1], -kPenalty * d * 3.0, 1e-12);
}

// A tilted, uneven configuration: every slave node closed, the clip points inside segments.
std::vector<double> unevenCoordinates() {
  return {3.02, 0.01, 2.05, -0.01, 0.97, 0.02, 0.01, 0.0, -0.2, -0.031, 1.45, -0.024, 3.2, -0.034};
}

double tangentError(bool rigidMaster, double* scale) {
  const auto x = unevenCoordinates();
  const Assembled a = assemble(*patchInterface(rigidMaster), x, 0.3);
  for (const auto& s : a.states) EXPECT_EQ(s.status, ContactStatus::Slip) << "the test wants every node closed";
  const auto residualAt = [&](const std::vector<double>& y) {
    return assemble(*patchInterface(rigidMaster), y, 0.3).residual;
  };
  return testing::tangentCentralDifferenceError(a.tangent, x, residualAt, scale);
}

TEST(MortarInterface, TangentIsTheCentralDifferenceOfTheResidualWithADeformableMaster) {
  double scale = 0;
  const double error = tangentError(false, &scale);
  EXPECT_GT(scale, 100.0);
  EXPECT_LT(error, 1e-6 * scale);
}

TEST(MortarInterface, TangentAndLoadDerivativeAreCentralDifferencesWithAMovingRigidMaster) {
  double scale = 0;
  const double error = tangentError(true, &scale);
  EXPECT_GT(scale, 100.0);
  EXPECT_LT(error, 1e-6 * scale);
  // ∂r/∂λ: the rigid master moves by λ · motion.
  const auto x = unevenCoordinates();
  const double lambda = 0.3;
  const Assembled a = assemble(*patchInterface(true), x, lambda);
  double dScale = 0;
  const double dError = testing::loadDerivativeCentralDifferenceError(
      a.dLambda, lambda, [&](double mu) { return assemble(*patchInterface(true), x, mu).residual; }, &dScale);
  EXPECT_GT(dScale, 1.0);
  EXPECT_LT(dError, 1e-6 * dScale);
}

TEST(MortarInterface, OpenNodesCarryNoForceAndCountAsOpenEvents) {
  auto interface = patchInterface(false);
  const Assembled a = assemble(*interface, patchCoordinates(-0.01), 0.0);  // master 0.01 above
  for (const auto& s : a.states) {
    EXPECT_EQ(s.status, ContactStatus::Open);
    EXPECT_NEAR(s.gap, 0.01, 1e-14);
  }
  for (double r : a.residual) EXPECT_EQ(r, 0.0);
  // Closing it: each slave node's change goes from open at the commit to closed in the trial state.
  interface->evaluate([&](GlobalIndex node, double* p) {
    const auto x = patchCoordinates(1e-3);
    p[0] = x[2 * node], p[1] = x[2 * node + 1];
  }, 0.0, true, [](const GlobalIndex*, int, const double*, const double*, const double*) {});
  for (const auto& c : interface->trialChanges()) {
    EXPECT_EQ(c.committedStatus, ContactStatus::Open);
    EXPECT_EQ(c.trialStatus, ContactStatus::Slip);
    EXPECT_NEAR(c.committedGap, 0.01, 1e-14);
    EXPECT_NEAR(c.trialGap, -1e-3, 1e-14);
  }
}

// Friction (eq. M9–M12): μ = 0.3, ε_T = 10³. The committed state is the uneven configuration; the trial one
// slides the slave nodes along x by `slide` (small: stick; large: slip), and the master a little.
constexpr double kFriction = 0.3;

std::unique_ptr<ContactInterfaceBase> frictionalInterface(bool rigidMaster) {
  ContactInterfaceSpec spec = patchSpec(rigidMaster);
  spec.law.frictionCoefficient = kFriction;
  spec.law.tangentialPenalty = kPenalty;
  return makeMortarInterface(spec, std::vector<char>(4, 1));
}

std::vector<double> slid(double slide) {
  auto x = unevenCoordinates();
  for (int node = 0; node < 4; ++node) x[2 * node] += slide * (1.0 + 0.1 * node);
  for (int node = 4; node < 7; ++node) x[2 * node] -= 0.2 * slide;
  return x;
}

/// The trial evaluation at x after committing the uneven configuration at λ = 0.3, and then, when
/// `stuck` > 0, the configuration slid by `stuck` (a stick state: a nonzero committed traction).
Assembled frictionalTrial(bool rigidMaster, const std::vector<double>& x, double lambda, double stuck = 0.0) {
  auto interface = frictionalInterface(rigidMaster);
  assemble(*interface, unevenCoordinates(), 0.3);  // evaluates and commits
  if (stuck > 0.0) assemble(*interface, slid(stuck), 0.3 + 0.5 * stuck);
  return assemble(*interface, x, lambda);  // the trial evaluation, then its commit
}

void expectFrictionalTangentIsTheCentralDifference(bool rigidMaster, double slide, ContactStatus expected,
                                                   double stuck = 0.0) {
  const auto x = slid(slide);
  const double lambda = 0.3 + 0.5 * slide;
  const Assembled a = frictionalTrial(rigidMaster, x, lambda, stuck);
  for (const auto& s : a.states) EXPECT_EQ(s.status, expected);
  const int n = static_cast<int>(x.size());
  const double h = 1e-7;
  double scale = 0, error = 0, frictionScale = 0;
  for (int j = 0; j < n; ++j) {
    auto plus = x, minus = x;
    plus[j] += h;
    minus[j] -= h;
    const auto rp = frictionalTrial(rigidMaster, plus, lambda, stuck).residual;
    const auto rm = frictionalTrial(rigidMaster, minus, lambda, stuck).residual;
    for (int i = 0; i < n; ++i) {
      scale = std::max(scale, std::abs(a.tangent[i * n + j]));
      error = std::max(error, std::abs((rp[i] - rm[i]) / (2 * h) - a.tangent[i * n + j]));
    }
  }
  for (int node = 0; node < 4; ++node) frictionScale = std::max(frictionScale, std::abs(a.residual[2 * node]));
  EXPECT_GT(frictionScale, 1e-3) << "a tangential force";
  EXPECT_GT(scale, 100.0);
  EXPECT_LT(error, 1e-6 * scale);
  if (rigidMaster) {
    const auto rp = frictionalTrial(true, x, lambda + h, stuck).residual;
    const auto rm = frictionalTrial(true, x, lambda - h, stuck).residual;
    double dError = 0, dScale = 0;
    for (int i = 0; i < n; ++i) {
      dScale = std::max(dScale, std::abs(a.dLambda[i]));
      dError = std::max(dError, std::abs((rp[i] - rm[i]) / (2 * h) - a.dLambda[i]));
    }
    EXPECT_GT(dScale, 1.0);
    EXPECT_LT(dError, 1e-6 * dScale);
  }
}

TEST(MortarInterface, FrictionalTangentInStickIsTheCentralDifferenceOfTheResidual) {
  expectFrictionalTangentIsTheCentralDifference(false, 1e-3, ContactStatus::Stick);
  expectFrictionalTangentIsTheCentralDifference(true, 1e-3, ContactStatus::Stick);
}

TEST(MortarInterface, FrictionalTangentInSlipIsTheCentralDifferenceOfTheResidual) {
  expectFrictionalTangentIsTheCentralDifference(false, 0.05, ContactStatus::Slip);
  expectFrictionalTangentIsTheCentralDifference(true, 0.05, ContactStatus::Slip);
}

TEST(MortarInterface, FrictionalTangentFromAStuckStateIsTheCentralDifferenceOfTheResidual) {
  // Committed in stick with a nonzero traction (slid by 1e-3), then a trial in stick and one in slip.
  expectFrictionalTangentIsTheCentralDifference(false, 2e-3, ContactStatus::Stick, 1e-3);
  expectFrictionalTangentIsTheCentralDifference(true, 2e-3, ContactStatus::Stick, 1e-3);
  expectFrictionalTangentIsTheCentralDifference(false, 0.05, ContactStatus::Slip, 1e-3);
  expectFrictionalTangentIsTheCentralDifference(true, 0.05, ContactStatus::Slip, 1e-3);
}

void expectSameAssembly(const Assembled& a, const Assembled& b) {
  EXPECT_EQ(a.residual, b.residual);
  EXPECT_EQ(a.tangent, b.tangent);
  EXPECT_EQ(a.dLambda, b.dLambda);
}

TEST(MortarInterface, EvaluationsReusingThePairsDerivativesGiveWhatAFreshInterfaceGives) {
  // The interface keeps its pairs' derivatives from one evaluation to the next and reuses those whose
  // inputs are unchanged (the Jacobian pass at the residual pass's iterate). Iterates x1, x2 (one master
  // node moved: the pairs on the other master segment stay), x1 again, and a moved rigid master, each
  // against a fresh interface's evaluation: the same residual, tangent and ∂r/∂λ to the bit.
  for (const bool rigidMaster : {false, true}) {
    for (const bool friction : {false, true}) {
      SCOPED_TRACE(std::string(rigidMaster ? "rigid" : "deformable") + (friction ? ", friction" : ""));
      // Committed at the uneven configuration (friction: the slip increments' start), as every fresh one.
      const auto fresh = [&] {
        auto interface = friction ? frictionalInterface(rigidMaster) : patchInterface(rigidMaster);
        assemble(*interface, unevenCoordinates(), 0.3);
        return interface;
      };
      auto reused = fresh();
      const auto x1 = slid(0.01);
      auto x2 = x1;
      x2[2 * 6 + 1] -= 0.004;  // master node 6 (deformable master) lower
      const Assembled first = testing::evaluateOnly<2>(*reused, x1, 0.3);
      EXPECT_GT(*std::max_element(first.tangent.begin(), first.tangent.end()), 100.0) << "closed nodes";
      expectSameAssembly(first, testing::evaluateOnly<2>(*fresh(), x1, 0.3));
      expectSameAssembly(testing::evaluateOnly<2>(*reused, x1, 0.3), first);
      expectSameAssembly(testing::evaluateOnly<2>(*reused, x2, 0.3), testing::evaluateOnly<2>(*fresh(), x2, 0.3));
      expectSameAssembly(testing::evaluateOnly<2>(*reused, x1, 0.3), first);
      expectSameAssembly(testing::evaluateOnly<2>(*reused, x1, 0.35), testing::evaluateOnly<2>(*fresh(), x1, 0.35));
    }
  }
}

TEST(MortarInterface, SlidingNodesCarryTheCoulombForceAgainstTheSlip) {
  // A flat patch slid by 0.05 along +x under a fixed master: every node slips, and the tangential force on
  // the slave is −μ times the normal force, against the motion.
  auto interface = frictionalInterface(false);
  const double d = 1e-3;
  assemble(*interface, patchCoordinates(d), 0.0);
  auto x = patchCoordinates(d);
  for (int node = 0; node < 4; ++node) x[2 * node] += 0.05;
  const Assembled a = assemble(*interface, x, 0.0);
  for (const auto& s : a.states) EXPECT_EQ(s.status, ContactStatus::Slip);
  const auto& force = interface->committedSlaveForce();
  EXPECT_NEAR(force[1], -kPenalty * d * 3.0, 1e-9);
  EXPECT_NEAR(force[0], -kFriction * kPenalty * d * 3.0, 1e-9);
}


// The augmented Lagrangian on the weighted quantities (theory-contact §13.4, eq. M22–M23): λ_N,k and λ_Tα,k
// per slave node, set by an update (ContactInterfaceBase::augment) to the tractions of a trial evaluation.
std::unique_ptr<ContactInterfaceBase> augmentedInterface(bool rigidMaster, bool friction, double slipTolerance = 0.0) {
  ContactInterfaceSpec spec = patchSpec(rigidMaster);
  if (friction) {
    spec.law.frictionCoefficient = kFriction;
    spec.law.tangentialPenalty = slipTolerance > 0.0 ? 0.0 : kPenalty;
    spec.law.slipTolerance = slipTolerance;
  }
  spec.law.enforcement = ContactLawParameters::Enforcement::AugmentedLagrangian;
  spec.law.penetrationTolerance = 1e-6;
  spec.law.elasticSlipTolerance = 1e-6;
  spec.law.maxAugmentations = 10;
  return makeMortarInterface(spec, std::vector<char>(4, 1));
}

void evaluateTrial(ContactInterfaceBase& interface, const std::vector<double>& x, double lambda) {
  testing::evaluateOnly<2>(interface, x, lambda);
}

TEST(MortarInterfaceAugmented, TheNormalMultiplierHoldsANodeAtAPositiveWeightedGapUntilACutBack) {
  // An update at a uniform penetration d gives λ_N,k = −ε_N d at every node; lifted to a gap d/2 the nodes
  // stay closed with the pressure ε_N d/2 (t_N = λ_N + ε_N g̃/A, eq. M22), and open past d; a rollback
  // forgets the update, a commit keeps it.
  const double d = 1e-3;
  auto interface = augmentedInterface(false, false);
  evaluateTrial(*interface, patchCoordinates(d), 0.0);
  EXPECT_NEAR(interface->trialViolation().penetration, d, 1e-15);
  interface->augment(true);
  auto held = interface->clone();
  const Assembled a = assemble(*held, patchCoordinates(-0.5 * d), 0.0);
  for (const auto& s : a.states) {
    EXPECT_EQ(s.status, ContactStatus::Slip);
    EXPECT_NEAR(s.gap, 0.5 * d, 1e-15);
    EXPECT_NEAR(s.pressure, 0.5 * kPenalty * d, 1e-12);
  }
  EXPECT_NEAR(held->trialViolation().penetration, 0.5 * d, 1e-15) << "a gap held open by λ_N counts";
  for (const auto& s : assemble(*interface->clone(), patchCoordinates(-1.5 * d), 0.0).states)
    EXPECT_EQ(s.status, ContactStatus::Open);
  // Committed closed: the multiplier stays the increment's (the converged state an equilibrium).
  for (const auto& s : assemble(*held, patchCoordinates(-0.5 * d), 0.0).states) EXPECT_NEAR(s.pressure, 0.5 * kPenalty * d, 1e-12);
  interface->rollback();
  for (const auto& s : assemble(*interface, patchCoordinates(-0.5 * d), 0.0).states)
    EXPECT_EQ(s.status, ContactStatus::Open) << "the rollback forgot the update";
}

TEST(MortarInterfaceAugmented, AnUpdateAddsThePenaltyTractionToTheMultiplierAtTheSameGap) {
  // At imposed positions (no structure to relax) an update at the penetration d leaves λ_N,k = −ε_N d, and
  // the next evaluation there t_N = λ_N + ε_N g̃/A = −2 ε_N d (eq. M22 after eq. 15.3).
  const double d = 1e-3;
  auto interface = augmentedInterface(false, false);
  evaluateTrial(*interface, patchCoordinates(d), 0.0);
  interface->augment(true);
  for (const auto& s : assemble(*interface, patchCoordinates(d), 0.0).states) EXPECT_NEAR(s.pressure, 2 * kPenalty * d, 1e-12);
}

// The interface updated at `updateAt` (after a commit at the uneven configuration at λ = 0.3): the trials of
// a central difference start from its multipliers.
std::unique_ptr<ContactInterfaceBase> updatedInterface(bool rigidMaster, bool friction, double slipTolerance,
                                                       const std::vector<double>& updateAt, double lambda) {
  auto interface = augmentedInterface(rigidMaster, friction, slipTolerance);
  assemble(*interface, unevenCoordinates(), 0.3);
  evaluateTrial(*interface, updateAt, lambda);
  interface->augment(true);
  return interface;
}

void expectAugmentedTangentIsTheCentralDifference(bool rigidMaster, bool friction, double slipTolerance, double slide,
                                                  ContactStatus expected) {
  SCOPED_TRACE(std::string(rigidMaster ? "rigid" : "deformable") + (friction ? ", friction" : "") +
               ", slip tolerance " + std::to_string(slipTolerance) + ", slide " + std::to_string(slide));
  const double lambda = 0.3 + 0.5 * slide;
  // The update at half the slide and 0.003 shallower than the trial: λ ≠ 0 and λ ≠ t.
  auto updateAt = slid(0.5 * slide);
  for (int node = 0; node < 4; ++node) updateAt[2 * node + 1] -= 0.003;
  const auto updated = updatedInterface(rigidMaster, friction, slipTolerance, updateAt, lambda);
  const auto x = slid(slide);
  const Assembled a = testing::evaluateOnly<2>(*updated->clone(), x, lambda);
  auto committed = updated->clone();
  const Assembled states = assemble(*committed, x, lambda);
  for (const auto& s : states.states) EXPECT_EQ(s.status, expected);
  // The multipliers are in the residual: it differs from the penalty law's at the same state.
  auto penalty = friction ? frictionalInterface(rigidMaster) : patchInterface(rigidMaster);
  assemble(*penalty, unevenCoordinates(), 0.3);
  const Assembled plain = testing::evaluateOnly<2>(*penalty, x, lambda);
  double difference = 0, frictionScale = 0;
  for (std::size_t i = 0; i < a.residual.size(); ++i) difference = std::max(difference, std::abs(a.residual[i] - plain.residual[i]));
  for (int node = 0; node < 4; ++node) frictionScale = std::max(frictionScale, std::abs(a.residual[2 * node]));
  EXPECT_GT(difference, 1e-3) << "the multipliers act";
  if (friction) {
    EXPECT_GT(frictionScale, 1e-3) << "a tangential force";
  }
  double scale = 0;
  const double error = testing::tangentCentralDifferenceError(
      a.tangent, x, [&](const std::vector<double>& y) { return testing::trialResidual<2>(*updated, y, lambda); }, &scale);
  EXPECT_GT(scale, 100.0);
  EXPECT_LT(error, 1e-6 * scale);
  if (rigidMaster) {
    double dScale = 0;
    const double dError = testing::loadDerivativeCentralDifferenceError(
        a.dLambda, lambda, [&](double mu) { return testing::trialResidual<2>(*updated, x, mu); }, &dScale);
    EXPECT_GT(dScale, 1.0);
    EXPECT_LT(dError, 1e-6 * dScale);
  }
}

TEST(MortarInterfaceAugmented, TangentWithMultipliersIsTheCentralDifferenceOfTheResidual) {
  for (const bool rigid : {false, true}) {
    expectAugmentedTangentIsTheCentralDifference(rigid, false, 0.0, 1e-3, ContactStatus::Slip);
    expectAugmentedTangentIsTheCentralDifference(rigid, true, 0.0, 1e-3, ContactStatus::Stick);
    expectAugmentedTangentIsTheCentralDifference(rigid, true, 0.0, 0.05, ContactStatus::Slip);
    // ε_T = μ|λ_N|/(s L_k), frozen between updates (the return mapping's frozenNormalTraction).
    expectAugmentedTangentIsTheCentralDifference(rigid, true, 0.01, 1e-3, ContactStatus::Stick);
    expectAugmentedTangentIsTheCentralDifference(rigid, true, 0.01, 0.05, ContactStatus::Slip);
  }
}

TEST(MortarInterfaceAugmented, AStickingNodesElasticSlipIsItsMotionOverTheIncrementPastItsMultiplier) {
  // A sticking node's elastic slip is ‖t_T − λ_T‖/ε_T (its weighted motion over the increment, eq. M23):
  // with the penalty law ‖t_T‖/ε_T; after an update at the same state, t_T − λ_T = ε_T Δũ/A again (the
  // slip increment's start stays at the commit), and λ_T is the traction of the update.
  auto interface = augmentedInterface(false, true);
  assemble(*interface, unevenCoordinates(), 0.3);
  const auto x = slid(1e-3);
  evaluateTrial(*interface, x, 0.3);
  const double before = interface->trialViolation().elasticSlip;
  EXPECT_GT(before, 1e-4);
  interface->augment(true);
  evaluateTrial(*interface, x, 0.3);
  EXPECT_NEAR(interface->trialViolation().elasticSlip, before, 1e-9 * before);
  // At the committed positions (no motion) the violation is gone, and the traction is the multiplier's.
  evaluateTrial(*interface, unevenCoordinates(), 0.3);
  EXPECT_LT(interface->trialViolation().elasticSlip, 1e-12);
}

}  // namespace
}  // namespace contessa::contact
