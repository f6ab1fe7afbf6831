// The node-to-facet contact element on a 2-node segment (2D node-to-segment, 6 dofs): residual (forces)
// and consistent tangent against central finite differences of the residual on all 6 dofs, for
// normal-only, stick and slip states. (These are the tests of the former NodeToSegmentContact2D, which the
// Line2Facet instantiation reproduced to round-off before it was removed.)
#include "contact/HistoryTransfer.hpp"
#include "contact/NodeToFacetContact.hpp"
#include "contact/FacetSelector.hpp"
#include "ElementTestTools.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using Mat6 = cc::Matrix<6, 6>;
using Vec6 = Vector<6>;
using Element = cc::NodeToFacetContact<cc::Line2Facet>;
using Geometry = cc::NodeToFacetGeometry<cc::Line2Facet>;

namespace {

// The element-test fixture's tools on the Line2 facet.
constexpr auto fromDofs = &ct::fromDofs<cc::Line2Facet>;
using ct::asymmetry;
using ct::relativeDifference;
using ct::solve;
using ct::toDofs;

cc::ContactHistory<1> inContact(int segment, double xiN, double tractionN, ContactStatus status) {
  return ct::committedHistory<1>(segment, {xiN}, {tractionN}, status);
}

/// Geometry with the slave node at parameter ξ on the segment x1 → x2, at signed distance g along n̄.
Geometry slaveAt(Vector<2> x1, Vector<2> x2, double xi, double gap) {
  const auto p = cc::SegmentProjection2D::evaluateAt({0.0, 0.0}, {{x1, x2}}, {xi});
  return {cc::add(p.position, cc::scaled(gap, p.normal)), {{x1, x2}}};
}

struct Configuration {
  std::string name;
  Vector<2> x1;
  Vector<2> x2;
  double xi;    // current ξ of the slave node
  double xiN;   // committed ξ_n
  double gap;   // current g_N (< 0: penetrating)
};

// l ≈ 2 – 3; the penetration is a few percent of the segment length, so the geometric terms
// (∝ g_N / l and t_T / t_N) are visible at the 1e-2 level.
const Configuration kConfigurations[] = {
    {"middle", {1.0, 0.0}, {-1.0, 0.0}, 0.05, -0.02, -0.04},
    {"near_end", {1.0, 0.0}, {-1.0, 0.0}, 0.95, 0.90, -0.03},
    {"inclined_stretched", {2.3, 0.9}, {-0.5, -0.6}, -0.3, -0.38, -0.06},
    {"large_sliding", {1.2, 0.2}, {-1.1, -0.1}, 0.7, -0.8, -0.05},
};


struct Case {
  const char* law;
  cc::ContactLawParameters parameters;
  double committedTraction;
  ContactStatus expected;
};

// ε_N = 1e3, ε_T = 5e2. Stick: μ large enough for every configuration; slip: μ = 0.2.
const Case kCases[] = {
    {"normal_only", {1e3, 0.0, 0.0}, 0.0, ContactStatus::Slip},
    {"stick", {1e3, 5e2, 50.0}, 1.5, ContactStatus::Stick},
    {"slip", {1e3, 5e2, 0.2}, 1.5, ContactStatus::Slip},
};

}  // namespace

TEST(NodeToFacetContactLine2, ConsistentTangentMatchesCentralDifferences) {
  ct::TangentCheck check{ct::kFdTolerance};
  for (const Case& c : kCases) {
    const Element element(c.parameters);
    for (const Configuration& conf : kConfigurations) {
      SCOPED_TRACE(std::string(c.law) + " / " + conf.name);
      const auto g = slaveAt(conf.x1, conf.x2, conf.xi, conf.gap);
      const auto committed = inContact(7, conf.xiN, c.committedTraction, ContactStatus::Stick);
      const auto r = element.evaluate(g, 7, committed);
      ASSERT_EQ(r.status, c.expected);
      EXPECT_NEAR(r.projection.xi[0], conf.xi, 1e-12);
      EXPECT_NEAR(r.projection.gap, conf.gap, 1e-12);
      check.expectClose(r.tangent, ct::finiteDifferenceTangent(element, g, committed.segment, committed, ct::kFdStep),
                        std::string(c.law) + " " + conf.name);
    }
  }
  check.printWorst("Line2");
}

// With a slip tolerance ε_T = μ|t_N|/(s L) depends on g_N: the tangent gains ∂t_T/∂g_N = ā_11 Δξ ∂ε_T/∂t_N ε_N
// in stick. Checked against central differences in stick and slip, at a normal penetration and at a
// penetration of 1e-5 of the segment (a nearly unloaded node: p = 1e-2 with ε_N = 1e3), with and
// without the cap (ct::kSlipToleranceCases).
TEST(NodeToFacetContactLine2, SlipToleranceTangentMatchesCentralDifferences) {
  ct::checkSlipToleranceTangents<cc::Line2Facet>(
      kConfigurations,
      [](const Configuration& conf, double gap) {
        // Committed traction at 10 % of the cone, in the direction of the motion.
        const double length = std::sqrt(cc::dot(cc::subtract(conf.x2, conf.x1), cc::subtract(conf.x2, conf.x1))) / 2.0;
        const double tn = 0.1 * 0.3 * 1e3 * std::abs(gap) * length * (conf.xi > conf.xiN ? 1.0 : -1.0);
        return std::make_pair(slaveAt(conf.x1, conf.x2, conf.xi, gap), inContact(7, conf.xiN, tn, ContactStatus::Stick));
      },
      ct::kFdTolerance, "Line2");
  const double facetLength = ct::kSlipToleranceFacetLength;
  // The new stick term is there and matters: without ∂ε_T/∂t_N the tangent misses the FD derivative.
  const Element element({1e3, 0.0, 0.3, 1.0}, cc::TangentTerms::Consistent);
  const Configuration& conf = kConfigurations[2];
  const auto g = slaveAt(conf.x1, conf.x2, conf.xi, conf.gap);
  const auto committed = inContact(7, conf.xiN, 0.0, ContactStatus::Stick);
  const auto r = element.evaluate(g, 7, committed, facetLength);
  ASSERT_EQ(r.status, ContactStatus::Stick);
  EXPECT_NE(r.friction.dTraction_dNormalTraction[0], 0.0);
  EXPECT_GT(asymmetry(r.tangent), 1e-3);  // ∂t/∂t_N ε_N D^1 Nᵀ: non-symmetric even in stick
}

// The secant slip tangent (SlipReversalDamping) changes the tangent only: same residual and trial state,
// and K_secant − K = k (∂ξ̄/∂u)(∂ξ̄/∂u)ᵀ with k the given ∂t_T1/∂ξ̄ (capped by the stick stiffness
// ε_T ā_11): symmetric, rank one, positive semi-definite. A sticking node is unaffected.
TEST(NodeToFacetContactLine2, SecantSlipTangentChangesOnlyTheTangent) {
  const Element element({1e3, 0.0, 0.3, 0.005});
  const double facetLength = 4.0;
  for (const Configuration& conf : kConfigurations) {
    SCOPED_TRACE(conf.name);
    const auto g = slaveAt(conf.x1, conf.x2, conf.xi, conf.gap);
    const auto committed = inContact(7, conf.xiN, 0.0, ContactStatus::Slip);
    const auto consistent = element.evaluate(g, 7, committed, facetLength);
    ASSERT_EQ(consistent.status, ContactStatus::Slip);
    const double stick = consistent.friction.tangentialPenalty * consistent.projection.metric(0, 0);
    for (double k : {0.25 * stick, 4.0 * stick}) {  // the second is capped at the stick stiffness
      const auto secant = element.evaluate(g, 7, committed, facetLength, cc::SlipTangent::secantOf(k));
      for (int i = 0; i < 6; ++i) EXPECT_EQ(consistent.residual[i], secant.residual[i]);
      EXPECT_EQ(consistent.trial, secant.trial);
      Mat6 difference = secant.tangent;
      cc::addScaled(difference, -1.0, consistent.tangent);
      const double size = cc::frobeniusNorm(difference);
      EXPECT_GT(size, 0.0);
      EXPECT_LT(asymmetry(difference), 1e-12);
      for (int i = 0; i < 6; ++i) {
        EXPECT_GE(difference(i, i), -1e-12 * size);
        for (int j = 0; j < 6; ++j)  // rank one: every 2 × 2 minor vanishes
          EXPECT_NEAR(difference(i, i) * difference(j, j), difference(i, j) * difference(j, i), 1e-10 * size * size);
      }
      // Linear in k below the cap; the trace of k (∂ξ̄/∂u)(∂ξ̄/∂u)ᵀ is k ‖∂ξ̄/∂u‖².
      double trace = 0.0;
      for (int i = 0; i < 6; ++i) trace += difference(i, i);
      if (k < stick) {
        const auto half = element.evaluate(g, 7, committed, facetLength, cc::SlipTangent::secantOf(0.5 * k));
        double halfTrace = 0.0;
        for (int i = 0; i < 6; ++i) halfTrace += half.tangent(i, i) - consistent.tangent(i, i);
        EXPECT_NEAR(halfTrace, 0.5 * trace, 1e-10 * trace);
      } else {
        const auto atCap = element.evaluate(g, 7, committed, facetLength, cc::SlipTangent::secantOf(stick));
        EXPECT_EQ(relativeDifference(atCap.tangent, secant.tangent), 0.0);
      }
    }
  }
  const Configuration& conf = kConfigurations[0];
  const Element sticking({1e3, 0.0, 0.3, 1.0});
  const auto g = slaveAt(conf.x1, conf.x2, conf.xi, conf.gap);
  const auto committed = inContact(7, conf.xiN, 0.0, ContactStatus::Stick);
  const auto a = sticking.evaluate(g, 7, committed, facetLength);
  const auto b = sticking.evaluate(g, 7, committed, facetLength, cc::SlipTangent::secantOf(1.0));
  ASSERT_EQ(a.status, ContactStatus::Stick);
  EXPECT_EQ(relativeDifference(a.tangent, b.tangent), 0.0);
}

// The normal secant of an open node (NormalToggleDamping): no force, the trial state of an open node, and the
// tangent k N Nᵀ with N = ∂g_N/∂u, the gap's derivative, compared with a central difference of g_N; a node in
// contact is unaffected (its tangent is the consistent one, ε_N N Nᵀ + …).
TEST(NodeToFacetContactLine2, OpenNodeNormalSecantIsTheGapsOuterProduct) {
  const Element element({1e3, 5e2, 0.2});
  const double k = 250.0;
  cc::SlipTangent secant;
  secant.normalStiffness = k;
  for (const Configuration& conf : kConfigurations) {
    SCOPED_TRACE(conf.name);
    const auto g = slaveAt(conf.x1, conf.x2, conf.xi, -conf.gap);  // open: in front of the segment
    const auto committed = inContact(7, conf.xiN, 0.0, ContactStatus::Stick);
    const auto plain = element.evaluate(g, 7, committed);
    const auto damped = element.evaluate(g, 7, committed, 0.0, secant);
    ASSERT_EQ(damped.status, ContactStatus::Open);
    EXPECT_EQ(damped.trial, plain.trial);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(damped.residual[i], 0.0);
    EXPECT_EQ(cc::frobeniusNorm(plain.tangent), 0.0);
    const Vec6 x = toDofs(g);
    Vec6 gapDerivative{};
    const double h = 1e-6;
    for (int j = 0; j < 6; ++j) {
      Vec6 plus = x, minus = x;
      plus[j] += h;
      minus[j] -= h;
      gapDerivative[j] = (element.evaluate(fromDofs(plus), 7, committed).gap -
                          element.evaluate(fromDofs(minus), 7, committed).gap) / (2.0 * h);
    }
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) EXPECT_NEAR(damped.tangent(i, j), k * gapDerivative[i] * gapDerivative[j], 1e-6 * k);
  }
  const Configuration& conf = kConfigurations[0];
  const auto closed = slaveAt(conf.x1, conf.x2, conf.xi, conf.gap);
  const auto committed = inContact(7, conf.xiN, 0.0, ContactStatus::Stick);
  EXPECT_EQ(relativeDifference(element.evaluate(closed, 7, committed).tangent,
                               element.evaluate(closed, 7, committed, 0.0, secant).tangent),
            0.0);
}

TEST(NodeToFacetContactLine2, SlipTangentIsNonSymmetricLikeItsFiniteDifference) {
  const Element element({1e3, 5e2, 0.2});
  for (const Configuration& conf : kConfigurations) {
    SCOPED_TRACE(conf.name);
    const auto g = slaveAt(conf.x1, conf.x2, conf.xi, conf.gap);
    const auto committed = inContact(7, conf.xiN, 1.5, ContactStatus::Slip);
    const auto r = element.evaluate(g, 7, committed);
    ASSERT_EQ(r.status, ContactStatus::Slip);
    const Mat6 fd = ct::finiteDifferenceTangent(element, g, committed.segment, committed, ct::kFdStep);
    EXPECT_LT(relativeDifference(r.tangent, fd), ct::kFdTolerance);
    EXPECT_GT(asymmetry(r.tangent), 1e-2);  // eq. (26): −μ ε_N n_T D^1 Nᵀ is not symmetric
    EXPECT_GT(asymmetry(fd), 1e-2);
  }
}

TEST(NodeToFacetContactLine2, PaperMainTermsAloneMissTheGeometricTerms) {
  // eq. (24)–(26) are the exact tangent only in the limit g_N → 0, t_T → 0; at a finite penetration the
  // geometric terms are needed to match the derivative of the residual.
  for (const Case& c : kCases) {
    const Element main(c.parameters, cc::TangentTerms::PaperMainTerms);
    const Element full(c.parameters);
    const Configuration& conf = kConfigurations[2];
    const auto g = slaveAt(conf.x1, conf.x2, conf.xi, conf.gap);
    const auto committed = inContact(7, conf.xiN, c.committedTraction, ContactStatus::Stick);
    const Mat6 fd = ct::finiteDifferenceTangent(full, g, committed.segment, committed, ct::kFdStep);
    const auto rMain = main.evaluate(g, 7, committed);
    EXPECT_GT(relativeDifference(rMain.tangent, fd), 1e-3) << c.law;
    // Same residual either way: only the tangent differs.
    const auto rFull = full.evaluate(g, 7, committed);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(rMain.residual[i], rFull.residual[i]);
    // The paper's stick matrix eq. (25) is symmetric, and eq. (24) alone is ε_N N Nᵀ.
    if (c.expected == ContactStatus::Stick || c.parameters.isFrictionless()) {
      EXPECT_LT(asymmetry(rMain.tangent), 1e-14);
    }
  }
}

TEST(NodeToFacetContactLine2, ContactForcePushesTheSlaveOutAndBalances) {
  const Element element({1e3, 5e2, 0.3});
  const Configuration& conf = kConfigurations[2];
  const auto g = slaveAt(conf.x1, conf.x2, conf.xi, conf.gap);
  const auto r = element.evaluate(g, 7, inContact(7, conf.xiN, 0.0, ContactStatus::Stick));
  const auto& n = r.projection.normal;
  EXPECT_LT(r.normalTraction, 0.0);
  EXPECT_NEAR(r.normalTraction, 1e3 * conf.gap, 1e-9);  // eq. (16)
  // Normal component of the force on the slave: ε_N |g_N| along +n̄ (out of the master body).
  EXPECT_NEAR(cc::dot(r.slaveForce(), n), 1e3 * std::abs(conf.gap), 1e-9);
  // Friction opposes the slave's motion relative to the master (ξ − ξ_n > 0 along ā_1).
  EXPECT_LT(cc::dot(r.slaveForce(), r.projection.covariantBasis[0]), 0.0);
  // Balance of forces and of moments (the residual is frame indifferent): rigid translations and the
  // rigid rotation δx = e_3 × x do no virtual work.
  const Vec6 x = toDofs(g);
  double fx = 0.0, fy = 0.0, moment = 0.0;
  for (int node = 0; node < 3; ++node) {
    fx += r.residual[2 * node];
    fy += r.residual[2 * node + 1];
    moment += -x[2 * node + 1] * r.residual[2 * node] + x[2 * node] * r.residual[2 * node + 1];
  }
  EXPECT_NEAR(fx, 0.0, 1e-10);
  EXPECT_NEAR(fy, 0.0, 1e-10);
  EXPECT_NEAR(moment, 0.0, 1e-10);
}

TEST(NodeToFacetContactLine2, OpenNodeHasNoForceAndFrictionlessNoTangentialForce) {
  const Element frictional({1e3, 5e2, 0.3});
  const auto open = frictional.evaluate(slaveAt({1.0, 0.0}, {-1.0, 0.0}, 0.2, 0.01), 7,
                                        inContact(7, 0.0, 2.0, ContactStatus::Stick));
  EXPECT_EQ(open.status, ContactStatus::Open);
  EXPECT_EQ(open.trial.status, ContactStatus::Open);
  EXPECT_EQ(open.trial.tangentialTraction[0], 0.0);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(open.residual[i], 0.0);
  EXPECT_EQ(cc::frobeniusNorm(open.tangent), 0.0);

  const Element frictionless({1e3, 0.0, 0.0});
  const auto g = slaveAt({1.0, 0.0}, {-1.0, 0.0}, 0.2, -0.01);
  const auto r = frictionless.evaluate(g, 7, inContact(7, -0.5, 0.0, ContactStatus::Slip));
  EXPECT_EQ(r.status, ContactStatus::Slip);
  EXPECT_EQ(r.tangentialTraction[0], 0.0);
  EXPECT_NEAR(r.slaveForce()[0], 0.0, 1e-12);  // horizontal segment: purely normal force
  EXPECT_NEAR(r.slaveForce()[1], 10.0, 1e-12);
}

TEST(NodeToFacetContactLine2, FirstContactStartsStickingWithoutTraction) {
  const Element element({1e3, 5e2, 0.3});
  const auto g = slaveAt({1.0, 0.0}, {-1.0, 0.0}, 0.4, -0.01);
  const cc::ContactHistory<1> open{};
  const auto r = element.evaluate(g, 3, open);  // committed: open
  EXPECT_EQ(r.status, ContactStatus::Stick);
  EXPECT_EQ(r.tangentialTraction[0], 0.0);
  EXPECT_EQ(r.trial.segment, 3);
  EXPECT_NEAR(r.trial.xi[0], 0.4, 1e-12);  // the stick reference point of the next increment
  const Mat6 fd = ct::finiteDifferenceTangent(element, g, open.segment, open, ct::kFdStep);
  EXPECT_LT(relativeDifference(r.tangent, fd), ct::kFdTolerance);
}

TEST(NodeToFacetContactLine2, TrialHistoryAccumulatesSlipAndCommitsThroughTheStore) {
  const Element element({1e3, 5e2, 0.2});
  cc::ContactHistoryStore<1> store(1);
  store.setTrial(0, inContact(7, -0.5, 0.0, ContactStatus::Stick));
  store.commit();
  // ‖ā_1‖ = 1: sliding from ξ = −0.5 to 0.3 is 0.8 of arc length, eq. (7).
  const auto r = element.evaluate(slaveAt({1.0, 0.0}, {-1.0, 0.0}, 0.3, -0.01), 7, store.committed(0));
  EXPECT_EQ(r.status, ContactStatus::Slip);
  EXPECT_NEAR(std::abs(r.tangentialTraction[0]), 0.2 * 10.0, 1e-12);
  EXPECT_NEAR(r.trial.accumulatedSlip, 0.8, 1e-12);
  store.setTrial(0, r.trial);
  EXPECT_EQ(store.committed(0).accumulatedSlip, 0.0);  // updated at commit only
  store.rollback();
  EXPECT_EQ(store.trial(0).accumulatedSlip, 0.0);
  store.setTrial(0, r.trial);
  store.commit();
  EXPECT_NEAR(store.committed(0).accumulatedSlip, 0.8, 1e-12);
  EXPECT_NEAR(store.committed(0).xi[0], 0.3, 1e-12);
}

TEST(NodeToFacetContactLine2, RejectsAHistoryLeftOnAnotherSegment) {
  const Element element({1e3, 5e2, 0.2});
  const auto g = slaveAt({1.0, 0.0}, {-1.0, 0.0}, 0.3, -0.01);
  EXPECT_THROW(element.evaluate(g, 8, inContact(7, 0.0, 0.0, ContactStatus::Stick)), std::logic_error);
}

TEST(NodeToFacetContactLine2, StickingNodeCrossingAVertexKeepsItsTraction) {
  // Two collinear segments of different lengths vs one long segment: after transferHistory the
  // physical tangential traction t_T1/‖ā_1‖ is the same as on the single segment.
  const Element element({1e3, 5e2, 50.0});
  const cc::MasterFacetNodes<cc::Line2Facet> right{0, {0, 1}, {{{3.0, 0.0}, {1.0, 0.0}}}};
  const cc::MasterFacetNodes<cc::Line2Facet> left{1, {1, 2}, {{{1.0, 0.0}, {-3.0, 0.0}}}};
  const cc::MasterFacetNodes<cc::Line2Facet> whole{2, {0, 2}, {{{3.0, 0.0}, {-3.0, 0.0}}}};
  // Committed: stuck at x = 1.4 with a physical traction of 0.6.
  const auto onRight = inContact(0, 0.6, 0.6 * 1.0, ContactStatus::Stick);
  const auto onWhole = inContact(2, -1.4 / 3.0, 0.6 * 3.0, ContactStatus::Stick);
  const auto transferred = cc::transferHistory(onRight, right, left);
  const Geometry now{{0.9, -0.01}, left.x};  // slid across the vertex at x = 1
  const auto a = element.evaluate(now, 1, transferred);
  const auto b = element.evaluate({{0.9, -0.01}, whole.x}, 2, onWhole);
  ASSERT_EQ(a.status, ContactStatus::Stick);
  ASSERT_EQ(b.status, ContactStatus::Stick);
  EXPECT_NEAR(a.tangentialTraction[0] / 2.0, b.tangentialTraction[0] / 3.0, 1e-10);
  EXPECT_NEAR(a.slaveForce()[0], b.slaveForce()[0], 1e-10);
  EXPECT_NEAR(a.slaveForce()[1], b.slaveForce()[1], 1e-10);
}

// ---- Newton on a tiny model: springs hold the three nodes, a force presses the slave into the segment.
namespace {

/// Residual norms of Newton on R(x) = k (x − X) + r_c(x) − F.
std::vector<double> newtonHistory(cc::TangentTerms terms) {
  const Element element({1e3, 5e2, 0.2}, terms);
  const Vec6 reference{0.3, -0.005, 1.0, 0.0, -1.0, 0.0};
  const Vec6 force{3.0, -8.0, 0.0, 0.0, 0.0, 0.0};  // presses and drags the slave: slips
  const double spring = 40.0;
  const auto committed = inContact(7, 0.3, 0.0, ContactStatus::Stick);
  Vec6 x = reference;
  std::vector<double> norms;
  for (int it = 0; it < 30; ++it) {
    const auto r = element.evaluate(fromDofs(x), 7, committed);
    Vec6 residual{};
    Mat6 k = r.tangent;
    for (int i = 0; i < 6; ++i) {
      residual[i] = spring * (x[i] - reference[i]) + r.residual[i] - force[i];
      k(i, i) += spring;
    }
    norms.push_back(cc::norm(residual));
    if (norms.back() < 1e-11) break;
    const Vec6 dx = solve(k, residual);
    for (int i = 0; i < 6; ++i) x[i] -= dx[i];
  }
  return norms;
}

}  // namespace

TEST(NodeToFacetContactLine2, ConsistentTangentGivesQuadraticNewtonConvergence) {
  const auto consistent = newtonHistory(cc::TangentTerms::Consistent);
  const auto paper = newtonHistory(cc::TangentTerms::PaperMainTerms);
  for (double v : consistent) std::printf("[ Newton   ] consistent %.3e\n", v);
  for (std::size_t i = 0; i < std::min<std::size_t>(paper.size(), 12); ++i)
    std::printf("[ Newton   ] paper main terms %.3e\n", paper[i]);
  ASSERT_LT(consistent.back(), 1e-11);
  EXPECT_LE(consistent.size(), 8u);
  // Quadratic: once in the asymptotic range r_{k+1} ≤ C r_k² (C ~ 1 here).
  const std::size_t n = consistent.size();
  ASSERT_GE(n, 3u);
  EXPECT_LT(consistent[n - 2], 10.0 * consistent[n - 3] * consistent[n - 3] + 1e-11);
  // The main terms alone converge only linearly: more iterations for the same tolerance.
  EXPECT_GT(paper.size(), n + 2);
}
