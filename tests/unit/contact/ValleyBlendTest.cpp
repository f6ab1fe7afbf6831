// The contact of a node within the band around a valley edge, blended over the two facets sharing it
// (contact/ValleyBlend.hpp; issue 22, point 3). Checked: which edges blend (valleys only, not coplanar or
// convex ones, not beyond the band); the gap equals the single facet's at and beyond the band's edge and
// the mean of the two at the valley's bottom; the force is continuous across the band's edge (the single
// facet's element there); swapping the two facets changes nothing; and the tangent against central
// differences of the residual over the union of both facets' nodes (2D vertex, 3D edge of flat and warped
// faces, at points across the band).
#include "contact/ValleyBlend.hpp"
#include "ValleyBlendTestTools.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace cc = contessa::contact;
using namespace contessa::contact::testing;

namespace {

constexpr double kPenalty = 1e3;
constexpr double kSlaveSize = 5.0;  // L_k: the band is b = min(1e-2 L_k, ½ ℓ) = 0.05 here

template <class Facet>
cc::ValleyBlendResult<Facet> blendAt(const typename Facet::Point& slave, const Facets<Facet>& facets, const cc::ValleyEdge& e) {
  return cc::evaluateValleyBlend<Facet>(cc::PenaltyNormalLaw(kPenalty), slave, facets[e.a], facets[e.b], e);
}

/// Worst entry-wise relative difference between the tangent and central differences of the residual (an
/// entry below 1e-6 of the largest is compared against that floor: the differences' round-off).
template <class Facet>
double tangentError(const typename Facet::Point& slave, const Facets<Facet>& facets, const cc::ValleyEdge& e) {
  const auto r = blendAt(slave, facets, e);
  EXPECT_TRUE(r.isActive());
  const int n = r.numDofs();
  const double h = 1e-6;
  double worst = 0.0, scale = 0.0;
  for (double v : r.tangent) scale = std::max(scale, std::abs(v));
  for (int d = 0; d < n; ++d) {
    auto sp = slave, sm = slave;
    auto fp = facets, fm = facets;
    perturb(sp, fp, r, e, d, h);
    perturb(sm, fm, r, e, d, -h);
    const auto rp = blendAt(sp, fp, e), rm = blendAt(sm, fm, e);
    for (int i = 0; i < n; ++i) {
      const double fd = (rp.residual[i] - rm.residual[i]) / (2.0 * h);
      const double k = r.tangent[static_cast<std::size_t>(i) * n + d];
      const double err = std::abs(fd - k) / std::max(std::abs(k), 1e-6 * scale);
      worst = std::max(worst, err);
    }
  }
  return worst;
}

}  // namespace

TEST(ValleyBlend, FindsValleysOnlyWithinTheBand2D) {
  const auto v = valley2D(0.02);
  const auto e = cc::findValleyEdge<cc::Line2Facet>({0.01, -0.001}, 0, v, v, kSlaveSize);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->b, 1u);
  EXPECT_NEAR(e->band, 0.05, 1e-15);
  EXPECT_NEAR(e->angle, 2.0 * std::atan(0.02), 1e-12);
  EXPECT_FALSE(cc::findValleyEdge<cc::Line2Facet>({-0.06, -0.001}, 0, v, v, kSlaveSize));  // past the band
  EXPECT_FALSE(cc::findValleyEdge<cc::Line2Facet>({0.01, -0.001}, 0, valley2D(0.0), valley2D(0.0), kSlaveSize));  // flat
  EXPECT_FALSE(cc::findValleyEdge<cc::Line2Facet>({0.01, -0.001}, 0, valley2D(-0.02), valley2D(-0.02), kSlaveSize));  // ridge
  EXPECT_FALSE(cc::findValleyEdge<cc::Line2Facet>({0.01, -0.001}, 0, valley2D(1e-4), valley2D(1e-4), kSlaveSize));  // < 1e-3 rad
}

TEST(ValleyBlend, GapJoinsTheFacetsAndIsSymmetric2D) {
  const auto v = valley2D(0.02);
  const double depth = -0.002;
  // At the bottom: the mean of the two facets' gaps (here equal), the force along the bisector (+y).
  const auto e = *cc::findValleyEdge<cc::Line2Facet>({0.0, depth}, 0, v, v, kSlaveSize);
  const auto bottom = blendAt<cc::Line2Facet>({0.0, depth}, v, e);
  EXPECT_NEAR(bottom.weight, 0.5, 1e-12);
  EXPECT_NEAR(bottom.gap, depth / std::sqrt(1.0 + 0.02 * 0.02), 1e-15);
  EXPECT_NEAR(bottom.residual[0], 0.0, 1e-15);
  // Swapping the facets: the same gap and slave force.
  const Facets<cc::Line2Facet> s{v[1], v[0]};  // the same facets (ids kept), listed the other way round
  for (double x : {-0.03, 0.0, 0.02}) {
    const auto e1 = cc::findValleyEdge<cc::Line2Facet>({x, depth}, 0, v, v, kSlaveSize);
    const auto e2 = cc::findValleyEdge<cc::Line2Facet>({x, depth}, 0, s, v, kSlaveSize);
    ASSERT_TRUE(e1 && e2);
    const auto r1 = blendAt<cc::Line2Facet>({x, depth}, v, *e1), r2 = blendAt<cc::Line2Facet>({x, depth}, s, *e2);
    EXPECT_NEAR(r1.gap, r2.gap, 1e-15);
    EXPECT_NEAR(r1.residual[0], r2.residual[0], 1e-12);
    EXPECT_NEAR(r1.residual[1], r2.residual[1], 1e-12);
  }
  // From the band's edge on (z = −b: x ≈ −b − 2 depth sin(θ/2), the two projections' offset) the blend is
  // facet a's element: its gap, and the force on every node. Within the band the selector takes it.
  const double edge = -e.band - 1e-3;
  EXPECT_FALSE(cc::findValleyEdge<cc::Line2Facet>({edge, depth}, 0, v, v, kSlaveSize));
  const auto r = blendAt<cc::Line2Facet>({edge, depth}, v, e);
  EXPECT_EQ(r.weight, 0.0);
  const cc::NodeToFacetContact<cc::Line2Facet> single({kPenalty, 0.0, 0.0});
  const auto a = single.evaluate({{edge, depth}, v[0].x}, 0, {});
  EXPECT_NEAR(r.gap, a.gap, 1e-15);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(r.residual[i], a.residual[i], 1e-13) << i;
  for (int i = 6; i < r.numDofs(); ++i) EXPECT_EQ(r.residual[i], 0.0) << i;
  // Just inside, the blend differs from the facet by O(t³) (S is C²): continuous.
  const auto inside = blendAt<cc::Line2Facet>({-e.band + 2e-4, depth}, v, e);
  const auto ai = single.evaluate({{-e.band + 2e-4, depth}, v[0].x}, 0, {});
  EXPECT_GT(inside.weight, 0.0);
  EXPECT_LT(inside.weight, 1e-6);
  EXPECT_NEAR(inside.residual[1], ai.residual[1], 1e-6 * std::abs(ai.residual[1]));
}

TEST(ValleyBlend, TangentMatchesFiniteDifferences2D) {
  const auto v = valley2D(0.02);
  for (double x : {-0.045, -0.02, -0.004, 0.0, 0.013, 0.04}) {
    const cc::Line2Facet::Point slave{x, -0.003};
    const auto e = cc::findValleyEdge<cc::Line2Facet>(slave, x < 0 ? 0 : 1, v, v, kSlaveSize);
    ASSERT_TRUE(e) << x;
    const double error = tangentError<cc::Line2Facet>(slave, v, *e);
    EXPECT_LT(error, 1e-5) << "x = " << x;
    std::printf("ValleyBlend 2D x = %g: tangent vs FD %.1e\n", x, error);
  }
}

TEST(ValleyBlend, FindsTheSharedEdgeIn3D) {
  const auto v = valley3D(0.02, 0.0);
  const auto e = cc::findValleyEdge<cc::Quad4Facet>({0.01, 0.5, -0.001}, 1, v, v, kSlaveSize);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->a, 1u);
  EXPECT_EQ(e->b, 0u);
  EXPECT_EQ(e->acrossA, 0);
  EXPECT_EQ(e->sideA, -1.0);
  EXPECT_EQ(e->acrossB, 0);
  EXPECT_EQ(e->sideB, 1.0);
  EXPECT_FALSE(cc::findValleyEdge<cc::Quad4Facet>({0.01, 0.5, -0.001}, 1, valley3D(0.0, 0.0), valley3D(0.0, 0.0), kSlaveSize));
  EXPECT_FALSE(cc::findValleyEdge<cc::Quad4Facet>({0.01, 0.5, -0.001}, 1, valley3D(-0.02, 0.0), valley3D(-0.02, 0.0), kSlaveSize));
}

TEST(ValleyBlend, TangentMatchesFiniteDifferences3D) {
  for (const auto& [warp, rotated] : {std::pair{0.0, false}, std::pair{0.05, false}, std::pair{0.05, true}}) {
    const auto v = valley3D(0.02, warp, rotated);
    for (const auto& slave : {cc::Quad4Facet::Point{-0.04, 0.5, -0.003}, cc::Quad4Facet::Point{-0.01, 0.2, -0.002},
                              cc::Quad4Facet::Point{0.0, 0.0, -0.002}, cc::Quad4Facet::Point{0.015, 0.9, -0.004},
                              cc::Quad4Facet::Point{0.045, 0.6, -0.001}}) {
      const auto e = cc::findValleyEdge<cc::Quad4Facet>(slave, slave[0] < 0 ? 0 : 1, v, v, kSlaveSize);
      ASSERT_TRUE(e);
      const double error = tangentError<cc::Quad4Facet>(slave, v, *e);
      EXPECT_LT(error, 1e-5) << "warp " << warp << " at (" << slave[0] << ", " << slave[1] << ", " << slave[2] << ")";
      std::printf("ValleyBlend 3D warp %g%s at (%g, %g): tangent vs FD %.1e\n", warp, rotated ? " rotated" : "", slave[0],
                  slave[1], error);
    }
  }
}

