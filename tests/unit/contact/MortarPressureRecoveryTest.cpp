// The nodal pressures a mortar interface reports, eq. (M6′) (contact/MortarPressureRecovery.hpp): the
// traction field Σ Φ_k p_k averaged over each node's support with the slave surface's mass matrix. Checked:
// a uniform pressure is kept to round-off on every face type (the patch tests' output unchanged); the
// force Σ A_a p̄_a equals Σ A_k p_k (the interface's force) for any p; on a uniform line the edge mode
// p_k = (√3 − 2)^k that the weighted gaps' pressures carry near a contact edge is annihilated at every
// interior node, and a linear field is kept; the weights of one square are its mass matrix' rows.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "contact/MortarPressureRecovery.hpp"

namespace contessa::contact {
namespace {

/// A slave surface of `nodes` nodes (0 … nodes − 1), `perFacet` nodes per facet and the facets' measures.
ContactInterfaceSpec surface(int dimension, int nodes, int perFacet, std::vector<GlobalIndex> facets,
                             std::vector<double> measures) {
  ContactInterfaceSpec spec;
  spec.name = "test";
  spec.dimension = dimension;
  spec.mortar = true;
  for (int k = 0; k < nodes; ++k) spec.slaveNodes.push_back(k);
  spec.slaveFacetNodes = perFacet;
  spec.slaveFacets = std::move(facets);
  spec.slaveFacetMeasures = std::move(measures);
  return spec;
}

/// A 2D line of segments of the given lengths.
ContactInterfaceSpec line(const std::vector<double>& lengths) {
  std::vector<GlobalIndex> facets;
  for (std::size_t s = 0; s < lengths.size(); ++s) facets.insert(facets.end(), {GlobalIndex(s), GlobalIndex(s + 1)});
  return surface(2, static_cast<int>(lengths.size()) + 1, 2, facets, lengths);
}

/// ∫ Φ_a dA per node: the rows of the mass matrix summed, from the weights and the supports' measures
/// (each test passes its own tributary measures).
double force(const std::vector<double>& area, const std::vector<double>& p) {
  double f = 0;
  for (std::size_t a = 0; a < p.size(); ++a) f += area[a] * p[a];
  return f;
}

void expectUniformKept(const ContactInterfaceSpec& spec) {
  const std::vector<double> p(spec.slaveNodes.size(), 1.7);
  for (double v : mortarPressureRecovery(spec).apply(p)) EXPECT_NEAR(v, 1.7, 1e-15);
}

TEST(MortarPressureRecovery, KeepsAUniformPressureOnEveryFaceType) {
  expectUniformKept(line({0.3, 0.5, 0.2, 0.9}));
  // Two 3-node segments (ends 0–1 and 1–2, mid-edge nodes 3 and 4): each side's two chords' lengths.
  expectUniformKept(surface(2, 5, 3, {0, 1, 3, 1, 2, 4}, {0.2, 0.3, 0.5, 0.4}));
  // Two triangles of the unit square; a parallelogram Quad4; a flat Tri6 (its four pieces' areas); a
  // flat Quad8 (four corner triangles and the mid-edge square, J = A/4 on [−1, 1]²); a flat Quad9 (four
  // quarters, J = 1/4 each on a 2 × 2 square) with a graded Jacobian on one quarter.
  expectUniformKept(surface(3, 4, 3, {0, 1, 2, 0, 2, 3}, {0.5, 0.5}));
  expectUniformKept(surface(3, 6, 4, {0, 1, 4, 3, 1, 2, 5, 4}, {1.0, 2.0}));
  expectUniformKept(surface(3, 6, 6, {0, 1, 2, 3, 4, 5}, {0.125, 0.125, 0.125, 0.125}));
  expectUniformKept(surface(3, 8, 8, {0, 1, 2, 3, 4, 5, 6, 7}, {0.5, 0.5, 0.5, 0.5, 0.5, 0.0, 0.0}));
  expectUniformKept(surface(3, 9, 9, {0, 1, 2, 3, 4, 5, 6, 7, 8},
                            {0.25, 0, 0, 0.25, 0.05, 0, 0.25, 0, -0.03, 0.25, 0, 0}));
}

TEST(MortarPressureRecovery, TheForceIsTheInterfacesForAnyPressure) {
  // Graded segments: A_a = half of each adjacent length (∫ Φ_a).
  const std::vector<double> lengths = {0.3, 0.5, 0.2, 0.9};
  const std::vector<double> area = {0.15, 0.4, 0.35, 0.55, 0.45};
  const std::vector<double> p = {2.0, -1.0, 0.5, 3.0, 0.0};
  EXPECT_NEAR(force(area, mortarPressureRecovery(line(lengths)).apply(p)), force(area, p), 1e-14);
  // A flat Tri6 of area 1/2: corners A/12 (one piece), mid-edge nodes A/4 (three pieces), A_piece = 1/8.
  const double corner = 0.125 / 3, mid = 0.125;
  const std::vector<double> tri6Area = {corner, corner, corner, mid, mid, mid};
  const std::vector<double> q = {1.0, 0.0, 2.0, -0.5, 4.0, 1.5};
  const auto tri6 = surface(3, 6, 6, {0, 1, 2, 3, 4, 5}, {0.125, 0.125, 0.125, 0.125});
  EXPECT_NEAR(force(tri6Area, mortarPressureRecovery(tri6).apply(q)), force(tri6Area, q), 1e-14);
  // A 3-node segment (ends 0, 1; mid-edge node 2) of chords 0.2 (0–2) and 0.6 (2–1): A = (0.1, 0.3, 0.4).
  const std::vector<double> line3Area = {0.1, 0.3, 0.4};
  const std::vector<double> s = {1.0, -2.0, 3.0};
  const auto line3 = surface(2, 3, 3, {0, 1, 2}, {0.2, 0.6});
  const auto recovered = mortarPressureRecovery(line3).apply(s);
  EXPECT_NEAR(force(line3Area, recovered), force(line3Area, s), 1e-14);
  // The end node 0 sees only the first chord: (2 p_0 + p_2) / 3.
  EXPECT_NEAR(recovered[0], (2.0 * 1.0 + 3.0) / 3.0, 1e-15);
}

TEST(MortarPressureRecovery, AnnihilatesTheEdgeModeAndKeepsALinearFieldOnAUniformLine) {
  const int segments = 12;
  const double h = 0.25;
  const auto recovery = mortarPressureRecovery(line(std::vector<double>(segments, h)));
  // M p = 0 at every interior node for p_k = r^k, r = √3 − 2 (1 + 4r + r² = 0): the mode that rings
  // inwards from a contact edge carries no force, and the reported value drops it.
  const double r = std::sqrt(3.0) - 2.0;
  std::vector<double> mode(segments + 1), linear(segments + 1);
  for (int k = 0; k <= segments; ++k) {
    mode[k] = std::pow(r, k);
    linear[k] = 2.0 + 0.7 * k * h;
  }
  const auto m = recovery.apply(mode), l = recovery.apply(linear);
  for (int k = 1; k < segments; ++k) {
    EXPECT_NEAR(m[k], 0.0, 1e-15) << "node " << k;
    EXPECT_NEAR(l[k], linear[k], 1e-14) << "node " << k;
  }
  // At the ends the support is one segment: (2 p_0 + p_1)/3.
  EXPECT_NEAR(m[0], (2.0 + r) / 3.0, 1e-15);
}

TEST(MortarPressureRecovery, OneSquaresWeightsAreItsMassMatrixRows) {
  // ∫ Φ_a Φ_b over a parallelogram: A/36 (4, 2, 1, 2) for a corner's row, normalised by A/4.
  const auto recovery = mortarPressureRecovery(surface(3, 4, 4, {0, 1, 2, 3}, {1.0}));
  const double expected[4] = {4.0 / 9, 2.0 / 9, 1.0 / 9, 2.0 / 9};
  for (int a = 0; a < 4; ++a) {
    ASSERT_EQ(recovery.rowStart[a + 1] - recovery.rowStart[a], 4u);
    for (std::size_t i = recovery.rowStart[a]; i < recovery.rowStart[a + 1]; ++i) {
      const int b = static_cast<int>(recovery.column[i]);
      EXPECT_NEAR(recovery.weight[i], expected[(b - a + 4) % 4], 1e-15) << a << ", " << b;
    }
  }
}

}  // namespace
}  // namespace contessa::contact
