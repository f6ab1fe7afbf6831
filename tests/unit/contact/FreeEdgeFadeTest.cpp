// The contact element past a free edge of its master surface (ContactPoint::freeEdgeReach): a penetrating
// node that the selector keeps on the boundary facet although its projection lies past the facet's free
// boundary carries the element's force times w = 1 − 3s² + 2s³, s = d/reach (d its distance past the
// boundary on the facet's extension), so its force goes continuously to zero over the reach (issue 22: a
// node row on a punch's edge switched on and off between Newton iterates). Checked: the weight, zero force
// and open status at and beyond the reach, and the consistent tangent of the faded element (frictionless,
// stick, slip; 2D end, 3D edge and corner, flat and warped faces) against central differences.
#include "ElementTestTools.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using cc::ContactPoint;

namespace {

using ct::kLaws;
using ct::Law;
constexpr double kReach = 0.05;

double expectedWeight(double d) {
  const double s = std::min(d / kReach, 1.0);
  return 1.0 - 3.0 * s * s + 2.0 * s * s * s;
}

template <class Facet>
double checkFadedTangent(const cc::NodeToFacetContact<Facet>& element, const cc::NodeToFacetGeometry<Facet>& g,
                         const cc::ContactHistory<Facet::kSurfaceDim>& committed, double expectedW,
                         const std::string& what) {
  const auto point = ContactPoint::projection(kReach);
  const auto r = element.evaluate(g, 3, committed, 0.0, cc::SlipTangent::consistent(), point);
  EXPECT_LT(r.gap, 0.0) << what;
  EXPECT_NE(r.status, ContactStatus::Open) << what;
  EXPECT_NEAR(r.freeEdgeWeight, expectedW, 1e-9) << what;
  EXPECT_GT(r.freeEdgeWeight, 0.0) << what;
  EXPECT_LT(r.freeEdgeWeight, 1.0) << what;
  return ct::expectTangentAtPointClose(element, g, committed, point, what);
}

}  // namespace

// 2D: the segment (2,0) → (0,0) (body below, n̄ = +y), free end at x = 2 (ξ̄ = −1). A node at (2 + d, −0.04).
TEST(FreeEdgeFade, WeightAndOpeningIn2D) {
  using Facet = cc::Line2Facet;
  const cc::NodeToFacetContact<Facet> element(kLaws[0].parameters);
  for (const double d : {0.0, 0.2 * kReach, 0.5 * kReach, 0.9 * kReach, kReach, 1.5 * kReach}) {
    const cc::NodeToFacetGeometry<Facet> g{{2.0 + d, -0.04}, {{{2.0, 0.0}, {0.0, 0.0}}}};
    const auto unfaded = element.evaluate(g, 3, {}, 0.0, cc::SlipTangent::consistent(), ContactPoint::projection());
    const auto faded = element.evaluate(g, 3, {}, 0.0, cc::SlipTangent::consistent(), ContactPoint::projection(kReach));
    SCOPED_TRACE("d = " + std::to_string(d));
    ASSERT_NE(unfaded.status, ContactStatus::Open);
    EXPECT_NEAR(unfaded.residual[1], 1e3 * -0.04, 1e-12);  // t_N = ε_N g_N on the slave's y row
    const double w = expectedWeight(d);
    EXPECT_NEAR(faded.freeEdgeWeight, w, 1e-12);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(faded.residual[i], w * unfaded.residual[i], 1e-12);
    EXPECT_NEAR(faded.normalTraction, w * unfaded.normalTraction, 1e-12);
    if (d >= kReach) {
      EXPECT_EQ(faded.status, ContactStatus::Open);
      EXPECT_EQ(faded.trial.status, ContactStatus::Open);
    } else {
      EXPECT_NE(faded.status, ContactStatus::Open);
    }
  }
  // Just past the end the weight is 1 to second order (C1 at the boundary): no jump where the fade starts.
  const cc::NodeToFacetGeometry<Facet> g{{2.0 + 1e-6, -0.04}, {{{2.0, 0.0}, {0.0, 0.0}}}};
  const auto faded = element.evaluate(g, 3, {}, 0.0, cc::SlipTangent::consistent(), ContactPoint::projection(kReach));
  EXPECT_NEAR(faded.freeEdgeWeight, 1.0, 1.01 * 3.0 * std::pow(1e-6 / kReach, 2));
}

TEST(FreeEdgeFade, TangentIn2DMatchesCentralDifferences) {
  using Facet = cc::Line2Facet;
  // A tilted deformable segment: its end node at (2, 0.1), the node past it along the extension.
  const std::array<Vector<2>, 2> master{{{2.0, 0.1}, {0.0, -0.05}}};
  double worst = 0.0;
  for (const Law& law : kLaws) {
    const cc::NodeToFacetContact<Facet> element(law.parameters);
    const auto committed = ct::committedHistory<1>(3, {-0.95}, {0.02});
    for (const double s : {0.3, 0.7}) {
      const auto p = cc::Projection<Facet>().project({2.0 + s * kReach, 0.05}, master);
      // The node past the end by s·reach along the extension, 0.03 below it.
      const Vector<2> t = cc::scaled(1.0 / cc::norm(p.covariantBasis[0]), p.covariantBasis[0]);
      const Vector<2> slave = cc::add(cc::add(master[0], cc::scaled(-s * kReach, t)), cc::scaled(-0.03, p.normal));
      worst = std::max(worst, checkFadedTangent(element, {slave, master}, committed, expectedWeight(s * kReach),
                                                std::string("2D end / s = ") + std::to_string(s) + " / " + law.name));
    }
  }
  std::printf("[ FD       ] free-edge fade 2D: worst relative error %.2e\n", worst);
}

// 3D: a flat face and a warped one; past the free edge node 1 → node 2 (ξ¹ > 1), and past the corner node 2
// (both ξ clamped).
TEST(FreeEdgeFade, TangentIn3DMatchesCentralDifferences) {
  using Facet = cc::Quad4Facet;
  const double worst = ct::worstOverLawsAndFaces([](const Law& law, const auto& element, const auto& committed,
                                                    const std::string& name, const auto& face) {
    double faceWorst = 0.0;
    for (const double s : {0.3, 0.7}) {
      // On the face's extension past ξ = (1 + δ, 0.3) or the corner (1 + δ, 1 + δ), 0.04 behind it; δ such
      // that the distance past the boundary is about s·reach (‖ā_α‖ ≈ 1 on both faces; the check reads the
      // weight back from d).
      for (const bool corner : {false, true}) {
        const double delta = s * kReach * (corner ? 0.5 : 1.0);
        const Vector<2> xi{1.0 + delta, corner ? 1.0 + delta : 0.3};
        const auto at = cc::Projection<Facet>::evaluateAt({}, face, xi);
        const Vector<3> slave = cc::add(at.position, cc::scaled(-0.04, at.normal));
        const auto p = cc::Projection<Facet>().project(slave, face);
        Vector<2> clamped = p.xi;
        for (auto& c : clamped) c = std::clamp(c, -1.0, 1.0);
        const double d = cc::norm(cc::subtract(p.position, cc::Projection<Facet>::evaluateAt({}, face, clamped).position));
        faceWorst = std::max(faceWorst, checkFadedTangent(element, {slave, face}, committed, expectedWeight(d),
                                                          std::string("3D ") + (corner ? "corner" : "edge") + " / " + name +
                                                              " / s = " + std::to_string(s) + " / " + law.name));
      }
    }
    return faceWorst;
  });
  std::printf("[ FD       ] free-edge fade 3D: worst relative error %.2e\n", worst);
}
