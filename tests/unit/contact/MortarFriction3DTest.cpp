// 3D mortar Coulomb friction (theory-contact.md §13, eq. M9′–M12′): the facet pair's weighted slip
// increments against their closed form and their exact first and second derivatives against central
// differences (Quad4 and Tri3 on both sides, a non-matching pair cut by the clip), and the interface's
// residual, tangent and ∂r/∂λ against central differences of its residual in stick and in slip, from a
// fresh and from a stuck committed state, on a deformable and on a rigid master, on quadrilateral and on
// triangle slave faces; the patch's stick and sliding forces against ε_T u A and μ N.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "contact/MortarFacetPair.hpp"
#include "contact/MortarInterface.hpp"
#include "contact/MortarSlipBasis.hpp"
#include "MortarTestTools.hpp"

namespace contessa::contact {
namespace {

constexpr int kM = kMortarFacetPairCoordinates;

// A warped slave quadrilateral under a warped, tilted master covering part of it (MortarFacetPairTest's
// uneven pair), and committed positions a little away from it: every node moved by a different amount.
FacetPairCoordinates<double> unevenPair() {
  return {0.02, -0.01, 0.01, 1.05, 0.03, -0.02, 0.97, 1.04, 0.015, -0.03, 0.98, 0.0,
          0.31, -0.22, -0.006, 0.28, 1.52, -0.013, 1.71, 1.47, -0.008, 1.69, -0.18, -0.011};
}
FacetPairCommitted committedOf(const FacetPairCoordinates<double>& x) {
  FacetPairCommitted then{};
  for (int i = 0; i < kM; ++i) then[i] = x[i] - 0.02 * std::cos(0.9 * i + 0.3) - (i % 3 == 0 ? 0.015 : 0.0);
  return then;
}

double slipOf(const MortarFacetPairGaps<double>& g, int a, int c) { return g.weightedSlip[a][c]; }

void expectSlipDerivativesAreCentralDifferences(FacetPairCoordinates<double> x, const MortarFacetPairShape& shape,
                                                double referenceArea) {
  // A triangle's fourth node's entries are unused: zero, as the interface passes them.
  if (shape.slaveNodes == 3) std::fill(&x[9], &x[12], 0.0);
  if (shape.masterNodes == 3) std::fill(&x[21], &x[24], 0.0);
  FacetPairCommitted then = committedOf(x);
  if (shape.slaveNodes == 3) std::fill(&then[9], &then[12], 0.0);
  if (shape.masterNodes == 3) std::fill(&then[21], &then[24], 0.0);
  const MortarFacetPairDerivatives d = facetPairDerivatives(x, referenceArea, shape, nullptr, &then);
  ASSERT_TRUE(d.overlaps);
  ASSERT_EQ(d.slipGradient.size(), 12u);
  const MortarFacetPairGaps<double> plain = facetPairGaps(x, referenceArea, shape, &then);
  const MortarFacetPairDerivatives withoutSlip = facetPairDerivatives(x, referenceArea, shape);
  const double h = 1e-6;
  for (int a = 0; a < shape.slaveNodes; ++a) {
    EXPECT_EQ(d.weightedGap[a], withoutSlip.weightedGap[a]) << "the slip leaves the gap alone";
    EXPECT_EQ(d.gradient[a], withoutSlip.gradient[a]);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(d.weightedSlip[a][c], slipOf(plain, a, c), 1e-16) << "values and derivatives agree";
      double scale = 0, gradientError = 0, hessianScale = 0, hessianError = 0;
      for (int j = 0; j < kM; ++j) {
        auto plus = x, minus = x;
        plus[j] += h;
        minus[j] -= h;
        const double fd = (slipOf(facetPairGaps(plus, referenceArea, shape, &then), a, c) -
                           slipOf(facetPairGaps(minus, referenceArea, shape, &then), a, c)) / (2 * h);
        scale = std::max(scale, std::abs(d.slipGradient[3 * a + c][j]));
        gradientError = std::max(gradientError, std::abs(fd - d.slipGradient[3 * a + c][j]));
        const MortarFacetPairDerivatives dp = facetPairDerivatives(plus, referenceArea, shape, nullptr, &then),
                                         dm = facetPairDerivatives(minus, referenceArea, shape, nullptr, &then);
        for (int i = 0; i < kM; ++i) {
          const double fdHessian = (dp.slipGradient[3 * a + c][i] - dm.slipGradient[3 * a + c][i]) / (2 * h);
          const double exact = d.slipHessian[3 * a + c][i * kM + j];
          hessianScale = std::max(hessianScale, std::abs(exact));
          hessianError = std::max(hessianError, std::abs(fdHessian - exact));
          EXPECT_NEAR(exact, d.slipHessian[3 * a + c][j * kM + i], 1e-12) << "a Hessian is symmetric";
        }
      }
      // Slip derivatives that are there: along the slave plane of the order of the mortar areas; across it
      // (c = 2) only through the master's tilt.
      EXPECT_GT(scale, c < 2 ? 0.01 : 1e-4);
      EXPECT_GT(hessianScale, c < 2 ? 1e-3 : 1e-5);
      EXPECT_LT(gradientError, 1e-8 * scale) << "slave node " << a << ", component " << c;
      EXPECT_LT(hessianError, 1e-7 * hessianScale) << "slave node " << a << ", component " << c;
    }
  }
}

TEST(MortarFacetPairSlip, QuadOnQuadSlipIncrementsAreDifferentiatedTwiceExactly) {
  expectSlipDerivativesAreCentralDifferences(unevenPair(), {4, 4}, 1.1);
}

TEST(MortarFacetPairSlip, TriangleSlipIncrementsAreDifferentiatedTwiceExactly) {
  expectSlipDerivativesAreCentralDifferences(unevenPair(), {3, 4}, 0.55);
  expectSlipDerivativesAreCentralDifferences(unevenPair(), {4, 3}, 1.0);
  expectSlipDerivativesAreCentralDifferences(unevenPair(), {3, 3}, 0.55);
}

TEST(MortarFacetPairSlip, ARigidSlideGivesTheTangentialSlipTimesTheMortarAreasAndNoNormalPart) {
  // The unit square slave on z = 0 under a master rectangle [0.3, 1.7] × [−0.2, 1.5] at z = −0.01, the slave
  // slid from its committed place by (0.04, −0.03, 0.005): the slip is the tangential part (0.04, −0.03, 0)
  // times each node's mortar area (the normal part 0.005 is the gap's change, not slip).
  const double z = -0.01;
  const FacetPairCoordinates<double> x = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                          0.3, -0.2, z, 0.3, 1.5, z, 1.7, 1.5, z, 1.7, -0.2, z};
  FacetPairCommitted then = x;
  const std::array<double, 3> slide{0.04, -0.03, 0.005};
  for (int a = 0; a < 4; ++a)
    for (int c = 0; c < 3; ++c) then[3 * a + c] -= slide[c];
  const MortarFacetPairGaps<double> g = facetPairGaps(x, 1.0, {4, 4}, &then);
  ASSERT_TRUE(g.overlaps);
  for (int a = 0; a < 4; ++a) {
    EXPECT_GT(g.mortarArea[a], 0.05);
    for (int c = 0; c < 2; ++c) EXPECT_NEAR(g.weightedSlip[a][c], slide[c] * g.mortarArea[a], 1e-15) << a << c;
    EXPECT_NEAR(g.weightedSlip[a][2], 0.0, 1e-16);
  }
  // Without committed positions, no slip.
  const MortarFacetPairGaps<double> frictionless = facetPairGaps(x, 1.0, {4, 4});
  for (int a = 0; a < 4; ++a) EXPECT_EQ(frictionless.weightedSlip[a][0], 0.0);
}

TEST(MortarSlipBasis, TheBasisIsOrthonormalAndRightHandedAndTheTransportKeepsTheVector) {
  const Vector<3> n = scaled(1.0 / std::sqrt(1.0 + 0.04 + 0.09), Vector<3>{0.2, -0.3, 1.0});
  const auto e = tangentBasis(n);
  EXPECT_NEAR(dot(e[0], e[0]), 1.0, 1e-15);
  EXPECT_NEAR(dot(e[1], e[1]), 1.0, 1e-15);
  EXPECT_NEAR(dot(e[0], e[1]), 0.0, 1e-15);
  const Vector<3> third = cross(e[0], e[1]);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(third[c], n[c], 1e-15);
  // A traction in the basis of n carried into the basis of z: its in-plane part kept (n's tilt removed).
  const auto z = tangentBasis({0.0, 0.0, 1.0});
  const Vector<2> t{0.3, -0.7};
  const Vector<2> carried = transportTraction(t, e, z);
  Vector<3> before{}, after{};
  for (int a = 0; a < 2; ++a) {
    addScaled(before, t[a], e[a]);
    addScaled(after, carried[a], z[a]);
  }
  EXPECT_NEAR(after[0], before[0], 1e-15);
  EXPECT_NEAR(after[1], before[1], 1e-15);
}

// The interface: a 2 × 2 slave face of unit squares on z = 0 (nodes 0–8, row-major), as quadrilaterals or
// each cut into two triangles, under a deformable master of two quadrilaterals whose common edge x = 0.7
// crosses the slave facets (nodes 9–14, a non-matching pair), or under a rigid quadrilateral moving by
// (0.1, −0.05, −0.02) per unit load factor. μ = 0.3, ε_N = ε_T = 10³.
constexpr double kPenalty = 1e3;
constexpr double kFriction = 0.3;

ContactInterfaceSpec faceSpec(bool rigidMaster, bool triangles) {
  ContactInterfaceSpec spec;
  spec.name = "face";
  spec.dimension = 3;
  spec.mortar = true;
  spec.slaveNodes = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  if (triangles) {
    spec.slaveFacets = {0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4, 3, 4, 7, 3, 7, 6, 4, 5, 8, 4, 8, 7};
    spec.slaveFacetMeasures.assign(8, 0.5);
  } else {
    spec.slaveFacets = {0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7};
    spec.slaveFacetMeasures.assign(4, 1.0);
  }
  // Each node's tributary area: a third of its triangles' (a quarter of its quadrilaterals').
  const double t = 1.0 / 6.0;
  spec.slaveAreas = triangles ? std::vector<double>{2 * t, 3 * t, t, 3 * t, 6 * t, 3 * t, t, 3 * t, 2 * t}
                              : std::vector<double>{0.25, 0.5, 0.25, 0.5, 1.0, 0.5, 0.25, 0.5, 0.25};
  spec.slaveFacetLengths.assign(9, 1.0);
  spec.slaveFacetNodes = triangles ? 3 : 4;
  spec.law.normalPenalty = kPenalty;
  spec.law.frictionCoefficient = kFriction;
  spec.law.tangentialPenalty = kPenalty;
  if (rigidMaster)
    testing::setMovingRigidPlate(spec, 2.3, 2.2);
  else
    spec.masterFacets = {9, 12, 13, 10, 10, 13, 14, 11};
  return spec;
}

struct Face {
  bool rigidMaster = false;
  bool triangles = false;
  /// Enforcement = Augmented Lagrangian (theory-contact §13.4): the trials start from multipliers an update
  /// has set (committedInterface).
  bool augmented = false;
  std::unique_ptr<ContactInterfaceBase> make() const {
    ContactInterfaceSpec spec = faceSpec(rigidMaster, triangles);
    if (augmented) {
      spec.law.enforcement = ContactLawParameters::Enforcement::AugmentedLagrangian;
      spec.law.penetrationTolerance = spec.law.elasticSlipTolerance = 1e-6;
      spec.law.maxAugmentations = 10;
    }
    return makeMortarInterface(spec, std::vector<char>(9, 1));
  }
};

using testing::faceCoordinates;
using testing::unevenFace;

// The uneven face with its slave nodes slid by `slide` along (1, 0.6) (a little more for higher nodes) and
// the master by −0.2 slide along x.
std::vector<double> slid(double slide) {
  auto x = unevenFace();
  for (int node = 0; node < 9; ++node) {
    x[3 * node] += slide * (1.0 + 0.05 * node);
    x[3 * node + 1] += 0.6 * slide;
  }
  for (int node = 9; node < 15; ++node) x[3 * node] -= 0.2 * slide;
  return x;
}

using testing::Assembled;

// The interface committed at the uneven face at λ = 0.3 and, when `stuck` > 0, at the face slid by `stuck`
// (a stick state with a nonzero committed traction): where every trial of a central difference starts.
// With the augmented Lagrangian, then updated (eq. 15.3) at the face slid by `update` and 0.003
// shallower: multipliers λ_N,k, λ_Tα,k that are neither 0 nor the trial's tractions.
std::unique_ptr<ContactInterfaceBase> committedInterface(const Face& face, double stuck, double update = 0.0) {
  auto interface = face.make();
  testing::assemble<3>(*interface, unevenFace(), 0.3);
  if (stuck > 0.0) testing::assemble<3>(*interface, slid(stuck), 0.3 + 0.5 * stuck);
  if (face.augmented) {
    auto x = slid(update);
    for (int node = 9; node < 15; ++node) x[3 * node + 2] += 0.003;
    testing::evaluateOnly<3>(*interface, x, 0.3 + 0.5 * update);
    interface->augment(true);
  }
  return interface;
}

void expectFrictionalTangentIsTheCentralDifference(const Face& face, double slide, ContactStatus expected,
                                                   double stuck = 0.0) {
  SCOPED_TRACE(std::string(face.rigidMaster ? "rigid" : "deformable") + (face.triangles ? ", Tri3" : ", Quad4") +
               (face.augmented ? ", augmented" : "") + ", slide " + std::to_string(slide) + ", stuck " +
               std::to_string(stuck));
  const auto x = slid(slide);
  const double lambda = 0.3 + 0.5 * slide;
  const auto committed = committedInterface(face, stuck, 0.5 * slide);
  const Assembled a = testing::assemble<3>(*committed->clone(), x, lambda);
  for (const auto& s : a.states) EXPECT_EQ(s.status, expected);
  double frictionScale = 0;
  for (int node = 0; node < 9; ++node)
    frictionScale = std::max({frictionScale, std::abs(a.residual[3 * node]), std::abs(a.residual[3 * node + 1])});
  EXPECT_GT(frictionScale, 1e-3) << "a tangential force";
  // Columns: every component of a slave corner (0), the slave's centre (4, on all four facets) and a master
  // corner (9), and one component drawn (seeded) for each other node: 21 of the 45 columns, each a pair of
  // trial evaluations.
  std::mt19937 draw(20261128u + static_cast<unsigned>(1000 * slide + 10 * stuck + 2 * face.rigidMaster + face.triangles));
  std::vector<int> columns = testing::nodeColumns<3>({0, 4, 9});
  for (int node = 0; node < 15; ++node)
    if (node != 0 && node != 4 && node != 9) columns.push_back(3 * node + static_cast<int>(draw() % 3));
  double scale = 0;
  const double error = testing::tangentColumnsCentralDifferenceError(
      a.tangent, x, [&](const std::vector<double>& y) { return testing::trialResidual<3>(*committed, y, lambda); },
      columns, &scale);
  EXPECT_GT(scale, 100.0);
  EXPECT_LT(error, 1e-6 * scale);
  if (face.rigidMaster) {
    double dScale = 0;
    const double dError = testing::loadDerivativeCentralDifferenceError(
        a.dLambda, lambda, [&](double mu) { return testing::trialResidual<3>(*committed, x, mu); }, &dScale);
    EXPECT_GT(dScale, 1.0);
    EXPECT_LT(dError, 1e-6 * dScale);
  }
}

TEST(MortarInterface3DFriction, TangentInStickIsTheCentralDifferenceOfTheResidual) {
  for (const bool rigid : {false, true})
    for (const bool triangles : {false, true})
      expectFrictionalTangentIsTheCentralDifference({rigid, triangles}, 1e-3, ContactStatus::Stick);
}

TEST(MortarInterface3DFriction, TangentInSlipIsTheCentralDifferenceOfTheResidual) {
  for (const bool rigid : {false, true})
    for (const bool triangles : {false, true})
      expectFrictionalTangentIsTheCentralDifference({rigid, triangles}, 0.05, ContactStatus::Slip);
}

TEST(MortarInterface3DFriction, TangentWithAugmentedLagrangianMultipliersIsTheCentralDifferenceOfTheResidual) {
  // eq. M22–M23: the multipliers are constants of the Newton iterations, so the tangent is the penalty's with
  // t_N = λ_N + ε_N g̃/A and the return mapping started from λ_T.
  for (const bool rigid : {false, true}) {
    expectFrictionalTangentIsTheCentralDifference({rigid, false, true}, 1e-3, ContactStatus::Stick);
    expectFrictionalTangentIsTheCentralDifference({rigid, true, true}, 0.05, ContactStatus::Slip);
    expectFrictionalTangentIsTheCentralDifference({rigid, false, true}, 2e-3, ContactStatus::Stick, 1e-3);
  }
}

TEST(MortarInterface3DFriction, TangentFromAStuckStateIsTheCentralDifferenceOfTheResidual) {
  // Committed in stick with a nonzero traction (slid by 1e-3), then a trial in stick and one in slip.
  for (const bool rigid : {false, true}) {
    expectFrictionalTangentIsTheCentralDifference({rigid, false}, 2e-3, ContactStatus::Stick, 1e-3);
    expectFrictionalTangentIsTheCentralDifference({rigid, true}, 0.05, ContactStatus::Slip, 1e-3);
  }
}

// A flat face pressed by d into the fixed deformable master and slid by u along (cos θ, sin θ): the
// patch's tangential force against the motion, ε_T u A in stick, μ ε_N d A in slip (A = 4), and every node
// stuck or slipping as Contact Beta counts them.
void expectPatchForces(bool triangles, double u, ContactStatus expected) {
  const double d = 1e-3, theta = 0.6;
  auto interface = Face{false, triangles}.make();
  testing::assemble<3>(*interface, faceCoordinates(d), 0.0);
  auto x = faceCoordinates(d);
  for (int node = 0; node < 9; ++node) {
    x[3 * node] += u * std::cos(theta);
    x[3 * node + 1] += u * std::sin(theta);
  }
  const Assembled a = testing::assemble<3>(*interface, x, 0.0);
  for (const auto& s : a.states) EXPECT_EQ(s.status, expected);
  EXPECT_EQ(a.counts.active, 9);
  EXPECT_EQ(a.counts.stick, expected == ContactStatus::Stick ? 9 : 0);
  EXPECT_EQ(a.counts.slip, expected == ContactStatus::Slip ? 9 : 0);
  const auto& force = interface->committedSlaveForce();
  const double normal = kPenalty * d * 4.0;
  const double tangential = expected == ContactStatus::Stick ? kPenalty * u * 4.0 : kFriction * normal;
  EXPECT_NEAR(force[2], -normal, 1e-12 * normal);
  EXPECT_NEAR(force[0], -tangential * std::cos(theta), 1e-12 * normal);
  EXPECT_NEAR(force[1], -tangential * std::sin(theta), 1e-12 * normal);
}

TEST(MortarInterface3DFriction, AStuckPatchCarriesTheStickSpringsForce) {
  expectPatchForces(false, 2e-5, ContactStatus::Stick);
  expectPatchForces(true, 2e-5, ContactStatus::Stick);
}

TEST(MortarInterface3DFriction, ASlidingPatchCarriesCoulombsForceAgainstTheSlip) {
  expectPatchForces(false, 0.05, ContactStatus::Slip);
  expectPatchForces(true, 0.05, ContactStatus::Slip);
}

TEST(MortarInterface3DFriction, TheCommittedTractionSurvivesACommitThatTurnsTheBasis) {
  // Stuck by a slide along x, committed, then the whole configuration turned about the x axis by 0.2 rad:
  // the nodes' bases turn with the face and the committed traction is carried into them. The turn moves
  // the slave and master points a gap apart by (R − I) n g, a slip across the axis (in the turned y–z
  // plane), none along it: the force along x is what it was.
  auto interface = Face{false, false}.make();
  const double d = 1e-3, u = 2e-5;
  testing::assemble<3>(*interface, faceCoordinates(d), 0.0);
  auto x = faceCoordinates(d);
  for (int node = 0; node < 9; ++node) x[3 * node] += u;
  testing::assemble<3>(*interface, x, 0.0);
  const double before = interface->committedSlaveForce()[0];
  EXPECT_NEAR(before, -kPenalty * u * 4.0, 1e-12);
  const double c = std::cos(0.2), s = std::sin(0.2);
  auto turned = x;
  for (std::size_t node = 0; node < 15; ++node) {
    turned[3 * node + 1] = c * x[3 * node + 1] - s * x[3 * node + 2];
    turned[3 * node + 2] = s * x[3 * node + 1] + c * x[3 * node + 2];
  }
  const Assembled a = testing::assemble<3>(*interface, turned, 0.0);
  for (const auto& st : a.states) EXPECT_EQ(st.status, ContactStatus::Stick);
  EXPECT_NEAR(interface->committedSlaveForce()[0], before, 1e-9 * std::abs(before));
}

TEST(MortarInterface3DFriction, ASecondCommitWithoutAnEvaluationChangesNothing) {
  // The continuation commits its initial state twice (IncrementBookkeeper: the step's end and the first
  // saved solution). The first commit carries the traction into the turned basis; the second, with no
  // evaluation between, must find the trial traction in that basis too, or the committed traction turns
  // by the basis' change (here 0.2 rad) and the residual at the committed state is no longer the converged
  // one (issue 25: on the block-on-base deck the diagonal nodes' bases turned by 90° at the second commit,
  // by round-off that differs with the rank count, so 1 and 2 ranks parted).
  const double d = 1e-3, u = 2e-5, c = std::cos(0.2), s = std::sin(0.2);
  auto x = faceCoordinates(d);
  for (int node = 0; node < 9; ++node) x[3 * node] += u;
  auto turned = x;
  for (std::size_t node = 0; node < 15; ++node) {
    turned[3 * node + 1] = c * x[3 * node + 1] - s * x[3 * node + 2];
    turned[3 * node + 2] = s * x[3 * node + 1] + c * x[3 * node + 2];
  }
  std::vector<double> residual[2];
  for (int commits = 1; commits <= 2; ++commits) {
    auto interface = Face{false, false}.make();
    testing::assemble<3>(*interface, faceCoordinates(d), 0.0);
    testing::assemble<3>(*interface, x, 0.0);
    testing::assemble<3>(*interface, turned, 0.0);
    if (commits == 2) interface->commit();
    residual[commits - 1] = testing::evaluateOnly<3>(*interface, turned, 0.0).residual;
  }
  double scale = 0;
  for (double r : residual[0]) scale = std::max(scale, std::abs(r));
  EXPECT_GT(scale, 1e-3) << "a tangential force";
  for (std::size_t i = 0; i < residual[0].size(); ++i) EXPECT_NEAR(residual[1][i], residual[0][i], 1e-13 * scale) << i;
}

}  // namespace
}  // namespace contessa::contact
