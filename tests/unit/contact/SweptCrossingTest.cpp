// The tunnelling check: the swept crossing test of a node against a moving facet (2D segment, 3D 4-node
// face), against closed-form crossing times and against brute-force sampling of random motions, and
// ContactInterfaceBase::tunnellingNodes on a rigid plate that passes through slave nodes.
#include "contact/SweptCrossing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "InterfaceTestTools.hpp"

namespace cc = contessa::contact;
using cc::Line2Facet;
using cc::Quad4Facet;
using P2 = cc::Vector<2>;
using P3 = cc::Vector<3>;

namespace {

// Segment (−1, 0) → (1, 0): the master body is on the left of the direction, above; the front (outside,
// n̄ = (0, −1)) is below.
const std::array<P2, 2> kSegment{{{-1.0, 0.0}, {1.0, 0.0}}};

TEST(SweptCrossing2D, NodeThroughStaticSegment) {
  const auto c = cc::sweptCrossing<Line2Facet>({0.2, -1.0}, {0.2, 1.0}, kSegment, kSegment);
  ASSERT_TRUE(c.crossed);
  EXPECT_NEAR(c.time, 0.5, 1e-14);
}

TEST(SweptCrossing2D, SegmentMovingThroughStaticNode) {
  // The segment moves from y = 1 to y = −3; the node at y = 0 is in front at t = 0, behind at t = 1,
  // on the segment at t = 1/4.
  const std::array<P2, 2> s0{{{-1.0, 1.0}, {1.0, 1.0}}}, s1{{{-1.0, -3.0}, {1.0, -3.0}}};
  const auto c = cc::sweptCrossing<Line2Facet>({0.3, 0.0}, {0.3, 0.0}, s0, s1);
  ASSERT_TRUE(c.crossed);
  EXPECT_NEAR(c.time, 0.25, 1e-14);
}

TEST(SweptCrossing2D, RotatingSegment) {
  // End b swings from (1, 1) to (1, −1) about a = (−1, 0): φ(t) = 1.3 − 3t for the node (0.5, 0.1).
  const std::array<P2, 2> s0{{{-1.0, 0.0}, {1.0, 1.0}}}, s1{{{-1.0, 0.0}, {1.0, -1.0}}};
  const auto c = cc::sweptCrossing<Line2Facet>({0.5, 0.1}, {0.5, 0.1}, s0, s1);
  ASSERT_TRUE(c.crossed);
  EXPECT_NEAR(c.time, 13.0 / 30.0, 1e-14);
}

TEST(SweptCrossing2D, BothEndsMovingQuadratic) {
  // a: (−1, 1) → (−1, −1), b: (1, 2) → (1, −2); the node (0, 0) is on the segment when its midpoint
  // height (1.5 − 3t) vanishes: t = 1/2 (φ is quadratic here: the segment also shortens).
  const std::array<P2, 2> s0{{{-1.0, 1.0}, {1.0, 2.0}}}, s1{{{-1.0, -1.0}, {1.0, -2.0}}};
  const auto c = cc::sweptCrossing<Line2Facet>({0.0, 0.0}, {0.0, 0.0}, s0, s1);
  ASSERT_TRUE(c.crossed);
  EXPECT_NEAR(c.time, 0.5, 1e-14);
}

TEST(SweptCrossing2D, NotACrossing) {
  // Leaving the body (back to front), parallel motion, passing beside the segment, grazing past its end,
  // and stopping in front of it.
  EXPECT_FALSE(cc::sweptCrossing<Line2Facet>({0.2, 1.0}, {0.2, -1.0}, kSegment, kSegment).crossed);
  EXPECT_FALSE(cc::sweptCrossing<Line2Facet>({-2.0, -0.5}, {2.0, -0.5}, kSegment, kSegment).crossed);
  EXPECT_FALSE(cc::sweptCrossing<Line2Facet>({1.5, -1.0}, {1.5, 1.0}, kSegment, kSegment).crossed);
  EXPECT_FALSE(cc::sweptCrossing<Line2Facet>({0.9, -0.1}, {1.3, 0.1}, kSegment, kSegment).crossed);
  EXPECT_FALSE(cc::sweptCrossing<Line2Facet>({0.2, -1.0}, {0.2, -1e-3}, kSegment, kSegment).crossed);
}

TEST(SweptCrossing2D, StartingOnTheSegmentCounts) {
  // A node touching at t = 0 (φ = 0) that ends behind has gone through.
  const auto c = cc::sweptCrossing<Line2Facet>({0.2, 0.0}, {0.2, 2.0}, kSegment, kSegment);
  ASSERT_TRUE(c.crossed);
  EXPECT_EQ(c.time, 0.0);
}

TEST(SweptCrossing, SignChangeRootsOfACubic) {
  // (t − 0.2)(t − 0.5)(t − 0.9) = t³ − 1.6 t² + 0.73 t − 0.09
  int n = 0;
  const auto r = cc::signChangeRootsInUnitInterval({-0.09, 0.73, -1.6, 1.0}, n);
  ASSERT_EQ(n, 3);
  EXPECT_NEAR(r[0], 0.2, 1e-14);
  EXPECT_NEAR(r[1], 0.5, 1e-14);
  EXPECT_NEAR(r[2], 0.9, 1e-14);
  // A double root does not change sign: (t − 0.5)² has none.
  cc::signChangeRootsInUnitInterval({0.25, -1.0, 1.0, 0.0}, n);
  EXPECT_EQ(n, 0);
}

// Brute force: the last sign change of φ on a fine grid, the node inside the segment there, and the
// node ending behind and inside. Cases within the grid's resolution of a decision boundary are skipped.
TEST(SweptCrossing2D, AgreesWithBruteForceSampling) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int crossed = 0, compared = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const P2 x0{u(rng), u(rng)}, x1{u(rng), u(rng)};
    const std::array<P2, 2> s0{{{-1.0 + 0.3 * u(rng), 0.3 * u(rng)}, {1.0 + 0.3 * u(rng), 0.3 * u(rng)}}};
    const std::array<P2, 2> s1{{{-1.0 + 0.5 * u(rng), u(rng)}, {1.0 + 0.5 * u(rng), u(rng)}}};
    const auto at = [&](double t, const P2& a, const P2& b) { return P2{(1 - t) * a[0] + t * b[0], (1 - t) * a[1] + t * b[1]}; };
    // φ and the segment coordinate s of the node's projection at time t.
    const auto state = [&](double t, double& phi, double& s) {
      const P2 x = at(t, x0, x1), a = at(t, s0[0], s1[0]), b = at(t, s0[1], s1[1]);
      const P2 d{b[0] - a[0], b[1] - a[1]}, r{x[0] - a[0], x[1] - a[1]};
      phi = r[0] * d[1] - r[1] * d[0];
      s = (r[0] * d[0] + r[1] * d[1]) / (d[0] * d[0] + d[1] * d[1]);
    };
    const int n = 20000;
    double phi0, s0c, phi1, s1c;
    state(0.0, phi0, s0c);
    state(1.0, phi1, s1c);
    bool expected = false, ambiguous = false;
    if (phi0 >= 0.0 && phi1 < 0.0) {
      if (std::abs(s1c - 0.5) > 0.5 + 1e-3)
        expected = false;
      else if (std::abs(std::abs(s1c - 0.5) - 0.5) < 1e-3)
        ambiguous = true;
      else {
        double prev, sPrev;
        state(1.0, prev, sPrev);
        for (int i = n - 1; i >= 0; --i) {
          double phi, s;
          state(static_cast<double>(i) / n, phi, s);
          if (phi >= 0.0 && prev < 0.0) {
            const double sm = 0.5 * (s + sPrev);
            ambiguous = std::abs(std::abs(sm - 0.5) - 0.5) < 2e-3;
            expected = std::abs(sm - 0.5) <= 0.5;
            break;
          }
          prev = phi;
          sPrev = s;
        }
      }
    }
    if (ambiguous) continue;
    ++compared;
    const auto c = cc::sweptCrossing<Line2Facet>(x0, x1, s0, s1);
    EXPECT_EQ(c.crossed, expected) << "trial " << trial;
    crossed += expected ? 1 : 0;
  }
  // Meaningful only with many of both outcomes.
  EXPECT_GT(compared, 2500);
  EXPECT_GT(crossed, 150);
  EXPECT_LT(crossed, compared - 150);
}

// 3D: the unit square z = 0, counter-clockwise seen from +z: n̄ = +z, the front is above.
const std::array<P3, 4> kFace{{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, {0.0, 1.0, 0.0}}};

TEST(SweptCrossing3D, NodeThroughStaticFace) {
  auto c = cc::sweptCrossing<Quad4Facet>({0.3, 0.6, 1.0}, {0.3, 0.6, -1.0}, kFace, kFace);
  ASSERT_TRUE(c.crossed);
  EXPECT_NEAR(c.time, 0.5, 1e-14);
  EXPECT_EQ(c.piece, 1);  // the triangle 0–2–3 (above the diagonal)
  c = cc::sweptCrossing<Quad4Facet>({0.5, 0.5, 1.0}, {0.5, 0.5, -3.0}, kFace, kFace);  // on the diagonal
  ASSERT_TRUE(c.crossed);
  EXPECT_NEAR(c.time, 0.25, 1e-14);
}

TEST(SweptCrossing3D, FaceMovingThroughStaticNode) {
  std::array<P3, 4> lifted = kFace;
  for (auto& p : lifted) p[2] = 2.0;
  const auto c = cc::sweptCrossing<Quad4Facet>({0.4, 0.4, 1.0}, {0.4, 0.4, 1.0}, kFace, lifted);
  ASSERT_TRUE(c.crossed);
  EXPECT_NEAR(c.time, 0.5, 1e-14);
}

TEST(SweptCrossing3D, TiltingFaceCubic) {
  // Node 2 rises from z = −1 to z = 3 (the face warps; each triangle's φ is a cubic in general). The
  // node (0.7, 0.2, 0.4) lies over triangle 0–1–2, whose plane is z = y · z_2: at the node
  // z = 0.2 z_2(t) = 0.2 (−1 + 4t), which reaches 0.4 at t = 3/4. At t = 1 the node is behind the
  // bilinear face too (z = x y z_2 = 0.42 there).
  std::array<P3, 4> f0 = kFace, f1 = kFace;
  f0[2][2] = -1.0;
  f1[2][2] = 3.0;
  const auto c = cc::sweptCrossing<Quad4Facet>({0.7, 0.2, 0.4}, {0.7, 0.2, 0.4}, f0, f1);
  ASSERT_TRUE(c.crossed);
  EXPECT_EQ(c.piece, 0);
  EXPECT_NEAR(c.time, 3.0 / 4.0, 1e-13);
  // At z = 0.5 the node ends behind the triangle (0.6 at t = 1) but in front of the warped face (0.42):
  // in the sliver between the face and its flat piece, not in contact, not a crossing (theory-contact §12).
  EXPECT_FALSE(cc::sweptCrossing<Quad4Facet>({0.7, 0.2, 0.5}, {0.7, 0.2, 0.5}, f0, f1).crossed);
}

TEST(SweptCrossing3D, NotACrossing) {
  EXPECT_FALSE(cc::sweptCrossing<Quad4Facet>({0.3, 0.6, -1.0}, {0.3, 0.6, 1.0}, kFace, kFace).crossed);  // leaving
  EXPECT_FALSE(cc::sweptCrossing<Quad4Facet>({1.2, 0.5, 1.0}, {1.2, 0.5, -1.0}, kFace, kFace).crossed);  // beside
  EXPECT_FALSE(cc::sweptCrossing<Quad4Facet>({0.5, 0.5, 1.0}, {0.5, 0.5, 0.1}, kFace, kFace).crossed);   // stops short
}

// ---- Curved facets: the node must end behind the facet, not only behind one of its flat pieces ----------

// A quadratic facet on the parent domain (z = 0 in 3D, y = 0 in 2D) whose mid-edge nodes are raised by 0.1
// (and a Quad9's centre by 0.2) into the master body, away from the front: the facet bulges away from the
// slave, as a master indented by it does, and lies up to 0.05 (its sagitta over each chord) behind its
// flat pieces. A node that comes from the front and stops between a piece and the facet has a positive gap
// on the facet and has not crossed it (the shallow ironing on Q8: a die node resting in the sliver of a
// 3-node edge was reported as tunnelling, docs/verification-contact.md §11).
// Depth d into the master body as a coordinate: the body of a segment traversed towards +x lies above it
// (+y), that of a counter-clockwise face below it (−z).
template <class Facet>
constexpr double kIntoBody = Facet::kSpaceDim == 2 ? 1.0 : -1.0;

template <class Facet>
std::array<typename Facet::Point, Facet::kNodes> bulgingFacet(int corners, double centreDepth = 0.0) {
  std::array<typename Facet::Point, Facet::kNodes> x{};
  for (int i = 0; i < Facet::kNodes; ++i) {
    const auto xi = Facet::nodeCoords(i);
    for (int a = 0; a < Facet::kSurfaceDim; ++a) x[i][a] = xi[a];
    const double depth = i < corners ? 0.0 : (centreDepth > 0.0 && i == Facet::kNodes - 1) ? centreDepth : 0.1;
    x[i][Facet::kSpaceDim - 1] = kIntoBody<Facet> * depth;
  }
  return x;
}

// The node comes straight in from depth −1 (in front) to depth `end` over the parent point `at`, where
// the facet lies at depth `surface` and its flat piece at depth `piece`: it must not cross when it stops
// between the two, and crosses through the piece at t = (1 + piece) / (1 + end) when it goes behind both.
template <class Facet>
void expectSliverIsNotACrossing(const std::array<typename Facet::Point, Facet::kNodes>& facet,
                                const typename Facet::SurfaceCoords& at, double piece, double surface) {
  const auto path = [&](double end) {
    typename Facet::Point x0{}, x1{};
    for (int a = 0; a < Facet::kSurfaceDim; ++a) x0[a] = x1[a] = at[a];
    x0[Facet::kSpaceDim - 1] = -kIntoBody<Facet>;
    x1[Facet::kSpaceDim - 1] = kIntoBody<Facet> * end;
    return cc::sweptCrossing<Facet>(x0, x1, facet, facet);
  };
  EXPECT_FALSE(path(0.5 * (piece + surface)).crossed) << "stopped between the piece and the facet";
  const double behind = surface + 0.05;
  const auto c = path(behind);
  ASSERT_TRUE(c.crossed) << "went behind the facet";
  EXPECT_NEAR(c.time, (1.0 + piece) / (1.0 + behind), 1e-12) << "entered through the flat piece";
}

TEST(SweptCrossingCurved, Line3SliverIsNotACrossing) {
  // Depth 0.1 (1 − ξ²) at ξ = 0.5: the facet at 0.075, the chord (ξ = 0 … 1) at 0.05.
  expectSliverIsNotACrossing<cc::Line3Facet>(bulgingFacet<cc::Line3Facet>(2), {0.5}, 0.05, 0.075);
}

TEST(SweptCrossingCurved, Tri6SliverIsNotACrossing) {
  // At the centroid: the facet 0.1 · 4 (L₀L₁ + L₁L₂ + L₂L₀) = 0.4/3, the middle triangle 0.1.
  expectSliverIsNotACrossing<cc::Tri6Facet>(bulgingFacet<cc::Tri6Facet>(3), {1.0 / 3.0, 1.0 / 3.0}, 0.1, 0.4 / 3.0);
}

TEST(SweptCrossingCurved, Quad8SliverIsNotACrossing) {
  // At the centre: four mid-edge functions of 1/2 each, 0.2; the middle quadrilateral of the mid-edge nodes 0.1.
  expectSliverIsNotACrossing<cc::Quad8Facet>(bulgingFacet<cc::Quad8Facet>(4), {0.0, 0.0}, 0.1, 0.2);
}

TEST(SweptCrossingCurved, Quad9SliverIsNotACrossing) {
  // The depths are 0.1 (2 − ξ² − η²) at the nodes, so the facet is that paraboloid: 0.15 at (0.5, 0.5),
  // on the diagonal centre – corner 2 of the triangle 8–5–2, whose depth there is 0.1.
  expectSliverIsNotACrossing<cc::Quad9Facet>(bulgingFacet<cc::Quad9Facet>(4, 0.2), {0.5, 0.5}, 0.1, 0.15);
}

// ---- ContactInterfaceBase::tunnellingNodes -------------------------------------------------------------

// Three slave nodes on y = 0 (x = 0, 1, 2), a rigid master above them moving down by `motion` at λ = 1.
cc::ContactInterfaceSpec plateSpec(std::vector<cc::Vector<2>> points, double motion) {
  return cc::testing::threeNodesUnderRigidLine(points, {0.0, -motion});
}

class Tunnelling : public ::testing::Test {
 protected:
  static void evaluate(cc::ContactInterfaceBase& i, double lambda) {
    const auto sink = [](const cc::GlobalIndex*, int, const double*, const double*, const double*) {};
    i.evaluate(cc::testing::threeNodesOnXAxis, lambda, true, sink);
  }
  // The plate: a line 0.5 above the nodes, traversed towards +x (the body above it); 4 long, so a
  // node more than 4 away from it is beyond the search reach.
  std::vector<cc::Vector<2>> line_{{-1.0, 0.5}, {3.0, 0.5}};
};

TEST_F(Tunnelling, PlateBeyondReachIsTunnelling) {
  const auto interface = cc::makeContactInterface(plateSpec(line_, 10.0), {1, 1, 1});
  auto& i = *interface;
  evaluate(i, 0.0);
  i.commit();
  evaluate(i, 1.0);  // the plate at y = −9.5: every node 9.5 behind it, out of reach, "open"
  const auto t = i.tunnellingNodes();
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[0].node, 0);
  EXPECT_NEAR(t[0].time, 0.05, 1e-12);  // the plate reaches y = 0 after 0.5 of its 10
}

TEST_F(Tunnelling, PenaltyPenetrationIsNot) {
  const auto interface = cc::makeContactInterface(plateSpec(line_, 10.0), {1, 1, 1});
  auto& i = *interface;
  evaluate(i, 0.0);
  i.commit();
  evaluate(i, 0.051);  // 0.01 of penetration: in contact
  EXPECT_TRUE(i.tunnellingNodes().empty());
  i.commit();
  evaluate(i, 0.06);  // deeper, still in contact
  EXPECT_TRUE(i.tunnellingNodes().empty());
  // From contact (penetrating at the commit) to beyond reach: went through.
  i.commit();
  evaluate(i, 1.0);
  EXPECT_EQ(i.tunnellingNodes().size(), 3u);
}

TEST_F(Tunnelling, RolledBackIncrementIsMeasuredFromTheCommit) {
  const auto interface = cc::makeContactInterface(plateSpec(line_, 10.0), {1, 1, 1});
  auto& i = *interface;
  evaluate(i, 0.0);
  i.commit();
  evaluate(i, 1.0);
  i.rollback();
  evaluate(i, 0.03);  // the cut-back attempt stops short of the nodes
  EXPECT_TRUE(i.tunnellingNodes().empty());
}

TEST_F(Tunnelling, ThroughAThinBodyToItsFarSide) {
  // A closed thin plate, 0.2 thick (body on the left of each edge): after the step the nodes are 2.3
  // above its top face, in reach and in front of it (g_N > 0): not in contact, but they went through.
  const std::vector<cc::Vector<2>> thin{{-1.0, 0.5}, {3.0, 0.5}, {3.0, 0.7}, {-1.0, 0.7}, {-1.0, 0.5}};
  const auto interface = cc::makeContactInterface(plateSpec(thin, 3.0), {1, 1, 1});
  auto& i = *interface;
  evaluate(i, 0.0);
  i.commit();
  evaluate(i, 1.0);
  const auto t = i.tunnellingNodes();
  ASSERT_EQ(t.size(), 3u);
  EXPECT_EQ(t[1].facet, 0);  // through the bottom face
}

TEST_F(Tunnelling, OnlyTheNodesThisRankEvaluates) {
  const auto interface = cc::makeContactInterface(plateSpec(line_, 10.0), {0, 1, 0});
  auto& i = *interface;
  evaluate(i, 0.0);
  i.commit();
  evaluate(i, 1.0);
  const auto t = i.tunnellingNodes();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].node, 1);
}

TEST_F(Tunnelling, MovingAwayIsNot) {
  const auto interface = cc::makeContactInterface(plateSpec(line_, -10.0), {1, 1, 1});
  auto& i = *interface;
  evaluate(i, 0.0);
  i.commit();
  evaluate(i, 1.0);
  EXPECT_TRUE(i.tunnellingNodes().empty());
}

}  // namespace
