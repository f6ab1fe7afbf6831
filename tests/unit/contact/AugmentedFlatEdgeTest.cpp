// The one entry that `contessa --check-jacobian` finds 0.2 off on the 3D frictional patch test
// (tests/regression/augmented/contact_patch_stick_3d.xml, issue 21): row "slave node 11 z", column "master
// node 26 y". Node 11 (x = 1, z = 0.5) sits exactly under the edge that master faces 1 and 3 share (z = 0.5),
// and node 26 is that edge's end on the free boundary x = 1. The faces are coplanar, so the selector takes
// the node to one of them extended (OnFacet, the flat-edge rule of FacetSelectorOptions::flatAngle). Moving
// node 26 in y by the check's step tilts the two faces in z by ±2h/0.5 rad the opposite ways: a ridge on one
// side of the step (the node then touches the edge point, AtEdge, with the bisecting normal), a valley on the
// other (the node stays on a face, which one decided by round-off). Each choice is a smooth branch of the
// residual with its own derivative in this column: the face's normal tilts with node 26 (±2 per unit y per
// unit pressure, of opposite signs on the two faces), the edge point's does not. The central difference
// across the two branches is neither; the check holds the status and the facet, not the contact point, so
// it compares across the kink.
//
// Here, on that geometry (the deck's faces, the node at the deck's penetration, the augmented law's defaults
// with multipliers, sticking): every branch's tangent equals central differences of its own residual at a
// step that stays on it, the branches' entries differ (W_A = −W_B ≠ 0, W_edge = 0), and the selector leaves
// the unperturbed branch on at least one side of a step of the check's size: the tangent is right, the
// check's difference crosses a kink (docs/verification-contact.md §12, "The Jacobian check at a flat edge").
#include "ElementTestTools.hpp"
#include "FlatEdgeFaces.hpp"

#include "contact/FacetSelector.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using flat_edge::Face;
using flat_edge::faceA;
using flat_edge::faceB;
using flat_edge::P3;
// Node 26 is the shared edge's free end (FlatEdgeFaces.hpp).
constexpr int kNode26OnA = flat_edge::kFreeEndOnA, kNode26OnB = flat_edge::kFreeEndOnB;

// Slave node 11 where the check met it: 3.3e-3 of the face short of the free end x = 1, on the shared edge
// z = 0.5, penetrating by 5e-6 mm (y > 0 is inside the upper block).
const P3 kSlave{0.99665, 5e-6, 0.5};

// The deck's law: automatic ε_N = 2e5, μ = 0.3, the default Slip Tolerance 0.005 on L_k = 0.5, the augmented
// Lagrangian with the multipliers of a first update (λ_N = −1 MPa, λ_T = 0.1 MPa along x).
cc::ContactLawParameters deckLaw() {
  cc::ContactLawParameters law{};
  law.normalPenalty = 2e5;
  law.frictionCoefficient = 0.3;
  law.slipTolerance = 0.005;
  law.enforcement = cc::ContactLawParameters::Enforcement::AugmentedLagrangian;
  law.penetrationTolerance = 1e-3;
  law.elasticSlipTolerance = 1e-4;
  law.maxAugmentations = 10;
  return law;
}
constexpr double kFacetLength = 0.5;

// The node's committed state on a face whose η is `eta` at the shared edge: sticking, its stick reference
// 1e-4 of ξ (1.25e-5 mm) behind along x, λ_T = 0.1 MPa × ‖ā_1‖ = 0.025 covariant.
cc::ContactHistory<2> stuckOn(int facet, double eta) {
  auto h = ct::committedHistory<2>(facet, {0.9866 - 1e-4, eta}, {0.025, 0.0});
  h.normalMultiplier = -1.0;
  h.tangentialMultiplier = {0.025, 0.0};
  return h;
}

struct Branch {
  std::string name;
  Face face;
  cc::ContactPoint point;
  int node26;
  double eta;
};

// The branch's tangent against central differences of its own residual (h = 1e-9: the slave's offset from
// the edge and the faces' tilt stay far from changing which branch this is), and its W entry.
double checkBranch(const Branch& b, ct::TangentCheck& check) {
  const cc::NodeToFacetContact<cc::Quad4Facet> element(deckLaw());
  const cc::NodeToFacetGeometry<cc::Quad4Facet> g{kSlave, b.face.x};
  const auto committed = stuckOn(b.face.id, b.eta);
  const auto r = element.evaluate(g, b.face.id, committed, kFacetLength, cc::SlipTangent::consistent(), b.point);
  EXPECT_EQ(r.status, ContactStatus::Stick) << b.name;
  check.expectClose(r.tangent,
                    ct::finiteDifferenceTangent(element, g, b.face.id, committed, 1e-9, kFacetLength, b.point), b.name);
  return r.tangent(2, 3 * (1 + b.node26) + 1);  // row: slave z; column: node 26 y
}

std::string describe(const cc::FacetSelection<cc::Quad4Facet>& s) {
  const char* kinds[] = {"OnFacet", "AtEdge", "AtVertex", "None"};
  return std::string(kinds[static_cast<int>(s.kind)]) + " facet " + std::to_string(s.facet);
}

}  // namespace

TEST(AugmentedFlatEdge, EveryBranchTangentMatchesCentralDifferencesAndTheBranchesDiffer) {
  ct::TangentCheck check{ct::kFdTolerance};
  const double onA = checkBranch({"face A extended", faceA(0), cc::ContactPoint::projection(), kNode26OnA, 1.0}, check);
  const double onB = checkBranch({"face B extended", faceB(0), cc::ContactPoint::projection(), kNode26OnB, -1.0}, check);
  // The edge point on A (its nodes 2 and 3, node 26 to node 21), behind the master surface (side −1: penetrating).
  const double atEdge =
      checkBranch({"edge point of A", faceA(0), cc::ContactPoint::edge(2, 3, -1.0), kNode26OnA, 1.0}, check);
  check.printWorst("the three branches at the flat edge");
  std::printf("[ W        ] slave z / node 26 y per unit area: face A %.4f, face B %.4f, edge point %.2e\n", onA,
              onB, atEdge);
  // A face's normal tilts by 2 per unit y of node 26 (the face is 0.5 long in z), under |t_N| = 2 MPa here:
  // |W| = 4 (measured 3.972; × the node's area 0.125: the check's W = −0.495), opposite on the two faces;
  // the edge point's normal along x^k − x_b does not turn in z (measured 1.2e-3, from the tangential
  // traction's terms: × 0.125, the check's one-sided FD of 3e-4 at increment 1, where the other side of
  // its shortened step fell on face B).
  EXPECT_NEAR(onA, -onB, 1e-6 * std::abs(onA));
  EXPECT_GT(std::abs(onA), 1.0);
  EXPECT_LT(std::abs(atEdge), 1e-3 * std::abs(onA));
}

TEST(AugmentedFlatEdge, TheChecksStepAtNode26LeavesTheBranchOfTheUnperturbedState) {
  // The selector at the unperturbed, coplanar faces and with node 26 moved by ±h, h = 1e-8 mm (the check's
  // step η max(|x_j|, ‖x‖∞, 1) with η = 1e-8): a node held in contact (λ_N = −1, ε_N = 2e5: g_N < 5e-6).
  const cc::FacetSelector<cc::Quad4Facet> selector;
  const double heldGap = 1.0 / 2e5;
  const auto at = [&](double lift) {
    return selector.select(kSlave, std::vector<Face>{faceA(lift), faceB(lift)}, kFacetLength, heldGap);
  };
  const auto base = at(0.0), plus = at(1e-8), minus = at(-1e-8);
  std::printf("[ select   ] node 26 at y = 0: %s; +1e-8: %s; -1e-8: %s\n", describe(base).c_str(),
              describe(plus).c_str(), describe(minus).c_str());
  ASSERT_EQ(base.kind, cc::SelectionKind::OnFacet);  // flat: no edge point (flatAngle)
  const auto same = [&](const cc::FacetSelection<cc::Quad4Facet>& s) { return s.kind == base.kind && s.facet == base.facet; };
  EXPECT_FALSE(same(plus) && same(minus)) << "both sides of the step on the unperturbed branch: no kink crossed";
  // The one on the ridge side touches the edge point: a branch whose W entry is 0 (test above).
  EXPECT_TRUE(plus.kind == cc::SelectionKind::AtEdge || minus.kind == cc::SelectionKind::AtEdge);
}
