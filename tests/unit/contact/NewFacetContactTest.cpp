// Contact on the faces of the simplex and quadratic families (Line3, Tri3, Tri6, Quad8, Quad9 facets), beyond
// the projection element of FacetFamiliesTest.cpp:
//  - the facet selector (one set of rules per dimension on the facet traits, FacetSelector.cpp): a node above
//    a facet, above a ridge between two facets (an interior edge: on quadratic faces the half edge corner –
//    mid-edge node), above a convex corner, and past the free boundary;
//  - the element past a free boundary (the fade, ContactPoint::freeEdgeReach) on every facet type, with the
//    triangle's clamp (the closest point of the unit triangle, past a leg, the hypotenuse and a corner), and
//    the element at an edge point or vertex of a quadratic facet: consistent tangents against central
//    differences (frictionless, stick, slip).
#include "ElementTestTools.hpp"

#include "contact/FacetSelector.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

using cc::ContactPoint;
using cc::SelectionKind;

namespace {

using ct::kLaws;
using ct::Law;
constexpr double kReach = 0.05;

/// A skewed facet: node i at an affine image of its parent coordinates, lifted out of plane by `warp` (a
/// quadratic bump on 3D faces, a sag on 2D segments), so quadratic facets are curved.
template <class Facet>
std::array<typename Facet::Point, Facet::kNodes> skewedFacet(double warp) {
  std::array<typename Facet::Point, Facet::kNodes> x{};
  for (int i = 0; i < Facet::kNodes; ++i) {
    const auto xi = Facet::nodeCoords(i);
    if constexpr (Facet::kSurfaceDim == 1) {
      x[i] = {0.3 + 1.1 * xi[0], warp * (1.0 - xi[0] * xi[0])};
    } else {
      x[i] = {0.2 + 1.1 * xi[0] + 0.25 * xi[1], -0.1 + 0.15 * xi[0] + 0.95 * xi[1],
              warp * (0.5 - xi[0] * xi[0] - 0.7 * xi[1] * xi[1] + 0.3 * xi[0] * xi[1])};
    }
  }
  return x;
}

/// Parent points just past the facet's boundary (by `delta` in parent coordinates): past the end ξ = 1 of a
/// segment; past an edge and a corner of a square; past each leg, the hypotenuse and a corner of a triangle.
template <class Facet>
std::vector<Vector<Facet::kSurfaceDim>> pastBoundary(double delta) {
  if constexpr (Facet::kSurfaceDim == 1) {
    return {{1.0 + delta}};
  } else if constexpr (Facet::kNodes == 3 || Facet::kNodes == 6) {
    const double h = delta / std::sqrt(2.0);
    return {{0.4, -delta}, {-delta, 0.3}, {0.6 + h, 0.4 + h}, {1.0 + h, -h}};
  } else {
    return {{1.0 + delta, 0.3}, {1.0 + 0.7 * delta, 1.0 + 0.7 * delta}};
  }
}

template <class Facet>
class NewFacetContact : public ::testing::Test {};

TYPED_TEST_SUITE(NewFacetContact, ct::NewFacetTypes, ct::FacetTypeName);

}  // namespace

// The parent domain's closest point: the identity inside; past a triangle's hypotenuse the foot of the
// perpendicular, with the projector along the hypotenuse as derivative; past a corner the corner, derivative 0.
TEST(NewFacetContact, TriangleClampIsTheClosestPointOfTheUnitTriangle) {
  const auto inside = cc::clampToTriangle({0.2, 0.3});
  EXPECT_EQ(inside.xi, (Vector<2>{0.2, 0.3}));
  EXPECT_EQ(inside.derivative(0, 0) * inside.derivative(1, 1), 1.0);
  const auto hyp = cc::clampToTriangle({0.8, 0.6});
  EXPECT_NEAR(hyp.xi[0], 0.6, 1e-15);
  EXPECT_NEAR(hyp.xi[1], 0.4, 1e-15);
  EXPECT_NEAR(hyp.derivative(0, 0), 0.5, 1e-15);
  EXPECT_NEAR(hyp.derivative(0, 1), -0.5, 1e-15);
  const auto leg = cc::clampToTriangle({0.3, -0.2});
  EXPECT_EQ(leg.xi, (Vector<2>{0.3, 0.0}));
  EXPECT_EQ(leg.derivative(0, 0), 1.0);
  EXPECT_EQ(leg.derivative(1, 1), 0.0);
  const auto corner = cc::clampToTriangle({1.3, -0.2});
  EXPECT_EQ(corner.xi, (Vector<2>{1.0, 0.0}));
  for (double d : corner.derivative.entries) EXPECT_EQ(d, 0.0);
}

// The faded element past the facet's free boundary: weight strictly between 0 and 1 and the consistent
// tangent against central differences, flat and curved facets, every law.
TYPED_TEST(NewFacetContact, FadedElementPastTheBoundaryMatchesCentralDifferences) {
  using Facet = TypeParam;
  constexpr int M = Facet::kSurfaceDim;
  double worst = 0.0;
  ct::forEachLaw<Facet>(kLaws, [&](const Law& law, const cc::NodeToFacetContact<Facet>& element) {
    cc::ContactHistory<M> committed = ct::committedHistory<M>(3, {}, {});
    for (int a = 0; a < M; ++a) {
      committed.xi[a] = 0.3 + 0.05 * a;
      committed.tangentialTraction[a] = a == 0 ? 0.02 : -0.01;
    }
    for (const double warp : {0.0, 0.1}) {
      const auto facet = skewedFacet<Facet>(warp);
      for (const auto& xi : pastBoundary<Facet>(0.4 * kReach)) {
        const auto at = cc::Projection<Facet>::evaluateAt(typename Facet::Point{}, facet, xi);
        const cc::NodeToFacetGeometry<Facet> g{cc::add(at.position, cc::scaled(-0.03, at.normal)), facet};
        const auto point = ContactPoint::projection(kReach);
        const auto r = element.evaluate(g, 3, committed, 0.0, cc::SlipTangent::consistent(), point);
        const std::string what = std::string(law.name) + " warp " + std::to_string(warp) + " at (" +
                                 std::to_string(xi[0]) + (M == 2 ? ", " + std::to_string(xi[M - 1]) : "") + ")";
        ASSERT_TRUE(r.projection.converged) << what;
        for (int a = 0; a < M; ++a) EXPECT_NEAR(r.projection.xi[a], xi[a], 1e-9) << what;
        EXPECT_GT(r.freeEdgeWeight, 0.0) << what;
        EXPECT_LT(r.freeEdgeWeight, 1.0) << what;
        worst = std::max(worst, ct::expectTangentAtPointClose(element, g, committed, point, what));
      }
    }
  });
  std::printf("[ FD       ] %d-node facet past its boundary: worst relative error %.2e\n", Facet::kNodes, worst);
}

// The element at a point of a half edge (corner – mid-edge node) and at a mid-edge node of a quadratic
// facet, and at a corner of a linear one: the boundary-point kinematics on the facet's nodes.
TYPED_TEST(NewFacetContact, EdgeAndVertexElementsMatchCentralDifferences) {
  using Facet = TypeParam;
  constexpr int M = Facet::kSurfaceDim;
  const auto facet = skewedFacet<Facet>(0.1);
  const auto segments = Facet::boundarySegments();
  const int i = segments[0][0], j = segments[0][1];
  // Outside the facet, off the segment i–j: 0.04 behind it (penetrating), a little past the segment's line.
  const auto centre = cc::Projection<Facet>::evaluateAt(typename Facet::Point{}, facet, Facet::center()).position;
  const auto onEdge = cc::add(cc::scaled(0.6, facet[i]), cc::scaled(0.4, facet[j]));
  const auto outward = cc::subtract(onEdge, centre);
  const auto n = cc::Projection<Facet>::evaluateAt(typename Facet::Point{}, facet, Facet::center()).normal;
  const auto slave = cc::add(cc::add(onEdge, cc::scaled(0.05, outward)), cc::scaled(-0.04, n));
  double worst = 0.0;
  for (const Law& law : kLaws) {
    const cc::NodeToFacetContact<Facet> element(law.parameters);
    const auto committed = ct::committedHistory<M>(3, {}, {});
    const cc::NodeToFacetGeometry<Facet> g{slave, facet};
    for (const ContactPoint& point : {ContactPoint::edge(i, j, -1.0), ContactPoint::vertex(j, -1.0)}) {
      if (M == 1 && point.kind == ContactPoint::Kind::Edge) continue;  // segments have no edges
      const auto r = element.evaluate(g, 3, committed, 0.0, cc::SlipTangent::consistent(), point);
      const std::string what = std::string(law.name) + (point.kind == ContactPoint::Kind::Edge ? " edge" : " vertex");
      EXPECT_LT(r.gap, 0.0) << what;
      worst = std::max(worst, ct::expectTangentAtPointClose(element, g, committed, point, what));
    }
  }
  std::printf("[ FD       ] %d-node facet, edge and vertex points: worst relative error %.2e\n", Facet::kNodes, worst);
}

// The selector on two neighbouring facets: the skewed facet and its mirror image across its first boundary
// edge (the two sharing that edge's nodes), folded into a ridge (each tilted down away from the edge by the
// node heights). A node above the middle of one facet is on it; a node straight above the shared edge's
// first half is at that edge (3D) or vertex (2D), the sides' normals averaged; a node far past the free
// boundary is not in contact.
TYPED_TEST(NewFacetContact, SelectorOnTwoFacetsSharingAnEdge) {
  using Facet = TypeParam;
  using Nodes = cc::MasterFacetNodes<Facet>;
  constexpr int D = Facet::kSpaceDim;
  Nodes a, b;
  a.id = 0;
  b.id = 1;
  a.x = skewedFacet<Facet>(0.0);
  for (int k = 0; k < Facet::kNodes; ++k) a.nodes[k] = k;
  // b: a turned by 180° about the line of a's first edge (3D; 2D: about a's node 0), its nodes renumbered
  // with the parent coordinates reversed (ξ ↔ η; 2D: ξ → −ξ) so that its normal agrees with a's. The nodes
  // on the line stay where they are and are shared.
  const auto segments = Facet::boundarySegments();
  const std::size_t corners = Facet::kNodes == 3 || Facet::kNodes == 6 ? 3 : 4;
  const auto edge = segments[0];
  const int e0 = edge[0];
  const int e1 = segments.size() > corners ? segments[1][1] : edge[1];  // the first edge's far corner
  const auto p0 = a.x[e0];
  const auto dir = cc::subtract(a.x[e1], p0);
  const auto offLine = [&](const typename Facet::Point& x) {  // x − p0 minus its part along the line (3D)
    const auto r = cc::subtract(x, p0);
    return D == 2 ? r : cc::subtract(r, cc::scaled(cc::dot(r, dir) / cc::dot(dir, dir), dir));
  };
  const auto reversed = [](cc::Vector<Facet::kSurfaceDim> xi) {
    if constexpr (Facet::kSurfaceDim == 1) return cc::Vector<1>{-xi[0]};
    else return cc::Vector<2>{xi[1], xi[0]};
  };
  for (int k = 0; k < Facet::kNodes; ++k) {
    int l = 0;
    while (cc::norm(cc::subtract(Facet::nodeCoords(l), reversed(Facet::nodeCoords(k)))) > 1e-12) ++l;
    b.x[k] = cc::subtract(a.x[l], cc::scaled(2.0, offLine(a.x[l])));
    b.nodes[k] = cc::norm(offLine(a.x[l])) < 1e-12 ? a.nodes[l] : 100 + k;
  }
  // Both facets fall away from the shared line against their normal: a convex ridge (2D: corner).
  const double side = cc::Projection<Facet>::evaluateAt(typename Facet::Point{}, a.x, Facet::center()).normal[D - 1] > 0.0
                          ? 1.0 : -1.0;
  for (auto* f : {&a, &b})
    for (auto& x : f->x) x[D - 1] -= side * 0.1 * cc::norm(offLine(x));
  const cc::FacetSelector<Facet> selector;
  const auto centreA = cc::Projection<Facet>::evaluateAt(typename Facet::Point{}, a.x, Facet::center());
  // Above a's centre, 0.02 outside: on facet a, positive gap.
  const auto above = cc::add(centreA.position, cc::scaled(0.02, centreA.normal));
  const auto onA = selector.select(above, {a, b});
  EXPECT_EQ(onA.kind, SelectionKind::OnFacet);
  EXPECT_EQ(onA.facet, 0);
  EXPECT_NEAR(onA.gap, 0.02, 1e-9);
  // Straight above (outside) a point of the shared edge's first half: the ridge's closest point.
  const auto ridgePoint = D == 2 ? a.x[e0] : cc::add(cc::scaled(0.7, a.x[edge[0]]), cc::scaled(0.3, a.x[edge[1]]));
  typename Facet::Point up{};
  up[D - 1] = side * 0.05;
  const auto atRidge = selector.select(cc::add(ridgePoint, up), {a, b});
  EXPECT_EQ(atRidge.kind, D == 2 ? SelectionKind::AtVertex : SelectionKind::AtEdge);
  EXPECT_NEAR(atRidge.gap, 0.05, 1e-9);
  if (D == 3) {
    EXPECT_TRUE((atRidge.edgeNodes == std::array<int, 2>{a.nodes[edge[0]], a.nodes[edge[1]]}) ||
                (atRidge.edgeNodes == std::array<int, 2>{a.nodes[edge[1]], a.nodes[edge[0]]}));
  } else {
    EXPECT_EQ(atRidge.vertexNode, a.nodes[e0]);
  }
  // Far past a's free boundary (opposite the ridge), level with the facets: not in contact.
  const auto away = cc::add(centreA.position, cc::scaled(3.0, cc::subtract(centreA.position, ridgePoint)));
  EXPECT_EQ(selector.select(away, {a, b}).kind, SelectionKind::None);
}
