// Coulomb friction in the blend of the two facets at a valley edge (contact/ValleyBlend.hpp, ValleyFriction;
// docs/theory-contact.md §6.5; issue 22, point 3). Checked: the tangent against central differences of the
// residual over the union of both facets' nodes, in stick and in slip, with a pressure-tied ε_T (slip
// tolerance) and at a first touch (closure fraction τ(g)), at w near 0, at 0.5 and near 1, in 2D (a vertex)
// and 3D (an edge of warped faces); at the band's edge the blend is the single facet's frictional element,
// history included; a node pressed straight into the valley does not slip (each facet's projection does);
// the forces do not depend on which facet's chart holds the history (transferred by HistoryTransfer, as
// when the selection changes); in slip the traction is on the Coulomb cone in the chart's metric.
#include "contact/HistoryTransfer.hpp"
#include "contact/ValleyBlend.hpp"
#include "ValleyBlendTestTools.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace cc = contessa::contact;
using namespace contessa::contact::testing;

namespace {

constexpr double kPenalty = 1e3;    // ε_N
constexpr double kTangential = 1e3;  // ε_T
constexpr double kMu = 0.3;
constexpr double kSlaveSize = 5.0;  // L_k: the band is b = 1e-2 L_k = 0.05

/// The frictional state a slave node comes from: its committed history stored on facet `stored` (the other
/// facet's is re-expressed from it, as ContactInterface does), or a first touch from an approach.
enum class Case { Stick, Slip, SlipTolerance, FirstTouch };

const char* name(Case c) {
  switch (c) {
    case Case::Stick: return "stick";
    case Case::Slip: return "slip";
    case Case::SlipTolerance: return "slip, slip tolerance";
    default: return "first touch";
  }
}

cc::ContactLawParameters lawOf(Case c) {
  cc::ContactLawParameters law{kPenalty, kTangential, kMu, 0.0};
  if (c == Case::SlipTolerance) law = {kPenalty, 0.0, kMu, 2e-5};  // ε_T = μ|t_N|/(s L_k)
  return law;
}

/// The law and the node's committed state in the chart of the edge's facet a (ValleyFriction).
template <class Facet>
struct Setup {
  static constexpr int M = Facet::kSurfaceDim;
  cc::ContactLawParameters law;
  cc::ContactHistory<M> committed{};
  cc::CommittedApproach<M> approach{};
};

/// The committed history of the node on facet a of `e`, against which it sticks or slips now: ξ_n a little
/// (stick) or far (slip) behind the node's current chart point ξ̃, t_T,n small. A first touch has no
/// committed contact and an approach from a gap of 1e-3 (τ ≈ 0.25), 5e-4 behind in ξ: it sticks.
template <class Facet>
Setup<Facet> setup(Case c, const typename Facet::Point& slave, const Facets<Facet>& facets, const cc::ValleyEdge& e) {
  constexpr int M = Facet::kSurfaceDim;
  Setup<Facet> s{lawOf(c), {}, {}};
  const auto xi = *cc::valleyChartPoint<Facet>(slave, facets[e.a], facets[e.b], e);
  if (c == Case::FirstTouch) {
    auto xi0 = xi;
    for (int al = 0; al < M; ++al) xi0[al] -= 5e-4 * (1.0 + al);
    s.approach = cc::CommittedApproach<M>::at(1e-3, xi0);
    return s;
  }
  const double behind = c == Case::Stick ? 2e-5 : 1e-2;
  for (int al = 0; al < M; ++al) {
    s.committed.xi[al] = xi[al] - behind * (1.0 + 0.5 * al);
    s.committed.tangentialTraction[al] = 0.02 * (1.0 - 0.4 * al);
  }
  s.committed.segment = facets[e.a].id;
  s.committed.status = c == Case::Stick ? cc::ContactStatus::Stick : cc::ContactStatus::Slip;
  s.committed.accumulatedSlip = 0.1;
  return s;
}

/// The blend on edge e (its facets a, b at positions e.a, e.b of `facets`) with friction.
template <class Facet>
cc::ValleyBlendResult<Facet> blendAt(const Setup<Facet>& s, const typename Facet::Point& slave, const Facets<Facet>& facets,
                                     const cc::ValleyEdge& e) {
  cc::ValleyFriction<Facet> friction;
  friction.law = &s.law;
  friction.committed = s.committed;
  friction.approach = s.approach;
  friction.facetLength = kSlaveSize;
  return cc::evaluateValleyBlend<Facet>(cc::PenaltyNormalLaw(kPenalty), slave, facets[e.a], facets[e.b], e, friction);
}

/// Worst entry-wise relative difference between the tangent and fourth-order central differences of the
/// residual (step h = 1e-5: truncation O(h⁴), round-off O(1e-16/h)); an entry below 1e-6 of the largest is
/// compared against that floor.
template <class Facet>
double tangentError(const Setup<Facet>& s, const typename Facet::Point& slave, const Facets<Facet>& facets,
                    const cc::ValleyEdge& e) {
  const auto r = blendAt(s, slave, facets, e);
  const int n = r.numDofs();
  const double h = 1e-5;
  double worst = 0.0, scale = 0.0;
  for (double v : r.tangent) scale = std::max(scale, std::abs(v));
  for (int d = 0; d < n; ++d) {
    std::array<cc::ValleyBlendResult<Facet>, 4> at;  // at x + 2h, x + h, x − h, x − 2h
    const std::array<double, 4> steps{2.0 * h, h, -h, -2.0 * h};
    for (int j = 0; j < 4; ++j) {
      auto sj = slave;
      auto fj = facets;
      perturb(sj, fj, r, e, d, steps[j]);
      at[j] = blendAt(s, sj, fj, e);
      EXPECT_EQ(at[j].status, r.status);  // no stick/slip switch within ±2h
    }
    for (int i = 0; i < n; ++i) {
      const double fd = (-at[0].residual[i] + 8.0 * at[1].residual[i] - 8.0 * at[2].residual[i] + at[3].residual[i]) / (12.0 * h);
      const double k = r.tangent[static_cast<std::size_t>(i) * n + d];
      const double err = std::abs(fd - k) / std::max(std::abs(k), 1e-6 * scale);
      worst = std::max(worst, err);
    }
  }
  return worst;
}

cc::ContactStatus expected(Case c) {
  return c == Case::Stick || c == Case::FirstTouch ? cc::ContactStatus::Stick : cc::ContactStatus::Slip;
}

/// At w near 0, 0.5 and near 1, in every case: the tangent against central differences, both facets in the
/// expected state.
template <class Facet>
void checkTangents(const Facets<Facet>& v, const std::vector<typename Facet::Point>& slaves, const char* label) {
  for (Case c : {Case::Stick, Case::Slip, Case::SlipTolerance, Case::FirstTouch}) {
    for (const auto& slave : slaves) {
      const std::size_t selected = slave[0] < 0.0 ? 0 : 1;
      const auto e = cc::findValleyEdge<Facet>(slave, selected, v, v, kSlaveSize);
      ASSERT_TRUE(e) << label << " x = " << slave[0];
      const auto s = setup<Facet>(c, slave, v, *e);
      const auto r = blendAt(s, slave, v, *e);
      ASSERT_TRUE(r.isActive() && r.frictional);
      EXPECT_EQ(r.status, expected(c)) << label << " " << name(c) << " x = " << slave[0];
      const double error = tangentError(s, slave, v, *e);
      EXPECT_LT(error, 1e-5) << label << " " << name(c) << " x = " << slave[0];
      std::printf("ValleyBlendFriction %s %s, w = %.3f: tangent vs FD %.1e\n", label, name(c), r.weight, error);
    }
  }
}

}  // namespace

TEST(ValleyBlendFriction, TangentMatchesFiniteDifferences2D) {
  // z ≈ x: w = 0.009 at x = −0.04, 0.5 at 0, 0.991 at 0.04 (b = 0.05).
  checkTangents<cc::Line2Facet>(valley2D(0.02), {{-0.04, -0.003}, {0.0, -0.003}, {0.04, -0.003}}, "2D");
}

TEST(ValleyBlendFriction, TangentMatchesFiniteDifferences3D) {
  checkTangents<cc::Quad4Facet>(valley3D(0.02, 0.05),
                                {{-0.04, 0.4, -0.003}, {0.0, 0.6, -0.003}, {0.04, 0.3, -0.003}}, "3D warped");
}

TEST(ValleyBlendFriction, IsTheFacetsElementAtTheBandsEdge) {
  // z = −b: w = 0, the blend is facet a's frictional element (residual on its dofs, nothing on b's own
  // node) and keeps the same history.
  const auto v = valley2D(0.02);
  const auto e = *cc::findValleyEdge<cc::Line2Facet>({-0.04, -0.003}, 0, v, v, kSlaveSize);
  const cc::Line2Facet::Point edge{-e.band - 2e-3, -0.003};
  for (Case c : {Case::Stick, Case::Slip, Case::FirstTouch}) {
    const auto s = setup<cc::Line2Facet>(c, edge, v, e);
    const auto r = blendAt(s, edge, v, e);
    ASSERT_EQ(r.weight, 0.0);
    const cc::NodeToFacetContact<cc::Line2Facet> element(s.law);
    const auto single = element.evaluate({edge, v[0].x}, 0, s.committed, kSlaveSize, cc::SlipTangent::consistent(),
                                         cc::ContactPoint::projection(), s.approach);
    EXPECT_EQ(single.status, expected(c));
    EXPECT_EQ(r.status, single.status);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(r.residual[i], single.residual[i], 1e-12) << name(c) << " " << i;
    for (int i = 6; i < r.numDofs(); ++i) EXPECT_EQ(r.residual[i], 0.0) << i;
    EXPECT_EQ(r.trial, single.trial) << name(c);
  }
}

TEST(ValleyBlendFriction, PressingIntoTheValleyIsNoSlip) {
  // A node at the valley's bottom pressed straight down: each facet's projection moves away from the edge
  // by |Δg| sin(θ/2) (a slip of 2e-5 per facet here), the chart point ξ̃ not at all: the stick traction
  // stays the committed one.
  const auto v = valley2D(0.02);
  const cc::Line2Facet::Point before{0.0, -0.001}, after{0.0, -0.003};
  const auto e = *cc::findValleyEdge<cc::Line2Facet>(after, 0, v, v, kSlaveSize);
  const cc::Projection<cc::Line2Facet> projection;
  const double facetSlip = projection.project(after, v[0].x).xi[0] - projection.project(before, v[0].x).xi[0];
  EXPECT_GT(std::abs(facetSlip), 1e-5);
  auto s = setup<cc::Line2Facet>(Case::Stick, after, v, e);
  s.committed.xi = *cc::valleyChartPoint<cc::Line2Facet>(before, v[0], v[1], e);
  const auto r = blendAt(s, after, v, e);
  EXPECT_EQ(r.status, cc::ContactStatus::Stick);
  EXPECT_NEAR(r.chartXi[0], s.committed.xi[0], 1e-15);
  EXPECT_NEAR(r.traction[0], s.committed.tangentialTraction[0], 1e-12);
}

TEST(ValleyBlendFriction, DoesNotDependOnWhichFacetIsPrimary) {
  // The edge found from a (the history in a's chart) or from b (the history transferred to b, as the
  // interface re-expresses it when the node's selected facet changes): the same force on every node.
  // Flat faces: there the chart map is the transfer's unfolding (on a warped face the transfer projects the
  // unfolded point, and the two differ by 1e-7 in ξ).
  const auto v = valley3D(0.02, 0.0);
  for (double x : {-0.02, 0.0, 0.03}) {
    const cc::Quad4Facet::Point slave{x, 0.45, -0.003};
    for (Case c : {Case::Stick, Case::Slip}) {
      const auto ea = *cc::findValleyEdge<cc::Quad4Facet>(slave, 0, v, v, kSlaveSize);
      const auto eb = *cc::findValleyEdge<cc::Quad4Facet>(slave, 1, v, v, kSlaveSize);
      const auto fromA = setup<cc::Quad4Facet>(c, slave, v, ea);
      auto fromB = fromA;
      fromB.committed = cc::transferHistory<cc::Quad4Facet>(fromA.committed, v[0], v[1]);
      const auto ra = blendAt(fromA, slave, v, ea), rb = blendAt(fromB, slave, v, eb);
      EXPECT_NEAR(ra.weight, 1.0 - rb.weight, 1e-12);
      EXPECT_EQ(ra.status, expected(c));
      EXPECT_EQ(rb.status, expected(c));
      // Union blocks: (slave, a's nodes, b's own) in ra; (slave, b's nodes, a's own) in rb: compare by node id.
      const auto nodeOf = [&](const cc::ValleyBlendResult<cc::Quad4Facet>& r, const cc::ValleyEdge& e, int block) {
        if (block == 0) return -1;
        const auto [f, i] = r.source[block];
        return v[f == 0 ? e.a : e.b].nodes[i];
      };
      double scale = 0.0;
      for (double value : ra.residual) scale = std::max(scale, std::abs(value));
      for (int ba = 0; ba < ra.numBlocks; ++ba)
        for (int bb = 0; bb < rb.numBlocks; ++bb) {
          if (nodeOf(ra, ea, ba) != nodeOf(rb, eb, bb)) continue;
          for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(ra.residual[3 * ba + k], rb.residual[3 * bb + k], 1e-12 * scale)
                << name(c) << " x = " << x << " node " << nodeOf(ra, ea, ba);
        }
    }
  }
}

TEST(ValleyBlendFriction, SlipIsOnTheCoulombCone) {
  // In slip ‖t_T‖ = √(t_α Ā^αβ t_β) = μ|t_N| (eq. 22b) in the chart's metric, across the band.
  const auto v = valley2D(0.02);
  for (double x : {-0.03, 0.0, 0.02}) {
    const cc::Line2Facet::Point slave{x, -0.003};
    const auto e = *cc::findValleyEdge<cc::Line2Facet>(slave, x < 0 ? 0 : 1, v, v, kSlaveSize);
    const auto r = blendAt(setup<cc::Line2Facet>(Case::Slip, slave, v, e), slave, v, e);
    ASSERT_EQ(r.status, cc::ContactStatus::Slip);
    EXPECT_NEAR(std::abs(r.traction[0]) / std::sqrt(r.chartMetric(0, 0)), kMu * std::abs(r.normalTraction), 1e-12);
  }
}
