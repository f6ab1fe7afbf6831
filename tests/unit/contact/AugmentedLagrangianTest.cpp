// The augmented Lagrangian of the node-to-facet element (docs/theory-contact.md §15): the normal traction
// min(0, λ_N + ε_N g_N), the Coulomb trial from λ_T, the multipliers handed back in the trial history, and
// the consistent tangent against central differences with nonzero multipliers (2D segment, 3D face), in
// normal contact, stick, slip and with the slip tolerance, at a penetration and at a positive gap still
// held by λ_N. Also the history store: a Uzawa update changes the committed multipliers only, a cut-back
// rolls them back, a commit keeps the converged tractions as the next increment's multipliers. And on an
// interface: a node that sticks keeps its stick reference and λ_T across a commit (eq. 15.4), and the
// element past a free end at a positive gap held by λ_N (where the selector now keeps such a node).
#include "ElementTestTools.hpp"
#include "InterfaceTestTools.hpp"

#include <gtest/gtest.h>

#include <array>
#include <iterator>
#include <string>
#include <vector>


namespace {

using Law = cc::ContactLawParameters;

Law augmented(double normalPenalty, double tangentialPenalty, double mu, double slipTolerance = 0.0) {
  Law law{};
  law.normalPenalty = normalPenalty;
  law.tangentialPenalty = tangentialPenalty;
  law.frictionCoefficient = mu;
  law.slipTolerance = slipTolerance;
  law.enforcement = Law::Enforcement::AugmentedLagrangian;
  law.penetrationTolerance = 1e-3;
  law.elasticSlipTolerance = 1e-3;
  law.maxAugmentations = 10;
  return law;
}

struct Case {
  const char* name;
  Law law;
  ContactStatus expected;
};

// ε_N = 1e3, ε_T = 5e2 (or μ|t_N|/(s L) with s = 1 or 0.005, L = 4); λ_N = −40: active up to g_N = 0.04.
const Case kCases[] = {
    {"normal_only", augmented(1e3, 0.0, 0.0), ContactStatus::Slip},
    {"stick", augmented(1e3, 5e2, 100.0), ContactStatus::Stick},
    {"slip", augmented(1e3, 5e2, 0.2), ContactStatus::Slip},
    {"stick_slip_tolerance", augmented(1e3, 0.0, 100.0, 1.0), ContactStatus::Stick},
    {"slip_slip_tolerance", augmented(1e3, 0.0, 0.2, 0.005), ContactStatus::Slip},
};
constexpr double kNormalMultiplier = -40.0;
constexpr double kFacetLength = 4.0;

template <int S>
cc::ContactHistory<S> withMultipliers(int facet, Vector<S> xi, Vector<S> traction, Vector<S> multiplier) {
  auto h = ct::committedHistory<S>(facet, xi, traction, ContactStatus::Stick);
  h.normalMultiplier = kNormalMultiplier;
  h.tangentialMultiplier = multiplier;
  return h;
}

// Slave node on the straight segment (0,0) → (2,0.4) at parameter ξ, at signed distance g along n̄.
cc::NodeToFacetGeometry<cc::Line2Facet> segmentSlave(double xi, double gap) {
  const Vector<2> a{0.0, 0.0}, b{2.0, 0.4};
  const auto p = cc::SegmentProjection2D::evaluateAt({0.0, 0.0}, {{a, b}}, {xi});
  return {cc::add(p.position, cc::scaled(gap, p.normal)), {{a, b}}};
}

// Slave node over the warped 4-node face at surface point ξ, at signed distance g along n̄.
using Face = std::array<Vector<3>, 4>;
const Face kWarped{{{0.0, 0.0, 0.0}, {2.0, 0.1, 0.4}, {2.2, 2.0, -0.1}, {-0.1, 1.9, 0.3}}};
cc::NodeToFacetGeometry<cc::Quad4Facet> faceSlave(Vector<2> xi, double gap) {
  const auto p = cc::FaceProjection3D::evaluateAt({0.0, 0.0, 0.0}, kWarped, xi);
  return {cc::add(p.position, cc::scaled(gap, p.normal)), kWarped};
}

template <class Facet, class Geometry, class Committed>
void checkCase(const Case& c, const Geometry& g, const Committed& committed, double gap, ct::TangentCheck& check,
               const std::string& label) {
  const cc::NodeToFacetContact<Facet> element(c.law);
  const auto r = element.evaluate(g, committed.segment, committed, kFacetLength);
  ASSERT_EQ(r.status, c.expected) << label;
  // eq. (15.1): t_N = λ_N + ε_N g_N, and the trial history hands the tractions to the next update.
  EXPECT_NEAR(r.normalTraction, kNormalMultiplier + 1e3 * gap, 1e-9) << label;
  EXPECT_EQ(r.trial.normalMultiplier, r.normalTraction) << label;
  EXPECT_EQ(r.trial.tangentialMultiplier, r.tangentialTraction) << label;
  const double h = 1e-7;
  check.expectClose(r.tangent, ct::finiteDifferenceTangent(element, g, committed.segment, committed, h, kFacetLength),
                    label);
}

}  // namespace

TEST(AugmentedNormalLaw, TractionIsTheMultiplierPlusThePenaltyGapWhileCompressive) {
  const cc::PenaltyNormalLaw law(1e3);
  EXPECT_EQ(law.traction(-0.01), -10.0);  // λ_N = 0: the penalty law, eq. (16)
  EXPECT_FALSE(law.isActive(0.01));
  EXPECT_TRUE(law.isActive(0.01, -40.0));  // held at a positive gap by its multiplier
  EXPECT_NEAR(law.traction(0.01, -40.0), -30.0, 1e-12);
  EXPECT_EQ(law.tractionDerivative(0.01, -40.0), 1e3);
  EXPECT_FALSE(law.isActive(0.05, -40.0));  // λ_N + ε_N g_N > 0: open
  EXPECT_EQ(law.traction(0.05, -40.0), 0.0);
}

TEST(AugmentedLagrangianElement, TrialTractionStartsFromTheMultiplierNotTheCommittedTraction) {
  // Stick on the segment: t^trial = λ_T + ε_T ā_11 Δξ (eq. 15.2), whatever t_T,n says.
  const cc::NodeToFacetContact<cc::Line2Facet> element(augmented(1e3, 5e2, 100.0));
  const double gap = -0.01, xi = 0.1, xiN = 0.05;
  const auto committed = withMultipliers<1>(3, {xiN}, {7.0}, {2.5});
  const auto r = element.evaluate(segmentSlave(xi, gap), 3, committed, kFacetLength);
  ASSERT_EQ(r.status, ContactStatus::Stick);
  const double metric = r.projection.metric(0, 0);
  EXPECT_NEAR(r.tangentialTraction[0], 2.5 + 5e2 * metric * (xi - xiN), 1e-9);
  // The penalty law of the same parameters starts from t_T,n and ignores the multipliers.
  Law penalty = augmented(1e3, 5e2, 100.0);
  penalty.enforcement = Law::Enforcement::Penalty;
  const auto p = cc::NodeToFacetContact<cc::Line2Facet>(penalty).evaluate(segmentSlave(xi, gap), 3, committed, kFacetLength);
  EXPECT_NEAR(p.tangentialTraction[0], 7.0 + 5e2 * metric * (xi - xiN), 1e-9);
  EXPECT_NEAR(p.normalTraction, 1e3 * gap, 1e-12);
  EXPECT_EQ(p.trial.normalMultiplier, 0.0);  // the penalty law keeps no multipliers
  EXPECT_EQ(p.trial.tangentialMultiplier[0], 0.0);
}

TEST(AugmentedLagrangianElement, SegmentTangentMatchesCentralDifferencesWithMultipliers) {
  ct::TangentCheck check{ct::kFdTolerance};
  for (const Case& c : kCases)
    for (const double gap : {-0.02, 0.015}) {  // penetrating, and open but held by λ_N
      const auto committed = withMultipliers<1>(3, {0.02}, {9.0}, {1.5});
      checkCase<cc::Line2Facet>(c, segmentSlave(0.3, gap), committed, gap, check,
                                std::string("Line2 ") + c.name + " g_N = " + std::to_string(gap));
    }
  check.printWorst("Line2 augmented Lagrangian");
}

TEST(AugmentedLagrangianElement, FaceTangentMatchesCentralDifferencesWithMultipliers) {
  ct::TangentCheck check{ct::kFdTolerance};
  for (const Case& c : kCases)
    for (const double gap : {-0.02, 0.015}) {
      const auto committed = withMultipliers<2>(7, {-0.38, 0.31}, {4.0, -2.0}, {1.5, -0.8});
      checkCase<cc::Quad4Facet>(c, faceSlave({-0.3, 0.4}, gap), committed, gap, check,
                                std::string("Quad4 ") + c.name + " g_N = " + std::to_string(gap));
    }
  check.printWorst("Quad4 augmented Lagrangian");
}

TEST(AugmentedLagrangianHistory, UzawaUpdateIsRolledBackByACutBackAndCarriedByACommit) {
  cc::ContactHistoryStore<1> store(2);
  cc::ContactHistory<1> trial;
  trial.status = ContactStatus::Stick;
  trial.segment = 0;
  trial.normalMultiplier = -5.0;  // the element's t_N and t_T: the next update's multipliers
  trial.tangentialMultiplier = {1.0};
  trial.tangentialTraction = {1.0};
  store.setTrial(0, trial);
  store.augment();
  EXPECT_EQ(store.committed(0).normalMultiplier, -5.0);
  EXPECT_EQ(store.committed(0).tangentialMultiplier[0], 1.0);
  EXPECT_EQ(store.committed(0).status, ContactStatus::Open);  // only the multipliers move within the increment
  store.rollback();
  EXPECT_EQ(store.committed(0).normalMultiplier, 0.0);
  EXPECT_EQ(store.trial(0).normalMultiplier, 0.0);
  // Update, converge (t_N = −6 with λ_N = −5), commit: λ_N stays the one used, λ_T becomes t_T.
  store.setTrial(0, trial);
  store.augment();
  trial.normalMultiplier = -6.0;
  trial.tangentialMultiplier = {1.5};
  store.setTrial(0, trial);
  store.commit();
  EXPECT_EQ(store.committed(0).normalMultiplier, -5.0);
  EXPECT_EQ(store.committed(0).tangentialMultiplier[0], 1.5);
  store.setTrial(0, trial);
  store.augment();
  EXPECT_EQ(store.committed(0).normalMultiplier, -6.0);
  store.rollback();  // back to the commit's multipliers, not to zero
  EXPECT_EQ(store.committed(0).normalMultiplier, -5.0);
  // A node that opened carries no multiplier into the next increment.
  cc::ContactHistory<1> open;
  store.setTrial(0, open);
  store.commit();
  EXPECT_EQ(store.committed(0).normalMultiplier, 0.0);
}

// The selector keeps a node held by λ_N at a positive gap past a free end (FacetSelector, `heldGap`): the
// element there, its force faded over ContactPoint::freeEdgeReach, against central differences (segment past
// its end ξ = 1 by 0.01, face past its edge ξ¹ = 1 by 0.01; g_N = +0.015, held by λ_N = −40 up to 0.04).
TEST(AugmentedLagrangianElement, TangentPastAFreeEndAtAPositiveGapMatchesCentralDifferences) {
  const double gap = 0.015;
  const auto point = cc::ContactPoint::projection(0.03);
  ct::TangentCheck check{ct::kFdTolerance};
  // The element past its facet's free end or edge, held at a positive gap by its multiplier: the expected
  // status, a weight strictly between 0 and 1, and the tangent against central differences.
  const auto expectPastTheEnd = [&](const auto& element, const auto& geometry, int node, const auto& history,
                                    const Case& c, const std::string& where) {
    const auto r = element.evaluate(geometry, node, history, kFacetLength, cc::SlipTangent::consistent(), point);
    ASSERT_EQ(r.status, c.expected) << where << c.name;
    EXPECT_GT(r.freeEdgeWeight, 0.0) << where << c.name;
    EXPECT_LT(r.freeEdgeWeight, 1.0) << where << c.name;
    check.expectClose(r.tangent, ct::finiteDifferenceTangent(element, geometry, node, history, 1e-7, kFacetLength, point),
                      where + c.name);
  };
  for (const Case& c : kCases) {
    expectPastTheEnd(cc::NodeToFacetContact<cc::Line2Facet>(c.law), segmentSlave(1.01, gap), 3,
                     withMultipliers<1>(3, {0.9}, {9.0}, {1.5}), c, "Line2 past its end ");
    expectPastTheEnd(cc::NodeToFacetContact<cc::Quad4Facet>(c.law), faceSlave({-0.3, 1.01}, gap), 7,
                     withMultipliers<2>(7, {-0.38, 0.91}, {4.0, -2.0}, {1.5, -0.8}), c, "Quad4 past its edge ");
  }
  check.printWorst("augmented Lagrangian past a free end");
}

namespace {

// Three slave nodes on y = 0 (x = 0, 1, 2; L_k = 1) under a rigid line at y = 0.5 that moves by λ (0.5, −1):
// it touches them at λ = 0.5 and drags them along x by 0.5 per unit λ; ε_N = 1e6, constant ε_T = 1e4,
// μ = 0.3: they stick (|t_T| ≤ 200 against μ|t_N| ≥ 3000 below).
std::unique_ptr<cc::ContactInterfaceBase> draggedPlate() {
  auto spec = ct::threeNodesUnderRigidLine({{-10.0, 0.5}, {10.0, 0.5}}, {0.5, -1.0});
  spec.law.frictionCoefficient = 0.3;
  spec.law.tangentialPenalty = 1e4;
  spec.law.slipTolerance = 0.0;
  spec.law.enforcement = Law::Enforcement::AugmentedLagrangian;
  spec.law.penetrationTolerance = 1e-3;
  spec.law.elasticSlipTolerance = 1e-4;
  spec.law.maxAugmentations = 10;
  return cc::makeContactInterface(spec, {1, 1, 1});
}

}  // namespace

TEST(AugmentedLagrangianInterface, AStickingNodeKeepsItsStickReferenceAndMultiplierAcrossACommit) {
  const auto plate = draggedPlate();
  const auto sink = [](const cc::GlobalIndex*, int, const double*, const double*, const double*) {};
  const auto slave = ct::threeNodesOnXAxis;
  plate->evaluate(slave, 0.51, true, sink);  // first touch at 0.5: stuck since, 0.005 of relative motion
  plate->commit();                            // the stick reference: here
  plate->evaluate(slave, 0.52, true, sink);   // 0.005 more
  EXPECT_NEAR(plate->trialViolation().elasticSlip, 0.005, 1e-9);
  plate->augment(true);                           // λ_T ← t_T (eq. 15.3)
  plate->evaluate(slave, 0.52, true, sink);
  plate->commit();
  const std::vector<double> converged = plate->committedSlaveForce();
  // The converged state is carried: the same positions give the same force after the commit.
  plate->evaluate(slave, 0.52, true, sink);
  plate->commit();
  for (std::size_t c = 0; c < converged.size(); ++c)
    EXPECT_NEAR(plate->committedSlaveForce()[c], converged[c], 1e-9 * std::abs(converged[1])) << c;
  // The elastic slip the updates test is the motion since the node stuck (eq. 15.4), 0.01 at λ = 0.53, not
  // the 0.005 since the last commit: per-increment motions below the tolerance do not add up unseen.
  plate->evaluate(slave, 0.53, true, sink);
  EXPECT_NEAR(plate->trialViolation().elasticSlip, 0.01, 1e-9);
}

// The stick multipliers' secant (eq. 15.7) reads an update's iterate as an equilibrium of the structure
// (t_T = F − K m), so it steps only at an update of a converged iterate; an early update (an unconverged
// iterate, §15 "Updates before convergence") is Uzawa's λ_T ← t_T, and the secant's memory skips it. The
// plate's nodes stuck at λ = 0.51; at λ = 0.52 the master has moved 0.005 past them. Update 1 (converged):
// nodes unmoved, m₁ = 0.005, t₁ = ε_T m₁ = 50. Update 2 at nodes pulled 0.001 along: m₂ = 0.004, t₂ = 50 +
// 40 = 90 (like a spring K = −Δt/Δm = 4e4). The committed force is the nodes' t_T = λ_T + ε_T m₂ times their
// total area 2.
TEST(AugmentedLagrangianInterface, TheStickSecantStepsAtConvergedUpdatesOnly) {
  const auto sink = [](const cc::GlobalIndex*, int, const double*, const double*, const double*) {};
  const auto pulled = [](double shift) {
    return [shift](cc::GlobalIndex node, double* x) {
      x[0] = static_cast<double>(node) + shift;
      x[1] = 0.0;
    };
  };
  const double penalty = 1e4, m1 = 0.005, m2 = 0.004, noise = 1e-4;  // n = Elastic Slip Tolerance × L_k
  // Force after update 1 (converged), update 2 (`secondAtEquilibrium`), an evaluation at update 2's iterate.
  const auto forceAfterTwoUpdates = [&](bool secondAtEquilibrium, double earlyShift) {
    const auto plate = draggedPlate();
    plate->evaluate(ct::threeNodesOnXAxis, 0.51, true, sink);
    plate->commit();
    plate->evaluate(pulled(0.0), 0.52, true, sink);
    plate->augment(true);
    if (earlyShift >= 0.0) {  // an early update in between
      plate->evaluate(pulled(earlyShift), 0.52, true, sink);
      plate->augment(false);
    }
    plate->evaluate(pulled(m1 - m2), 0.52, true, sink);
    plate->augment(secondAtEquilibrium);
    plate->evaluate(pulled(m1 - m2), 0.52, true, sink);
    plate->commit();
    return std::abs(plate->committedSlaveForce()[0]) / 2.0;
  };
  // Eq. (15.7) by hand: K̃ from the two converged updates (t, m) and the step from the latest multiplier λ.
  const auto secantTraction = [&](double t1, double t2, double lambda) {
    const double k = (t2 - t1) * (m1 - m2) / ((m1 - m2) * (m1 - m2) + noise * noise);
    const double g = k / penalty, f = 1.0 + g / (1.0 + g / 999.0);
    return lambda + f * (t2 - lambda) + penalty * m2;  // the new λ_T plus the stretch ε_T m₂
  };
  const double t1 = penalty * m1, t2 = t1 + penalty * m2;
  // Early second update: Uzawa's, λ_T = t₂ (the force 130 = 90 + 40).
  EXPECT_NEAR(forceAfterTwoUpdates(false, -1.0), t2 + penalty * m2, 1e-9 * t2);
  // Converged second update: the secant's step, about five times Uzawa's here.
  const double secant = forceAfterTwoUpdates(true, -1.0);
  EXPECT_NEAR(secant, secantTraction(t1, t2, t1), 1e-9 * secant);
  EXPECT_GT(secant, 2.0 * (t2 + penalty * m2));
  // An early update between them (nodes pulled 0.0005: λ_T = 50 + 45 = 95) is Uzawa's and is not in the
  // secant's memory: the step pairs the two converged updates.
  const double lambdaEarly = t1 + penalty * (m1 - 0.0005);
  EXPECT_NEAR(forceAfterTwoUpdates(true, 0.0005), secantTraction(t1, lambdaEarly + penalty * m2, lambdaEarly),
              1e-9 * secant);
}

// ---- Every facet family, at its projection, an edge point and a vertex ---------------------------------

namespace {

// A skewed, curved facet (quadratic faces are curved by the lift, linear ones stay as they are): node i at
// an affine image of its parent coordinates, lifted by a quadratic bump (3D) or sag (2D).
template <class Facet>
std::array<typename Facet::Point, Facet::kNodes> curvedFacet() {
  std::array<typename Facet::Point, Facet::kNodes> x{};
  for (int i = 0; i < Facet::kNodes; ++i) {
    const auto xi = Facet::nodeCoords(i);
    if constexpr (Facet::kSurfaceDim == 1)
      x[i] = {0.3 + 1.1 * xi[0], 0.1 * (1.0 - xi[0] * xi[0])};
    else
      x[i] = {0.2 + 1.1 * xi[0] + 0.25 * xi[1], -0.1 + 0.15 * xi[0] + 0.95 * xi[1],
              0.1 * (0.5 - xi[0] * xi[0] - 0.7 * xi[1] * xi[1] + 0.3 * xi[0] * xi[1])};
  }
  return x;
}

template <class Facet>
class AugmentedFacetFamilies : public ::testing::Test {};
using AllFacetTypes = ::testing::Types<cc::Line2Facet, cc::Quad4Facet, cc::Line3Facet, cc::Tri3Facet, cc::Tri6Facet,
                                       cc::Quad8Facet, cc::Quad9Facet>;
TYPED_TEST_SUITE(AugmentedFacetFamilies, AllFacetTypes);

}  // namespace

// The augmented element with nonzero multipliers (λ_N = −40, λ_T ≠ 0; the slip-tolerance ε_T frozen at
// μ|λ_N|/(s L_k), and the capped variant) on every facet type: at a projection inside the facet, penetrating
// and at a positive gap held by λ_N, and at an edge point and a vertex of its boundary (the boundary-point
// kinematics of §6.4 with the augmented traction): tangents against central differences.
TYPED_TEST(AugmentedFacetFamilies, TangentMatchesCentralDifferencesAtEveryContactPoint) {
  using Facet = TypeParam;
  constexpr int M = Facet::kSurfaceDim;
  const auto facet = curvedFacet<Facet>();
  const auto centre = cc::Projection<Facet>::evaluateAt(typename Facet::Point{}, facet, Facet::center());
  Vector<M> xiN{}, multiplier{};
  for (int a = 0; a < M; ++a) {
    xiN[a] = Facet::center()[a] + (a == 0 ? 0.02 : -0.015);
    multiplier[a] = a == 0 ? 1.5 : -0.8;
  }
  const auto committed = withMultipliers<M>(3, xiN, multiplier, multiplier);
  // Inside: the centre's normal line. On the boundary: off the first boundary segment i–j, a little past it.
  const auto segment = Facet::boundarySegments()[0];
  const int i = segment[0], j = segment[1];
  const auto onEdge = cc::add(cc::scaled(0.6, facet[i]), cc::scaled(0.4, facet[j]));
  const auto outward = cc::subtract(onEdge, centre.position);
  std::vector<Case> cases(std::begin(kCases), std::end(kCases));
  cases.push_back({"stick_slip_tolerance_capped", augmented(1e3, 500.0, 100.0, 1.0), ContactStatus::Stick});
  ct::TangentCheck check{ct::kFdTolerance};
  for (const Case& c : cases) {
    const cc::NodeToFacetContact<Facet> element(c.law);
    const auto expectClose = [&](const cc::NodeToFacetGeometry<Facet>& g, const cc::ContactPoint& point,
                                 const std::string& where) {
      const auto r = element.evaluate(g, 3, committed, kFacetLength, cc::SlipTangent::consistent(), point);
      ASSERT_NE(r.status, ContactStatus::Open) << where << c.name;
      check.expectClose(r.tangent, ct::finiteDifferenceTangent(element, g, 3, committed, 1e-7, kFacetLength, point),
                        where + c.name);
    };
    for (const double gap : {-0.02, 0.015})
      expectClose({cc::add(centre.position, cc::scaled(gap, centre.normal)), facet}, cc::ContactPoint::projection(),
                  "inside g_N = " + std::to_string(gap) + " ");
    const auto behind = cc::add(cc::add(onEdge, cc::scaled(0.05, outward)), cc::scaled(-0.02, centre.normal));
    if constexpr (M == 2) expectClose({behind, facet}, cc::ContactPoint::edge(i, j, -1.0), "edge point ");
    expectClose({behind, facet}, cc::ContactPoint::vertex(j, -1.0), "vertex ");
  }
  check.printWorst((std::to_string(Facet::kNodes) + "-node facet, augmented, every contact point").c_str());
}
