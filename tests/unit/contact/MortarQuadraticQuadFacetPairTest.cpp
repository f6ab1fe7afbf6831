// The 3D mortar kernel on 8- and 9-node quadrilaterals (MortarQuadraticFacetPair: a Quad8 on its four corner
// triangles and the quadrilateral of its mid-edge nodes, a Quad9 on its four quarters; the pieces' linear
// and bilinear weights; the quadratic geometry at the Gauss points): the nodal mortar areas of those
// weights, the patch test (a uniform gap's weighted gaps are the gap times those areas) on matching and
// non-matching pairs, a mid-edge or centre node sliding in the face, the consistent loads a uniform
// pressure gives the slave nodes, the exact gradient and Hessian against central differences (Quad8 on
// Quad8 cut by the clip, Quad9 on a Quad4, a Quad4 on a Quad9, a Quad8 on a Tri6), and the mortar
// interface on Quad8 and Quad9 faces: uniform pressure, tangent and ∂r/∂λ against central differences.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "contact/MortarInterface.hpp"
#include "contact/MortarQuadraticFacetPair.hpp"
#include "MortarQuadraticTestTools.hpp"
#include "MortarTestTools.hpp"

namespace contessa::contact {
namespace {

using Point = std::array<double, 3>;
using Face = std::vector<Point>;

Point mid(const Point& a, const Point& b) { return {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])}; }

// A Quad8 of corners a, b, c, d (anticlockwise seen from the side its normal points to) with straight
// edges; a Quad9 adds the centre (the corners' mean: a parallelogram's centre).
Face quad8(const Point& a, const Point& b, const Point& c, const Point& d) {
  return {a, b, c, d, mid(a, b), mid(b, c), mid(c, d), mid(d, a)};
}
Face quad9(const Point& a, const Point& b, const Point& c, const Point& d) {
  Face f = quad8(a, b, c, d);
  f.push_back(mid(mid(a, c), mid(b, d)));
  return f;
}
// The same face ordered the other way round (its normal reversed): corners a, d, c, b.
Face reversed(const Face& f) {
  Face r = {f[0], f[3], f[2], f[1]};
  if (f.size() == 6) return {f[0], f[2], f[1], f[5], f[4], f[3]};  // a Tri6: corners a, c, b
  if (f.size() >= 8) r.insert(r.end(), {f[7], f[6], f[5], f[4]});
  if (f.size() == 9) r.push_back(f[8]);
  return r;
}

template <int Slots>
QuadraticFacetPairCoordinates<double, Slots> pairOf(const Face& slave, const Face& master) {
  QuadraticFacetPairCoordinates<double, Slots> x{};
  for (std::size_t a = 0; a < slave.size(); ++a)
    for (int c = 0; c < 3; ++c) x[3 * a + c] = slave[a][c];
  for (std::size_t b = 0; b < master.size(); ++b)
    for (int c = 0; c < 3; ++c) x[3 * Slots + 3 * b + c] = master[b][c];
  return x;
}

MortarFaceNodes faceNodes(const Face& f) {
  MortarFaceNodes x{};
  std::copy(f.begin(), f.end(), x.begin());
  return x;
}

// The pair's shape with a quadratic slave: the measures of its pieces in `reference` (eq. M20).
MortarFacetPairShape shapeOf(const Face& reference, int masterNodes) {
  MortarFacetPairShape shape{static_cast<int>(reference.size()), masterNodes, {}};
  shape.slavePieceAreas = mortarFacetPieceMeasures(faceNodes(reference), shape.slaveNodes);
  return shape;
}

// A flat parallelogram slave on z = 0 (straight edges, mid-edge nodes at the middles).
const Point kA{0.0, 0.0, 0.0}, kB{1.2, 0.1, 0.0}, kC{1.4, 1.0, 0.0}, kD{0.2, 0.9, 0.0};
double slaveArea() { return 1.2 * 0.9 - 0.1 * 0.2; }
Face slaveFace(int nodes) { return nodes == 8 ? quad8(kA, kB, kC, kD) : quad9(kA, kB, kC, kD); }
// A rigid plane at z = gap (a Quad4 covering the slave, normal down).
Face planeAt(double gap) { return {{-1, -1, gap}, {-1, 2, gap}, {2, 2, gap}, {2, -1, gap}}; }

TEST(MortarQuadraticQuadFacetPair, ThePiecesWeightsGiveEveryNodeAPositiveShareOfTheArea) {
  // eq. M18 on a flat parallelogram: Quad8 A/24 at a corner (one corner triangle), 5A/24 at a mid-edge
  // node (two triangles and a quarter of the middle quadrilateral, half the face); Quad9 A/16 at a corner,
  // A/8 at a mid-edge node, A/4 at the centre (one, two and four quarters' quarters).
  const double A = slaveArea();
  const auto q8 = mortarFacetNodeAreas(faceNodes(slaveFace(8)), 8);
  for (int a = 0; a < 4; ++a) EXPECT_NEAR(q8[a], A / 24.0, 1e-14) << a;
  for (int a = 4; a < 8; ++a) EXPECT_NEAR(q8[a], 5.0 * A / 24.0, 1e-14) << a;
  const auto q9 = mortarFacetNodeAreas(faceNodes(slaveFace(9)), 9);
  for (int a = 0; a < 4; ++a) EXPECT_NEAR(q9[a], A / 16.0, 1e-14) << a;
  for (int a = 4; a < 8; ++a) EXPECT_NEAR(q9[a], A / 8.0, 1e-14) << a;
  EXPECT_NEAR(q9[8], A / 4.0, 1e-14);
  for (int nodes : {8, 9}) {
    EXPECT_NEAR(mortarFacetReferenceArea(faceNodes(slaveFace(nodes)), nodes), A, 1e-14) << nodes;
    // A curved face (mid-edge nodes and centre lifted, warped pieces): still all positive, summing to its
    // pieces' projected areas.
    Face curved = slaveFace(nodes);
    for (int a = 4; a < nodes; ++a) curved[a][2] = 0.05 + 0.02 * a;
    const auto bent = mortarFacetNodeAreas(faceNodes(curved), nodes);
    double sum = 0;
    for (int a = 0; a < nodes; ++a) {
      EXPECT_GT(bent[a], 0.0) << nodes << " " << a;
      sum += bent[a];
    }
    EXPECT_NEAR(sum, mortarFacetReferenceArea(faceNodes(curved), nodes), 1e-14) << nodes;
  }
}

template <class Gaps>
void expectPatch(const Gaps& sum, const MortarFaceNodes& slave, int nodes, double gap) {
  const auto areas = mortarFacetNodeAreas(slave, nodes);
  for (int a = 0; a < nodes; ++a) {
    EXPECT_NEAR(sum.mortarArea[a], areas[a], 1e-14) << a;
    EXPECT_NEAR(sum.weightedGap[a], gap * areas[a], 1e-15) << a;
  }
}

TEST(MortarQuadraticQuadFacetPair, AUniformGapOnMatchingPairsIsTheGapTimesTheNodalAreas) {
  const double gap = -0.01;
  for (int nodes : {8, 9}) {
    Face master = reversed(slaveFace(nodes));
    for (auto& p : master) p[2] = gap;
    const Face slave = slaveFace(nodes);
    if (nodes == 8) {
      const auto g = facetPairGaps(pairOf<8>(slave, master), 0.0, shapeOf(slave, 8));
      ASSERT_TRUE(g.overlaps);
      expectPatch(g, faceNodes(slave), 8, gap);
    } else {
      const auto g = facetPairGaps(pairOf<9>(slave, master), 0.0, shapeOf(slave, 9));
      ASSERT_TRUE(g.overlaps);
      expectPatch(g, faceNodes(slave), 9, gap);
    }
  }
}

// Masters tiling the rectangle [−0.5, 1.9] × [−0.4, 1.5] at z = gap, cut at x = 0.53 (through the slave's
// pieces), their mid-edge nodes on edge 0–1 moved to a third of it, so that the masters' own maps are not
// affine: the patch test holds regardless (a flat master's gap is uniform).
std::vector<Face> tilingMasters(int nodes, double gap) {
  const Point p0{-0.5, -0.4, gap}, p1{0.53, -0.4, gap}, p2{0.53, 1.5, gap}, p3{-0.5, 1.5, gap};
  const Point q1{1.9, -0.4, gap}, q2{1.9, 1.5, gap};
  std::vector<Face> faces;
  if (nodes == 6) {
    const auto tri = [](const Point& a, const Point& b, const Point& c) {
      return Face{a, b, c, mid(a, b), mid(b, c), mid(c, a)};
    };
    faces = {reversed(tri(p0, p1, p2)), reversed(tri(p0, p2, p3)), reversed(tri(p1, q1, q2)), reversed(tri(p1, q2, p2))};
  } else {
    const auto make = nodes == 8 ? quad8 : quad9;
    faces = {reversed(make(p0, p1, p2, p3)), reversed(make(p1, q1, q2, p2))};
  }
  for (auto& m : faces) {
    const int firstMid = nodes == 6 ? 3 : 4;
    for (int c = 0; c < 2; ++c) m[firstMid][c] = m[0][c] + (m[1][c] - m[0][c]) / 3.0;
  }
  return faces;
}

TEST(MortarQuadraticQuadFacetPair, NonMatchingMastersSumToTheGapTimesTheNodalAreas) {
  const double gap = -0.02;
  // A Quad8 slave on two Quad8 masters and on two Quad9 masters; a Quad9 slave on four Tri6 masters.
  struct Case {
    int slaveNodes, masterNodes;
  };
  for (const Case c : {Case{8, 8}, Case{8, 9}, Case{9, 6}}) {
    const Face slave = slaveFace(c.slaveNodes);
    MortarQuadraticFacetPairGaps<double, 9> sum;
    int overlapping = 0;
    for (const Face& m : tilingMasters(c.masterNodes, gap)) {
      const auto add = [&](const auto& g) {
        overlapping += g.overlaps ? 1 : 0;
        for (int a = 0; a < c.slaveNodes; ++a) sum.mortarArea[a] += g.mortarArea[a], sum.weightedGap[a] += g.weightedGap[a];
      };
      if (c.slaveNodes == 8 && c.masterNodes == 8)
        add(facetPairGaps(pairOf<8>(slave, m), 0.0, shapeOf(slave, c.masterNodes)));
      else
        add(facetPairGaps(pairOf<9>(slave, m), 0.0, shapeOf(slave, c.masterNodes)));
    }
    EXPECT_GE(overlapping, 2) << c.slaveNodes << " on " << c.masterNodes;
    const auto areas = mortarFacetNodeAreas(faceNodes(slave), c.slaveNodes);
    for (int a = 0; a < c.slaveNodes; ++a) {
      EXPECT_NEAR(sum.mortarArea[a], areas[a], 1e-13) << c.slaveNodes << " on " << c.masterNodes << ": " << a;
      EXPECT_NEAR(sum.weightedGap[a], gap * areas[a], 1e-14) << c.slaveNodes << " on " << c.masterNodes << ": " << a;
    }
  }
}

TEST(MortarQuadraticQuadFacetPair, NodesSlidingInTheFaceChangeNoWeightedGap) {
  // eq. M20's measure, J_0 / J on a 4-node piece: under a uniform gap, moving mid-edge node 4 (and on the
  // Quad9 the centre and node 5) in the face's plane makes the pieces trapezoids, whose own nodal integrals
  // ∫ Φ_a dA change (by 1.5 % and more here, checked below); the weighted gaps stay g A_a of the reference
  // face, to the 6-point rule's error on a trapezoid, where the map from the projection plane to the
  // piece's coordinates is not affine (measured 1e-9 of g A_a on the Quad8, 1.2e-7 on the Quad9).
  const double gap = -0.01;
  for (int nodes : {8, 9}) {
    const Face reference = slaveFace(nodes);
    Face moved = reference;
    moved[4][0] += 0.07, moved[4][1] += 0.05;
    if (nodes == 9) moved[8][0] -= 0.06, moved[8][1] += 0.04, moved[5][1] -= 0.05;
    const auto areas = mortarFacetNodeAreas(faceNodes(reference), nodes);
    const auto current = mortarFacetNodeAreas(faceNodes(moved), nodes);
    double change = 0;
    for (int a = 0; a < nodes; ++a) change = std::max(change, std::abs(current[a] / areas[a] - 1.0));
    EXPECT_GT(change, 1.5e-2) << nodes;
    const auto check = [&](const auto& g) {
      for (int a = 0; a < nodes; ++a)
        EXPECT_NEAR(g.weightedGap[a], gap * areas[a], 1e-6 * std::abs(gap * areas[a])) << nodes << ": " << a;
    };
    if (nodes == 8)
      check(facetPairGaps(pairOf<8>(moved, planeAt(gap)), 0.0, shapeOf(reference, 4)));
    else
      check(facetPairGaps(pairOf<9>(moved, planeAt(gap)), 0.0, shapeOf(reference, 4)));
  }
}

TEST(MortarQuadraticQuadFacetPair, AUniformPressureLoadsTheSlaveNodesConsistently) {
  // Under a rigid quadrilateral at a uniform gap, p_a = p at every node gives the slave nodes the forces
  // Σ_k p ∂g̃_k/∂x_a = p ∫ N_a n dA (the weights a partition of unity): the consistent loads of a flat
  // parallelogram, Quad8 −A/12 at a corner and A/3 at a mid-edge node, Quad9 A/36, A/9 and 4A/9.
  const double gap = -0.01, A = slaveArea();
  const auto expectLoads = [&](const auto& d, int nodes, const std::vector<double>& expected) {
    ASSERT_TRUE(d.overlaps);
    for (int a = 0; a < nodes; ++a) {
      double force = 0;
      for (int k = 0; k < nodes; ++k) force += d.gradient[k][3 * a + 2];
      EXPECT_NEAR(-force, expected[a] * A, 1e-13) << nodes << ": " << a;  // ∂g/∂z_a = −N_a
    }
  };
  const double c8 = -1.0 / 12.0, m8 = 1.0 / 3.0;
  expectLoads(facetPairDerivatives(pairOf<8>(slaveFace(8), planeAt(gap)), 0.0, shapeOf(slaveFace(8), 4)), 8,
              {c8, c8, c8, c8, m8, m8, m8, m8});
  const double c9 = 1.0 / 36.0, m9 = 1.0 / 9.0;
  expectLoads(facetPairDerivatives(pairOf<9>(slaveFace(9), planeAt(gap)), 0.0, shapeOf(slaveFace(9), 4)), 9,
              {c9, c9, c9, c9, m9, m9, m9, m9, 4.0 / 9.0});
}

// A flat square slave face [0, 0.5]² at z = 0 under a flat master of the same faces at z = gap, shifted by d
// along x: the slave's own face and its two neighbours (matching faces, as the 2 × 2 patch's at the
// solution), so that every slave piece edge across x lies on a master piece edge at d = 0 (the Quad8's
// diagonals and x = 0, 0.25, 0.5; the Quad9's x = 0, 0.25, 0.5). The summed weighted gaps, mortar areas and
// the gaps' derivative along the shift.
struct ShiftedMatching {
  double area = 0, weightedGap = 0, derivative = 0;  // summed over the slave nodes and the three masters
};
ShiftedMatching shiftedMatching(int nodes, double gap, double d) {
  const Point a{0, 0, 0}, b{0.5, 0, 0}, c{0.5, 0.5, 0}, e{0, 0.5, 0};
  const Face slave = nodes == 8 ? quad8(a, b, c, e) : quad9(a, b, c, e);
  const MortarFacetPairShape shape = shapeOf(slave, nodes);
  ShiftedMatching out;
  for (double offset : {-0.5, 0.0, 0.5}) {
    const auto at = [&](const Point& p) { return Point{p[0] + offset + d, p[1], gap}; };
    const Face master = reversed(nodes == 8 ? quad8(at(a), at(b), at(c), at(e)) : quad9(at(a), at(b), at(c), at(e)));
    const auto add = [&](const auto& g) {
      for (int k = 0; k < nodes; ++k) {
        out.area += g.mortarArea[k], out.weightedGap += g.weightedGap[k];
        for (int m = 0; m < nodes; ++m) out.derivative += g.gradient[k][3 * nodes + 3 * m];  // ∂/∂(master x)
      }
    };
    if (nodes == 8)
      add(facetPairDerivatives(pairOf<8>(slave, master), 0.0, shape));
    else
      add(facetPairDerivatives(pairOf<9>(slave, master), 0.0, shape));
  }
  return out;
}

TEST(MortarQuadraticQuadFacetPair, MatchingMastersShiftedAcrossTheSlavePieceEdgesKeepTheWeightedGapsSmooth) {
  // The coincident piece edges of theory-contact §13.2: a slave vertex within the clip's snap band of a
  // master piece edge is on it in both master pieces that share the edge (MortarClipping.hpp). The sum over
  // the masters is then the whole slave face, A g, on both sides of d = 0, and its derivative along the shift
  // is zero, as its central difference across d = 0. When the vertex counted inside the neighbouring piece,
  // a sliver of the offset's width was integrated twice: area A + L |d| (L = 1.5 on the Quad8, 1 on the
  // Quad9), a kink at d = 0 whose one-sided derivatives ±g L alternated between Newton's iterates.
  const double gap = -1e-3, A = 0.25;
  for (int nodes : {8, 9}) {
    for (double d : {-3e-7, -1e-7, -1e-8, 0.0, 1e-8, 1e-7, 3e-7}) {
      const ShiftedMatching m = shiftedMatching(nodes, gap, d);
      EXPECT_NEAR(m.area, A, 1e-14) << nodes << " d " << d;
      EXPECT_NEAR(m.weightedGap, gap * A, 1e-16) << nodes << " d " << d;
      EXPECT_NEAR(m.derivative, 0.0, 1e-16) << nodes << " d " << d;
    }
    const double h = 1e-7;
    const double centralDifference =
        (shiftedMatching(nodes, gap, h).weightedGap - shiftedMatching(nodes, gap, -h).weightedGap) / (2 * h);
    EXPECT_NEAR(centralDifference, shiftedMatching(nodes, gap, 0.5 * h).derivative, 1e-11) << nodes;
  }
}

// A curved, warped slave under a tilted, curved master that covers part of it (the clip cuts its pieces).
Face unevenSlave(int nodes) {
  Face s = slaveFace(nodes);
  const double lift[9] = {0.01, -0.02, 0.015, 0.005, 0.03, -0.02, 0.025, 0.01, 0.02};
  for (int a = 0; a < nodes; ++a) s[a][2] += lift[a], s[a][0] += 0.01 * std::sin(3.0 * a);
  s[5][0] += 0.04;
  return s;
}
Face unevenMaster(int nodes) {
  if (nodes == 6)  // a curved Tri6
    return reversed(Face{{0.31, -0.22, -0.006}, {2.2, 0.5, -0.013}, {-0.4, 1.9, -0.008}, {1.25, 0.14, -0.03},
                         {0.9, 1.2, 0.005}, {-0.045, 0.84, -0.007}});
  const Point a{0.41, -0.22, -0.006}, b{1.72, 0.18, -0.013}, c{1.5, 1.3, -0.01}, d{0.3, 1.17, -0.008};
  Face m = reversed(nodes == 8 ? quad8(a, b, c, d) : quad9(a, b, c, d));
  m[4][2] -= 0.02, m[5][2] += 0.015, m[7][1] += 0.03;
  return m;
}

template <int Slots>
void expectDerivativesAreCentralDifferences(const QuadraticFacetPairCoordinates<double, Slots>& x,
                                            const MortarFacetPairShape& shape, const std::vector<int>& hessianColumns) {
  testing::expectDerivativesAreCentralDifferences<Slots>(x, shape, 0.6, hessianColumns);
}

TEST(MortarQuadraticQuadFacetPair, GradientAndHessianOfQuad8OnQuad8CutByTheClipAreCentralDifferences) {
  // Reference pieces of the flat parallelogram: the current ones moved, lifted and warped. Hessian columns
  // of a slave corner, a slave mid-edge node, a master corner and a master mid-edge node.
  expectDerivativesAreCentralDifferences<8>(pairOf<8>(unevenSlave(8), unevenMaster(8)), shapeOf(slaveFace(8), 8),
                                            {1, 3 * 5 + 2, 3 * 8 + 2, 3 * 8 + 3 * 5});
}

TEST(MortarQuadraticQuadFacetPair, GradientAndHessianOfQuad9OnAQuadAndOfAQuadOnAQuad9AreCentralDifferences) {
  const Face quad = {{0.3, -0.2, -0.01}, {0.25, 1.3, -0.02}, {1.5, 1.2, -0.005}, {1.35, -0.15, -0.012}};
  expectDerivativesAreCentralDifferences<9>(pairOf<9>(unevenSlave(9), quad), shapeOf(slaveFace(9), 4),
                                            {3 * 8 + 2, 3 * 4, 3 * 9 + 1});
  const Face s = unevenSlave(9);
  expectDerivativesAreCentralDifferences<9>(pairOf<9>({s[0], s[1], s[2], s[3]}, unevenMaster(9)), {4, 9, {}},
                                            {2, 3 * 9 + 3 * 8 + 2, 3 * 9 + 3 * 5});
}

TEST(MortarQuadraticQuadFacetPair, GradientAndHessianOfQuad8OnATri6AreCentralDifferences) {
  expectDerivativesAreCentralDifferences<8>(pairOf<8>(unevenSlave(8), unevenMaster(6)), shapeOf(slaveFace(8), 6),
                                            {3 * 6 + 1, 3 * 8 + 3 * 4 + 2});
}

// The interface on quadratic quadrilaterals: two Quad8 slave facets side by side on the unit square at
// z = 0 (13 nodes), or one Quad9 (9 nodes), under the moving rigid plate or a deformable master of the
// same type (one facet over the square, normal down).
constexpr double kPenalty = 1e3;

struct QuadFaces {
  int nodes;                      // 8 or 9
  std::vector<double> x;          // the slave nodes, then the master's
  std::vector<GlobalIndex> slaveFacets, masterFacet;
  int slaveCount() const { return static_cast<int>(x.size() / 3) - nodes; }
};

// The slave grid and the master facet over [−0.3, 1.3]², penetration d below z = 0.
QuadFaces quadFaces(int nodes, double d) {
  QuadFaces f{nodes, {}, {}, {}};
  const auto add = [&](const Point& p) {
    f.x.insert(f.x.end(), p.begin(), p.end());
    return static_cast<GlobalIndex>(f.x.size() / 3 - 1);
  };
  if (nodes == 8) {
    // Corners 0–5 (two rows of three), mid-edge nodes 6–12.
    for (double y : {0.0, 1.0})
      for (double xx : {0.0, 0.5, 1.0}) add({xx, y, 0.0});
    for (const Point& p : {Point{0.25, 0, 0}, Point{0.75, 0, 0}, Point{0.25, 1, 0}, Point{0.75, 1, 0}, Point{0, 0.5, 0},
                           Point{0.5, 0.5, 0}, Point{1, 0.5, 0}})
      add(p);
    f.slaveFacets = {0, 1, 4, 3, 6, 11, 8, 10, 1, 2, 5, 4, 7, 12, 9, 11};
  } else {
    const Face q = quad9({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0});
    for (int a = 0; a < 9; ++a) f.slaveFacets.push_back(add(q[a]));
  }
  const Face m = reversed(nodes == 8 ? quad8({-0.3, -0.3, -d}, {1.3, -0.3, -d}, {1.3, 1.3, -d}, {-0.3, 1.3, -d})
                                     : quad9({-0.3, -0.3, -d}, {1.3, -0.3, -d}, {1.3, 1.3, -d}, {-0.3, 1.3, -d}));
  for (const Point& p : m) f.masterFacet.push_back(add(p));
  return f;
}

ContactInterfaceSpec quadSpec(const QuadFaces& f, bool rigidMaster) {
  ContactInterfaceSpec spec;
  spec.name = "quad" + std::to_string(f.nodes);
  spec.dimension = 3;
  spec.mortar = true;
  for (int k = 0; k < f.slaveCount(); ++k) spec.slaveNodes.push_back(k);
  spec.slaveFacets = f.slaveFacets;
  spec.slaveFacetNodes = f.nodes;
  spec.masterFacetNodes = rigidMaster ? 4 : f.nodes;
  spec.slaveFacetLengths.assign(spec.slaveNodes.size(), 1.0);
  spec.slaveAreas.assign(spec.slaveNodes.size(), 0.0);
  for (std::size_t s = 0; s < f.slaveFacets.size(); s += f.nodes) {
    MortarFaceNodes nodes{};
    for (int a = 0; a < f.nodes; ++a)
      for (int c = 0; c < 3; ++c) nodes[a][c] = f.x[3 * f.slaveFacets[s + a] + c];
    const auto measures = mortarFacetPieceMeasures(nodes, f.nodes);
    spec.slaveFacetMeasures.insert(spec.slaveFacetMeasures.end(), measures.begin(),
                                   measures.begin() + mortarFaceMeasures(f.nodes));
    const auto areas = mortarFacetNodeAreas(nodes, f.nodes);
    for (int a = 0; a < f.nodes; ++a) spec.slaveAreas[f.slaveFacets[s + a]] += areas[a];
  }
  spec.law.normalPenalty = kPenalty;
  if (rigidMaster)
    testing::setMovingRigidPlate(spec, 1.3, 1.2);
  else
    spec.masterFacets = f.masterFacet;
  return spec;
}

std::unique_ptr<ContactInterfaceBase> quadInterface(int nodes, bool rigidMaster) {
  const QuadFaces f = quadFaces(nodes, 0.0);
  return makeMortarInterface(quadSpec(f, rigidMaster), std::vector<char>(f.slaveCount(), 1));
}

TEST(MortarInterfaceQuad8Quad9, AFlatPenetrationGivesTheSamePressureAtEveryNodeAndTheConsistentLoads) {
  const double d = 1e-3, p = kPenalty * d;
  for (int nodes : {8, 9})
    for (bool rigid : {false, true}) {
      QuadFaces f = quadFaces(nodes, d);
      const int slaves = f.slaveCount();
      if (rigid)  // the rigid plane sits at z = −0.03 (its body above): the slave face at −0.03 + d penetrates it by d
        for (int k = 0; k < slaves; ++k) f.x[3 * k + 2] = -0.03 + d;
      const auto a = testing::assemble<3>(*quadInterface(nodes, rigid), f.x, 0.0);
      for (const auto& s : a.states) EXPECT_NEAR(s.pressure, p, 1e-12 * p) << nodes << " " << rigid;
      EXPECT_EQ(a.counts.active, slaves);
      // The consistent loads, facet by facet (area 1/2 each for the Quad8s, 1 for the Quad9): Quad8 −A/12
      // at a corner, A/3 at a mid-edge node; Quad9 A/36, A/9, 4A/9. The force on the slave is −p times
      // them along z (r is the slave's residual, the contact force on it taken with a minus sign).
      std::vector<double> load(slaves, 0.0);
      const double A = nodes == 8 ? 0.5 : 1.0;
      for (std::size_t s = 0; s < f.slaveFacets.size(); s += nodes)
        for (int k = 0; k < nodes; ++k)
          load[f.slaveFacets[s + k]] += (nodes == 8 ? (k < 4 ? -1.0 / 12.0 : 1.0 / 3.0) : (k < 4 ? 1.0 / 36.0 : k < 8 ? 1.0 / 9.0 : 4.0 / 9.0)) * A;
      for (int k = 0; k < slaves; ++k) EXPECT_NEAR(a.residual[3 * k + 2], p * load[k], 1e-14) << nodes << " " << rigid << ": " << k;
    }
}

// Every node moved a little: curved facets, the master's edges inside the slave facets.
std::vector<double> unevenFaces(int nodes) {
  std::vector<double> x = quadFaces(nodes, 0.02).x;
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += 0.013 * std::sin(1.7 * double(i) + 0.4);
  return x;
}

TEST(MortarInterfaceQuad8Quad9, TangentAndLoadDerivativeAreCentralDifferencesOfTheResidual) {
  for (int nodes : {8, 9})
    for (bool rigid : {false, true}) {
      const auto x = unevenFaces(nodes);  // the rigid plane at z = −0.03: 0.017 to 0.043 into it
      const auto a = testing::assemble<3>(*quadInterface(nodes, rigid), x, 0.3);
      for (const auto& s : a.states) EXPECT_NE(s.status, ContactStatus::Open) << "the test wants every node closed";
      // A slave corner, a slave mid-edge node (Quad8: node 11, on both facets; Quad9: the centre 8), a
      // master corner and a master mid-edge node.
      const int slaves = quadFaces(nodes, 0.0).slaveCount();
      std::vector<int> columns = nodes == 8 ? std::vector<int>{0, 11} : std::vector<int>{0, 8};
      if (!rigid) columns.insert(columns.end(), {slaves, slaves + 5});
      double scale = 0;
      const double error = testing::tangentColumnsCentralDifferenceError(
          a.tangent, x,
          [&](const std::vector<double>& y) { return testing::assemble<3>(*quadInterface(nodes, rigid), y, 0.3).residual; },
          testing::nodeColumns<3>(columns), &scale);
      EXPECT_GT(scale, 10.0) << nodes << " " << rigid;
      EXPECT_LT(error, 1e-6 * scale) << nodes << " " << rigid;
      if (!rigid) continue;
      double dScale = 0;
      const double dError = testing::loadDerivativeCentralDifferenceError(
          a.dLambda, 0.3, [&](double mu) { return testing::assemble<3>(*quadInterface(nodes, true), x, mu).residual; },
          &dScale);
      EXPECT_GT(dScale, 0.1) << nodes;
      EXPECT_LT(dError, 1e-6 * dScale) << nodes;
    }
}

}  // namespace
}  // namespace contessa::contact
