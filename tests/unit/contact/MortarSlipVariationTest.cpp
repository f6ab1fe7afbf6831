// The mortar virtual slips δũ_a (MortarSlipVariation.hpp, theory-contact.md §13, eq. M11″): what the nodal
// tangential tractions work on in the frictional residual. Checked on the 2D segment pair, the 3D Tri3/Quad4
// facet pair and the quadratic (Tri6, Quad8, Quad9) pairs, each cut by the clip:
// - B_a is the derivative of the weighted slip increment Δũ_a with respect to the current positions at a
//   frozen segmentation, i.e. minus its derivative with respect to the committed positions (Δũ_a is linear
//   in them): central differences in the committed positions, to round-off;
// - Δũ_a = B_a · (x − x_n) (the identity the residual's choice rests on);
// - ∂B_a/∂x against central differences of B_a (1e-7 relative), and the full gradient of Δũ_a, which the
//   kernels also give (and the return mapping uses), equals B_a + (∂B_a/∂x)ᵀ (x − x_n);
// - a rigid master's derivatives along its motion are the free master's contracted with the motion;
// - a slave facet half under a master's free edge, slid by s: B_a applied to a uniform tangential virtual
//   displacement is the node's mortar area exactly (so a uniform traction gives μ F_N), while the slip
//   increment's gradient adds s times the edge integral of N_a, the term that lowered the friction force
//   of the Coulomb block sliding past the base's edge (verification-contact §9.4).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

#include "contact/MortarFacetPair.hpp"
#include "contact/MortarQuadraticFacetPair.hpp"
#include "contact/MortarSegment.hpp"
#include "MortarQuadraticTestTools.hpp"

namespace contessa::contact {
namespace {

/// A kernel under test: coordinates and committed positions → slip values per entry (slot a, component c:
/// a · rows + c), and the derivatives' virtual slips, their gradients and the slip gradients.
struct SlipKernel {
  int coordinates = 0;  ///< C
  int committed = 0;    ///< how many leading coordinates have committed positions
  int entries = 0;      ///< slots × rows
  std::function<std::vector<double>(const std::vector<double>& x, const std::vector<double>& then)> slips;
  struct Derivatives {
    std::vector<std::vector<double>> variation, variationGradient, slipGradient;
  };
  std::function<Derivatives(const std::vector<double>& x, const std::vector<double>& then)> derivatives;
};

double largest(const std::vector<double>& v) {
  double m = 0.0;
  for (double e : v) m = std::max(m, std::abs(e));
  return m;
}

// differenced: the coordinates j whose column of ∂B/∂x is checked against central differences of B (each a
// pair of derivative evaluations); empty: every coordinate.
void expectVirtualSlipsAreExact(const SlipKernel& k, const std::vector<double>& x, const std::vector<double>& then,
                                const std::vector<int>& usedEntries, std::vector<int> differenced = {}) {
  const int C = k.coordinates;
  const SlipKernel::Derivatives d = k.derivatives(x, then);
  ASSERT_EQ(static_cast<int>(d.variation.size()), k.entries);
  const std::vector<double> slip = k.slips(x, then);
  const double h = 1e-6;
  // ∂Δũ/∂x_n by central differences (exact up to round-off: Δũ is linear in x_n).
  std::vector<std::vector<double>> committedDerivative(C, std::vector<double>(k.entries, 0.0));
  for (int i = 0; i < k.committed; ++i) {
    auto plus = then, minus = then;
    plus[i] += h;
    minus[i] -= h;
    const std::vector<double> sp = k.slips(x, plus), sm = k.slips(x, minus);
    for (int e = 0; e < k.entries; ++e) committedDerivative[i][e] = (sp[e] - sm[e]) / (2 * h);
  }
  if (differenced.empty())
    for (int j = 0; j < C; ++j) differenced.push_back(j);
  std::vector<SlipKernel::Derivatives> dp(C), dm(C);
  for (int j : differenced) {
    auto plus = x, minus = x;
    plus[j] += h;
    minus[j] -= h;
    dp[j] = k.derivatives(plus, then);
    dm[j] = k.derivatives(minus, then);
  }
  for (int e : usedEntries) {
    const std::vector<double>& b = d.variation[e];
    const std::vector<double>& db = d.variationGradient[e];
    const double scale = largest(b), gradientScale = largest(db), slipScale = largest(d.slipGradient[e]);
    EXPECT_GT(scale, 1e-6) << "entry " << e;
    EXPECT_GT(gradientScale, 1e-8) << "entry " << e;
    double identity = 0.0;
    for (int i = 0; i < C; ++i) {
      const double moved = i < k.committed ? x[i] - then[i] : 0.0;
      identity += b[i] * moved;
      if (i < k.committed)
        EXPECT_NEAR(b[i], -committedDerivative[i][e], 1e-9 * scale) << "entry " << e << ", coordinate " << i;
      else
        EXPECT_EQ(b[i], 0.0) << "a coordinate that is no position (a 2D neighbour node): no virtual slip";
    }
    EXPECT_NEAR(slip[e], identity, 1e-13 * std::max(1.0, std::abs(slip[e]))) << "Δũ = B · (x − x_n), entry " << e;
    double gradientError = 0.0, fullError = 0.0;
    for (int j : differenced)
      for (int i = 0; i < C; ++i) {
        const double fd = (dp[j].variation[e][i] - dm[j].variation[e][i]) / (2 * h);
        gradientError = std::max(gradientError, std::abs(fd - db[i * C + j]));
      }
    for (int j = 0; j < C; ++j) {
      double full = b[j];
      for (int i = 0; i < C; ++i) full += db[i * C + j] * (i < k.committed ? x[i] - then[i] : 0.0);
      fullError = std::max(fullError, std::abs(full - d.slipGradient[e][j]));
    }
    EXPECT_LT(gradientError, 1e-7 * gradientScale) << "entry " << e;
    EXPECT_LT(fullError, 1e-12 * std::max(slipScale, scale)) << "∇Δũ = B + (∂B/∂x)ᵀ (x − x_n), entry " << e;
  }
}

// ---- 3D Tri3/Quad4 pairs -------------------------------------------------------------------------------

constexpr int kM = kMortarFacetPairCoordinates;
FacetPairCoordinates<double> unevenPair() {  // MortarFriction3DTest's: warped, tilted, cut by the clip
  return {0.02, -0.01, 0.01, 1.05, 0.03, -0.02, 0.97, 1.04, 0.015, -0.03, 0.98, 0.0,
          0.31, -0.22, -0.006, 0.28, 1.52, -0.013, 1.71, 1.47, -0.008, 1.69, -0.18, -0.011};
}
std::vector<double> committedNear(const std::vector<double>& x, int count) {
  std::vector<double> then(x.size(), 0.0);
  for (int i = 0; i < count; ++i) then[i] = x[i] - 0.02 * std::cos(0.9 * i + 0.3) - (i % 3 == 0 ? 0.015 : 0.0);
  return then;
}
template <std::size_t N>
std::array<double, N> arrayOf(const std::vector<double>& v) {
  std::array<double, N> a{};
  std::copy(v.begin(), v.begin() + N, a.begin());
  return a;
}
template <class Derivatives>
SlipKernel::Derivatives derivativesOf(const Derivatives& g) {
  SlipKernel::Derivatives d;
  for (std::size_t e = 0; e < g.slipVariation.size(); ++e) {
    d.variation.emplace_back(g.slipVariation[e].begin(), g.slipVariation[e].end());
    d.variationGradient.emplace_back(g.slipVariationGradient[e].begin(), g.slipVariationGradient[e].end());
  }
  return d;
}

SlipKernel linearKernel(const MortarFacetPairShape& shape, double referenceArea, const double* motion = nullptr) {
  SlipKernel k;
  k.coordinates = kM;
  k.committed = kM;
  k.entries = 3 * kMortarFacetNodes;
  k.slips = [=](const std::vector<double>& x, const std::vector<double>& then) {
    const FacetPairCommitted t = arrayOf<kM>(then);
    const auto g = facetPairGaps(arrayOf<kM>(x), referenceArea, shape, &t);
    std::vector<double> out;
    for (int a = 0; a < kMortarFacetNodes; ++a)
      for (int c = 0; c < 3; ++c) out.push_back(g.weightedSlip[a][c]);
    return out;
  };
  k.derivatives = [=](const std::vector<double>& x, const std::vector<double>& then) {
    const FacetPairCommitted t = arrayOf<kM>(then);
    const MortarFacetPairDerivatives g = facetPairDerivatives(arrayOf<kM>(x), referenceArea, shape, motion, &t);
    SlipKernel::Derivatives d = derivativesOf(g);
    for (const auto& s : g.slipGradient) d.slipGradient.emplace_back(s.begin(), s.end());
    return d;
  };
  return k;
}

std::vector<double> unusedZeroed(FacetPairCoordinates<double> x, const MortarFacetPairShape& shape) {
  if (shape.slaveNodes == 3) std::fill(&x[9], &x[12], 0.0);
  if (shape.masterNodes == 3) std::fill(&x[21], &x[24], 0.0);
  return {x.begin(), x.end()};
}

void expectLinearPair(const MortarFacetPairShape& shape, double referenceArea) {
  const std::vector<double> x = unusedZeroed(unevenPair(), shape);
  std::vector<double> then = committedNear(x, kM);
  if (shape.slaveNodes == 3) std::fill(&then[9], &then[12], 0.0);
  if (shape.masterNodes == 3) std::fill(&then[21], &then[24], 0.0);
  std::vector<int> entries;
  for (int e = 0; e < 3 * shape.slaveNodes; ++e) entries.push_back(e);
  expectVirtualSlipsAreExact(linearKernel(shape, referenceArea), x, then, entries);
}

TEST(MortarSlipVariation, FacetPairVirtualSlipsAreExact) {
  expectLinearPair({4, 4}, 1.1);
  expectLinearPair({3, 4}, 0.55);
  expectLinearPair({4, 3}, 1.0);
  expectLinearPair({3, 3}, 0.55);
}

TEST(MortarSlipVariation, ARigidMastersVirtualSlipsAreTheFreeMastersAlongItsMotion) {
  const std::vector<double> x = unusedZeroed(unevenPair(), {4, 4});
  const FacetPairCommitted then = arrayOf<kM>(committedNear(x, kM));
  const double motion[12] = {0.3, -0.2, 0.1, 0.3, -0.2, 0.1, 0.3, -0.2, 0.1, 0.3, -0.2, 0.1};
  const auto free = facetPairDerivatives(arrayOf<kM>(x), 1.1, {4, 4}, nullptr, &then);
  const auto rigid = facetPairDerivatives(arrayOf<kM>(x), 1.1, {4, 4}, motion, &then);
  for (std::size_t e = 0; e < free.slipVariation.size(); ++e) {
    const double scale = largest({free.slipVariationGradient[e].begin(), free.slipVariationGradient[e].end()});
    double along = 0.0;
    for (int i = 12; i < kM; ++i) along += free.slipVariation[e][i] * motion[i - 12];
    EXPECT_NEAR(rigid.slipVariation[e][12], along, 1e-14);
    for (int i = 0; i < 12; ++i) {
      EXPECT_NEAR(rigid.slipVariation[e][i], free.slipVariation[e][i], 1e-14);
      double column = 0.0;
      for (int j = 12; j < kM; ++j) column += free.slipVariationGradient[e][i * kM + j] * motion[j - 12];
      EXPECT_NEAR(rigid.slipVariationGradient[e][i * kM + 12], column, 1e-13 * scale);
      for (int j = 0; j < 12; ++j)
        EXPECT_NEAR(rigid.slipVariationGradient[e][i * kM + j], free.slipVariationGradient[e][i * kM + j], 1e-13 * scale);
    }
  }
}

TEST(MortarSlipVariation, AFacetSlidingPastAMastersEdgeGetsTheMortarAreaNotTheOverlapsChange) {
  // The unit square slave (normal +z) half under a master whose free edge is the line x = 0.5, slid by
  // s = 0.05 along x since the last commit. A uniform virtual displacement δ along x: B_a · δ is N_a's
  // integral over the overlap, the mortar area (∫ over x ∈ [0.5, 1] of the bilinear N_a: 1/16 at the
  // nodes x = 0, 3/16 at x = 1); the slip increment's gradient adds s ∫_edge N_a dl = 0.05 · 1/4 (the
  // overlap grows by δ along the edge, where N_a integrates to 1/4), a force per node of order the
  // increment's slip.
  const double s = 0.05;
  const std::vector<double> x = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, -0.2, 0, 0.5, 1.2, 0, 2, 1.2, 0, 2, -0.2, 0};
  std::vector<double> then = x;
  for (int a = 0; a < 4; ++a) then[3 * a] -= s;
  const FacetPairCommitted t = arrayOf<kM>(then);
  const MortarFacetPairDerivatives d = facetPairDerivatives(arrayOf<kM>(x), 1.0, {4, 4}, nullptr, &t);
  ASSERT_TRUE(d.overlaps);
  const double area[4] = {1.0 / 16, 3.0 / 16, 3.0 / 16, 1.0 / 16};
  for (int a = 0; a < 4; ++a) {
    EXPECT_NEAR(d.mortarArea[a], area[a], 1e-14);
    EXPECT_NEAR(d.weightedSlip[a][0], s * area[a], 1e-15);
    double virtualSlip = 0.0, slipGradient = 0.0;
    for (int j = 0; j < 4; ++j) {
      virtualSlip += d.slipVariation[3 * a][3 * j];
      slipGradient += d.slipGradient[3 * a][3 * j];
    }
    EXPECT_NEAR(virtualSlip, d.mortarArea[a], 1e-14) << "node " << a;
    EXPECT_NEAR(slipGradient - d.mortarArea[a], s * 0.25, 1e-12) << "node " << a;
  }
}

// ---- 2D segment pair -------------------------------------------------------------------------------------

TEST(MortarSlipVariation, SegmentPairVirtualSlipsAreExact) {
  // MortarTest's tilted pair with neighbours, clipped at a slave end and a master end.
  const std::vector<double> x = {1.1, 0.05, -0.02, -0.07, 0.35, -0.03, 1.6, 0.12, 2.0, 0.3, -1.0, -0.35};
  const std::vector<double> then = {1.05, 0.04, -0.08, -0.075, 0.38, -0.03, 1.63, 0.115, 0, 0, 0, 0};
  const MortarSlaveNeighbours neighbours{{1, 1}};
  SlipKernel k;
  k.coordinates = kMortarPairCoordinates;
  k.committed = 8;
  k.entries = 2;
  k.slips = [=](const std::vector<double>& y, const std::vector<double>& n) {
    const SegmentPairCommitted c = arrayOf<8>(n);
    const auto g = segmentPairGaps(arrayOf<kMortarPairCoordinates>(y), 1.2, neighbours, &c);
    return std::vector<double>{g.weightedSlip[0], g.weightedSlip[1]};
  };
  k.derivatives = [=](const std::vector<double>& y, const std::vector<double>& n) {
    const SegmentPairCommitted c = arrayOf<8>(n);
    const MortarPairDerivatives g = segmentPairDerivatives(arrayOf<kMortarPairCoordinates>(y), 1.2, neighbours, &c);
    SlipKernel::Derivatives d = derivativesOf(g);
    for (const auto& s : g.slipGradient) d.slipGradient.emplace_back(s.begin(), s.end());
    return d;
  };
  expectVirtualSlipsAreExact(k, x, then, {0, 1});
}

// ---- quadratic pairs ---------------------------------------------------------------------------------------

using testing::Face;
using testing::faceNodes;
using testing::mid;
using testing::Point;
using testing::reversed;
Face quadraticFace(int nodes, const Point& a, const Point& b, const Point& c, const Point& d) {
  if (nodes == 6) return {a, b, d, mid(a, b), mid(b, d), mid(d, a)};
  Face f = {a, b, c, d, mid(a, b), mid(b, c), mid(c, d), mid(d, a)};
  if (nodes == 9) f.push_back(mid(mid(a, c), mid(b, d)));
  return f;
}

template <int Slots>
void expectQuadraticPair(int slaveNodes, int masterNodes) {
  constexpr int C = 6 * Slots;
  const Point a{0.0, 0.0, 0.0}, b{1.2, 0.1, 0.0}, c{1.4, 1.0, 0.0}, d{0.2, 0.9, 0.0};
  const Face reference = quadraticFace(slaveNodes, a, b, c, d);
  Face slave = reference;
  for (int n = 0; n < slaveNodes; ++n) slave[n][2] += 0.02 * std::sin(2.0 * n + 1.0), slave[n][0] += 0.01 * std::cos(3.0 * n);
  const Point ma{0.41, -0.22, -0.006}, mb{1.72, 0.18, -0.013}, mc{1.5, 1.3, -0.01}, md{0.3, 1.17, -0.008};
  Face master = reversed(masterNodes == 4 ? Face{ma, mb, mc, md} : quadraticFace(masterNodes, ma, mb, mc, md));
  if (masterNodes > 4) master[4][2] += 0.015;
  MortarFacetPairShape shape{slaveNodes, masterNodes, {}};
  shape.slavePieceAreas = mortarFacetPieceMeasures(faceNodes(reference), slaveNodes);
  std::vector<double> x(C, 0.0);
  for (int n = 0; n < slaveNodes; ++n)
    for (int k = 0; k < 3; ++k) x[3 * n + k] = slave[n][k];
  for (int n = 0; n < masterNodes; ++n)
    for (int k = 0; k < 3; ++k) x[3 * (Slots + n) + k] = master[n][k];
  std::vector<double> then = committedNear(x, C);
  for (int i = 0; i < C; ++i) {
    const int node = i / 3;
    if (node < Slots ? node >= slaveNodes : node - Slots >= masterNodes) then[i] = 0.0;
  }
  SlipKernel k;
  k.coordinates = C;
  k.committed = C;
  k.entries = 3 * Slots;
  k.slips = [=](const std::vector<double>& y, const std::vector<double>& n) {
    const QuadraticFacetPairCommitted<Slots> t = arrayOf<C>(n);
    const auto g = facetPairGaps(arrayOf<C>(y), 0.6, shape, &t);
    std::vector<double> out;
    for (int s = 0; s < Slots; ++s)
      for (int e = 0; e < 3; ++e) out.push_back(g.weightedSlip[s][e]);
    return out;
  };
  k.derivatives = [=](const std::vector<double>& y, const std::vector<double>& n) {
    const QuadraticFacetPairCommitted<Slots> t = arrayOf<C>(n);
    const auto g = facetPairDerivatives(arrayOf<C>(y), 0.6, shape, nullptr, &t);
    SlipKernel::Derivatives dd = derivativesOf(g);
    for (const auto& s : g.slipGradient) dd.slipGradient.emplace_back(s.begin(), s.end());
    return dd;
  };
  // The mid-edge and centre nodes' entries (a Tri6 corner's weight is its flat pieces' hat: all slots used).
  std::vector<int> entries;
  for (int e = 0; e < 3 * slaveNodes; ++e) entries.push_back(e);
  // ∂B/∂x's columns against central differences: the three of the first slave and the first master corner,
  // and one component drawn (seeded) for every other node: each a pair of evaluations that differentiate the
  // pair twice, every column 276 of them over the three pairs (57 s of the suite).
  std::mt19937 draw(20261128u + static_cast<unsigned>(slaveNodes * 10 + masterNodes));
  std::vector<int> differenced = {0, 1, 2, 3 * Slots, 3 * Slots + 1, 3 * Slots + 2};
  for (int node = 0; node < 2 * Slots; ++node)
    if (node != 0 && node != Slots) differenced.push_back(3 * node + static_cast<int>(draw() % 3));
  expectVirtualSlipsAreExact(k, x, then, entries, differenced);
}

TEST(MortarSlipVariation, QuadraticPairVirtualSlipsAreExact) {
  expectQuadraticPair<6>(6, 6);
  expectQuadraticPair<8>(8, 4);
  expectQuadraticPair<9>(9, 9);
}

}  // namespace
}  // namespace contessa::contact
