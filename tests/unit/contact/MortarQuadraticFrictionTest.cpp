// 3D mortar Coulomb friction on quadratic faces (theory-contact.md §13.1, eq. M21; MortarQuadraticFacetPair):
// the weighted slip increments of Tri6, Quad8 and Quad9 pairs against their closed form (a rigid slide gives
// the tangential slide times the nodes' mortar areas, no normal part) and their exact first and second
// derivatives against central differences (Tri6 on Tri6, Tri6 on Quad4, Quad8 on Quad8, Quad9 on Quad4, a
// Quad4 on a Quad9, all cut by the clip, warped and curved); the interface on Tri6, Quad8 and Quad9 faces:
// residual, tangent and ∂r/∂λ against central differences of the residual in stick and in slip, on a
// deformable and on a rigid master; and a pressed, slid patch's forces against ε_T u A and μ ε_N d A.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "contact/MortarInterface.hpp"
#include "contact/MortarQuadraticFacetPair.hpp"
#include "MortarQuadraticTestTools.hpp"
#include "MortarTestTools.hpp"

namespace contessa::contact {
namespace {

using testing::Face;
using testing::faceNodes;
using testing::mid;
using testing::Point;
using testing::reversed;
// Faces of corners a, b, c(, d), anticlockwise seen from the side their normal points to, straight edges.
Face tri6(const Point& a, const Point& b, const Point& c) { return {a, b, c, mid(a, b), mid(b, c), mid(c, a)}; }
Face quad8(const Point& a, const Point& b, const Point& c, const Point& d) {
  return {a, b, c, d, mid(a, b), mid(b, c), mid(c, d), mid(d, a)};
}
Face quad9(const Point& a, const Point& b, const Point& c, const Point& d) {
  Face f = quad8(a, b, c, d);
  f.push_back(mid(mid(a, c), mid(b, d)));
  return f;
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
// The pair's shape: the measures of the slave's pieces in `reference` (eq. M20) when it is quadratic.
MortarFacetPairShape shapeOf(const Face& reference, int masterNodes) {
  MortarFacetPairShape shape{static_cast<int>(reference.size()), masterNodes, {}};
  shape.slavePieceAreas = mortarFacetPieceMeasures(faceNodes(reference), shape.slaveNodes);
  return shape;
}

// Flat reference slaves, and warped, curved current ones under tilted, curved masters covering part of them.
Face flatSlave(int nodes) {
  const Point a{0.0, 0.0, 0.0}, b{1.2, 0.1, 0.0}, c{1.4, 1.0, 0.0}, d{0.2, 0.9, 0.0};
  if (nodes == 6) return tri6(a, b, d);
  return nodes == 8 ? quad8(a, b, c, d) : quad9(a, b, c, d);
}
Face unevenSlave(int nodes) {
  Face s = flatSlave(nodes);
  const double lift[9] = {0.01, -0.02, 0.015, 0.005, 0.03, -0.02, 0.025, 0.01, 0.02};
  for (int a = 0; a < nodes; ++a) s[a][2] += lift[a], s[a][0] += 0.01 * std::sin(3.0 * a);
  s[nodes == 6 ? 4 : 5][0] += 0.04;
  return s;
}
Face unevenMaster(int nodes) {
  const Point a{0.41, -0.22, -0.006}, b{1.72, 0.18, -0.013}, c{1.5, 1.3, -0.01}, d{0.3, 1.17, -0.008};
  if (nodes == 4) return reversed({a, b, c, d});
  Face m = reversed(nodes == 6 ? tri6(a, b, Point{-0.3, 1.4, -0.008}) : nodes == 8 ? quad8(a, b, c, d) : quad9(a, b, c, d));
  m[3][2] -= 0.02, m[4][2] += 0.015, m[5][1] += 0.03;
  return m;
}

template <int Slots>
QuadraticFacetPairCommitted<Slots> committedOf(const QuadraticFacetPairCoordinates<double, Slots>& x,
                                               const MortarFacetPairShape& shape) {
  QuadraticFacetPairCommitted<Slots> then{};
  for (int i = 0; i < 6 * Slots; ++i) {
    const int node = i / 3;
    const bool used = node < Slots ? node < shape.slaveNodes : node - Slots < shape.masterNodes;
    if (used) then[i] = x[i] - 0.02 * std::cos(0.9 * i + 0.3) - (i % 3 == 0 ? 0.015 : 0.0);
  }
  return then;
}

// The slip increments' gradient over every coordinate and their Hessian over `columns` against central
// differences; the gaps are those of the frictionless kernel, to the bit.
template <int Slots>
void expectSlipDerivativesAreCentralDifferences(const QuadraticFacetPairCoordinates<double, Slots>& x,
                                                const MortarFacetPairShape& shape, const std::vector<int>& columns) {
  constexpr int kM = 6 * Slots;
  const QuadraticFacetPairCommitted<Slots> then = committedOf<Slots>(x, shape);
  const double referenceArea = 0.6;
  const auto d = facetPairDerivatives(x, referenceArea, shape, nullptr, &then);
  ASSERT_TRUE(d.overlaps);
  ASSERT_EQ(d.slipGradient.size(), static_cast<std::size_t>(3 * Slots));
  const auto plain = facetPairGaps(x, referenceArea, shape, &then);
  const auto withoutSlip = facetPairDerivatives(x, referenceArea, shape);
  const double h = 1e-6;
  std::vector<std::array<double, 3 * Slots>> fd(kM);
  for (int j = 0; j < kM; ++j) {
    auto plus = x, minus = x;
    plus[j] += h;
    minus[j] -= h;
    const auto gp = facetPairGaps(plus, referenceArea, shape, &then), gm = facetPairGaps(minus, referenceArea, shape, &then);
    for (int a = 0; a < Slots; ++a)
      for (int c = 0; c < 3; ++c) fd[j][3 * a + c] = (gp.weightedSlip[a][c] - gm.weightedSlip[a][c]) / (2 * h);
  }
  std::vector<MortarQuadraticPairDerivatives<Slots>> dp, dm;
  for (int j : columns) {
    auto plus = x, minus = x;
    plus[j] += h;
    minus[j] -= h;
    dp.push_back(facetPairDerivatives(plus, referenceArea, shape, nullptr, &then));
    dm.push_back(facetPairDerivatives(minus, referenceArea, shape, nullptr, &then));
  }
  for (int a = 0; a < shape.slaveNodes; ++a) {
    EXPECT_EQ(d.weightedGap[a], withoutSlip.weightedGap[a]) << "the slip leaves the gap alone";
    EXPECT_EQ(d.gradient[a], withoutSlip.gradient[a]);
    for (int c = 0; c < 3; ++c) {
      const int e = 3 * a + c;
      EXPECT_NEAR(d.weightedSlip[a][c], plain.weightedSlip[a][c], 1e-16) << "values and derivatives agree";
      double scale = 0, gradientError = 0, hessianScale = 0, hessianError = 0;
      for (int j = 0; j < kM; ++j) {
        scale = std::max(scale, std::abs(d.slipGradient[e][j]));
        gradientError = std::max(gradientError, std::abs(fd[j][e] - d.slipGradient[e][j]));
      }
      for (std::size_t k = 0; k < columns.size(); ++k)
        for (int i = 0; i < kM; ++i) {
          const int j = columns[k];
          const double exact = d.slipHessian[e][i * kM + j];
          hessianScale = std::max(hessianScale, std::abs(exact));
          hessianError = std::max(hessianError, std::abs((dp[k].slipGradient[e][i] - dm[k].slipGradient[e][i]) / (2 * h) - exact));
          EXPECT_NEAR(exact, d.slipHessian[e][j * kM + i], 1e-12) << "a Hessian is symmetric";
        }
      // Derivatives that are there: in the slave's plane of the order of the mortar areas (a corner's
      // small: 0.002 to 0.01 measured); across it (c = 2) through the master's tilt only.
      EXPECT_GT(scale, c < 2 ? 1e-3 : 1e-5) << "slave node " << a << ", component " << c;
      EXPECT_GT(hessianScale, c < 2 ? 1e-4 : 1e-6) << "slave node " << a << ", component " << c;
      EXPECT_LT(gradientError, 1e-8 * scale) << "slave node " << a << ", component " << c;
      EXPECT_LT(hessianError, 1e-7 * hessianScale) << "slave node " << a << ", component " << c;
    }
  }
}

TEST(MortarQuadraticFacetPairSlip, Tri6SlipIncrementsAreDifferentiatedTwiceExactly) {
  // Hessian columns: a slave corner, a slave mid-edge node, a master corner, a master mid-edge node.
  expectSlipDerivativesAreCentralDifferences<6>(pairOf<6>(unevenSlave(6), unevenMaster(6)), shapeOf(flatSlave(6), 6),
                                                {1, 3 * 4, 3 * 6 + 2, 3 * 6 + 3 * 4 + 1});
  expectSlipDerivativesAreCentralDifferences<6>(pairOf<6>(unevenSlave(6), unevenMaster(4)), shapeOf(flatSlave(6), 4),
                                                {3 * 3 + 2, 3 * 6 + 3 * 2});
}

TEST(MortarQuadraticFacetPairSlip, Quad8AndQuad9SlipIncrementsAreDifferentiatedTwiceExactly) {
  expectSlipDerivativesAreCentralDifferences<8>(pairOf<8>(unevenSlave(8), unevenMaster(8)), shapeOf(flatSlave(8), 8),
                                                {1, 3 * 5 + 2, 3 * 8 + 2, 3 * 8 + 3 * 5});
  expectSlipDerivativesAreCentralDifferences<9>(pairOf<9>(unevenSlave(9), unevenMaster(4)), shapeOf(flatSlave(9), 4),
                                                {3 * 8 + 2, 3 * 4, 3 * 9 + 1});
  const Face s = unevenSlave(9);
  expectSlipDerivativesAreCentralDifferences<9>(pairOf<9>({s[0], s[1], s[2], s[3]}, unevenMaster(9)), {4, 9, {}},
                                                {2, 3 * 9 + 3 * 8 + 2});
}

TEST(MortarQuadraticFacetPairSlip, ARigidSlideGivesTheTangentialSlipTimesTheMortarAreasAndNoNormalPart) {
  // The flat slave on z = 0 under a plane at z = −0.01 covering it, slid from its committed place by
  // (0.04, −0.03, 0.005): the slip is (0.04, −0.03, 0) times each node's mortar area (0.005 is the gap's
  // change), and none without committed positions.
  const auto check = [](auto x, int nodes) {
    const MortarFacetPairShape shape = shapeOf(flatSlave(nodes), 4);
    auto then = x;
    const Point slide{0.04, -0.03, 0.005};
    for (int a = 0; a < nodes; ++a)
      for (int c = 0; c < 3; ++c) then[3 * a + c] -= slide[c];
    const auto g = facetPairGaps(x, 0.0, shape, &then);
    ASSERT_TRUE(g.overlaps);
    for (int a = 0; a < nodes; ++a) {
      EXPECT_GT(g.mortarArea[a], 0.02) << nodes << " " << a;
      for (int c = 0; c < 2; ++c) EXPECT_NEAR(g.weightedSlip[a][c], slide[c] * g.mortarArea[a], 1e-15) << nodes << " " << a;
      EXPECT_NEAR(g.weightedSlip[a][2], 0.0, 1e-16);
      EXPECT_EQ(facetPairGaps(x, 0.0, shape).weightedSlip[a][0], 0.0);
    }
  };
  const Face plane = {{-1, -1, -0.01}, {-1, 2, -0.01}, {2, 2, -0.01}, {2, -1, -0.01}};
  check(pairOf<6>(flatSlave(6), plane), 6);
  check(pairOf<8>(flatSlave(8), plane), 8);
  check(pairOf<9>(flatSlave(9), plane), 9);
}

// The interface on quadratic faces: two Tri6 or two Quad8 slave facets tiling the unit square on z = 0, or
// one Quad9, under a deformable master facet of the same type over [−0.3, 1.3]² (normal down) or the moving
// rigid plate. μ = 0.3, ε_N = ε_T = 10³.
constexpr double kPenalty = 1e3;
constexpr double kFriction = 0.3;

struct QuadraticFaces {
  int nodes;                   // 6, 8 or 9
  bool rigidMaster;
  std::vector<double> x;       // the slave nodes, then the master's
  std::vector<GlobalIndex> slaveFacets, masterFacet;
  int slaveCount() const { return static_cast<int>(x.size() / 3) - static_cast<int>(masterFacet.size()); }
};

QuadraticFaces facesOf(int nodes, bool rigidMaster, double d) {
  QuadraticFaces f{nodes, rigidMaster, {}, {}, {}};
  const auto add = [&](const Point& p) {
    f.x.insert(f.x.end(), p.begin(), p.end());
    return static_cast<GlobalIndex>(f.x.size() / 3 - 1);
  };
  if (nodes == 6) {  // a 3 × 3 grid of spacing 0.5, the square cut along its diagonal
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) add({0.5 * i, 0.5 * j, 0.0});
    f.slaveFacets = {0, 2, 8, 1, 5, 4, 0, 8, 6, 4, 7, 3};
  } else if (nodes == 8) {  // corners 0–5 (two rows of three), mid-edge nodes 6–12
    for (double y : {0.0, 1.0})
      for (double xx : {0.0, 0.5, 1.0}) add({xx, y, 0.0});
    for (const Point& p : {Point{0.25, 0, 0}, Point{0.75, 0, 0}, Point{0.25, 1, 0}, Point{0.75, 1, 0}, Point{0, 0.5, 0},
                           Point{0.5, 0.5, 0}, Point{1, 0.5, 0}})
      add(p);
    f.slaveFacets = {0, 1, 4, 3, 6, 11, 8, 10, 1, 2, 5, 4, 7, 12, 9, 11};
  } else {
    for (const Point& p : quad9({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0})) f.slaveFacets.push_back(add(p));
  }
  if (rigidMaster) return f;
  const Point a{-0.3, -0.3, -d}, b{1.3, -0.3, -d}, c{1.3, 1.3, -d}, e{-0.3, 1.3, -d};
  const Face m = reversed(nodes == 6 ? tri6(a, Point{2.9, -0.3, -d}, Point{-0.3, 2.9, -d}) : nodes == 8 ? quad8(a, b, c, e) : quad9(a, b, c, e));
  for (const Point& p : m) f.masterFacet.push_back(add(p));
  return f;
}

ContactInterfaceSpec specOf(const QuadraticFaces& f) {
  ContactInterfaceSpec spec;
  spec.name = "quadratic" + std::to_string(f.nodes);
  spec.dimension = 3;
  spec.mortar = true;
  for (int k = 0; k < f.slaveCount(); ++k) spec.slaveNodes.push_back(k);
  spec.slaveFacets = f.slaveFacets;
  spec.slaveFacetNodes = f.nodes;
  spec.masterFacetNodes = f.rigidMaster ? 4 : f.nodes;
  spec.slaveFacetLengths.assign(spec.slaveNodes.size(), 1.0);
  spec.slaveAreas.assign(spec.slaveNodes.size(), 0.0);
  for (std::size_t s = 0; s < f.slaveFacets.size(); s += f.nodes) {
    MortarFaceNodes nodes{};
    for (int a = 0; a < f.nodes; ++a)
      for (int c = 0; c < 3; ++c) nodes[a][c] = f.x[3 * f.slaveFacets[s + a] + c];
    const auto measures = mortarFacetPieceMeasures(nodes, f.nodes);
    spec.slaveFacetMeasures.insert(spec.slaveFacetMeasures.end(), measures.begin(), measures.begin() + mortarFaceMeasures(f.nodes));
    const auto areas = mortarFacetNodeAreas(nodes, f.nodes);
    for (int a = 0; a < f.nodes; ++a) spec.slaveAreas[f.slaveFacets[s + a]] += areas[a];
  }
  spec.law.normalPenalty = kPenalty;
  spec.law.tangentialPenalty = kPenalty;
  spec.law.frictionCoefficient = kFriction;
  if (f.rigidMaster)
    testing::setMovingRigidPlate(spec, 1.3, 1.2);
  else
    spec.masterFacets = f.masterFacet;
  return spec;
}

std::unique_ptr<ContactInterfaceBase> interfaceOf(int nodes, bool rigidMaster) {
  const QuadraticFaces f = facesOf(nodes, rigidMaster, 0.0);
  return makeMortarInterface(specOf(f), std::vector<char>(f.slaveCount(), 1));
}

// Every node moved a little (curved facets, the master's edges inside the slave's), 0.02 into the deformable
// master (the rigid plate sits at z = −0.03, its body above: 0.017 to 0.043 into it).
std::vector<double> unevenFaces(int nodes, bool rigidMaster) {
  std::vector<double> x = facesOf(nodes, rigidMaster, 0.02).x;
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += 0.013 * std::sin(1.7 * double(i) + 0.4);
  return x;
}
// The uneven faces with the slave slid by `slide` along (1, 0.6) (a little more for higher nodes) and the
// master by −0.2 slide along x.
std::vector<double> slid(int nodes, bool rigidMaster, double slide) {
  const QuadraticFaces f = facesOf(nodes, rigidMaster, 0.0);
  std::vector<double> x = unevenFaces(nodes, rigidMaster);
  for (int node = 0; node < static_cast<int>(x.size() / 3); ++node) {
    const bool slave = node < f.slaveCount();
    x[3 * node] += slave ? slide * (1.0 + 0.05 * node) : -0.2 * slide;
    if (slave) x[3 * node + 1] += 0.6 * slide;
  }
  return x;
}

// The interface committed at the uneven faces at λ = 0.3: where every trial of a central difference starts.
std::unique_ptr<ContactInterfaceBase> committedInterface(int nodes, bool rigid) {
  auto interface = interfaceOf(nodes, rigid);
  testing::assemble<3>(*interface, unevenFaces(nodes, rigid), 0.3);
  return interface;
}

void expectFrictionalTangentIsTheCentralDifference(int nodes, bool rigid, double slide, ContactStatus expected) {
  SCOPED_TRACE(std::to_string(nodes) + "-node faces, " + (rigid ? "rigid" : "deformable") + " master, slide " +
               std::to_string(slide));
  const auto x = slid(nodes, rigid, slide);
  const double lambda = 0.3 + 0.5 * slide;
  const auto committed = committedInterface(nodes, rigid);
  const testing::Assembled a = testing::assemble<3>(*committed->clone(), x, lambda);
  const int slaves = facesOf(nodes, rigid, 0.0).slaveCount();
  for (const auto& s : a.states) EXPECT_EQ(s.status, expected);
  double frictionScale = 0;
  for (int node = 0; node < slaves; ++node)
    frictionScale = std::max({frictionScale, std::abs(a.residual[3 * node]), std::abs(a.residual[3 * node + 1])});
  EXPECT_GT(frictionScale, 1e-3) << "a tangential force";
  // Columns of a slave corner, the next slave node (Tri6: a mid-edge node; Quad8, Quad9: a corner), the last
  // (a mid-edge node; a Quad9's centre), and on a deformable master a corner and a mid-edge node of it.
  std::vector<int> columns = {0, 1, slaves - 1};
  if (!rigid) columns.insert(columns.end(), {slaves, slaves + 4});
  double scale = 0;
  const double error = testing::tangentColumnsCentralDifferenceError(
      a.tangent, x, [&](const std::vector<double>& y) { return testing::trialResidual<3>(*committed, y, lambda); },
      testing::nodeColumns<3>(columns), &scale);
  EXPECT_GT(scale, 10.0);
  EXPECT_LT(error, 1e-6 * scale);
  if (!rigid) return;
  double dScale = 0;
  const double dError = testing::loadDerivativeCentralDifferenceError(
      a.dLambda, lambda, [&](double mu) { return testing::trialResidual<3>(*committed, x, mu); }, &dScale);
  EXPECT_GT(dScale, 0.1);
  EXPECT_LT(dError, 1e-6 * dScale);
}

TEST(MortarInterfaceQuadraticFriction, TangentInStickIsTheCentralDifferenceOfTheResidual) {
  for (int nodes : {6, 8, 9})
    for (bool rigid : {false, true}) expectFrictionalTangentIsTheCentralDifference(nodes, rigid, 1e-4, ContactStatus::Stick);
}

TEST(MortarInterfaceQuadraticFriction, TangentInSlipIsTheCentralDifferenceOfTheResidual) {
  for (int nodes : {6, 8, 9})
    for (bool rigid : {false, true}) expectFrictionalTangentIsTheCentralDifference(nodes, rigid, 0.05, ContactStatus::Slip);
}

// The flat faces pressed by d into the fixed deformable master and slid by u along (cos θ, sin θ): the
// patch's tangential force against the motion, ε_T u A in stick, μ ε_N d A in slip (A = 1), every node
// stuck or slipping as Contact Beta counts them. The stick slide is 2e-4, not smaller: on the Quad9 pair the
// slave's centre node (where its four quarters meet) then lies u (cos θ, sin θ) from the master's, and the
// clip of a slave quarter against the diagonally opposite master quarter is a rectangle of u² cos θ sin θ;
// below kMortarSnap (1e-9) of the quarter's area the kernel drops it (MortarQuadraticFacetPair.cpp,
// addPiecePair), which at u = 2e-5 (area 7.5e-10 of the quarter) took 3.7e-10 off the normal force and
// 6.8e-7 off the stick force (the dropped corner's derivative, of order u, not u²).
void expectPatchForces(int nodes, double u, ContactStatus expected) {
  SCOPED_TRACE(std::to_string(nodes) + "-node faces, slide " + std::to_string(u));
  const double d = 1e-3, theta = 0.6;
  auto interface = interfaceOf(nodes, false);
  const QuadraticFaces f = facesOf(nodes, false, d);
  testing::assemble<3>(*interface, f.x, 0.0);
  auto x = f.x;
  for (int node = 0; node < f.slaveCount(); ++node) {
    x[3 * node] += u * std::cos(theta);
    x[3 * node + 1] += u * std::sin(theta);
  }
  const testing::Assembled a = testing::assemble<3>(*interface, x, 0.0);
  for (const auto& s : a.states) EXPECT_EQ(s.status, expected);
  EXPECT_EQ(a.counts.active, f.slaveCount());
  EXPECT_EQ(a.counts.stick, expected == ContactStatus::Stick ? f.slaveCount() : 0);
  EXPECT_EQ(a.counts.slip, expected == ContactStatus::Slip ? f.slaveCount() : 0);
  const auto& force = interface->committedSlaveForce();
  const double normal = kPenalty * d;
  const double tangential = expected == ContactStatus::Stick ? kPenalty * u : kFriction * normal;
  EXPECT_NEAR(force[2], -normal, 1e-12 * normal);
  EXPECT_NEAR(force[0], -tangential * std::cos(theta), 1e-12 * normal);
  EXPECT_NEAR(force[1], -tangential * std::sin(theta), 1e-12 * normal);
}

TEST(MortarInterfaceQuadraticFriction, AStuckPatchCarriesTheStickSpringsForceAndASlidingOneCoulombs) {
  for (int nodes : {6, 8, 9}) {
    expectPatchForces(nodes, 2e-4, ContactStatus::Stick);
    expectPatchForces(nodes, 0.05, ContactStatus::Slip);
  }
}

}  // namespace
}  // namespace contessa::contact
