// The 3D mortar kernel (MortarFacetPair: projection, Sutherland–Hodgman clipping, centroid triangulation)
// and the 3D mortar interface: the weighted gaps of non-matching facet pairs against their closed form,
// their exact first and second derivatives against central differences (facets cut by the clip, warped
// quadrilaterals, triangles), and the interface's residual, tangent and ∂r/∂λ against central differences
// of its residual.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "contact/MortarFacetPair.hpp"
#include "contact/MortarInterface.hpp"
#include "MortarTestTools.hpp"

namespace contessa::contact {
namespace {

constexpr int kM = kMortarFacetPairCoordinates;

// The unit square slave facet on z = 0 (anticlockwise seen from +z: its normal points up, out of the
// body below) under a master rectangle [x0, x1] × [y0, y1] at height z (clockwise seen from +z: its
// normal points down, out of the body above).
FacetPairCoordinates<double> flatPair(double x0, double x1, double y0, double y1, double z) {
  return {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, x0, y0, z, x0, y1, z, x1, y1, z, x1, y0, z};
}

TEST(MortarFacetPair, WeightedGapsOfAFlatPartialOverlapAreTheGapTimesTheMortarAreas) {
  // The master covers x ∈ [0.3, 1] of the slave: ∫ N_0 = ∫_0.3^1 (1 − x) dx ∫_0^1 (1 − y) dy = 0.245 × 0.5,
  // ∫ N_1 = ∫_0.3^1 x dx × 0.5 = 0.455 × 0.5 (N_0 = (1 − x)(1 − y), N_1 = x (1 − y), ...).
  const double gap = -0.01;
  const MortarFacetPairGaps<double> g = facetPairGaps(flatPair(0.3, 1.7, -0.2, 1.5, gap), 1.0);
  ASSERT_TRUE(g.overlaps);
  const double expected[4] = {0.1225, 0.2275, 0.2275, 0.1225};
  for (int a = 0; a < 4; ++a) {
    EXPECT_NEAR(g.mortarArea[a], expected[a], 1e-14) << a;
    EXPECT_NEAR(g.weightedGap[a], gap * expected[a], 1e-15) << a;
  }
  // A stretched slave facet (reference area 2 against a current 1): the measure is the reference area's.
  const MortarFacetPairGaps<double> stretched = facetPairGaps(flatPair(0.3, 1.7, -0.2, 1.5, gap), 2.0);
  EXPECT_NEAR(stretched.mortarArea[1], 2 * expected[1], 1e-14);
}

TEST(MortarFacetPair, AnObliqueMasterCutsTheSlaveAlongItsEdgesAndTheAreasSumToTheOverlap) {
  // A unit master square turned by 30° about the slave's centre (clockwise from +z): the clip polygon is
  // the octagon where each slave edge meets the two master edges crossing it, a master edge being the line
  // n · (p − c) = ½ of outward normal n. Its area (shoelace of those 8 points) is the sum of the mortar
  // areas, and the gap being uniform, g̃_a = g ∫ N_a.
  const double c = 0.5, t = M_PI / 6, s = std::sin(t), co = std::cos(t), gap = -0.02;
  FacetPairCoordinates<double> x = flatPair(0, 1, 0, 1, gap);
  const double corners[4][2] = {{-0.5, -0.5}, {-0.5, 0.5}, {0.5, 0.5}, {0.5, -0.5}};
  for (int b = 0; b < 4; ++b) {
    x[12 + 3 * b] = c + co * corners[b][0] - s * corners[b][1];
    x[13 + 3 * b] = c + s * corners[b][0] + co * corners[b][1];
  }
  const MortarFacetPairGaps<double> g = facetPairGaps(x, 1.0);
  ASSERT_TRUE(g.overlaps);
  std::vector<std::array<double, 2>> octagon;
  const double normals[4][2] = {{co, s}, {-s, co}, {-co, -s}, {s, -co}};
  const double slaveEdges[4][4] = {{0, 0, 1, 0}, {1, 0, 0, 1}, {1, 1, -1, 0}, {0, 1, 0, -1}};  // start, direction
  for (const auto& e : slaveEdges) {
    std::vector<double> params;
    for (const auto& n : normals) {
      const double along = n[0] * e[2] + n[1] * e[3];
      if (std::abs(along) < 1e-12) continue;
      const double p = (0.5 - n[0] * (e[0] - c) - n[1] * (e[1] - c)) / along;
      if (p > 0 && p < 1) params.push_back(p);
    }
    std::sort(params.begin(), params.end());
    for (double p : params) octagon.push_back({e[0] + p * e[2], e[1] + p * e[3]});
  }
  ASSERT_EQ(octagon.size(), 8u);
  double twiceArea = 0;
  for (std::size_t i = 0; i < octagon.size(); ++i) {
    const auto& p = octagon[i];
    const auto& q = octagon[(i + 1) % octagon.size()];
    twiceArea += p[0] * q[1] - p[1] * q[0];
  }
  double overlap = 0;
  for (double m : g.mortarArea) overlap += m;
  EXPECT_NEAR(overlap, 0.5 * twiceArea, 1e-13);
  EXPECT_LT(overlap, 0.95);  // a real cut
  for (int a = 0; a < 4; ++a) {
    EXPECT_NEAR(g.weightedGap[a], gap * g.mortarArea[a], 1e-15);
    EXPECT_NEAR(g.mortarArea[a], 0.25 * overlap, 1e-13) << "the octagon is symmetric about the centre";
  }
}

TEST(MortarFacetPair, PairsThatDoNotFaceOrOverlapOrLieFarAwayCountNothing) {
  EXPECT_FALSE(facetPairGaps(flatPair(1.2, 2.0, 0.0, 1.0, 0.0), 1.0).overlaps);  // beside the slave
  FacetPairCoordinates<double> turned = flatPair(0, 1, 0, 1, 0.0);               // normal up, like the slave's
  std::swap(turned[15], turned[21]), std::swap(turned[16], turned[22]);
  EXPECT_FALSE(facetPairGaps(turned, 1.0).overlaps);
  EXPECT_FALSE(facetPairGaps(flatPair(0, 1, 0, 1, -3.0), 1.0).overlaps);  // far behind: another side
  EXPECT_FALSE(facetPairGaps(flatPair(0, 1, 0, 1, 3.0), 1.0).overlaps);   // far in front
  EXPECT_TRUE(facetPairGaps(flatPair(0, 1, 0, 1, 0.5), 1.0).overlaps);
}

// A warped slave quadrilateral under a warped, tilted master that covers part of it: the clip cuts the
// slave facet, its vertices mix slave nodes, master nodes and edge crossings.
FacetPairCoordinates<double> unevenPair() {
  return {0.02, -0.01, 0.01, 1.05, 0.03, -0.02, 0.97, 1.04, 0.015, -0.03, 0.98, 0.0,
          0.31, -0.22, -0.006, 0.28, 1.52, -0.013, 1.71, 1.47, -0.008, 1.69, -0.18, -0.011};
}

void expectDerivativesAreCentralDifferences(const FacetPairCoordinates<double>& x, const MortarFacetPairShape& shape,
                                            double referenceArea) {
  const MortarFacetPairDerivatives d = facetPairDerivatives(x, referenceArea, shape);
  ASSERT_TRUE(d.overlaps);
  const MortarFacetPairGaps<double> plain = facetPairGaps(x, referenceArea, shape);
  const double h = 1e-6;
  for (int a = 0; a < shape.slaveNodes; ++a) {
    EXPECT_NEAR(d.weightedGap[a], plain.weightedGap[a], 1e-17);
    double scale = 0, gradientError = 0, hessianScale = 0, hessianError = 0;
    for (int j = 0; j < kM; ++j) {
      auto plus = x, minus = x;
      plus[j] += h;
      minus[j] -= h;
      const double fd =
          (facetPairGaps(plus, referenceArea, shape).weightedGap[a] - facetPairGaps(minus, referenceArea, shape).weightedGap[a]) /
          (2 * h);
      scale = std::max(scale, std::abs(d.gradient[a][j]));
      gradientError = std::max(gradientError, std::abs(fd - d.gradient[a][j]));
      const MortarFacetPairDerivatives dp = facetPairDerivatives(plus, referenceArea, shape),
                                       dm = facetPairDerivatives(minus, referenceArea, shape);
      for (int i = 0; i < kM; ++i) {
        const double fdHessian = (dp.gradient[a][i] - dm.gradient[a][i]) / (2 * h);
        hessianScale = std::max(hessianScale, std::abs(d.hessian[a][i * kM + j]));
        hessianError = std::max(hessianError, std::abs(fdHessian - d.hessian[a][i * kM + j]));
        EXPECT_NEAR(d.hessian[a][i * kM + j], d.hessian[a][j * kM + i], 1e-12) << "a Hessian is symmetric";
      }
    }
    EXPECT_GT(scale, 0.05);  // derivatives that are there (each node's share of the overlap is 0.03 ... 0.3)
    EXPECT_GT(hessianScale, 0.01);
    EXPECT_LT(gradientError, 1e-8 * scale) << "slave node " << a;
    EXPECT_LT(hessianError, 1e-7 * hessianScale) << "slave node " << a;
  }
}

TEST(MortarFacetPair, GradientAndHessianOfQuadOnQuadCutByTheClipAreCentralDifferences) {
  expectDerivativesAreCentralDifferences(unevenPair(), {4, 4}, 1.1);
}

TEST(MortarFacetPair, GradientAndHessianOfTrianglesAreCentralDifferences) {
  // A triangle slave (nodes 0, 1, 2 of the uneven quadrilateral) under the quadrilateral master, and the
  // quadrilateral slave under a triangle master (its nodes 0, 1, 2): the fourth nodes' entries unused.
  FacetPairCoordinates<double> x = unevenPair();
  for (int i = 9; i < 12; ++i) x[i] = 0.0;
  expectDerivativesAreCentralDifferences(x, {3, 4}, 0.55);
  x = unevenPair();
  for (int i = 21; i < 24; ++i) x[i] = 0.0;
  expectDerivativesAreCentralDifferences(x, {4, 3}, 1.0);
}

TEST(MortarFacetPair, ARigidMasterIsDifferentiatedAlongItsMotion) {
  // The master's twelve coordinates (entries 12–23) moving by a translation: the derivatives along it, in
  // entry 12, are the full derivatives contracted with the motion; the slave entries are unchanged and
  // the master's other entries zero (what the interface's ∂r/∂λ reads of a rigid master).
  const FacetPairCoordinates<double> x = unevenPair();
  const MortarFacetPairShape shape{4, 4};
  std::array<double, 12> motion{};
  for (int b = 0; b < 4; ++b) motion[3 * b] = 0.2, motion[3 * b + 1] = -0.1, motion[3 * b + 2] = 0.6;
  const MortarFacetPairDerivatives full = facetPairDerivatives(x, 1.1, shape);
  const MortarFacetPairDerivatives along = facetPairDerivatives(x, 1.1, shape, motion.data());
  ASSERT_TRUE(along.overlaps);
  const auto contract = [&](const auto& h, int i) {  // Σ_k H[i][12 + k] motion_k
    double sum = 0;
    for (int k = 0; k < 12; ++k) sum += h[i * kM + 12 + k] * motion[k];
    return sum;
  };
  for (int a = 0; a < 4; ++a) {
    const auto &g = full.gradient[a], &ga = along.gradient[a];
    const auto &h = full.hessian[a], &ha = along.hessian[a];
    EXPECT_EQ(along.weightedGap[a], full.weightedGap[a]);
    double gradientAlong = 0, curvatureAlong = 0, scale = 0;
    for (int k = 0; k < 12; ++k) {
      gradientAlong += g[12 + k] * motion[k];
      curvatureAlong += contract(h, 12 + k) * motion[k];
    }
    for (double v : h) scale = std::max(scale, std::abs(v));
    EXPECT_GT(std::abs(gradientAlong), 1e-3) << "the motion moves the gap";
    EXPECT_NEAR(ga[12], gradientAlong, 1e-13);
    EXPECT_NEAR(ha[12 * kM + 12], curvatureAlong, 1e-12 * scale);
    for (int k = 13; k < kM; ++k) EXPECT_EQ(ga[k], 0.0);
    for (int i = 0; i < 12; ++i) {
      EXPECT_NEAR(ga[i], g[i], 1e-14);
      EXPECT_NEAR(ha[i * kM + 12], contract(h, i), 1e-12 * scale) << i;
      for (int j = 0; j < 12; ++j) EXPECT_NEAR(ha[i * kM + j], h[i * kM + j], 1e-12 * scale) << i << ", " << j;
    }
  }
}

TEST(MortarFacetPair, AFlatRigidMasterGivesTheDeformableMastersSlaveDerivativesAndAMotionlessOneTheMovingOnes) {
  // A warped slave facet half under a flat master: with the master rigid, the kernel takes its fused
  // Gauss-point path (MortarFacetPair.cpp, addFusedGaussPoint) and, motionless, 12 variables instead of 13.
  // The slave entries are the deformable master's (the generic path) to round-off, a motionless master's
  // are a moving one's to the bit, and a motionless master's own entries are zeros.
  FacetPairCoordinates<double> x = flatPair(0.3, 1.7, -0.2, 1.5, -0.01);
  const double warp[12] = {0.01, 0.02, 0.003, -0.02, 0.01, -0.004, 0.03, -0.01, 0.002, 0.0, 0.02, -0.001};
  for (int i = 0; i < 12; ++i) x[i] += warp[i];
  std::array<double, 12> still{}, motion{};
  for (int b = 0; b < 4; ++b) motion[3 * b] = 0.3, motion[3 * b + 1] = 0.1, motion[3 * b + 2] = -0.5;
  const MortarFacetPairDerivatives full = facetPairDerivatives(x, 0.9);
  const MortarFacetPairDerivatives moving = facetPairDerivatives(x, 0.9, {}, motion.data());
  const MortarFacetPairDerivatives fixed = facetPairDerivatives(x, 0.9, {}, still.data());
  ASSERT_TRUE(full.overlaps && moving.overlaps && fixed.overlaps);
  for (int a = 0; a < 4; ++a) {
    double scale = 0;
    for (double v : full.hessian[a]) scale = std::max(scale, std::abs(v));
    EXPECT_GT(scale, 1e-3);
    EXPECT_EQ(fixed.weightedGap[a], full.weightedGap[a]);
    for (int i = 0; i < 12; ++i) {
      EXPECT_NEAR(fixed.gradient[a][i], full.gradient[a][i], 1e-14) << a << ", " << i;
      EXPECT_EQ(fixed.gradient[a][i], moving.gradient[a][i]) << a << ", " << i;
      for (int j = 0; j < 12; ++j) {
        EXPECT_NEAR(fixed.hessian[a][i * kM + j], full.hessian[a][i * kM + j], 1e-13 * scale) << a << ", " << i << ", " << j;
        EXPECT_EQ(fixed.hessian[a][i * kM + j], moving.hessian[a][i * kM + j]) << a << ", " << i << ", " << j;
      }
    }
    for (int i = 12; i < kM; ++i) {
      EXPECT_EQ(fixed.gradient[a][i], 0.0);
      for (int j = 0; j < kM; ++j) EXPECT_EQ(fixed.hessian[a][i * kM + j], 0.0);
    }
  }
}

/// Every field of two derivative records the same to the bit (zeros' signs aside).
void expectSameRecord(const MortarFacetPairDerivatives& a, const MortarFacetPairDerivatives& b, const char* what) {
  const auto same = [&](const double* x, const double* y, std::size_t n, const char* field) {
    for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(x[i], y[i]) << what << ": " << field << " entry " << i;
  };
  EXPECT_EQ(a.overlaps, b.overlaps) << what;
  same(a.weightedGap.data(), b.weightedGap.data(), 4, "weightedGap");
  same(a.mortarArea.data(), b.mortarArea.data(), 4, "mortarArea");
  for (int k = 0; k < 4; ++k) {
    same(a.gradient[k].data(), b.gradient[k].data(), kM, "gradient");
    same(a.hessian[k].data(), b.hessian[k].data(), kM * kM, "hessian");
    same(a.weightedSlip[k].data(), b.weightedSlip[k].data(), 3, "weightedSlip");
  }
  const auto sameRows = [&](const auto& x, const auto& y, const char* field) {
    ASSERT_EQ(x.size(), y.size()) << what << ": " << field;
    for (std::size_t r = 0; r < x.size(); ++r) same(x[r].data(), y[r].data(), x[r].size(), field);
  };
  sameRows(a.slipGradient, b.slipGradient, "slipGradient");
  sameRows(a.slipHessian, b.slipHessian, "slipHessian");
  sameRows(a.slipVariation, b.slipVariation, "slipVariation");
  sameRows(a.slipVariationGradient, b.slipVariationGradient, "slipVariationGradient");
}

TEST(MortarFacetPair, DerivativesWrittenIntoAKeptRecordAreTheReturnedOnes) {
  // MortarInterface keeps one record per pair and refills it in place: whatever the record held before (a
  // frictional pair's slips, an overlapping pair's entries), the refilled record is the returned one.
  FacetPairCoordinates<double> x = flatPair(0.3, 1.7, -0.2, 1.5, -0.01);
  const double warp[12] = {0.01, 0.02, 0.003, -0.02, 0.01, -0.004, 0.03, -0.01, 0.002, 0.0, 0.02, -0.001};
  for (int i = 0; i < 12; ++i) x[i] += warp[i];
  FacetPairCommitted then = x;
  for (int a = 0; a < 4; ++a) then[3 * a] -= 1e-3;
  std::array<double, 12> still{}, motion{};
  for (int b = 0; b < 4; ++b) motion[3 * b + 2] = 1.0;
  const FacetPairCoordinates<double> apart = flatPair(1.2, 2.0, 0.0, 1.0, -0.01);
  MortarFacetPairDerivatives record;
  facetPairDerivatives(x, 0.9, {}, still.data(), &then, record);
  expectSameRecord(record, facetPairDerivatives(x, 0.9, {}, still.data(), &then), "frictional");
  facetPairDerivatives(x, 0.9, {}, motion.data(), nullptr, record);
  expectSameRecord(record, facetPairDerivatives(x, 0.9, {}, motion.data()), "frictionless after frictional");
  facetPairDerivatives(apart, 0.9, {}, nullptr, nullptr, record);
  const MortarFacetPairDerivatives none = facetPairDerivatives(apart, 0.9);
  EXPECT_FALSE(none.overlaps);
  expectSameRecord(record, none, "apart after overlapping");
  facetPairDerivatives(x, 0.9, {}, nullptr, nullptr, record);
  expectSameRecord(record, facetPairDerivatives(x, 0.9), "deformable master");
}

TEST(MortarFacetPair, TheClipVerticesAreDifferentiatedToo) {
  // Moving a master node sideways moves the clip polygon's edge: the weighted gaps owe it the edge term
  // g N_a ∂(clip)/∂x_m, not zero for a flat parallel pair whose gap is uniform (no other dependence on x_m's
  // in-plane position): d g̃_a / d x_m0 = g ∂(mortar area)/∂x_m0.
  const double gap = -0.01;
  const MortarFacetPairDerivatives d = facetPairDerivatives(flatPair(0.3, 1.7, -0.2, 1.5, gap), 1.0);
  // Moving master nodes 0 and 1 (x = 0.3) by δ along x shrinks the overlap by δ: with one of them moved the
  // edge turns; their sum is the translation's derivative, −∫_edge N_a = −(∫_0^1 N_a(0.3, y) dy).
  for (int a = 0; a < 4; ++a) {
    const double along = d.gradient[a][12] + d.gradient[a][15];
    const double edgeIntegral = (a == 0 || a == 3 ? 0.7 : 0.3) * 0.5;
    EXPECT_NEAR(along, -gap * edgeIntegral, 1e-13) << a;
  }
}

// The interface: a 2 × 2 slave face of unit quadrilaterals on z = 0 (nodes 0–8, row-major in x then y)
// under a deformable master of two quadrilaterals whose common edge x = 0.7 crosses the slave facets
// (nodes 9–14), or under a rigid quadrilateral.
constexpr double kPenalty = 1e3;

ContactInterfaceSpec faceSpec(bool rigidMaster) {
  ContactInterfaceSpec spec;
  spec.name = "face";
  spec.dimension = 3;
  spec.mortar = true;
  spec.slaveNodes = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  spec.slaveFacets = {0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7};
  spec.slaveFacetMeasures = {1.0, 1.0, 1.0, 1.0};
  spec.slaveAreas = {0.25, 0.5, 0.25, 0.5, 1.0, 0.5, 0.25, 0.5, 0.25};
  spec.slaveFacetLengths.assign(9, 1.0);
  spec.law.normalPenalty = kPenalty;
  if (rigidMaster) {
    testing::setMovingRigidPlate(spec, 2.3, 2.2);
  } else {
    // Nodes 9–11 at y = −0.2 (x = −0.1, 0.7, 2.1), 12–14 at y = 2.2: two quadrilaterals, normal down.
    spec.masterFacets = {9, 12, 13, 10, 10, 13, 14, 11};
  }
  return spec;
}

using testing::faceCoordinates;
using testing::unevenFace;

using testing::Assembled;

Assembled assemble(ContactInterfaceBase& interface, const std::vector<double>& x, double lambda) {
  return testing::assemble<3>(interface, x, lambda);
}

std::unique_ptr<ContactInterfaceBase> faceInterface(bool rigidMaster) {
  return makeMortarInterface(faceSpec(rigidMaster), std::vector<char>(9, 1));
}

TEST(MortarInterface3D, NonMatchingFlatPenetrationGivesTheSamePressureAtEverySlaveNode) {
  const double d = 1e-3;
  auto interface = faceInterface(false);
  const Assembled a = assemble(*interface, faceCoordinates(d), 0.0);
  for (const auto& s : a.states) EXPECT_NEAR(s.pressure, kPenalty * d, 1e-12 * kPenalty * d);
  double slaveForce = 0, masterForce = 0;
  for (int node = 0; node < 15; ++node) (node < 9 ? slaveForce : masterForce) -= a.residual[3 * node + 2];
  EXPECT_NEAR(slaveForce, -kPenalty * d * 4.0, 1e-12);  // pressure × slave area 4, pushing the slave down
  EXPECT_NEAR(masterForce, kPenalty * d * 4.0, 1e-12);
  EXPECT_NEAR(interface->committedSlaveForce()[2], -kPenalty * d * 4.0, 1e-12);
  // Frictionless: every node closed and active, none counted as sticking or slipping (issue 25, point 4).
  EXPECT_EQ(a.counts.active, 9);
  EXPECT_EQ(a.counts.stick, 0);
  EXPECT_EQ(a.counts.slip, 0);
}

double tangentError(bool rigidMaster, double* scale) {
  const auto x = unevenFace();
  const Assembled a = assemble(*faceInterface(rigidMaster), x, 0.3);
  for (const auto& s : a.states) EXPECT_NE(s.status, ContactStatus::Open) << "the test wants every node closed";
  const auto residualAt = [&](const std::vector<double>& y) {
    return assemble(*faceInterface(rigidMaster), y, 0.3).residual;
  };
  return testing::tangentCentralDifferenceError(a.tangent, x, residualAt, scale);
}

TEST(MortarInterface3D, TangentIsTheCentralDifferenceOfTheResidualWithADeformableMaster) {
  double scale = 0;
  const double error = tangentError(false, &scale);
  EXPECT_GT(scale, 100.0);
  EXPECT_LT(error, 1e-6 * scale);
}

TEST(MortarInterface3D, TangentAndLoadDerivativeAreCentralDifferencesWithAMovingRigidMaster) {
  double scale = 0;
  const double error = tangentError(true, &scale);
  EXPECT_GT(scale, 100.0);
  EXPECT_LT(error, 1e-6 * scale);
  const auto x = unevenFace();
  const double lambda = 0.3;
  const Assembled a = assemble(*faceInterface(true), x, lambda);
  double dScale = 0;
  const double dError = testing::loadDerivativeCentralDifferenceError(
      a.dLambda, lambda, [&](double mu) { return assemble(*faceInterface(true), x, mu).residual; }, &dScale);
  EXPECT_GT(dScale, 1.0);
  EXPECT_LT(dError, 1e-6 * dScale);
}

TEST(MortarInterface3D, TheSlaveNeighboursAreThoseOfTheNodesFacets) {
  const ContactInterfaceSpec spec = faceSpec(false);
  EXPECT_EQ(mortarSlaveNeighbours(spec, 4), (std::vector<std::size_t>{4, 0, 1, 2, 3, 5, 6, 7, 8}));
  EXPECT_EQ(mortarSlaveNeighbours(spec, 0), (std::vector<std::size_t>{0, 1, 3, 4}));
}

}  // namespace
}  // namespace contessa::contact
