// 3D mortar Coulomb friction under a master that nothing but the contact holds along the slip (a body on soft
// springs; tests/regression/audit/mortar_friction_floating_master.xml, docs/verification-contact.md §9.5): a
// slipping node has no stiffness along its slip (eq. 27), so Newton's step carries it across its stick range
// into slip the other way and the next one back. Once its slip reverses at three iterates in a row (the cycle;
// one or two are also an overshoot and its correction, left to Newton) the node's tangent takes the secant of its
// traction between the two iterates along the slip (SlipReversalDamping): checked here as the secant itself
// (K Δx = Δr between the two iterates), the residual unchanged, the same iterate evaluated twice unchanged,
// the consistent tangents of the Jacobian check (the secant counted, not applied), and, after a single
// reversal or none, the tangent still the central difference of the residual.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <memory>
#include <cmath>
#include <vector>

#include "contact/MortarInterface.hpp"
#include "MortarTestTools.hpp"

namespace contessa::contact {
namespace {

constexpr double kPenalty = 1e3;
constexpr double kFriction = 0.3;
constexpr double kPressed = 1e-3;  // the master's penetration: pressure ε_N d = 1, stick limit μ p = 0.3

// One unit-square slave facet on z = 0 (nodes 0–3, its normal +z) under one master square of side 1.4 at
// z = −d (nodes 4–7, its normal −z) that covers it whatever the slides below: the weighted slip of each
// slave node is the master's slide times its mortar area 1/4.
ContactInterfaceSpec squareSpec() {
  ContactInterfaceSpec spec;
  spec.name = "floating";
  spec.dimension = 3;
  spec.mortar = true;
  spec.slaveNodes = {0, 1, 2, 3};
  spec.slaveFacets = {0, 1, 2, 3};
  spec.slaveFacetMeasures = {1.0};
  spec.slaveAreas.assign(4, 0.25);
  spec.slaveFacetLengths.assign(4, 1.0);
  spec.slaveFacetNodes = 4;
  spec.masterFacets = {4, 5, 6, 7};
  spec.law.normalPenalty = kPenalty;
  spec.law.frictionCoefficient = kFriction;
  spec.law.tangentialPenalty = kPenalty;
  return spec;
}

// The pair with the master slid by (u, v) from its pressed place.
std::vector<double> slidMaster(double u, double v) {
  std::vector<double> x = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  for (const auto& corner : {std::array<double, 2>{-0.2, -0.2}, {-0.2, 1.2}, {1.2, 1.2}, {1.2, -0.2}})
    x.insert(x.end(), {corner[0] + u, corner[1] + v, -kPressed});
  return x;
}

std::unique_ptr<ContactInterfaceBase> pressed() {
  auto interface = makeMortarInterface(squareSpec(), std::vector<char>(4, 1));
  testing::assemble<3>(*interface, slidMaster(0, 0), 0.0);  // stuck, no traction: the increment's start
  return interface;
}

// The residual of a Newton iterate at x from the pressed state (it depends on the committed state only).
std::vector<double> residualAt(const std::vector<double>& x) {
  auto interface = pressed();
  return testing::evaluateOnly<3>(*interface, x, 0.0).residual;
}

double largest(const std::vector<double>& v) {
  double m = 0;
  for (double e : v) m = std::max(m, std::abs(e));
  return m;
}

// The master slid by s along (cos θ, sin θ): every node slipping along ±(cos θ, sin θ) for |s| ε_T > μ p.
std::vector<double> slidAlong(double s) {
  const double theta = 0.6;
  return slidMaster(s * std::cos(theta), s * std::sin(theta));
}

// The tangent at x is the central difference of the residual (1e-6 of its largest entry): no secant in it.
void expectConsistent(const std::vector<double>& tangent, const std::vector<double>& x) {
  double scale = 0;
  const double error = testing::tangentCentralDifferenceError(tangent, x, residualAt, &scale);
  EXPECT_GT(scale, 50.0);
  EXPECT_LT(error, 1e-6 * scale);
}

// The Newton iterates `earlier` from the pressed state, then x: x's tangent, which has no secant node.
std::vector<double> tangentAfter(const std::vector<std::vector<double>>& earlier, const std::vector<double>& x) {
  auto interface = pressed();
  for (const auto& e : earlier) testing::evaluateOnly<3>(*interface, e, 0.0);
  std::vector<double> tangent = testing::evaluateOnly<3>(*interface, x, 0.0).tangent;
  EXPECT_EQ(interface->secantTangentNodes(), 0);
  return tangent;
}

TEST(MortarFrictionFloatingMaster, ARepeatedReversalTakesTheSecantOfItsTractionAndKeepsItsResidual) {
  // Iterates A, B, A, B: the master slid by +u, −u, +u, −u along (cos θ, sin θ), every node slipping
  // (ε_T u = 5 > μ p = 0.3), so that the slip reverses at the second iterate (an overshoot?), at the third
  // (corrected?) and at the fourth: the cycle, whose secant starts there (kRepeatedReversal = 3 in a row).
  // Between A and B the nodes' tractions go from +μp to −μp along the slip while the gaps stay: the secant tangent maps
  // x_B − x_A onto r_B − r_A exactly, where the consistent one has no stiffness along the slip and maps it
  // onto the normal part only (0 here).
  const double u = 5e-3;
  const auto xA = slidAlong(u);
  const auto xB = slidAlong(-u);
  auto interface = pressed();
  testing::evaluateOnly<3>(*interface, xA, 0.0);
  testing::evaluateOnly<3>(*interface, xB, 0.0);
  EXPECT_EQ(interface->secantTangentNodes(), 0) << "a single reversal is left to Newton";
  const testing::Assembled a = testing::evaluateOnly<3>(*interface, xA, 0.0);
  EXPECT_EQ(interface->secantTangentNodes(), 0) << "an overshoot and its correction are left to Newton";
  const testing::Assembled b = testing::evaluateOnly<3>(*interface, xB, 0.0);
  EXPECT_EQ(interface->secantTangentNodes(), 4) << "the third in a row: every node's secant";
  for (const auto& state : {a, b}) EXPECT_GT(largest(state.residual), 0.05) << "a tangential force";
  // The trial states as the history reports them after a commit of the same iterate (a separate interface).
  {
    auto check = pressed();
    const testing::Assembled committed = testing::assemble<3>(*check, xB, 0.0);
    for (const auto& s : committed.states) EXPECT_EQ(s.status, ContactStatus::Slip);
  }
  // The residual is the undamped one, bit for bit.
  const std::vector<double> fresh = residualAt(xB);
  for (std::size_t i = 0; i < fresh.size(); ++i) EXPECT_EQ(b.residual[i], fresh[i]) << i;
  // The secant: K_B (x_B − x_A) = r_B − r_A in the slave nodes' rows, and in the sum of the master nodes'
  // rows (the force on the master). Each master node's row alone also carries t (δũ_B − δũ_A), the change of
  // the master's shape functions at the slave's points as it slides (M_l, bilinear in the shift), which the
  // tangent at B has to first order only.
  const int n = static_cast<int>(xA.size());
  const double scale = largest(b.residual);
  std::vector<double> kDx(n, 0.0);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) kDx[i] += b.tangent[i * n + j] * (xB[j] - xA[j]);
  for (int i = 0; i < 12; ++i) EXPECT_NEAR(kDx[i], b.residual[i] - a.residual[i], 1e-10 * scale) << "slave row " << i;
  for (int c = 0; c < 3; ++c) {
    double k = 0, dr = 0;
    for (int node = 4; node < 8; ++node) {
      k += kDx[3 * node + c];
      dr += b.residual[3 * node + c] - a.residual[3 * node + c];
    }
    EXPECT_NEAR(k, dr, 1e-10 * scale) << "the force on the master, component " << c;
  }
  EXPECT_GT(std::abs(b.residual[0] - a.residual[0]), 0.05 * scale) << "the traction reversed";
  // The same iterate evaluated again (the Jacobian after the residual) changes nothing.
  const testing::Assembled again = testing::evaluateOnly<3>(*interface, xB, 0.0);
  EXPECT_EQ(again.tangent, b.tangent);
  EXPECT_EQ(again.residual, b.residual);
  // With consistent tangents (the Jacobian check's W) the same iterate has the central difference of the
  // residual as its tangent, and the secant nodes are still counted.
  {
    auto consistent = interface->clone();
    consistent->setConsistentTangents(true);
    const testing::Assembled c = testing::evaluateOnly<3>(*consistent, xB, 0.0);
    EXPECT_EQ(consistent->secantTangentNodes(), 4);
    EXPECT_EQ(c.residual, b.residual);
    expectConsistent(c.tangent, xB);
    double scale = 0;
    EXPECT_GT(testing::tangentCentralDifferenceError(b.tangent, xB, residualAt, &scale), 1e-3 * scale)
        << "the secant is no derivative of the residual";
  }
  // A commit ends the cycle's memory: the next increment's first iterate has the consistent tangent.
  interface->commit();
  auto restarted = makeMortarInterface(squareSpec(), std::vector<char>(4, 1));
  testing::assemble<3>(*restarted, slidMaster(0, 0), 0.0);
  testing::evaluateOnly<3>(*restarted, xB, 0.0);
  restarted->commit();
  const auto xC = slidMaster(0.5 * u, 0.0);
  EXPECT_EQ(testing::evaluateOnly<3>(*interface, xC, 0.0).tangent, testing::evaluateOnly<3>(*restarted, xC, 0.0).tangent);
}

TEST(MortarFrictionFloatingMaster, ASingleReversalKeepsTheConsistentTangent) {
  // One reversal (an overshoot, which the next iterate corrects): the consistent tangent, the central
  // difference of the residual, where node-to-segment would take the secant.
  const auto x = slidAlong(-4e-3);
  for (const auto& s : testing::assemble<3>(*pressed(), x, 0.0).states) EXPECT_EQ(s.status, ContactStatus::Slip);
  expectConsistent(tangentAfter({slidAlong(5e-3)}, x), x);
}

TEST(MortarFrictionFloatingMaster, WithoutAReversalTheTangentIsTheCentralDifferenceOfTheResidual) {
  // Two slipping iterates the same way, then a third: no reversal, the consistent tangent (central
  // differences of the residual, 1e-6 of its largest entry), as at an increment's first iterate.
  const auto x = slidMaster(5e-3, 3e-3);
  expectConsistent(tangentAfter({slidMaster(4e-3, 1e-3), slidMaster(6e-3, 2e-3)}, x), x);
}

TEST(MortarFrictionFloatingMaster, AReversalIntoStickKeepsTheStickTangent) {
  // A reversal across a narrow range (the two iterates 2e-4 apart, ε_T × 1e-4 = 0.1 < μ p: the second
  // sticks) is no slip cycle: a sticking node keeps its consistent stick tangent, the central difference.
  const auto x = slidMaster(-1e-4, 0);
  for (const auto& s : testing::assemble<3>(*pressed(), x, 0.0).states) EXPECT_EQ(s.status, ContactStatus::Stick);
  expectConsistent(tangentAfter({slidMaster(5e-3, 0)}, x), x);
}

}  // namespace
}  // namespace contessa::contact
