// The contact element at a vertex or an edge point of its facet (ContactPoint): a slave node past the
// facet's boundary whose closest point on the master surface is that vertex or edge point (under a
// valley, in a concave corner, on a line of master nodes). Its consistent tangent against central
// differences (frictionless, stick, slip; 2D vertex, 3D edge and vertex), the force towards the point, and
// continuity with the ordinary element where the point's region meets the facet's (issue 22).
#include "ElementTestTools.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using cc::ContactPoint;

namespace {

using ct::kLaws;
using ct::Law;

// The element at `point` penetrates and is closed; its tangent against central differences.
template <class Facet>
double checkTangent(const cc::NodeToFacetContact<Facet>& element, const cc::NodeToFacetGeometry<Facet>& g,
                    const cc::ContactHistory<Facet::kSurfaceDim>& committed, const ContactPoint& point,
                    const std::string& what) {
  const auto r = element.evaluate(g, 3, committed, 0.0, cc::SlipTangent::consistent(), point);
  EXPECT_LT(r.gap, 0.0) << what;
  EXPECT_NE(r.status, ContactStatus::Open) << what;
  return ct::expectTangentAtPointClose(element, g, committed, point, what);
}

}  // namespace

// 2D: the segment (2,0) → (0,0) (master body below, n̄ = +y) ends at vertex (0,0), local node 1. A node
// at (−0.03, −0.05) is under the valley the segment forms with a neighbour rising to the left: its
// closest point is the vertex, g_N = −‖x^k − x_v‖.
TEST(ContactPoint, VertexIn2DTangentMatchesCentralDifferences) {
  using Facet = cc::Line2Facet;
  cc::NodeToFacetGeometry<Facet> g{{-0.03, -0.05}, {{{2.0, 0.0}, {0.0, 0.0}}}};
  const auto point = ContactPoint::vertex(1, -1.0);
  for (const Law& law : kLaws) {
    const cc::NodeToFacetContact<Facet> element(law.parameters);
    const auto committed = ct::committedHistory<1>(3, {0.9}, {0.02});
    checkTangent(element, g, committed, point, std::string("2D vertex / ") + law.name);
    const auto r = element.evaluate(g, 3, committed, 0.0, cc::SlipTangent::consistent(), point);
    EXPECT_NEAR(r.gap, -std::hypot(0.03, 0.05), 1e-15);
    if (law.parameters.isFrictionless()) {
      // The force pulls the node straight to the vertex: −r_slave = −ε_N (x^k − x_v), and the vertex
      // node takes the opposite force.
      EXPECT_NEAR(-r.residual[0], 1e3 * 0.03, 1e-12);
      EXPECT_NEAR(-r.residual[1], 1e3 * 0.05, 1e-12);
      EXPECT_NEAR(r.residual[4], -r.residual[0], 1e-12);
      EXPECT_NEAR(r.residual[2], 0.0, 1e-15);
    }
  }
}

// 3D: a flat face and a warped one; the edge node 1 → node 2 and the vertex node 2.
TEST(ContactPoint, EdgeAndVertexIn3DTangentMatchCentralDifferences) {
  using Facet = cc::Quad4Facet;
  const double worst = ct::worstOverLawsAndFaces([](const Law& law, const auto& element, const auto& committed,
                                                    const std::string& name, const auto& face) {
    // Past edge 1–2 (x = 2 on the flat face), below the surface.
    const Vector<3> edgeSlave = cc::add(cc::add(face[1], cc::scaled(0.35, cc::subtract(face[2], face[1]))),
                                        Vector<3>{0.03, 0.01, -0.04});
    const double edge = checkTangent(element, {edgeSlave, face}, committed, ContactPoint::edge(1, 2, -1.0),
                                     "3D edge / " + name + " / " + law.name);
    const Vector<3> vertexSlave = cc::add(face[2], Vector<3>{0.03, 0.02, -0.05});
    const double vertex = checkTangent(element, {vertexSlave, face}, committed, ContactPoint::vertex(2, -1.0),
                                       "3D vertex / " + name + " / " + law.name);
    return std::max(edge, vertex);
  });
  std::printf("[ FD       ] contact point: worst relative error %.2e\n", worst);
  // The edge point moves with the node along the edge: the gap is the distance to the edge's line.
  const cc::NodeToFacetContact<Facet> element(kLaws[0].parameters);
  const auto r = element.evaluate({{2.03, 0.7, -0.04}, ct::kFlatFace}, 3, {}, 0.0, cc::SlipTangent::consistent(),
                                  ContactPoint::edge(1, 2, -1.0));
  EXPECT_NEAR(r.gap, -0.05, 1e-14);
}

// Where the vertex region meets the facet's (the node straight below the facet's end), the vertex element
// and the ordinary element are the same: the force does not jump as the node crosses from one to the other.
TEST(ContactPoint, VertexElementJoinsTheFacetElementContinuously) {
  using Facet = cc::Line2Facet;
  const cc::NodeToFacetContact<Facet> element(kLaws[0].parameters);
  const cc::NodeToFacetGeometry<Facet> g{{0.0, -0.05}, {{{2.0, 0.0}, {0.0, 0.0}}}};
  const auto atVertex = element.evaluate(g, 3, {}, 0.0, cc::SlipTangent::consistent(), ContactPoint::vertex(1, -1.0));
  const auto onFacet = element.evaluate(g, 3, {});
  EXPECT_NEAR(atVertex.gap, onFacet.gap, 1e-15);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(atVertex.residual[i], onFacet.residual[i], 1e-12) << i;
  const cc::NodeToFacetContact<cc::Quad4Facet> element3(kLaws[0].parameters);
  const cc::NodeToFacetGeometry<cc::Quad4Facet> g3{{2.0, 0.7, -0.05}, ct::kFlatFace};
  const auto atEdge = element3.evaluate(g3, 3, {}, 0.0, cc::SlipTangent::consistent(), ContactPoint::edge(1, 2, -1.0));
  const auto onFace = element3.evaluate(g3, 3, {});
  for (int i = 0; i < 15; ++i) EXPECT_NEAR(atEdge.residual[i], onFace.residual[i], 1e-12) << i;
}
