// The 3D mortar kernel on 6-node triangles (MortarQuadraticFacetPair: flat pieces, the pieces' linear
// weights, quadratic geometry at the Gauss points): the nodal mortar areas of those weights, the patch
// test (a uniform gap's weighted gaps are the gap times those areas) on matching and non-matching Tri6
// pairs and under a rigid quadrilateral, the consistent loads a uniform pressure gives the slave nodes, the
// exact gradient and Hessian against central differences (Tri6 on Tri6 cut by the clip, Tri6 on Quad4,
// Tri3 on Tri6), and the mortar interface on a Tri6 face: uniform pressure, tangent and ∂r/∂λ against
// central differences of the residual.
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

constexpr int kM = kQuadraticFacetPairCoordinates;
using Point = std::array<double, 3>;

Point mid(const Point& a, const Point& b) { return {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])}; }

// A Tri6 of corners a, b, c (anticlockwise seen from the side its normal points to) with straight edges.
std::array<Point, 6> tri6(const Point& a, const Point& b, const Point& c) { return {a, b, c, mid(a, b), mid(b, c), mid(c, a)}; }
// The same face ordered the other way round (its normal reversed): corners a, c, b.
std::array<Point, 6> reversed(const std::array<Point, 6>& f) { return {f[0], f[2], f[1], f[5], f[4], f[3]}; }

QuadraticFacetPairCoordinates<double> pairOf(const std::array<Point, 6>& slave, const std::vector<Point>& master) {
  QuadraticFacetPairCoordinates<double> x{};
  for (int a = 0; a < 6; ++a)
    for (int c = 0; c < 3; ++c) x[3 * a + c] = slave[a][c];
  for (std::size_t b = 0; b < master.size(); ++b)
    for (int c = 0; c < 3; ++c) x[18 + 3 * b + c] = master[b][c];
  return x;
}
std::vector<Point> asVector(const std::array<Point, 6>& f) { return {f.begin(), f.end()}; }

MortarFaceNodes faceNodes(const std::array<Point, 6>& f) {
  MortarFaceNodes x{};
  std::copy(f.begin(), f.end(), x.begin());
  return x;
}

const std::array<Point, 6> kSlave = tri6({0.0, 0.0, 0.0}, {1.2, 0.1, 0.0}, {0.2, 0.9, 0.0});
double slaveArea() { return 0.5 * (1.2 * 0.9 - 0.1 * 0.2); }

// The pair's shape with a Tri6 slave: its pieces' areas in `reference` (the measure, eq. M20).
MortarFacetPairShape tri6Shape(int masterNodes, const std::array<Point, 6>& reference) {
  MortarFacetPairShape shape{6, masterNodes, {}};
  shape.slavePieceAreas = mortarFacetPieceMeasures(faceNodes(reference), 6);
  return shape;
}

TEST(MortarQuadraticFacetPair, ThePiecesLinearWeightsGiveEveryNodeAPositiveShareOfTheArea) {
  // eq. M18 on a flat face with straight edges: A/12 at a corner (one piece), A/4 at a mid-edge node (three).
  const double A = slaveArea();
  const auto areas = mortarFacetNodeAreas(faceNodes(kSlave), 6);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(areas[a], A / 12.0, 1e-14) << a;
  for (int a = 3; a < 6; ++a) EXPECT_NEAR(areas[a], A / 4.0, 1e-14) << a;
  EXPECT_NEAR(mortarFacetReferenceArea(faceNodes(kSlave), 6), A, 1e-14);
  // A curved face (mid-edge nodes lifted): still all positive, summing to its pieces' area.
  auto curved = kSlave;
  for (int a = 3; a < 6; ++a) curved[a][2] = 0.05;
  const auto bent = mortarFacetNodeAreas(faceNodes(curved), 6);
  double sum = 0;
  for (int a = 0; a < 6; ++a) {
    EXPECT_GT(bent[a], 0.0);
    sum += bent[a];
  }
  EXPECT_NEAR(sum, mortarFacetReferenceArea(faceNodes(curved), 6), 1e-14);
}

TEST(MortarQuadraticFacetPair, AUniformGapOnAMatchingTri6PairIsTheGapTimesTheNodalAreas) {
  const double gap = -0.01;
  auto master = reversed(kSlave);
  for (auto& p : master) p[2] = gap;
  const auto areas = mortarFacetNodeAreas(faceNodes(kSlave), 6);
  const auto g = facetPairGaps(pairOf(kSlave, asVector(master)), slaveArea(), tri6Shape(6, kSlave));
  ASSERT_TRUE(g.overlaps);
  for (int a = 0; a < 6; ++a) {
    EXPECT_NEAR(g.mortarArea[a], areas[a], 1e-14) << a;
    EXPECT_NEAR(g.weightedGap[a], gap * areas[a], 1e-15) << a;
  }
}

TEST(MortarQuadraticFacetPair, NonMatchingTri6MastersSumToTheGapTimesTheNodalAreas) {
  // Two Tri6 masters tiling the square [−0.5, 1.7] × [−0.4, 1.5] along its diagonal, which cuts the
  // slave's pieces; their mid-edge nodes moved along the (straight) edges, so that the masters' own maps are
  // not affine: the patch test holds regardless (a flat master's gap is uniform).
  const double gap = -0.02;
  const Point p0{-0.5, -0.4, gap}, p1{1.7, -0.4, gap}, p2{1.7, 1.5, gap}, p3{-0.5, 1.5, gap};
  std::array<std::array<Point, 6>, 2> masters = {reversed(tri6(p0, p1, p2)), reversed(tri6(p0, p2, p3))};
  for (auto& m : masters) {  // mid-edge node 3 (edge 0–1) at a third instead of the middle
    for (int c = 0; c < 2; ++c) m[3][c] = m[0][c] + (m[1][c] - m[0][c]) / 3.0;
  }
  const auto areas = mortarFacetNodeAreas(faceNodes(kSlave), 6);
  std::array<double, 6> sum{}, weighted{};
  int overlapping = 0;
  for (const auto& m : masters) {
    const auto g = facetPairGaps(pairOf(kSlave, asVector(m)), slaveArea(), tri6Shape(6, kSlave));
    overlapping += g.overlaps ? 1 : 0;
    for (int a = 0; a < 6; ++a) sum[a] += g.mortarArea[a], weighted[a] += g.weightedGap[a];
  }
  EXPECT_EQ(overlapping, 2);
  for (int a = 0; a < 6; ++a) {
    EXPECT_NEAR(sum[a], areas[a], 1e-13) << a;
    EXPECT_NEAR(weighted[a], gap * areas[a], 1e-14) << a;
  }
}

TEST(MortarQuadraticFacetPair, AMidEdgeNodeSlidingInTheFaceChangesNoWeightedGap) {
  // eq. M20's measure per piece: under a uniform gap, moving mid-edge node 3 in the face's plane (the
  // pieces' areas change, their reference ones do not) leaves every weighted gap g A_a; a measure per face
  // (A_0 / ΣA) would shift weight between the nodes by the pieces' area change.
  const double gap = -0.01;
  const std::vector<Point> plane = {{-1, -1, gap}, {-1, 2, gap}, {2, 2, gap}, {2, -1, gap}};
  auto moved = kSlave;
  moved[3][0] += 0.07, moved[3][1] += 0.05;
  const auto areas = mortarFacetNodeAreas(faceNodes(kSlave), 6);
  const auto g = facetPairGaps(pairOf(moved, plane), slaveArea(), tri6Shape(4, kSlave));
  for (int a = 0; a < 6; ++a) EXPECT_NEAR(g.weightedGap[a], gap * areas[a], 1e-15) << a;
}

TEST(MortarQuadraticFacetPair, AUniformPressureLoadsTheSlaveNodesConsistently) {
  // Under a rigid quadrilateral at a uniform gap, p_a = p at every node gives the slave nodes the forces
  // Σ_k p ∂g̃_k/∂x_a = p ∫ N_a n dA (the weights a partition of unity): the Tri6's consistent loads, 0 at a corner
  // and A/3 at a mid-edge node of a flat face, which is what a uniform traction on a Tet10 face is.
  const double gap = -0.01, A = slaveArea();
  const std::vector<Point> plane = {{-1, -1, gap}, {-1, 2, gap}, {2, 2, gap}, {2, -1, gap}};
  const auto d = facetPairDerivatives(pairOf(kSlave, plane), A, tri6Shape(4, kSlave));
  ASSERT_TRUE(d.overlaps);
  for (int a = 0; a < 6; ++a) {
    double force = 0;
    for (int k = 0; k < 6; ++k) force += d.gradient[k][3 * a + 2];
    EXPECT_NEAR(-force, a < 3 ? 0.0 : A / 3.0, 1e-13) << a;  // ∂g/∂z_a = −N_a: the gap shrinks as the slave rises
  }
}

// A curved, warped Tri6 slave under a tilted, curved Tri6 master that covers part of it.
std::array<Point, 6> unevenSlave() {
  auto s = tri6({0.02, -0.01, 0.01}, {1.05, 0.03, -0.02}, {0.1, 1.04, 0.015});
  s[3][2] += 0.03, s[4][2] -= 0.02, s[5][2] += 0.025, s[4][0] += 0.04;
  return s;
}
std::array<Point, 6> unevenMaster() {
  auto m = reversed(tri6({0.31, -0.22, -0.006}, {1.52, 0.28, -0.013}, {-0.2, 1.17, -0.008}));
  m[3][2] -= 0.02, m[4][2] += 0.015, m[5][1] += 0.03;
  return m;
}

// The Hessian's columns of a slave corner, a slave mid-edge node and two master nodes.
void expectDerivativesAreCentralDifferences(const QuadraticFacetPairCoordinates<double>& x,
                                            const MortarFacetPairShape& shape, double referenceArea) {
  testing::expectDerivativesAreCentralDifferences<kQuadraticFacetNodes>(
      x, shape, referenceArea, {1, 11, 3 * shape.slaveNodes == 18 ? 20 : 18, 3 * 6 + 3 * (shape.masterNodes - 1) + 2});
}

TEST(MortarQuadraticFacetPair, GradientAndHessianOfTri6OnTri6CutByTheClipAreCentralDifferences) {
  // Reference pieces of the flat kSlave: the current ones stretched, the measure below 1.
  expectDerivativesAreCentralDifferences(pairOf(unevenSlave(), asVector(unevenMaster())), tri6Shape(6, kSlave), 0.6);
}

TEST(MortarQuadraticFacetPair, GradientAndHessianOfTri6OnAQuadAndOfATriangleOnATri6AreCentralDifferences) {
  const std::vector<Point> quad = {{0.3, -0.2, -0.01}, {0.25, 1.3, -0.02}, {1.4, 1.2, -0.005}, {1.35, -0.15, -0.012}};
  expectDerivativesAreCentralDifferences(pairOf(unevenSlave(), quad), tri6Shape(4, kSlave), 0.55);
  const auto s = unevenSlave();
  expectDerivativesAreCentralDifferences(pairOf({s[0], s[1], s[2], {}, {}, {}}, asVector(unevenMaster())), {3, 6}, 0.5);
}

// The interface on a Tri6 face: two Tri6 slave facets tiling the unit square on z = 0 (nodes 0–8 on a
// 3 × 3 grid of spacing 0.5, row-major) under a rigid quadrilateral (a plane at z = −d) or a deformable
// Tri6 master (nodes 9–14, one triangle over the square, normal down).
constexpr double kPenalty = 1e3;

ContactInterfaceSpec tri6Spec(bool rigidMaster, const std::vector<double>& x) {
  ContactInterfaceSpec spec;
  spec.name = "tri6";
  spec.dimension = 3;
  spec.mortar = true;
  spec.slaveNodes = {0, 1, 2, 3, 4, 5, 6, 7, 8};
  spec.slaveFacets = {0, 2, 8, 1, 5, 4, 0, 8, 6, 4, 7, 3};
  spec.slaveFacetNodes = 6;
  spec.masterFacetNodes = rigidMaster ? 4 : 6;
  spec.slaveFacetLengths.assign(9, 1.0);
  spec.slaveAreas.assign(9, 0.0);
  for (std::size_t f = 0; f < spec.slaveFacets.size(); f += 6) {
    MortarFaceNodes nodes{};
    for (int a = 0; a < 6; ++a)
      for (int c = 0; c < 3; ++c) nodes[a][c] = x[3 * spec.slaveFacets[f + a] + c];
    const auto pieces = mortarFacetPieceMeasures(nodes, 6);
    spec.slaveFacetMeasures.insert(spec.slaveFacetMeasures.end(), pieces.begin(), pieces.begin() + 4);
    const auto areas = mortarFacetNodeAreas(nodes, 6);
    for (int a = 0; a < 6; ++a) spec.slaveAreas[spec.slaveFacets[f + a]] += areas[a];
  }
  spec.law.normalPenalty = kPenalty;
  if (rigidMaster) {
    testing::setMovingRigidPlate(spec, 1.3, 1.2);
  } else {
    spec.masterFacets = {9, 10, 11, 12, 13, 14};
  }
  return spec;
}

std::vector<double> tri6Coordinates(double penetration) {
  std::vector<double> x;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) x.insert(x.end(), {0.5 * i, 0.5 * j, 0.0});
  // A master triangle covering the square, clockwise from +z (normal down), mid-edge nodes at the middles.
  const Point a{-0.3, -0.3, -penetration}, b{-0.3, 2.5, -penetration}, c{2.5, -0.3, -penetration};
  for (const Point& p : tri6(a, b, c)) x.insert(x.end(), p.begin(), p.end());
  return x;
}

std::unique_ptr<ContactInterfaceBase> tri6Interface(bool rigidMaster) {
  return makeMortarInterface(tri6Spec(rigidMaster, tri6Coordinates(0.0)), std::vector<char>(9, 1));
}

TEST(MortarInterfaceTri6, AFlatPenetrationGivesTheSamePressureAtEveryNodeAndTheConsistentLoads) {
  const double d = 1e-3;
  for (bool rigid : {false, true}) {
    auto interface = tri6Interface(rigid);
    std::vector<double> x = tri6Coordinates(d);
    if (rigid)  // the rigid plane sits at z = −0.03 (its body above): the slave face at −0.03 + d penetrates it by d
      for (int node = 0; node < 9; ++node) x[3 * node + 2] = -0.03 + d;
    const auto a = testing::assemble<3>(*interface, x, 0.0);
    for (const auto& s : a.states) EXPECT_NEAR(s.pressure, kPenalty * d, 1e-12 * kPenalty * d) << rigid;
    // The corners of the two Tri6 (nodes 0, 2, 6, 8) take no force, the mid-edge nodes p A/3 per facet.
    for (int node : {0, 2, 6, 8}) EXPECT_NEAR(a.residual[3 * node + 2], 0.0, 1e-14) << node;
    EXPECT_NEAR(-a.residual[3 * 4 + 2], -kPenalty * d * 2 * 0.5 / 3.0, 1e-14);  // node 4: the diagonal's middle, two facets
    EXPECT_NEAR(-a.residual[3 * 1 + 2], -kPenalty * d * 0.5 / 3.0, 1e-14);
    EXPECT_EQ(a.counts.active, 9);
  }
}

// Every node moved a little: curved facets, the master's edges inside the slave facets.
std::vector<double> unevenTri6Face() {
  std::vector<double> x = tri6Coordinates(0.02);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += 0.013 * std::sin(1.7 * double(i) + 0.4);
  return x;
}

TEST(MortarInterfaceTri6, TangentAndLoadDerivativeAreCentralDifferencesOfTheResidual) {
  for (bool rigid : {false, true}) {
    const auto x = unevenTri6Face();  // the rigid plane at z = −0.03: 0.017 to 0.043 into it
    const auto a = testing::assemble<3>(*tri6Interface(rigid), x, 0.3);
    for (const auto& s : a.states) EXPECT_NE(s.status, ContactStatus::Open) << "the test wants every node closed";
    // Slave corners 0 and 8, slave mid-edge nodes 1 and 4 (4 on both facets), master corner 9, mid-edge 13.
    double scale = 0;
    const std::vector<int> columns = rigid ? std::vector<int>{0, 1, 4, 8} : std::vector<int>{0, 1, 4, 8, 9, 13};
    const double error = testing::tangentColumnsCentralDifferenceError(
        a.tangent, x, [&](const std::vector<double>& y) { return testing::assemble<3>(*tri6Interface(rigid), y, 0.3).residual; },
        testing::nodeColumns<3>(columns), &scale);
    EXPECT_GT(scale, 10.0) << rigid;
    EXPECT_LT(error, 1e-6 * scale) << rigid;
    if (!rigid) continue;
    double dScale = 0;
    const double dError = testing::loadDerivativeCentralDifferenceError(
        a.dLambda, 0.3, [&](double mu) { return testing::assemble<3>(*tri6Interface(true), x, mu).residual; }, &dScale);
    EXPECT_GT(dScale, 0.1);
    EXPECT_LT(dError, 1e-6 * dScale);
  }
}

}  // namespace
}  // namespace contessa::contact
