// The cell families (Mesh.hpp's topology tables, ShapeFunctions, CellGeometry, and Mesh::validate's
// checks for them): every type's sides against its mid-edge nodes and its reference cell, the shape
// functions against their defining properties, the measure, and a good, an inverted, a tangled and a
// badly placed mid-edge node element of every type with its one-line message.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "MeshTestSupport.hpp"
#include "mesh/CellGeometry.hpp"
#include "mesh/Mesh.hpp"
#include "mesh/MeshConversion.hpp"
#include "mesh/MeshDistribution.hpp"
#include "mesh/Generators.hpp"
#include "mesh/ShapeFunctions.hpp"

using namespace contessa::mesh;
using test_support::messageOf;

namespace {

const CellType kNewTypes[] = {CellType::Tri3,  CellType::Tri6,  CellType::Quad8,  CellType::Quad9,  CellType::Tet4,
                              CellType::Tet10, CellType::Hex20, CellType::Hex27, CellType::Wedge6, CellType::Wedge15};
const CellType kAllTypes[] = {CellType::Quad4, CellType::Hex8,  CellType::Tri3,   CellType::Tri6,
                              CellType::Quad8, CellType::Quad9, CellType::Tet4,   CellType::Tet10,
                              CellType::Hex20, CellType::Hex27, CellType::Wedge6, CellType::Wedge15};

using Point = std::array<double, 3>;

Point reference(CellType t, int a) { return referenceNode(t, a); }

Point centroid(CellType t) {
  Point c{0, 0, 0};
  for (int a = 0; a < numCorners(t); ++a)
    for (int i = 0; i < 3; ++i) c[i] += reference(t, a)[i] / numCorners(t);
  return c;
}

// The reference cell mapped by x = A ξ + b: the node coordinates, node-major.
std::vector<double> affineCell(CellType t, const double A[3][3], const double* b) {
  const int d = cellDimension(t);
  std::vector<double> x;
  for (int a = 0; a < nodesPerCell(t); ++a) {
    const Point xi = reference(t, a);
    for (int i = 0; i < d; ++i) {
      double v = b[i];
      for (int k = 0; k < d; ++k) v += A[i][k] * xi[k];
      x.push_back(v);
    }
  }
  return x;
}

const double kShear[3][3] = {{1.3, 0.2, -0.1}, {0.1, 0.9, 0.3}, {-0.2, 0.15, 1.1}};
const double kShift[3] = {0.5, -1.0, 2.0};

double det(int d, const double A[3][3]) {
  if (d == 2) return A[0][0] * A[1][1] - A[0][1] * A[1][0];
  return A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) - A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
         A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
}

double referenceMeasure(CellType t) {
  switch (numCorners(t)) {
    case 3: return 0.5;                                       // unit triangle
    case 4: return cellDimension(t) == 2 ? 4.0 : 1.0 / 6.0;  // [−1, 1]², unit tetrahedron
    case 6: return 1.0;                                       // unit triangle × [−1, 1]
    default: return 8.0;                                      // [−1, 1]³
  }
}

// A one-block mesh of one cell with nodes x (0 .. n−1 in order).
Mesh oneCell(CellType t, const std::vector<double>& x) {
  Mesh m;
  m.dimension = cellDimension(t);
  m.coordinates = x;
  ElementBlock b{"b", t, {0}, {}};
  for (int a = 0; a < nodesPerCell(t); ++a) b.connectivity.push_back(a);
  m.blocks.push_back(b);
  return m;
}

}  // namespace

TEST(CellFamilies, NamesCountsAndLookupByNodeCount) {
  for (CellType t : kAllTypes) {
    CellType found = CellType::Quad4;
    ASSERT_TRUE(cellTypeOf(cellDimension(t), nodesPerCell(t), found)) << exodusCellName(t);
    EXPECT_EQ(found, t) << exodusCellName(t);
    EXPECT_EQ(static_cast<int>(midEdgeNodes(t).size()) > 0, cellOrder(t) == 2) << exodusCellName(t);
  }
  EXPECT_STREQ(exodusCellName(CellType::Tet10), "TETRA10");
  EXPECT_STREQ(exodusCellName(CellType::Wedge15), "WEDGE15");
  EXPECT_EQ(nodesPerCell(CellType::Hex27), 27);
  CellType none;
  EXPECT_FALSE(cellTypeOf(3, 5, none));  // a pyramid
  EXPECT_FALSE(cellTypeOf(2, 10, none));
}

// Each side: its corners are corners of the cell, its mid-edge nodes sit (in the reference cell) at
// the middle of consecutive corners in the side's order, a centre node at the centre; the corner order
// is counter-clockwise seen from outside (3D) or has the cell on its left (2D).
TEST(CellFamilies, SidesFollowTheExodusOrderAndPointOutwards) {
  for (CellType t : kAllTypes) {
    const std::string name = exodusCellName(t);
    const int d = cellDimension(t);
    const Point c = centroid(t);
    for (int s = 0; s < numSides(t); ++s) {
      const auto nodes = sideNodes(t, s);
      const int k = numSideCorners(t, s);
      ASSERT_EQ(static_cast<int>(nodes.size()), k + (cellOrder(t) == 2 ? k : 0) + (t == CellType::Hex27 ? 1 : 0) -
                                                    (d == 2 && cellOrder(t) == 2 ? 1 : 0))
          << name << " side " << s;
      Point sideCentre{0, 0, 0};
      for (int i = 0; i < k; ++i) {
        EXPECT_LT(nodes[i], numCorners(t)) << name;
        for (int j = 0; j < 3; ++j) sideCentre[j] += reference(t, nodes[i])[j] / k;
      }
      const int mids = d == 2 ? (cellOrder(t) == 2 ? 1 : 0) : (cellOrder(t) == 2 ? k : 0);
      for (int i = 0; i < mids; ++i) {
        const Point a = reference(t, nodes[i]), b = reference(t, nodes[(i + 1) % k]), m = reference(t, nodes[k + i]);
        for (int j = 0; j < 3; ++j) EXPECT_DOUBLE_EQ(m[j], (a[j] + b[j]) / 2) << name << " side " << s << " node " << k + i;
      }
      if (t == CellType::Hex27) {
        for (int j = 0; j < 3; ++j) EXPECT_DOUBLE_EQ(reference(t, nodes[8])[j], sideCentre[j]) << "HEX27 side " << s;
      }
      // Outward: the normal from the corner order points from the cell's centroid to the side's.
      const Point p0 = reference(t, nodes[0]), p1 = reference(t, nodes[1]), p2 = reference(t, nodes[k - 1]);
      double outward = 0;
      if (d == 2) {
        const double tx = p1[0] - p0[0], ty = p1[1] - p0[1];  // the cell on the left: normal (ty, −tx)
        outward = ty * (sideCentre[0] - c[0]) - tx * (sideCentre[1] - c[1]);
      } else {
        const double u[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
        const double v[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        for (int j = 0; j < 3; ++j) outward += n[j] * (sideCentre[j] - c[j]);
      }
      EXPECT_GT(outward, 0) << name << " side " << s;
    }
  }
}

// N_a(ξ_b) = δ_ab; Σ N_a = 1 and Σ N_a x_a = A ξ + b at any point (the geometry is exact for an
// affine map); Σ ∂N_a/∂ξ x_a = A there, so det J = det A and the measure is det A × the reference's.
TEST(CellFamilies, ShapeFunctionsInterpolateAndReproduceAffineMaps) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (CellType t : kAllTypes) {
    const std::string name = exodusCellName(t);
    const int d = cellDimension(t), n = nodesPerCell(t);
    std::vector<double> N(n), dN(n * d);
    for (int b = 0; b < n; ++b) {
      shapeValues(t, reference(t, b).data(), N.data());
      for (int a = 0; a < n; ++a) EXPECT_NEAR(N[a], a == b ? 1.0 : 0.0, 1e-14) << name << " N" << a << " at node " << b;
    }
    const auto x = affineCell(t, kShear, kShift);
    for (int trial = 0; trial < 5; ++trial) {
      double xi[3] = {u(rng), u(rng), 2 * u(rng) - 1};
      if (numCorners(t) == 4 && d == 3) xi[2] = u(rng) * (1 - xi[0] - xi[1]);  // inside the tetrahedron
      if (numCorners(t) == 8 || (numCorners(t) == 4 && d == 2)) xi[0] = 2 * xi[0] - 1, xi[1] = 2 * xi[1] - 1;
      shapeValues(t, xi, N.data());
      shapeGradients(t, xi, dN.data());
      double sum = 0;
      for (double v : N) sum += v;
      EXPECT_NEAR(sum, 1, 1e-13) << name;
      for (int i = 0; i < d; ++i) {
        double xi_i = kShift[i];
        for (int k = 0; k < d; ++k) xi_i += kShear[i][k] * xi[k];
        double mapped = 0;
        for (int a = 0; a < n; ++a) mapped += N[a] * x[a * d + i];
        EXPECT_NEAR(mapped, xi_i, 1e-13) << name;
        for (int k = 0; k < d; ++k) {
          double J = 0;
          for (int a = 0; a < n; ++a) J += dN[a * d + k] * x[a * d + i];
          EXPECT_NEAR(J, kShear[i][k], 1e-13) << name << " dx" << i << "/dxi" << k;
        }
      }
    }
    EXPECT_NEAR(cellMeasure(t, x.data()), det(d, kShear) * referenceMeasure(t), 1e-12) << name;
  }
}

// A quadratic cell with a curved edge (a mid-edge node pushed outwards): the measure gains the
// parabolic segment's area 2/3 · chord · sagitta, as the quadrature is exact for it.
TEST(CellFamilies, MeasureOfACurvedTri6AndQuad8) {
  const double identity[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, zero[3] = {0, 0, 0};
  auto tri = affineCell(CellType::Tri6, identity, zero);
  tri[3 * 2 + 1] -= 0.1;  // node 3, middle of the edge (0,0)–(1,0), pushed to y = −0.1
  EXPECT_NEAR(cellMeasure(CellType::Tri6, tri.data()), 0.5 + 2.0 / 3 * 1 * 0.1, 1e-14);
  auto quad = affineCell(CellType::Quad8, identity, zero);
  quad[4 * 2 + 1] -= 0.3;  // node 4, middle of the edge (−1,−1)–(1,−1)
  EXPECT_NEAR(cellMeasure(CellType::Quad8, quad.data()), 4 + 2.0 / 3 * 2 * 0.3, 1e-13);
}

TEST(CellFamilies, GoodCellsOfEveryTypePassTheChecks) {
  for (CellType t : kAllTypes) {
    const Mesh m = oneCell(t, affineCell(t, kShear, kShift));
    EXPECT_EQ(messageOf([&] { m.validate("cell"); }), "<no InputError>") << exodusCellName(t);
  }
}

TEST(CellFamilies, MirroredCellsAreInverted) {
  for (CellType t : kNewTypes) {
    const double mirror[3][3] = {{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, zero[3] = {0, 0, 0};
    const Mesh m = oneCell(t, affineCell(t, mirror, zero));
    const std::string expected =
        cellDimension(t) == 2 ? "cell: element 1 of block 'b' is inverted (clockwise node order): list its nodes counter-clockwise"
        : numCorners(t) == 4  ? "cell: element 1 of block 'b' is inverted (left-handed node order): list nodes 1, 2, 3 "
                                "counter-clockwise seen from node 4"
                              : "cell: element 1 of block 'b' is inverted (left-handed node order): list the bottom face "
                                "counter-clockwise seen from the top face, then the top face in the same order";
    EXPECT_EQ(messageOf([&] { m.validate("cell"); }), expected) << exodusCellName(t);
  }
}

// A mid-edge node moved along its edge: by 20 % of the edge's length the cell is still valid (its
// Jacobian at the nearer corner is 1 − 4 · 0.2 of the straight cell's); by 30 % it is refused, naming
// the node and its corners.
TEST(CellFamilies, MidEdgeNodeOffTheMiddleOfItsEdge) {
  for (CellType t : kNewTypes) {
    if (cellOrder(t) == 1) continue;
    const int d = cellDimension(t);
    const MidEdgeNode e = midEdgeNodes(t).back();
    for (double shift : {0.2, 0.3}) {
      auto x = affineCell(t, kShear, kShift);
      for (int i = 0; i < d; ++i) x[e.middle * d + i] += shift * (x[e.second * d + i] - x[e.first * d + i]);
      const Mesh m = oneCell(t, x);
      const std::string message = messageOf([&] { m.validate("cell"); });
      if (shift < 0.25) {
        EXPECT_EQ(message, "<no InputError>") << exodusCellName(t);
        continue;
      }
      EXPECT_EQ(message, "cell: element 1 of block 'b' has its mid-edge node " + std::to_string(e.middle + 1) +
                             " off the middle of the edge from node " + std::to_string(e.first + 1) + " to node " +
                             std::to_string(e.second + 1) +
                             " by 30 % of the edge's length (at most 25 % is accepted): check the mid-edge node order (" +
                             exodusCellName(t) + " in Exodus order) and the node's coordinates")
          << exodusCellName(t);
    }
  }
}

// A corner pushed inside the cell past the opposite corners' plane (mid-edge nodes following, at the
// middle of their edges): the Jacobian is negative there but not everywhere.
TEST(CellFamilies, ReentrantCornerIsTangled) {
  for (CellType t : kNewTypes) {
    if (numCorners(t) == 3 || (numCorners(t) == 4 && cellDimension(t) == 3)) continue;  // simplices: affine, never tangled
    const int d = cellDimension(t);
    const double identity[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, zero[3] = {0, 0, 0};
    auto x = affineCell(t, identity, zero);
    const int moved = numCorners(t) == 6 ? 4 : 2;  // a corner of the top face (wedge) or corner 3
    const Point c = centroid(t);
    for (int i = 0; i < d; ++i) x[moved * d + i] = c[i] - 0.3 * (x[moved * d + i] - c[i]);  // through the centre
    for (const MidEdgeNode& e : midEdgeNodes(t))
      for (int i = 0; i < d; ++i) x[e.middle * d + i] = (x[e.first * d + i] + x[e.second * d + i]) / 2;
    const Mesh m = oneCell(t, x);
    const std::string message = messageOf([&] { m.validate("cell"); });
    EXPECT_NE(message.find("cell: element 1 of block 'b' is tangled (its Jacobian is negative at "), std::string::npos)
        << exodusCellName(t) << ": " << message;
  }
}

// Side sets: a face two cells share is interior, whatever the families (a hexahedron and a wedge
// sharing a quadrilateral face; two Tet10 sharing a triangle), found by the face's corners.
TEST(CellFamilies, SideSetsOnSharedFacesAreInterior) {
  Mesh m;
  m.dimension = 3;
  // Hex8 on [0,1]³ and a Wedge6 beyond x = 1 extruded along y: its triangles (1,0,0) (1,0,1) (2,0,0)
  // at y = 0 and y = 1, its quadrilateral side 1 the hexahedron's side 2 (x = 1).
  m.coordinates = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 2, 0, 0, 2, 1, 0};
  m.blocks.push_back(ElementBlock{"hex", CellType::Hex8, {0}, {0, 1, 2, 3, 4, 5, 6, 7}});
  m.blocks.push_back(ElementBlock{"wedge", CellType::Wedge6, {1}, {1, 5, 8, 2, 6, 9}});
  EXPECT_EQ(messageOf([&] { m.validate("mixed"); }), "<no InputError>");
  Mesh bad = m;
  bad.sideSets.push_back(SideSet{"x1", {0}, {1}});  // hex side 2: x = 1
  EXPECT_EQ(messageOf([&] { bad.validate("mixed"); }),
            "mixed: side set 'x1' holds side 2 of element 1, which element 2 shares: an interior side, not on the "
            "boundary of the mesh");
  Mesh good = m;
  good.sideSets.push_back(SideSet{"ends", {1, 1}, {3, 4}});  // the wedge's triangles
  EXPECT_EQ(messageOf([&] { good.validate("mixed"); }), "<no InputError>");
}

// A contact surface takes the sides of every family, as facets of their node count (MasterFacet.hpp): TRI3
// faces of tetrahedra, TRI6 of quadratic ones, QUAD8 of Hex20; a surface of hexahedra and prisms holds the
// prisms' triangles as quadrilaterals with their last node twice; other mixtures are refused in one line.
TEST(CellFamilies, ContactSurfacesTakeTheSidesOfEveryFamily) {
  BoxSpec spec;
  const Mesh tets = splitIntoSimplices(generateBox(spec));
  const ReplicatedSurface tri3 = surfaceOfSideSet(tets, "top");
  EXPECT_EQ(tri3.nodesPerFacet, 3);
  EXPECT_EQ(tri3.elements.size(), 2u);
  EXPECT_EQ(surfaceOfSideSet(withMidEdgeNodes(tets), "top").nodesPerFacet, 6);
  EXPECT_EQ(surfaceOfSideSet(withMidEdgeNodes(generateBox(spec)), "top").nodesPerFacet, 8);
  EXPECT_EQ(surfaceOfSideSet(withMidEdgeNodes(generateBox(spec), true), "top").nodesPerFacet, 9);
  EXPECT_EQ(surfaceOfSideSet(generateBox(spec), "top").elements.size(), 1u);

  // Hex8 on [0,1]³ and a Wedge6 beyond x = 1 (as in SideSetsOnSharedFacesAreInterior): the hex's side 4
  // (y = 0) and the wedge's triangle side 3 (y = 0).
  Mesh m;
  m.dimension = 3;
  m.coordinates = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 2, 0, 0, 2, 1, 0};
  m.blocks.push_back(ElementBlock{"hex", CellType::Hex8, {0}, {0, 1, 2, 3, 4, 5, 6, 7}});
  m.blocks.push_back(ElementBlock{"wedge", CellType::Wedge6, {1}, {1, 5, 8, 2, 6, 9}});
  m.sideSets.push_back(SideSet{"front", {0, 1}, {0, 3}});
  const ReplicatedSurface mixed = surfaceOfSideSet(m, "front");
  ASSERT_EQ(mixed.nodesPerFacet, 4);
  const auto triangle = sideNodes(CellType::Wedge6, 3);
  ASSERT_EQ(triangle.size(), 3u);
  const std::vector<GlobalIndex> wedge{1, 5, 8, 2, 6, 9};
  EXPECT_EQ(std::vector<GlobalIndex>(mixed.facetNodes.begin() + 4, mixed.facetNodes.end()),
            (std::vector<GlobalIndex>{wedge[triangle[0]], wedge[triangle[1]], wedge[triangle[2]], wedge[triangle[2]]}));
  const Mesh quadratic = withMidEdgeNodes(m);
  EXPECT_EQ(messageOf([&] { surfaceOfSideSet(quadratic, "front"); }),
            "side set 'front' mixes sides of 6 and 8 nodes: a contact surface takes one facet type (or linear "
            "triangles with quadrilaterals)");
}

// A flat simplex has zero Jacobian everywhere: degenerate, named so.
TEST(CellFamilies, FlatSimplicesAreDegenerate) {
  const Mesh tet = oneCell(CellType::Tet4, {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
  EXPECT_EQ(messageOf([&] { tet.validate("flat"); }),
            "flat: element 1 of block 'b' is degenerate (zero volume): its nodes lie on one plane");
  const Mesh tri = oneCell(CellType::Tri3, {0, 0, 1, 1, 2, 2});
  EXPECT_EQ(messageOf([&] { tri.validate("flat"); }),
            "flat: element 1 of block 'b' is degenerate (zero area): its nodes lie on one line");
}
