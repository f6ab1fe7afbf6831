// The facet selector's rules that the augmented Lagrangian's frictional patch test exposed
// (docs/theory-contact.md §3 and §15, "The frictional patch test"): a node held in contact by its multiplier
// at a positive gap past a free end stays on the end facet (the free-edge rule tests λ_N + ε_N g_N < 0, not
// g_N < 0); a vertex or edge point shared by flat facets (normals within FacetSelectorOptions::flatAngle) is
// no corner (the node stays on the facet it overshoots least instead of touching the point along
// x^k − x_b).
#include "contact/FacetSelector.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace cc = contessa::contact;

namespace {

using Segment = cc::MasterFacetNodes<cc::Line2Facet>;
using Face = cc::MasterFacetNodes<cc::Quad4Facet>;
using P2 = cc::Vector<2>;
using P3 = cc::Vector<3>;

// Faces A over [0, 1] × [0, 1] in z = 0 and B beyond the shared edge x = 1 (nodes 1, 4), B's far edge at
// z = slope (slope < 0: a convex ridge); normals +z-ish, the master body below. Free boundary: y = 0, y = 1,
// x = 0, x = 2.
Face faceA() { return Face{0, {0, 1, 4, 3}, {P3{0, 0, 0}, P3{1, 0, 0}, P3{1, 1, 0}, P3{0, 1, 0}}}; }
Face faceB(double slope) { return Face{1, {1, 2, 5, 4}, {P3{1, 0, 0}, P3{2, 0, slope}, P3{2, 1, slope}, P3{1, 1, 0}}}; }

}  // namespace

TEST(AugmentedSelection, NodeHeldAtAPositiveGapPastAFreeEndStaysOnTheEndSegment) {
  // The top of a block y < 0 from x = 1 to x = 0 (counter-clockwise: right to left); the node is past the
  // free end x = 1 by 0.01 (within 3e-2 of L_k = 1) and 1e-6 above the segment's extension.
  const std::vector<Segment> top{Segment{0, {0, 1}, {P2{1.0, 0.0}, P2{0.0, 0.0}}}};
  const cc::FacetSelector<cc::Line2Facet> selector;
  const P2 node{1.01, 1e-6};
  EXPECT_EQ(selector.select(node, top, 1.0).kind, cc::SelectionKind::None);  // the penalty law: open
  // λ_N = −2e-6 ε_N holds it up to g_N = 2e-6 (eq. 15.1): in contact, on the end segment extended.
  const auto held = selector.select(node, top, 1.0, 2e-6);
  ASSERT_EQ(held.kind, cc::SelectionKind::OnFacet);
  EXPECT_EQ(held.facet, 0);
  EXPECT_NEAR(held.gap, 1e-6, 1e-15);
  EXPECT_EQ(selector.select(node, top, 1.0, 0.5e-6).kind, cc::SelectionKind::None);  // held up to 5e-7 only
  EXPECT_EQ(selector.select({1.04, 1e-6}, top, 1.0, 2e-6).kind, cc::SelectionKind::None);  // beyond the reach
}

TEST(AugmentedSelection, NodeHeldAtAPositiveGapPastAFreeBoundaryStaysOnTheBoundaryFace) {
  const std::vector<Face> faces{faceA(), faceB(0.0)};
  const cc::FacetSelector<cc::Quad4Facet> selector;
  const P3 node{0.5, -0.024, 1e-6};  // past y = 0 by 0.024 < 3e-2 L_k, 1e-6 above
  EXPECT_EQ(selector.select(node, faces, 1.0).kind, cc::SelectionKind::None);
  const auto held = selector.select(node, faces, 1.0, 2e-6);
  ASSERT_EQ(held.kind, cc::SelectionKind::OnFacet);
  EXPECT_EQ(held.facet, 0);
  EXPECT_NEAR(held.gap, 1e-6, 1e-15);
}

// FacetSelectorOptions::flatAngle is 1e-12 (round-off); the rule is shown with a ridge of 1e-7 rad, which a
// node can be placed in the wedge of, under flatAngle = 1e-6.
cc::FacetSelectorOptions flatBelow(double angle) {
  cc::FacetSelectorOptions options;
  options.flatAngle = angle;
  return options;
}

TEST(AugmentedSelection, AnEdgeBetweenFlatFacesIsNoRidge) {
  // A node 1e-3 above the 1e-7 rad ridge and 2e-11 past the edge over A lies outside both faces (B's
  // projection falls 8e-11 short of B). As a ridge, the node touches the edge point along x^k − x_b, a
  // normal 2e-8 rad off A's for this offset and arbitrary as g_N → 0; flat, it stays on A, the face it
  // overshoots least, extended.
  const std::vector<Face> faces{faceA(), faceB(-1e-7)};
  const P3 node{1.0 + 2e-11, 0.5, 1e-3};
  const auto flat = cc::FacetSelector<cc::Quad4Facet>(flatBelow(1e-6)).select(node, faces, 1.0);
  ASSERT_EQ(flat.kind, cc::SelectionKind::OnFacet);
  EXPECT_EQ(flat.facet, 0);
  EXPECT_NEAR(flat.gap, 1e-3, 1e-12);
  EXPECT_EQ(flat.normal[2], 1.0);
  // Every shared edge a ridge (the former rule), and the default's 1e-12: the node touches the edge.
  EXPECT_EQ(cc::FacetSelector<cc::Quad4Facet>(flatBelow(0.0)).select(node, faces, 1.0).kind, cc::SelectionKind::AtEdge);
  EXPECT_EQ(cc::FacetSelector<cc::Quad4Facet>().select(node, faces, 1.0).kind, cc::SelectionKind::AtEdge);
}

TEST(AugmentedSelection, AVertexBetweenCollinearSegmentsIsNoCorner) {
  // The top of a block, right to left: (2, −1e-7) → (1, 0) → (0, 0), a convex kink of 1e-7 rad at x = 1. A
  // node 1e-3 above, 2e-11 right of the vertex, projects outside both segments.
  const std::vector<Segment> top{Segment{10, {0, 1}, {P2{2.0, -1e-7}, P2{1.0, 0.0}}}, Segment{11, {1, 2}, {P2{1.0, 0.0}, P2{0.0, 0.0}}}};
  const P2 node{1.0 + 2e-11, 1e-3};
  const auto flat = cc::FacetSelector<cc::Line2Facet>(flatBelow(1e-6)).select(node, top, 1.0);
  ASSERT_EQ(flat.kind, cc::SelectionKind::OnFacet);
  EXPECT_EQ(flat.facet, 11);  // overshot by 4e-11 in ξ; segment 10 by 1.6e-10
  EXPECT_NEAR(flat.gap, 1e-3, 1e-12);
  EXPECT_EQ(cc::FacetSelector<cc::Line2Facet>(flatBelow(0.0)).select(node, top, 1.0).kind, cc::SelectionKind::AtVertex);
  EXPECT_EQ(cc::FacetSelector<cc::Line2Facet>().select(node, top, 1.0).kind, cc::SelectionKind::AtVertex);
}
