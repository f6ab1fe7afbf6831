// Closest-point projection (eq. 1–5) and the local choice of the master segment of a slave node.
#include "contact/Projection.hpp"
#include "contact/FacetSelector.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace cc = contessa::contact;
using cc::Vector;

namespace {

constexpr double kTol = 1e-12;

// The top side of a block that occupies y < 0, ordered counter-clockwise around the block: right to left.
cc::SegmentProjection2D::NodeCoords topOfBlock(double xRight, double xLeft) { return {{{xRight, 0.0}, {xLeft, 0.0}}}; }

}  // namespace

TEST(Projection2D, SlaveAboveTheMiddleHasXiZeroAndPositiveGap) {
  const auto p = cc::SegmentProjection2D().project({1.0, 0.3}, topOfBlock(2.0, 0.0));
  ASSERT_TRUE(p.converged);
  EXPECT_NEAR(p.xi[0], 0.0, kTol);
  EXPECT_NEAR(p.gap, 0.3, kTol);
  EXPECT_NEAR(p.position[0], 1.0, kTol);
  EXPECT_NEAR(p.position[1], 0.0, kTol);
  // eq. (5) in 2D: outward normal of the counter-clockwise boundary of the block (pointing to +y).
  EXPECT_NEAR(p.normal[0], 0.0, kTol);
  EXPECT_NEAR(p.normal[1], 1.0, kTol);
  EXPECT_NEAR(p.metric(0, 0), 1.0, kTol);         // ā_1 = (x_2 − x_1)/2 = (−1, 0)
  EXPECT_NEAR(p.inverseMetric(0, 0), 1.0, kTol);
  EXPECT_NEAR(p.contravariantBasis[0][0], -1.0, kTol);
  EXPECT_FALSE(p.isPenetrating());
}

TEST(Projection2D, SlaveBelowTheSurfaceHasNegativeGap) {
  const auto p = cc::SegmentProjection2D().project({1.0, -0.2}, topOfBlock(2.0, 0.0));
  EXPECT_NEAR(p.xi[0], 0.0, kTol);
  EXPECT_NEAR(p.gap, -0.2, kTol);
  EXPECT_TRUE(p.isPenetrating());  // eq. (6)
}

TEST(Projection2D, SlaveNearTheSegmentEnd) {
  // x̄ = H_1 (2,0) + H_2 (0,0) = (1 − ξ, 0), so x = 0.05 is ξ = 0.95.
  const auto p = cc::SegmentProjection2D().project({0.05, 0.1}, topOfBlock(2.0, 0.0));
  EXPECT_NEAR(p.xi[0], 0.95, kTol);
  EXPECT_NEAR(p.shape[0], 0.025, kTol);
  EXPECT_NEAR(p.shape[1], 0.975, kTol);
  EXPECT_NEAR(p.gap, 0.1, kTol);
  EXPECT_TRUE(p.isInside(0.0));
  const auto beyond = cc::SegmentProjection2D().project({-0.1, 0.1}, topOfBlock(2.0, 0.0));
  EXPECT_NEAR(beyond.xi[0], 1.1, kTol);  // not clamped
  EXPECT_FALSE(beyond.isInside(1e-8));
}

TEST(Projection2D, InclinedSegmentMatchesTheAnalyticalProjection) {
  const Vector<2> x1{3.0, 1.5};
  const Vector<2> x2{-1.0, -0.5};
  const Vector<2> slave{0.4, 1.7};
  const auto p = cc::SegmentProjection2D().project(slave, {{x1, x2}});
  ASSERT_TRUE(p.converged);
  // Straight segment: r(ξ) is linear in ξ, one Newton step is exact, the second only confirms it.
  EXPECT_LE(p.iterations, 2);
  const Vector<2> e = cc::subtract(x2, x1);
  const double l2 = cc::dot(e, e);
  const double xiExact = 2.0 * cc::dot(cc::subtract(slave, x1), e) / l2 - 1.0;
  EXPECT_NEAR(p.xi[0], xiExact, kTol);
  // eq. (1): the distance vector is orthogonal to ā_1, and its length is |g_N| (eq. 4).
  const Vector<2> d = cc::subtract(slave, p.position);
  EXPECT_NEAR(cc::dot(d, p.covariantBasis[0]), 0.0, kTol);
  EXPECT_NEAR(std::abs(p.gap), cc::norm(d), kTol);
  // n̄ = ā_1 × e_3/‖ā_1‖ = (a_y, −a_x)/‖ā_1‖: here ā_1 = (−2, −1), n̄ = (−1, 2)/√5.
  EXPECT_NEAR(p.normal[0], -1.0 / std::sqrt(5.0), kTol);
  EXPECT_NEAR(p.normal[1], 2.0 / std::sqrt(5.0), kTol);
  EXPECT_GT(p.gap, 0.0);
  EXPECT_NEAR(p.metric(0, 0), l2 / 4.0, kTol);
}

TEST(Projection2D, NormalPointsOutOfACounterClockwiseBody) {
  // Unit square ordered counter-clockwise: a point outside each side has g_N > 0, inside g_N < 0.
  const std::array<Vector<2>, 4> corner{{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}};
  const std::array<Vector<2>, 4> outside{{{0.5, -0.2}, {1.2, 0.5}, {0.5, 1.2}, {-0.2, 0.5}}};
  for (int side = 0; side < 4; ++side) {
    const cc::SegmentProjection2D::NodeCoords segment{{corner[side], corner[(side + 1) % 4]}};
    EXPECT_NEAR(cc::SegmentProjection2D().project(outside[side], segment).gap, 0.2, kTol) << "side " << side;
    EXPECT_NEAR(cc::SegmentProjection2D().project({0.5, 0.5}, segment).gap, -0.5, kTol) << "side " << side;
  }
}

TEST(Projection3D, WarpedQuadFaceConvergesInAFewNewtonIterations) {
  // Counter-clockwise seen from +z: n̄ = ā_1 × ā_2 (eq. 5) points to +z.
  const cc::FaceProjection3D::NodeCoords face{{{0.0, 0.0, 0.0}, {2.0, 0.1, 0.4}, {2.2, 2.0, -0.1}, {-0.1, 1.9, 0.3}}};
  const Vector<3> slave{0.7, 1.3, 0.9};
  const auto p = cc::FaceProjection3D().project(slave, face);
  ASSERT_TRUE(p.converged);
  EXPECT_LE(p.iterations, 6);
  EXPECT_TRUE(p.isInside(0.0));
  const Vector<3> d = cc::subtract(slave, p.position);
  for (int alpha = 0; alpha < 2; ++alpha) EXPECT_NEAR(cc::dot(d, p.covariantBasis[alpha]), 0.0, 1e-12);  // eq. (1)
  EXPECT_NEAR(std::abs(p.gap), cc::norm(d), 1e-12);  // d ∥ n̄
  EXPECT_GT(p.gap, 0.0);
  EXPECT_GT(p.normal[2], 0.0);
  // ā^α · ā_β = δ^α_β
  for (int alpha = 0; alpha < 2; ++alpha)
    for (int beta = 0; beta < 2; ++beta)
      EXPECT_NEAR(cc::dot(p.contravariantBasis[alpha], p.covariantBasis[beta]), alpha == beta ? 1.0 : 0.0, 1e-12);
  // It is the closest point: no point of a fine grid on the face is closer.
  double closest = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 200; ++i)
    for (int j = 0; j <= 200; ++j) {
      const auto q = cc::FaceProjection3D::evaluateAt(slave, face, {-1.0 + 0.01 * i, -1.0 + 0.01 * j});
      closest = std::min(closest, cc::norm(cc::subtract(slave, q.position)));
    }
  EXPECT_LE(cc::norm(d), closest + 1e-14);
  EXPECT_GT(cc::norm(d), closest - 1e-3);
}

namespace {

/// eq. (1) holds at ξ̄: (x^k − x̄)·ā_α = 0, relative to the sizes involved.
void expectOrthogonal(const Vector<3>& slave, const cc::ProjectionResult<cc::Quad4Facet>& p) {
  const Vector<3> d = cc::subtract(slave, p.position);
  for (int alpha = 0; alpha < 2; ++alpha)
    EXPECT_NEAR(cc::dot(d, p.covariantBasis[alpha]), 0.0, 1e-12 * (1.0 + cc::norm(d)) * cc::norm(p.covariantBasis[alpha]));
  EXPECT_NEAR(std::abs(p.gap), cc::norm(d), 1e-12 * (1.0 + cc::norm(d)));
}

}  // namespace

TEST(Projection3D, FlatFaceIsExactAndStartsFromTheClosestPiece) {
  // Flat, not a parallelogram: x̄(ξ) is still bilinear, so Newton iterates; the start is the closest
  // point of the nearer triangle, which is already close.
  const cc::FaceProjection3D::NodeCoords face{{{0.0, 0.0, 0.0}, {2.4, 0.2, 0.0}, {2.1, 1.8, 0.0}, {-0.3, 2.2, 0.0}}};
  for (const Vector<2> xi : {Vector<2>{0.0, 0.0}, Vector<2>{0.9, -0.7}, Vector<2>{-0.99, 0.98}}) {
    const auto onFace = cc::FaceProjection3D::evaluateAt({0.0, 0.0, 0.0}, face, xi);
    const Vector<3> slave = cc::add(onFace.position, Vector<3>{0.0, 0.0, -0.3});
    const auto p = cc::FaceProjection3D().project(slave, face);
    ASSERT_TRUE(p.converged);
    EXPECT_LE(p.iterations, 5);
    EXPECT_NEAR(p.xi[0], xi[0], 1e-12);
    EXPECT_NEAR(p.xi[1], xi[1], 1e-12);
    EXPECT_NEAR(p.gap, -0.3, 1e-12);
    expectOrthogonal(slave, p);
  }
}

TEST(Projection3D, FarOutsideAWarpedFaceConvergesOnItsExtension) {
  // Far beyond an edge and a corner of a warped face: the unclamped projection onto the bilinear
  // extension (ξ̄ outside [−1, 1]², for the selector to judge), reached with limited, backtracked steps.
  const cc::FaceProjection3D::NodeCoords face{{{0.0, 0.0, 0.0}, {2.0, 0.1, 0.4}, {2.2, 2.0, -0.1}, {-0.1, 1.9, 0.3}}};
  for (const Vector<3> slave : {Vector<3>{6.0, 1.0, 0.5}, Vector<3>{-3.0, -4.0, 2.0}, Vector<3>{1.0, 9.0, -1.0}}) {
    const auto p = cc::FaceProjection3D().project(slave, face);
    ASSERT_TRUE(p.converged);
    EXPECT_FALSE(p.isInside(0.1));
    expectOrthogonal(slave, p);
    // A local minimum of the distance on the extension: no nearby surface point is closer.
    const double distance = cc::norm(cc::subtract(slave, p.position));
    for (int i = -2; i <= 2; ++i)
      for (int j = -2; j <= 2; ++j) {
        const auto q = cc::FaceProjection3D::evaluateAt(slave, face, {p.xi[0] + 0.05 * i, p.xi[1] + 0.05 * j});
        EXPECT_GE(cc::norm(cc::subtract(slave, q.position)), distance - 1e-12);
      }
  }
}

TEST(Projection3D, NearlyDegenerateFaceFallsBackToAnotherStart) {
  // A face collapsed almost to a triangle (nodes 2 and 3 a hair apart): near the collapsed edge ā_1 nearly
  // vanishes; projections inside the triangle still converge.
  const cc::FaceProjection3D::NodeCoords face{{{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {1.0, 2.0, 0.0}, {1.0 - 1e-9, 2.0, 0.0}}};
  for (const Vector<3> slave : {Vector<3>{1.0, 1.9, 0.2}, Vector<3>{0.7, 0.5, -0.1}, Vector<3>{1.0, 2.0, 0.05}}) {
    const auto p = cc::FaceProjection3D().project(slave, face);
    ASSERT_TRUE(p.converged) << slave[0] << " " << slave[1];
    EXPECT_NEAR(std::abs(p.gap), std::abs(slave[2]), 1e-9);
    EXPECT_NEAR(p.position[0], slave[0], 1e-6);
    EXPECT_NEAR(p.position[1], slave[1], 1e-6);
  }
  // Nodes 2 and 3 coincident: ā_1 = 0 along the collapsed edge η = 1, so Newton cannot start there ...
  const cc::FaceProjection3D::NodeCoords collapsed{{{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {1.0, 2.0, 0.0}, {1.0, 2.0, 0.0}}};
  EXPECT_FALSE(cc::FaceProjection3D().project({1.0, 1.2, 0.3}, collapsed, {0.3, 1.0}).converged);
  const auto inside = cc::FaceProjection3D().project({1.0, 1.2, 0.3}, collapsed);
  ASSERT_TRUE(inside.converged);
  EXPECT_EQ(inside.starts, 1);
  EXPECT_NEAR(inside.gap, 0.3, 1e-12);
  // ... and a node just beyond the collapsed corner has its two closest starts there: both fail, the
  // fallback (the centre) converges, on the extension beyond the corner (η̄ > 1: outside, for the selector).
  const Vector<3> beyond{1.0, 2.05, 0.05};
  const auto p = cc::FaceProjection3D().project(beyond, collapsed);
  ASSERT_TRUE(p.converged);
  EXPECT_EQ(p.starts, 3);
  EXPECT_NEAR(p.xi[1], 1.05, 1e-12);
  EXPECT_FALSE(p.isInside(0.01));
  EXPECT_NEAR(std::abs(p.gap), 0.05, 1e-12);
  expectOrthogonal(beyond, p);
}

TEST(Projection3D, GapIsInvariantUnderRigidRotation) {
  const cc::FaceProjection3D::NodeCoords face{{{0.0, 0.0, 0.0}, {2.0, 0.1, 0.4}, {2.2, 2.0, -0.1}, {-0.1, 1.9, 0.3}}};
  const Vector<3> slave{0.7, 1.3, -0.2};
  const auto reference = cc::FaceProjection3D().project(slave, face);
  ASSERT_TRUE(reference.converged);
  for (const double angle : {0.3, 1.9, -2.6}) {
    const double c = std::cos(angle), s = std::sin(angle);
    // About the x axis, then about z: a general rotation, plus a translation.
    auto move = [&](const Vector<3>& x) {
      const Vector<3> r1{x[0], c * x[1] - s * x[2], s * x[1] + c * x[2]};
      return Vector<3>{c * r1[0] - s * r1[1] + 3.0, s * r1[0] + c * r1[1] - 1.0, r1[2] + 0.5};
    };
    cc::FaceProjection3D::NodeCoords rotated{};
    for (int i = 0; i < 4; ++i) rotated[i] = move(face[i]);
    const auto p = cc::FaceProjection3D().project(move(slave), rotated);
    ASSERT_TRUE(p.converged);
    EXPECT_NEAR(p.gap, reference.gap, 1e-13);
    EXPECT_NEAR(p.xi[0], reference.xi[0], 1e-12);
    EXPECT_NEAR(p.xi[1], reference.xi[1], 1e-12);
  }
}

// ---- Segment selection --------------------------------------------------------------------------------

namespace {

cc::MasterFacetNodes<cc::Line2Facet> segment(int id, int node1, int node2, Vector<2> x1, Vector<2> x2) {
  return {id, {node1, node2}, {x1, x2}};
}

}  // namespace

TEST(FacetSelectorLine2, NodeSlidesFromOneSegmentToTheNext) {
  // Top of a block, counter-clockwise: nodes 0 (2, 0.1) → 1 (0, 0) → 2 (−2, 0), a slight convex kink.
  const std::vector<cc::MasterFacetNodes<cc::Line2Facet>> candidates{segment(10, 0, 1, {2.0, 0.1}, {0.0, 0.0}),
                                                    segment(11, 1, 2, {0.0, 0.0}, {-2.0, 0.0})};
  const cc::FacetSelector<cc::Line2Facet> selector;
  double previousGap = std::numeric_limits<double>::quiet_NaN();
  int switches = 0;
  int previousSegment = 10;
  for (int step = 0; step <= 100; ++step) {
    const double x = 0.5 - 0.01 * step;  // the node slides right to left across the vertex at x = 0
    const auto s = selector.select({x, -0.01}, candidates);
    ASSERT_NE(s.kind, cc::SelectionKind::None) << "x = " << x;
    EXPECT_TRUE(s.isPenetrating()) << "x = " << x;
    if (s.facet != previousSegment) {
      ++switches;
      EXPECT_LE(x, 1e-3) << "switched too early";  // the projection leaves segment 10 only past the vertex region
    }
    previousSegment = s.facet;
    if (!std::isnan(previousGap)) {
      EXPECT_NEAR(s.gap, previousGap, 2e-3) << "gap jumps at x = " << x;
    }
    previousGap = s.gap;
  }
  EXPECT_EQ(switches, 1);
  EXPECT_EQ(previousSegment, 11);
  // Exactly on the left segment far from the vertex: ξ inside, g_N = −0.01.
  const auto left = selector.select({-1.0, -0.01}, candidates);
  EXPECT_EQ(left.kind, cc::SelectionKind::OnFacet);
  EXPECT_EQ(left.facet, 11);
  EXPECT_NEAR(left.gap, -0.01, kTol);
}

TEST(FacetSelectorLine2, ConvexCornerUsesTheClosestVertex) {
  // Block [−2, 0]², counter-clockwise: right side node 1 (0,−2) → node 2 (0,0), top node 2 → node 3 (−2, 0).
  const std::vector<cc::MasterFacetNodes<cc::Line2Facet>> candidates{segment(0, 1, 2, {0.0, -2.0}, {0.0, 0.0}),
                                                    segment(1, 2, 3, {0.0, 0.0}, {-2.0, 0.0})};
  const cc::FacetSelector<cc::Line2Facet> selector;
  // Outside the corner: both projections fall outside their segments.
  const auto outside = selector.select({0.3, 0.4}, candidates);
  ASSERT_EQ(outside.kind, cc::SelectionKind::AtVertex);
  EXPECT_EQ(outside.vertexNode, 2);
  EXPECT_NEAR(outside.gap, 0.5, kTol);
  EXPECT_NEAR(outside.normal[0], 0.6, kTol);
  EXPECT_NEAR(outside.normal[1], 0.8, kTol);
  EXPECT_FALSE(outside.isPenetrating());
  // Penetrating near the corner: inside both, the smaller |g_N| (right side) pushes out the shortest way.
  const auto inside = selector.select({-0.1, -0.3}, candidates);
  ASSERT_EQ(inside.kind, cc::SelectionKind::OnFacet);
  EXPECT_EQ(inside.facet, 0);
  EXPECT_NEAR(inside.gap, -0.1, kTol);
  EXPECT_NEAR(inside.normal[0], 1.0, kTol);
}

TEST(FacetSelectorLine2, ConcaveCornerTakesTheSmallerGap) {
  // Valley: body below the polyline (2,2) → (0,0) → (−2,2), ordered counter-clockwise (right to left).
  const std::vector<cc::MasterFacetNodes<cc::Line2Facet>> candidates{segment(0, 0, 1, {2.0, 2.0}, {0.0, 0.0}),
                                                    segment(1, 1, 2, {0.0, 0.0}, {-2.0, 2.0})};
  const cc::FacetSelector<cc::Line2Facet> selector;
  // Above the valley the node projects inside both arms: the nearer arm wins.
  const auto above = selector.select({0.1, 0.5}, candidates);
  ASSERT_EQ(above.kind, cc::SelectionKind::OnFacet);
  EXPECT_EQ(above.facet, 0);
  EXPECT_NEAR(above.gap, 0.4 / std::sqrt(2.0), kTol);
  const auto mirrored = selector.select({-0.1, 0.5}, candidates);
  EXPECT_EQ(mirrored.facet, 1);
  EXPECT_NEAR(mirrored.gap, 0.4 / std::sqrt(2.0), kTol);
  // Penetrating under the valley vertex: projections outside both arms, contact with the vertex,
  // a negative gap and a normal that points up, out of the master body.
  const auto under = selector.select({0.05, -0.2}, candidates);
  ASSERT_EQ(under.kind, cc::SelectionKind::AtVertex);
  EXPECT_EQ(under.vertexNode, 1);
  EXPECT_NEAR(under.gap, -std::hypot(0.05, 0.2), kTol);
  EXPECT_GT(under.normal[1], 0.9);
  EXPECT_TRUE(under.isPenetrating());
  EXPECT_EQ(under.facet, 0);  // the arm whose projection overshoots least (ξ = 1.075 vs −1.125)
}

TEST(FacetSelectorLine2, NodeLeavingTheMasterSurfaceIsNotInContact) {
  // Free end at node 2 (−2, 0): beyond it there is no master surface.
  const std::vector<cc::MasterFacetNodes<cc::Line2Facet>> candidates{segment(0, 0, 1, {2.0, 0.0}, {0.0, 0.0}),
                                                    segment(1, 1, 2, {0.0, 0.0}, {-2.0, 0.0})};
  const cc::FacetSelector<cc::Line2Facet> selector;
  const auto gone = selector.select({-2.3, -0.01}, candidates);
  EXPECT_EQ(gone.kind, cc::SelectionKind::None);
  EXPECT_FALSE(gone.isPenetrating());
  EXPECT_EQ(gone.facet, -1);
  // Within the free-edge reach (3e-2 of the slave facet size L_k = 1) it is still on the segment.
  const auto atEnd = selector.select({-2.0 - 1e-10, -0.01}, candidates, 1.0);
  EXPECT_EQ(atEnd.kind, cc::SelectionKind::OnFacet);
  EXPECT_EQ(atEnd.facet, 1);
  EXPECT_TRUE(atEnd.isPenetrating());
  // No candidates at all.
  EXPECT_EQ(selector.select({0.0, 0.0}, {}).kind, cc::SelectionKind::None);
}

TEST(FacetSelectorLine2, PenetratingNodeJustPastAFreeEndStaysInContact) {
  // A flush edge: the end segment (0,0)→(−2,0) ends at the free vertex (−2, 0). A node at x = −2.024 is
  // past the end by less than 3e-2 of its slave facet size L_k = 1 (FacetSelectorOptions::freeEdgeTolerance).
  const std::vector<cc::MasterFacetNodes<cc::Line2Facet>> candidates{segment(0, 0, 1, {2.0, 0.0}, {0.0, 0.0}),
                                                    segment(1, 1, 2, {0.0, 0.0}, {-2.0, 0.0})};
  const cc::FacetSelector<cc::Line2Facet> selector;
  const auto penetrating = selector.select({-2.024, -0.01}, candidates, 1.0);
  EXPECT_EQ(penetrating.kind, cc::SelectionKind::OnFacet);
  EXPECT_EQ(penetrating.facet, 1);
  EXPECT_NEAR(penetrating.gap, -0.01, 1e-12);
  // The same place above the surface is off the master (an open node past the end), and a penetrating
  // node past the end by more than the tolerance is off it too, though only 1.8 % of the segment out.
  EXPECT_EQ(selector.select({-2.024, 0.01}, candidates, 1.0).kind, cc::SelectionKind::None);
  EXPECT_EQ(selector.select({-2.036, -0.01}, candidates, 1.0).kind, cc::SelectionKind::None);
  EXPECT_EQ(selector.select({-2.3, -0.01}, candidates, 1.0).kind, cc::SelectionKind::None);
  // A node sitting on the end, penetrating by round-off, stays on.
  EXPECT_EQ(selector.select({-2.0, -1e-9}, candidates).kind, cc::SelectionKind::OnFacet);
}
