// The slave nodes' tributary areas of every facet type (ContactSurface.hpp, tributaryAreas): positive at
// every node, summing to the facet's area (a uniform contact pressure transmits its total force), and on
// undistorted facets the values the docs give: the consistent ∫ H_i dA for Tri3, Quad4, Line3, Quad9; the
// sub-facet areas for Tri6 and Quad8, whose consistent integrals are 0 and −A/12 at the corners.
#include "contact/ContactSurface.hpp"
#include "contact/Projection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numeric>

namespace cc = contessa::contact;

namespace {

/// A facet's nodes at an affine image of its parent nodes: x = x0 + J ξ (J: space × surface dimension),
/// an undistorted facet (straight edges, centred mid-edge nodes) of area |det| × parent area.
template <class Facet>
std::array<typename Facet::Point, Facet::kNodes> affineFacet() {
  std::array<typename Facet::Point, Facet::kNodes> x{};
  for (int i = 0; i < Facet::kNodes; ++i) {
    const auto xi = Facet::nodeCoords(i);
    if constexpr (Facet::kSpaceDim == 2) {
      x[i] = {1.0 + 0.8 * xi[0], 2.0 + 0.6 * xi[0]};  // length 2 × 1.0
    } else {
      // ξ^1 → (1.2, 0.3, 0.1), ξ^2 → (0.4, 0.9, −0.2): a parallelogram map tilted out of the plane
      x[i] = {0.5 + 1.2 * xi[0] + 0.4 * xi[1], -0.3 + 0.3 * xi[0] + 0.9 * xi[1], 2.0 + 0.1 * xi[0] - 0.2 * xi[1]};
    }
  }
  return x;
}

/// Area of the affine image of the parent domain (length in 2D).
template <class Facet>
double affineArea() {
  if constexpr (Facet::kSpaceDim == 2) {
    return 2.0;  // parent length 2 × ‖(0.8, 0.6)‖
  } else {
    const cc::Vector<3> n = cc::cross({1.2, 0.3, 0.1}, {0.4, 0.9, -0.2});
    const double parent = Facet::kNodes == 3 || Facet::kNodes == 6 ? 0.5 : 4.0;
    return parent * cc::norm(n);
  }
}

/// The consistent ∫ H_i dA by the facet's rule.
template <class Facet>
std::array<double, Facet::kNodes> consistent(const std::array<typename Facet::Point, Facet::kNodes>& x) {
  std::array<double, Facet::kNodes> a{};
  for (const auto& q : Facet::quadrature()) {
    const auto p = cc::Projection<Facet>::evaluateAt(typename Facet::Point{}, x, q.xi);
    const double dA = cc::norm(Facet::areaNormal(p.covariantBasis)) * q.weight;
    for (int i = 0; i < Facet::kNodes; ++i) a[i] += p.shape[i] * dA;
  }
  return a;
}

/// Expected fractions of the area at the corners and at the other nodes (mid-edge, then a centre).
template <class Facet>
void expectFractions(const std::array<double, Facet::kNodes>& a, double area, int corners, double corner,
                     double midEdge, double centre = 0.0) {
  for (int i = 0; i < Facet::kNodes; ++i) {
    const double expected = i < corners ? corner : (Facet::kNodes == 9 && i == 8 ? centre : midEdge);
    EXPECT_NEAR(a[i] / area, expected, 1e-14) << "node " << i;
  }
}

template <class Facet>
void expectPositiveAndComplete(const std::array<typename Facet::Point, Facet::kNodes>& x, double area,
                               double tolerance) {
  double facetArea = 0;
  const auto a = cc::tributaryAreas<Facet>(x, false, facetArea);
  EXPECT_NEAR(facetArea, area, tolerance * area);
  EXPECT_NEAR(std::accumulate(a.begin(), a.end(), 0.0), facetArea, 1e-14 * facetArea);
  for (int i = 0; i < Facet::kNodes; ++i) EXPECT_GT(a[i], 0.05 * facetArea / Facet::kNodes) << "node " << i;
}

}  // namespace

TEST(TributaryAreas, LinearAndPositiveConsistentFacetsTakeTheConsistentIntegral) {
  double area = 0;
  const auto tri3 = cc::tributaryAreas<cc::Tri3Facet>(affineFacet<cc::Tri3Facet>(), false, area);
  EXPECT_NEAR(area, affineArea<cc::Tri3Facet>(), 1e-14);
  expectFractions<cc::Tri3Facet>(tri3, area, 3, 1.0 / 3.0, 0.0);
  const auto quad4 = cc::tributaryAreas<cc::Quad4Facet>(affineFacet<cc::Quad4Facet>(), false, area);
  EXPECT_NEAR(area, affineArea<cc::Quad4Facet>(), 1e-14);
  expectFractions<cc::Quad4Facet>(quad4, area, 4, 0.25, 0.0);
  const auto line3 = cc::tributaryAreas<cc::Line3Facet>(affineFacet<cc::Line3Facet>(), false, area);
  EXPECT_NEAR(area, affineArea<cc::Line3Facet>(), 1e-14);
  expectFractions<cc::Line3Facet>(line3, area, 2, 1.0 / 6.0, 2.0 / 3.0);
  const auto quad9 = cc::tributaryAreas<cc::Quad9Facet>(affineFacet<cc::Quad9Facet>(), false, area);
  EXPECT_NEAR(area, affineArea<cc::Quad9Facet>(), 1e-13);
  expectFractions<cc::Quad9Facet>(quad9, area, 4, 1.0 / 36.0, 1.0 / 9.0, 4.0 / 9.0);
}

// Why Tri6 and Quad8 do not take ∫ H_i dA: a uniform pressure's consistent load is zero at a Tri6 corner
// and pulls (−A/12) at a Quad8 corner. Their sub-facet areas are positive and sum to the area.
TEST(TributaryAreas, Tri6AndQuad8TakeTheirSubFacetsNotTheNonPositiveCorners) {
  const auto tri6 = affineFacet<cc::Tri6Facet>();
  const double tri6Area = affineArea<cc::Tri6Facet>();
  expectFractions<cc::Tri6Facet>(consistent<cc::Tri6Facet>(tri6), tri6Area, 3, 0.0, 1.0 / 3.0);
  double area = 0;
  expectFractions<cc::Tri6Facet>(cc::tributaryAreas<cc::Tri6Facet>(tri6, false, area), tri6Area, 3, 1.0 / 12.0, 0.25);
  EXPECT_NEAR(area, tri6Area, 1e-14);

  const auto quad8 = affineFacet<cc::Quad8Facet>();
  const double quad8Area = affineArea<cc::Quad8Facet>();
  expectFractions<cc::Quad8Facet>(consistent<cc::Quad8Facet>(quad8), quad8Area, 4, -1.0 / 12.0, 1.0 / 3.0);
  expectFractions<cc::Quad8Facet>(cc::tributaryAreas<cc::Quad8Facet>(quad8, false, area), quad8Area, 4, 1.0 / 24.0,
                                  5.0 / 24.0);
  EXPECT_NEAR(area, quad8Area, 1e-13);
}

// On curved and distorted facets (nodes moved off the affine positions by up to 8 % of the size) every weight
// stays positive and the weights sum to the facet's area as its quadrature measures it.
TEST(TributaryAreas, CurvedFacetsKeepPositiveWeightsThatSumToTheArea) {
  const auto perturbed = [](auto x) {
    for (std::size_t i = 0; i < x.size(); ++i)
      for (std::size_t c = 0; c < x[i].size(); ++c) x[i][c] += 0.08 * std::sin(1.3 * i + 2.1 * c + 0.5);
    return x;
  };
  const auto measured = [](const auto& x, auto facet) {
    using Facet = decltype(facet);
    double area = 0;
    for (const auto& q : Facet::quadrature())
      area += cc::norm(Facet::areaNormal(cc::Projection<Facet>::evaluateAt({}, x, q.xi).covariantBasis)) * q.weight;
    return area;
  };
  const auto line3 = perturbed(affineFacet<cc::Line3Facet>());
  expectPositiveAndComplete<cc::Line3Facet>(line3, measured(line3, cc::Line3Facet{}), 1e-14);
  const auto tri6 = perturbed(affineFacet<cc::Tri6Facet>());
  expectPositiveAndComplete<cc::Tri6Facet>(tri6, measured(tri6, cc::Tri6Facet{}), 1e-14);
  const auto quad8 = perturbed(affineFacet<cc::Quad8Facet>());
  expectPositiveAndComplete<cc::Quad8Facet>(quad8, measured(quad8, cc::Quad8Facet{}), 1e-14);
  const auto quad9 = perturbed(affineFacet<cc::Quad9Facet>());
  expectPositiveAndComplete<cc::Quad9Facet>(quad9, measured(quad9, cc::Quad9Facet{}), 1e-14);
}

// A 3-node edge of an axisymmetric surface (revolved about the y axis, r = x): ∫ H_i 2π r ds with r linear
// along a straight edge of length L is 2π L (r_0/6, r_1/6, 2 r̄/3), r̄ the mid-edge radius; they sum to the
// band's area 2π r̄ L.
TEST(TributaryAreas, RevolvedThreeNodeEdgeGivesTheBandAreas) {
  const std::array<cc::Line3Facet::Point, 3> edge{{{2.0, 0.0}, {3.2, 1.6}, {2.6, 0.8}}};  // L = 2
  double length = 0;
  const auto a = cc::tributaryAreas<cc::Line3Facet>(edge, true, length);
  EXPECT_NEAR(length, 2.0, 1e-14);
  EXPECT_NEAR(a[0], 2 * M_PI * 2.0 * 2.0 / 6.0, 1e-12);
  EXPECT_NEAR(a[1], 2 * M_PI * 2.0 * 3.2 / 6.0, 1e-12);
  EXPECT_NEAR(a[2], 2 * M_PI * 2.0 * 2.0 * 2.6 / 3.0, 1e-12);
  EXPECT_NEAR(a[0] + a[1] + a[2], 2 * M_PI * 2.6 * 2.0, 1e-12);
}

// A revolved surface of 3-node edges whose first corner lies on the axis: ∫ H 2πr ds gives that node no weight,
// and ContactSurface names it with its edge (the mid node, the far corner, their radii), the others not.
TEST(TributaryAreas, RevolvedThreeNodeEdgesNameTheirNodeOnTheAxis) {
  contessa::mesh::ReplicatedSurface facets;
  facets.name = "outer";
  facets.dimension = 2;
  facets.nodesPerFacet = 3;
  // Two edges along y = 0 from the axis: nodes 10 (r = 0), 11 (r = 0.5, mid), 12 (r = 1), 13 (r = 1.5, mid),
  // 14 (r = 2); Line3 order: corner, corner, mid.
  facets.elements = {0, 1};
  facets.sides = {0, 0};
  facets.facetNodes = {10, 12, 11, 12, 14, 13};
  facets.nodes = {10, 11, 12, 13, 14};
  facets.coordinates = {0.0, 0.0, 0.5, 0.0, 1.0, 0.0, 1.5, 0.0, 2.0, 0.0};
  const auto surface = cc::ContactSurface::fromSurface(facets, "test", true);
  EXPECT_NEAR(surface.areas[0], 0.0, 1e-15);  // Gauss round-off of an exact 0
  ASSERT_EQ(surface.axisNodes.size(), 1u);
  const auto& axis = surface.axisNodes[0];
  EXPECT_EQ(surface.nodes[axis.node], 10);
  EXPECT_EQ(surface.nodes[axis.mid], 11);
  EXPECT_EQ(surface.nodes[axis.far], 12);
  EXPECT_DOUBLE_EQ(axis.rMid, 0.5);
  EXPECT_DOUBLE_EQ(axis.rFar, 1.0);
  // Not revolved (plane strain): every node has its weight, none is recovered.
  EXPECT_TRUE(cc::ContactSurface::fromSurface(facets, "test", false).axisNodes.empty());
}

// The value on the axis of a field sampled exactly at an edge's mid node and far corner: exact for a + b r²
// (a constant among them), and Hertz's p0 √(1 − r²/a²) to its leading error p0 r_mid² r_far² / (8 a⁴), on a
// straight edge and on a curved one (the mid node on a circle through the axis, not at half the radius).
TEST(TributaryAreas, ValueOnTheAxisIsTheEdgesEvenFieldThere) {
  const auto exactFor = [](const cc::AxisNode& e) {
    const auto quadratic = [](double r) { return 3.0 - 2.5 * r * r; };
    EXPECT_NEAR(cc::valueOnAxis(e, quadratic(e.rMid), quadratic(e.rFar)), 3.0, 1e-13);
    EXPECT_NEAR(cc::valueOnAxis(e, 7.0, 7.0), 7.0, 1e-13);
  };
  const double p0 = 50.0, a = 0.7;
  const auto hertz = [&](double r) { return p0 * std::sqrt(1.0 - r * r / (a * a)); };
  for (const double h : {0.05, 0.1, 0.2}) {
    cc::AxisNode straight;
    straight.rMid = 0.5 * h;
    straight.rFar = h;
    exactFor(straight);
    // A straight edge: (4 f_mid − f_far) / 3.
    EXPECT_NEAR(cc::valueOnAxis(straight, 4.0, 1.0), 5.0, 1e-13);
    // A circle of radius 10 through the axis, an arc of angle θ: r = 10 sin θ at the far corner, 10 sin(θ/2)
    // at the mid node.
    const double theta = std::asin(h / 10.0);
    cc::AxisNode curved;
    curved.rMid = 10.0 * std::sin(0.5 * theta);
    curved.rFar = h;
    exactFor(curved);
    for (const auto& e : {straight, curved}) {
      const double recovered = cc::valueOnAxis(e, hertz(e.rMid), hertz(e.rFar));
      const double leading = p0 * e.rMid * e.rMid * e.rFar * e.rFar / (8 * std::pow(a, 4));
      EXPECT_GT(recovered, p0);  // the next terms of the series are of the same sign
      EXPECT_NEAR(recovered - p0, leading, 0.5 * leading) << "h = " << h;
      EXPECT_LT(std::abs(recovered / p0 - 1), h <= 0.1 ? 1e-4 : 2e-3) << "h = " << h;
    }
  }
}
