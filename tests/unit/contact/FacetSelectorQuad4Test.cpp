// The 3D facet selector (FacetSelector<Quad4Facet>): faces, interior edges (ridges and valleys), corner
// vertices, free boundaries and collapsed faces; and a node sliding across an edge through the whole
// interface (ContactInterfaceBase on a rigid quad surface): a continuous gap and exactly one contribution.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "contact/ContactInterface.hpp"
#include "contact/ContactSurface.hpp"
#include "contact/FacetSelector.hpp"
#include "mesh/Generators.hpp"

namespace {

namespace cc = contessa::contact;
using Face = cc::MasterFacetNodes<cc::Quad4Facet>;
using P = cc::Vector<3>;

// Two faces sharing the edge x = 1 (nodes 1, 4): A over [0, 1] × [0, 1] in z = 0, B beyond it, either
// coplanar (slope 0), bent down (a convex ridge, slope < 0) or up (a valley, slope > 0). Normals +z-ish.
std::vector<Face> twoFaces(double slope) {
  const double zb = slope;  // z of B's far edge (x = 2)
  return {Face{0, {0, 1, 4, 3}, {P{0, 0, 0}, P{1, 0, 0}, P{1, 1, 0}, P{0, 1, 0}}},
          Face{1, {1, 2, 5, 4}, {P{1, 0, 0}, P{2, 0, zb}, P{2, 1, zb}, P{1, 1, 0}}}};
}

// The exact distance from x to the union of the two (flat) faces of twoFaces(slope), signed by side.
double exactGap(const P& x, double slope) {
  // Face A: the plane z = 0 over x ∈ [0, 1]; face B: the plane through the edge with the given slope.
  const double ux = 1.0 / std::sqrt(1 + slope * slope), uz = slope / std::sqrt(1 + slope * slope);  // B's tangent
  const double nx = -uz, nz = ux;  // B's normal
  const double along = (x[0] - 1) * ux + x[2] * uz;
  double best = 1e300, signed_ = 0;
  auto take = [&](double d, double s) {
    if (d < best) best = d, signed_ = s;
  };
  if (x[0] <= 1) take(std::abs(x[2]), x[2]);
  if (along >= 0) take(std::abs((x[0] - 1) * nx + x[2] * nz), (x[0] - 1) * nx + x[2] * nz);
  const double de = std::hypot(x[0] - 1, x[2]);
  take(de, x[2] >= 0 ? de : -de);
  return signed_;
}

class EdgeCrossing : public ::testing::TestWithParam<double> {};

// A node moved across the shared edge at a fixed height (above, and penetrating): the gap equals the exact
// distance to the surface at every position (so it is continuous), the face changes once, and outside the
// ridge (above a convex one, below a valley) the closest point is on the edge itself.
TEST_P(EdgeCrossing, GapIsTheDistanceToTheSurface) {
  const double slope = GetParam();
  const auto faces = twoFaces(slope);
  const cc::FacetSelector<cc::Quad4Facet> selector;
  for (double z : {0.05, -0.01}) {
    int switches = 0, previous = -1;
    bool sawEdge = false;
    for (int i = 0; i <= 400; ++i) {
      const P x{0.5 + i * 0.0025, 0.4, z};
      const auto s = selector.select(x, faces);
      ASSERT_NE(s.kind, cc::SelectionKind::None) << "x = " << x[0] << ", z = " << z;
      EXPECT_NEAR(s.gap, exactGap(x, slope), 1e-10) << "x = " << x[0] << ", z = " << z;
      if (previous >= 0 && s.facet != previous) ++switches;
      previous = s.facet;
      sawEdge = sawEdge || s.kind == cc::SelectionKind::AtEdge;
    }
    EXPECT_EQ(switches, 1) << "z = " << z;
    // Only outside the ridge: above a convex one, below a valley.
    EXPECT_EQ(sawEdge, (slope < 0.0 && z > 0.0) || (slope > 0.0 && z < 0.0)) << "z = " << z;
  }
}

INSTANTIATE_TEST_SUITE_P(FacetSelectorQuad4, EdgeCrossing, ::testing::Values(0.0, -0.5, 0.5));

// Above a valley the node lies inside both faces' parent domains: the smaller |g_N| wins.
TEST(FacetSelectorQuad4, ValleyTakesTheSmallerGap) {
  const auto faces = twoFaces(1.0);  // B rises at 45°
  const cc::FacetSelector<cc::Quad4Facet> selector;
  const auto s = selector.select({0.9, 0.5, 0.3}, faces);  // 0.3 above A, (0.3 − (−0.1))/√2·… from B
  ASSERT_EQ(s.kind, cc::SelectionKind::OnFacet);
  const double gapB = (-(0.9 - 1) + 0.3) / std::sqrt(2.0);  // n_B = (−1, 0, 1)/√2
  EXPECT_EQ(s.facet, gapB < 0.3 ? 1 : 0);
  EXPECT_NEAR(s.gap, std::min(gapB, 0.3), 1e-12);
}

// The corner of a cube (three faces, outward normals +x, +y, +z): a node outside the corner is at the
// vertex, with the distance to it as gap, and the element goes to the face it is most above.
TEST(FacetSelectorQuad4, ConvexCornerUsesTheVertex) {
  // Vertex 0 at the origin; the unit cube [−1, 0]³; faces counter-clockwise seen from outside.
  const std::vector<Face> faces{
      Face{0, {0, 3, 2, 1}, {P{0, 0, 0}, P{-1, 0, 0}, P{-1, -1, 0}, P{0, -1, 0}}},   // z = 0, normal +z
      Face{1, {0, 5, 4, 3}, {P{0, 0, 0}, P{0, 0, -1}, P{-1, 0, -1}, P{-1, 0, 0}}},   // y = 0, normal +y
      Face{2, {0, 1, 6, 5}, {P{0, 0, 0}, P{0, -1, 0}, P{0, -1, -1}, P{0, 0, -1}}}};  // x = 0, normal +x
  for (const auto& f : faces) {
    const auto p = cc::Projection<cc::Quad4Facet>::evaluateAt(P{}, f.x, cc::Quad4Facet::center());
    EXPECT_NEAR(cc::dot(p.normal, P{1, 1, 1}), 1.0, 1e-12) << "face " << f.id;  // one of the axes
  }
  const cc::FacetSelector<cc::Quad4Facet> selector;
  const auto s = selector.select({0.1, 0.2, 0.3}, faces);
  ASSERT_EQ(s.kind, cc::SelectionKind::AtVertex);
  EXPECT_EQ(s.vertexNode, 0);
  EXPECT_NEAR(s.gap, std::sqrt(0.14), 1e-12);
  EXPECT_EQ(s.facet, 0);  // z is the largest component of the direction
  // Beside one edge of the corner (x < 0): the edge y = z = 0.
  const auto e = selector.select({-0.5, 0.2, 0.3}, faces);
  ASSERT_EQ(e.kind, cc::SelectionKind::AtEdge);
  EXPECT_NEAR(e.gap, std::hypot(0.2, 0.3), 1e-12);
}

// A flat plate of two faces with a free boundary: beyond it a node is off the surface, even next to the
// vertex the two faces share on the boundary (an open fan); a penetrating node just past it stays on.
TEST(FacetSelectorQuad4, FreeBoundaryIsNotAnEdgeToContact) {
  const auto faces = twoFaces(0.0);  // the boundary y = 0 holds vertex 1, shared by both faces
  const cc::FacetSelector<cc::Quad4Facet> selector;
  EXPECT_EQ(selector.select({1.0, -0.2, 0.05}, faces).kind, cc::SelectionKind::None);
  EXPECT_EQ(selector.select({1.0, -0.2, -0.05}, faces).kind, cc::SelectionKind::None);
  // Past the boundary by 0.024, within 3e-2 of the slave facet size L_k = 1 (FacetSelectorOptions::
  // freeEdgeTolerance): still on, however little it penetrates.
  const auto flush = selector.select({0.5, -0.024, -0.01}, faces, 1.0);
  EXPECT_EQ(flush.kind, cc::SelectionKind::OnFacet);
  EXPECT_EQ(flush.facet, 0);
  EXPECT_NEAR(flush.gap, -0.01, 1e-12);
  EXPECT_EQ(selector.select({0.5, -0.024, -1e-7}, faces, 1.0).kind, cc::SelectionKind::OnFacet);
  // Past it by 0.036: off, however deep it penetrates.
  EXPECT_EQ(selector.select({0.5, -0.036, -0.01}, faces, 1.0).kind, cc::SelectionKind::None);
  EXPECT_EQ(selector.select({0.5, -0.036, -0.5}, faces, 1.0).kind, cc::SelectionKind::None);
  // Past a corner of the surface: the distance to the corner counts (0.018·√2 on, 0.024·√2 off).
  EXPECT_EQ(selector.select({-0.018, -0.018, -0.01}, faces, 1.0).kind, cc::SelectionKind::OnFacet);
  EXPECT_EQ(selector.select({-0.024, -0.024, -0.01}, faces, 1.0).kind, cc::SelectionKind::None);
}

// The free-edge rule is a length of the slave mesh, not a fraction of the master facet: a node 1.11 past
// the edge of a punch face 70 wide (1.6 % of it, within the 0.1 in ξ of the former rule) is off; the same
// node 1e-4 past it is on (L_k = 5.56, the punch deck's block at 18 elements).
TEST(FacetSelectorQuad4, FreeEdgeRuleDoesNotGrowWithTheFacet) {
  const Face punch = Face{0, {0, 1, 2, 3}, {P{-10, -10, 0}, P{60, -10, 0}, P{60, 60, 0}, P{-10, 60, 0}}};
  const cc::FacetSelector<cc::Quad4Facet> selector;
  const double slaveSize = 100.0 / 18.0;
  EXPECT_EQ(selector.select({61.11, 20.0, -0.05}, {punch}, slaveSize).kind, cc::SelectionKind::None);
  EXPECT_EQ(selector.select({60.0 + 1e-4, 20.0, -0.05}, {punch}, slaveSize).kind, cc::SelectionKind::OnFacet);
  EXPECT_EQ(selector.select({59.0, 20.0, -1e-6}, {punch}, slaveSize).kind, cc::SelectionKind::OnFacet);
}

// A node beside a punch split into faces, past its free edge: the punch's interior edges and vertices are
// farther than its free edge, so they are not the surface's closest point and do not hold the node (they
// held it, 11 mm away, beside a punch of 10 mm faces).
TEST(FacetSelectorQuad4, InteriorEdgesDoNotHoldANodePastTheFreeEdge) {
  std::vector<Face> faces;
  const auto point = [](int i, int j) { return -1 - (i * 8 + j); };
  int id = 0;
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) {
      const double x0 = -10 + 10 * i, y0 = -10 + 10 * j;
      faces.push_back(Face{id++, {point(i, j), point(i + 1, j), point(i + 1, j + 1), point(i, j + 1)},
                           {P{x0, y0, 0}, P{x0 + 10, y0, 0}, P{x0 + 10, y0 + 10, 0}, P{x0, y0 + 10, 0}}});
    }
  const cc::FacetSelector<cc::Quad4Facet> selector;
  for (const double y : {0.0, 3.0, 25.0})
    for (const double z : {-0.5, -1e-3, 0.0, 0.5}) {
      SCOPED_TRACE("y = " + std::to_string(y) + ", z = " + std::to_string(z));
      EXPECT_EQ(selector.select({61.11, y, z}, faces, 5.56).kind, cc::SelectionKind::None);
    }
  // Inside, on an interior edge and vertex of the split punch: on a face, with the flat gap.
  const auto onEdge = selector.select({50.0, 3.0, -1e-3}, faces, 5.56);
  EXPECT_EQ(onEdge.kind, cc::SelectionKind::OnFacet);
  EXPECT_NEAR(onEdge.gap, -1e-3, 1e-15);
  const auto onVertex = selector.select({50.0, 0.0, -1e-3}, faces, 5.56);
  EXPECT_EQ(onVertex.kind, cc::SelectionKind::OnFacet);
  EXPECT_NEAR(onVertex.gap, -1e-3, 1e-15);
}

// A collapsed face (a triangle with its apex twice) next to a regular one, sharing the apex as a corner:
// a node at the apex goes to the regular face, where the collapsed face has no metric.
TEST(FacetSelectorQuad4, CollapsedApexIsHandedToTheNeighbour) {
  const Face collapsed = Face{0, {1, 2, 4, 4}, {P{1, 0, 0}, P{2, 0.5, 0}, P{1, 1, 0}, P{1, 1, 0}}};
  const Face regular = Face{1, {0, 1, 4, 3}, {P{0, 0, 0}, P{1, 0, 0}, P{1, 1, 0}, P{0, 1, 0}}};
  const cc::FacetSelector<cc::Quad4Facet> selector;
  const auto s = selector.select({1.0, 1.0, -0.01}, {collapsed, regular});
  ASSERT_EQ(s.kind, cc::SelectionKind::OnFacet);
  EXPECT_EQ(s.facet, 1);
  EXPECT_NEAR(s.gap, -0.01, 1e-12);
  // Away from the apex the collapsed face is an ordinary (triangular) face.
  const auto t = selector.select({1.3, 0.5, -0.01}, {collapsed, regular});
  ASSERT_EQ(t.kind, cc::SelectionKind::OnFacet);
  EXPECT_EQ(t.facet, 0);
  EXPECT_NEAR(t.gap, -0.01, 1e-12);
}

// ---- the 3D interface -----------------------------------------------------------------------------------

// One slave node (mesh node 7) under a rigid surface of two quads (twoFaces(slope), moving by λ·(0,0,1)),
// tributary area 2.
cc::ContactInterfaceSpec oneNodeUnderTwoQuads(double slope) {
  cc::ContactInterfaceSpec spec;
  spec.name = "plate";
  spec.dimension = 3;
  spec.slaveNodes = {7};
  spec.slaveAreas = {2.0};
  spec.slaveFacetLengths = {1.0};
  spec.rigidMaster = true;
  for (const auto& f : twoFaces(slope))
    for (const auto& x : f.x) spec.rigidSurface.points.insert(spec.rigidSurface.points.end(), x.begin(), x.end());
  spec.rigidSurface.facets = {0, 1, 2, 3, 4, 5, 6, 7};
  spec.rigidSurface.motion = {0.0, 0.0, 1.0};
  spec.law.normalPenalty = 1e3;
  return spec;
}

TEST(ContactInterface3D, NodeSlidingAcrossAnEdgeHasOneContributionAndAContinuousForce) {
  for (double slope : {0.0, -0.3}) {
    const auto interface = cc::makeContactInterface(oneNodeUnderTwoQuads(slope), {1});
    double previousForce = -1;
    for (int i = 0; i <= 200; ++i) {
      const P node{0.5 + i * 0.005, 0.5, -0.01};
      int calls = 0;
      double fz = 0;
      interface->evaluate([&](cc::GlobalIndex n, double* x) {
                            ASSERT_EQ(n, 7);
                            for (int c = 0; c < 3; ++c) x[c] = node[c];
                          },
                          0.0, true,
                          [&](const cc::GlobalIndex* dofs, int n, const double* r, const double*, const double* drdl) {
                            ++calls;
                            ASSERT_EQ(n, 15);
                            EXPECT_EQ(dofs[0], 21);
                            EXPECT_EQ(dofs[2], 23);
                            for (int j = 3; j < 15; ++j) EXPECT_EQ(dofs[j], -1);  // rigid master: no unknowns
                            fz = -r[2];
                            // The rigid master moves up: the penetration grows, the slave is pushed harder.
                            EXPECT_GT(-drdl[2], 0.0);
                          });
      const double g = exactGap(node, slope);
      if (g < 0) {
        EXPECT_EQ(calls, 1) << "x = " << node[0];
        // The normal force of the penalty law, ε_N |g_N| A, along the normal (+z part checked).
        EXPECT_GT(fz, 0.0);
        if (previousForce >= 0) {
          EXPECT_NEAR(fz, previousForce, 1e3 * 2.0 * 0.01 * 0.2) << "x = " << node[0];
        }
        previousForce = fz;
      } else {
        EXPECT_EQ(calls, 0) << "x = " << node[0];
      }
    }
  }
}

// Tunnelling in 3D: a plate moving through the node within the increment, ending beyond reach.
TEST(ContactInterface3D, PlatePassingThroughANodeIsTunnelling) {
  auto spec = oneNodeUnderTwoQuads(0.0);
  spec.rigidSurface.motion = {0.0, 0.0, 10.0};  // the plate at z = 0 (normal +z) moves up through the node at z = 0.5
  const auto interface = cc::makeContactInterface(spec, {1});
  const auto at = [](cc::GlobalIndex, double* x) {
    x[0] = 0.5;
    x[1] = 0.5;
    x[2] = 0.5;
  };
  const auto ignore = [](const cc::GlobalIndex*, int, const double*, const double*, const double*) {};
  interface->evaluate(at, 0.0, true, ignore);
  interface->commit();
  interface->evaluate(at, 1.0, true, ignore);
  const auto t = interface->tunnellingNodes();
  ASSERT_EQ(t.size(), 1u);
  EXPECT_EQ(t[0].facet, 0);
  EXPECT_NEAR(t[0].time, 0.05, 1e-9);
}

// ---- ContactSurface: side-set geometry ------------------------------------------------------------------

// The top of a graded box: the tributary areas sum to the face area, a corner node of a uniform face
// carries a quarter of its one face, the faces' normals point out of the body (+y).
TEST(ContactSurface, TributaryAreasOfAHexSideSet) {
  contessa::mesh::BoxSpec box;
  box.lx = 2.0, box.ly = 1.0, box.lz = 3.0;
  box.nx = 2, box.ny = 1, box.nz = 3;
  box.biasX = 1.5;
  const auto mesh = contessa::mesh::generateBox(box);
  const auto s = cc::ContactSurface::fromSideSet(mesh, mesh.sideSet("top"), "test");
  ASSERT_EQ(s.nodesPerFacet, 4);
  EXPECT_EQ(s.nodes.size(), 3u * 4u);
  double total = 0;
  for (double a : s.areas) total += a;
  EXPECT_NEAR(total, 2.0 * 3.0, 1e-12);
  for (std::size_t f = 0; f < s.facets.size(); f += 4) {
    std::array<P, 4> x{};
    for (int a = 0; a < 4; ++a)
      for (int c = 0; c < 3; ++c) x[a][c] = mesh.coordinates[3 * s.facets[f + a] + c];
    const auto p = cc::Projection<cc::Quad4Facet>::evaluateAt(P{}, x, cc::Quad4Facet::center());
    EXPECT_NEAR(p.normal[1], 1.0, 1e-12);
  }
}

TEST(ContactSurface, RigidQuadChecksNameTheParameter) {
  cc::RigidSurface r;
  r.points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  r.facets = {0, 1, 2, 3};
  r.motion = {0, 0, -1};
  EXPECT_NO_THROW(cc::validateRigidSurface(r, 3, "S"));
  auto expectError = [](cc::RigidSurface bad, const std::string& text) {
    try {
      cc::validateRigidSurface(bad, 3, "S");
      ADD_FAILURE() << "no error for " << text;
    } catch (const contessa::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
  };
  auto bad = r;
  bad.points.pop_back();
  expectError(bad, "S/Points: expected x0, y0, z0");
  bad = r;
  bad.facets = {0, 1, 2, 4};
  expectError(bad, "S/Facets: facet 1: point index 4 out of range");
  bad = r;
  bad.facets = {0, 1, 3, 2};  // folded (a bow tie)
  expectError(bad, "S/Facets: facet 1: degenerate or folded");
  bad = r;
  bad.facets = {0, 1, 2};
  expectError(bad, "S/Facets: expected 4 point indices per facet");
  bad = r;
  bad.motion = {0, -1};
  expectError(bad, "S/Motion: expected three values");
}

}  // namespace

// ---- Finite-difference checks of the interface at the selector's edge cases --------------------------------
namespace fd {

// A deformable master of mesh nodes 0 … n−1 (their positions in `x`, 3 per node) and one slave node n.
struct Setup {
  std::vector<std::array<int, 4>> faces;  ///< node ids, oriented
  std::vector<double> x;                  ///< positions of all nodes, slave last
};

cc::ContactInterfaceSpec spec(const Setup& s) {
  cc::ContactInterfaceSpec spec;
  spec.name = "fd";
  spec.dimension = 3;
  const int slave = static_cast<int>(s.x.size() / 3) - 1;
  spec.slaveNodes = {slave};
  spec.slaveAreas = {0.7};
  spec.slaveFacetLengths = {1.0};
  for (const auto& f : s.faces) spec.masterFacets.insert(spec.masterFacets.end(), f.begin(), f.end());
  spec.law.normalPenalty = 1e3;
  return spec;
}

// The assembled residual and tangent (dense, over every node's dofs) of one evaluation without history.
void evaluate(cc::ContactInterfaceBase& i, const std::vector<double>& x, std::vector<double>& r,
              std::vector<double>& k, int& elements) {
  const std::size_t n = x.size();
  r.assign(n, 0.0);
  k.assign(n * n, 0.0);
  elements = 0;
  i.evaluate([&](cc::GlobalIndex node, double* p) { for (int c = 0; c < 3; ++c) p[c] = x[3 * node + c]; }, 0.0, false,
             [&](const cc::GlobalIndex* dofs, int m, const double* re, const double* ke, const double*) {
               ++elements;
               for (int a = 0; a < m; ++a) {
                 if (dofs[a] < 0) continue;
                 r[dofs[a]] += re[a];
                 for (int b = 0; b < m; ++b)
                   if (dofs[b] >= 0) k[dofs[a] * n + dofs[b]] += ke[a * m + b];
               }
             });
}

// The tangent against central differences of the residual over every dof; the selection must be `kind`.
void expectTangentMatchesDifferences(const Setup& s, cc::SelectionKind kind) {
  const auto interface = cc::makeContactInterface(spec(s), {1});
  // The selection the evaluation makes, from the selector on the same faces.
  std::vector<cc::MasterFacetNodes<cc::Quad4Facet>> faces;
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    cc::MasterFacetNodes<cc::Quad4Facet> m;
    m.id = static_cast<int>(f);
    for (int a = 0; a < 4; ++a) {
      m.nodes[a] = s.faces[f][a];
      for (int c = 0; c < 3; ++c) m.x[a][c] = s.x[3 * s.faces[f][a] + c];
    }
    faces.push_back(m);
  }
  const std::size_t n = s.x.size();
  const P slave{s.x[n - 3], s.x[n - 2], s.x[n - 1]};
  const auto selection = cc::FacetSelector<cc::Quad4Facet>().select(slave, faces);
  ASSERT_EQ(selection.kind, kind);
  ASSERT_LT(selection.gap, 0.0);

  std::vector<double> r, k, rp, rm, kk;
  int elements = 0;
  evaluate(*interface, s.x, r, k, elements);
  ASSERT_EQ(elements, 1);
  double scale = 0;
  for (double v : k) scale = std::max(scale, std::abs(v));
  const double h = 1e-6;
  double worst = 0;
  for (std::size_t j = 0; j < n; ++j) {
    auto xp = s.x, xm = s.x;
    xp[j] += h;
    xm[j] -= h;
    int ep = 0, em = 0;
    evaluate(*interface, xp, rp, kk, ep);
    evaluate(*interface, xm, rm, kk, em);
    ASSERT_EQ(ep, 1);
    ASSERT_EQ(em, 1);
    for (std::size_t i = 0; i < n; ++i) worst = std::max(worst, std::abs((rp[i] - rm[i]) / (2 * h) - k[i * n + j]));
  }
  EXPECT_LT(worst, 1e-6 * scale) << "largest |K - FD| " << worst << " of max |K| " << scale;
}

}  // namespace fd

// Under a valley (a concave edge seen from the slave), in the wedge where the node projects outside both
// faces: AtEdge, the element on the chosen face extended beyond its edge. Two faces, nodes 0–5, slave 6.
TEST(ContactInterface3DTangent, AtAValleyEdgeMatchesFiniteDifferences) {
  fd::Setup s;
  s.faces = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  s.x = {0, 0, 0, 1, 0, 0, 2, 0, 0.6, 0, 1, 0, 1, 1.05, 0, 2, 1, 0.6,  // B rises: a valley along x = 1
         1.004, 0.45, -0.01};                                           // below the edge, in the wedge
  fd::expectTangentMatchesDifferences(s, cc::SelectionKind::AtEdge);
}

// Under a convex ridge a penetrating node lies inside both faces: the smaller |g_N| (OnFacet) near the edge.
TEST(ContactInterface3DTangent, UnderAConvexRidgeMatchesFiniteDifferences) {
  fd::Setup s;
  s.faces = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  s.x = {0, 0, 0, 1, 0, 0, 2, 0, -0.6, 0, 1, 0, 1, 1.05, 0, 2, 1, -0.6, 0.98, 0.45, -0.02};
  fd::expectTangentMatchesDifferences(s, cc::SelectionKind::OnFacet);
}

// Outside a concave corner (three faces of a cavity, normals into it): AtVertex, the element on the face
// most in line with the node, extended. Nodes 0–6, slave 7.
TEST(ContactInterface3DTangent, AtAConcaveCornerVertexMatchesFiniteDifferences) {
  fd::Setup s;
  // The corner at node 0 of the cube [−1, 0]³, faces ordered so their normals point into the cube (−x, −y, −z).
  s.faces = {{0, 1, 2, 3}, {0, 3, 4, 5}, {0, 5, 6, 1}};
  s.x = {0, 0, 0, 0, -1, 0, -1, -1.1, 0, -1, 0, 0, -1, 0, -1, 0, 0, -1, 0, -1, -1,
         0.1, 0.2, 0.3};
  fd::expectTangentMatchesDifferences(s, cc::SelectionKind::AtVertex);
}
