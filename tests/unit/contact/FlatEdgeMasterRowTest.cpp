// The entry that `contessa --check-jacobian` found 0.2 off at increment 2 of the 3D stick patch on its
// matching 2 x 2 faces (tests/regression/augmented/contact_patch_stick_3d.xml in four increments, issue 21):
// row "master node 27 z", column "node 27 y". Node 27 (x = 1, z = 0.5) is the free-boundary end of the edge
// that the coplanar master faces 1 and 3 share, and slave node 12 sits exactly under it. Measured in the
// run (W = −0.2498, FD = −0.2997): the step +h put node 12 on face 1, −h on face 3 (the unperturbed one),
// −h/2 on face 1 again (round-off decides between the faces), so the check fell back to the first-order
// difference (f(x − h) − f(x))/(−h) on face 3's branch, whose entry bends: its slopes over ±0.1 h gave
// W = −0.2498 exactly, and f'' ≈ 1e5, so h f''/2 = 0.05 at h = 1e-6, the whole error. No tangent error:
// a kink (which face) and a bend (the normal force times the face's tilt, both linear in node 27's y).
//
// Here, the smallest configuration: one node-to-face element per branch (face A = facet 1, face B = facet 3,
// the edge point of A), sticking, with the penalty law and the augmented Lagrangian: each branch's tangent
// equals central differences of its own residual; the entry master z / master y is opposite on the faces
// and 0 at the edge point (three branches); the faces' entries bend so that a first-order one-sided
// difference at the check's step is off by more than the check's bound, the second-order one (with the
// half step, what the check uses) is not.
#include "ElementTestTools.hpp"
#include "FlatEdgeFaces.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using flat_edge::Face;
using flat_edge::faceA;
using flat_edge::faceB;
using flat_edge::P3;
// The vertex (1, 0, 0.5), Exodus node 27: the shared edge's free end (FlatEdgeFaces.hpp).
constexpr int kVertexOnA = flat_edge::kFreeEndOnA, kVertexOnB = flat_edge::kFreeEndOnB;

// Slave node 12 just inside the free end x = 1, on the shared edge z = 0.5, penetrating as in the run:
// by 5e-6 mm with the penalty law (t_N = −1 MPa), by 1e-6 mm with the augmented one (λ_N = −1 MPa on top).
P3 slave(bool augmented) { return P3{0.9999, augmented ? 1e-6 : 5e-6, 0.5}; }
constexpr double kFacetLength = 0.5;

// The deck's law: automatic ε_N = 2e5, μ = 0.3, the default Slip Tolerance 0.005 on L_k = 0.5; penalty or
// the augmented Lagrangian with the multipliers of a first update (λ_N = −1 MPa, λ_T along x).
cc::ContactLawParameters deckLaw(bool augmented) {
  cc::ContactLawParameters law{};
  law.normalPenalty = 2e5;
  law.frictionCoefficient = 0.3;
  law.slipTolerance = 0.005;
  if (augmented) {
    law.enforcement = cc::ContactLawParameters::Enforcement::AugmentedLagrangian;
    law.penetrationTolerance = 1e-3;
    law.elasticSlipTolerance = 1e-4;
    law.maxAugmentations = 10;
  }
  return law;
}

// Sticking on `facet`, its stick reference 1e-4 of ξ behind along x.
cc::ContactHistory<2> stuckOn(int facet, double eta, bool augmented) {
  auto h = ct::committedHistory<2>(facet, {0.9998 - 1e-4, eta}, {0.025, 0.0});
  if (augmented) {
    h.normalMultiplier = -1.0;
    h.tangentialMultiplier = {0.025, 0.0};
  }
  return h;
}

struct Branch {
  std::string name;
  Face (*face)(double);
  cc::ContactPoint point;
  int vertex;
  double eta;
};

struct Entry {
  double w = 0;           ///< the tangent's entry master z / master y
  double firstOrder = 0;  ///< (r(y + h) − r(y)) / h at the check's step h = 1e-6
  double secondOrder = 0; ///< the same side with the half step: [4(r_h/2 − r_0) − (r_h − r_0)] / h
};

// The branch's tangent against central differences of its own residual (the element evaluated on this
// branch whatever the step), and the entry with its one-sided differences.
Entry checkBranch(const Branch& b, bool augmented, ct::TangentCheck& check) {
  const cc::NodeToFacetContact<cc::Quad4Facet> element(deckLaw(augmented));
  const auto committed = stuckOn(b.face(0).id, b.eta, augmented);
  const auto residualAt = [&](double lift) {
    const cc::NodeToFacetGeometry<cc::Quad4Facet> g{slave(augmented), b.face(lift).x};
    return element.evaluate(g, b.face(0).id, committed, kFacetLength, cc::SlipTangent::consistent(), b.point);
  };
  const auto r = residualAt(0.0);
  const std::string label = b.name + (augmented ? " (augmented)" : " (penalty)");
  EXPECT_EQ(r.status, ContactStatus::Stick) << label;
  const cc::NodeToFacetGeometry<cc::Quad4Facet> g{slave(augmented), b.face(0).x};
  check.expectClose(r.tangent, ct::finiteDifferenceTangent(element, g, b.face(0).id, committed, 1e-9, kFacetLength, b.point),
                    label);
  const int row = 3 * (1 + b.vertex) + 2, column = 3 * (1 + b.vertex) + 1;
  constexpr double h = 1e-6;
  const double r0 = r.residual[row], rh = residualAt(h).residual[row], rHalf = residualAt(h / 2).residual[row];
  return {r.tangent(row, column), (rh - r0) / h, (4 * (rHalf - r0) - (rh - r0)) / h};
}

}  // namespace

TEST(FlatEdgeMasterRow, EveryBranchIsExactTheFacesBendAndOnlyTheSecondOrderOneSidedDifferenceSeesW) {
  for (const bool augmented : {false, true}) {
    ct::TangentCheck check{ct::kFdTolerance};
    const Branch a{"face A", faceA, cc::ContactPoint::projection(), kVertexOnA, 1.0};
    const Branch b{"face B", faceB, cc::ContactPoint::projection(), kVertexOnB, -1.0};
    const Branch edge{"edge point of A", faceA, cc::ContactPoint::edge(2, 3, -1.0), kVertexOnA, 1.0};
    const Entry onA = checkBranch(a, augmented, check), onB = checkBranch(b, augmented, check),
                atEdge = checkBranch(edge, augmented, check);
    check.printWorst(augmented ? "the three branches, augmented" : "the three branches, penalty");
    for (const auto& [name, e] : {std::pair{"face A", onA}, std::pair{"face B", onB}, std::pair{"edge", atEdge}})
      std::printf("[ entry    ] %s %s: W %.5g, first-order one-sided %.5g, second-order %.5g\n",
                  augmented ? "augmented" : "penalty", name, e.w, e.firstOrder, e.secondOrder);
    // Three branches: the faces' normals tilt by ±2 per unit y of the vertex (0.5 long in z), under the
    // normal force, in opposite directions; the edge point's normal, along x^k − x_b, does not.
    EXPECT_NEAR(onA.w, -onB.w, 1e-6 * std::abs(onA.w));
    EXPECT_GT(std::abs(onA.w), 1.0);
    EXPECT_LT(std::abs(atEdge.w), 1e-3 * std::abs(onA.w));
    // The faces bend: the normal force and the tilt are both linear in the vertex's y, so their product
    // has f'' = 2 · ∂t_N/∂y · ∂n_z/∂y ≈ 2 ε_N · 2 = 8e5 per unit area. At the check's step the first-order
    // difference is off by h f''/2 ≈ 0.2 of W (0.05 / 0.25 in the run, times the node's area), above the
    // check's bound 1e-4 a hundredfold and more; with the half step (second order) it is below that bound.
    for (const Entry& e : {onA, onB}) {
      EXPECT_GT(std::abs(e.firstOrder - e.w), 1e-2 * std::abs(e.w));
      EXPECT_LT(std::abs(e.secondOrder - e.w), 1e-4 * std::abs(e.w));
    }
  }
}
