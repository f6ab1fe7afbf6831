// Transitional: NodeToFacetContact<Line2Facet> against the old NodeToSegmentContact2D, residual and tangent
// to round-off over normal / stick / slip / slip tolerance / secant / first contact / paper terms.
#include "contact/NodeToFacetContact.hpp"
#include "contact/NodeToSegmentContact2D.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace cc = contessa::contact;
using cc::ContactStatus;
using cc::Vector;

TEST(NodeToFacetContactLine2, ReproducesTheOldNodeToSegmentElement) {
  struct Geometry {
    Vector<2> x1, x2;
    double xi, xiN, gap;
  };
  const Geometry geometries[] = {{{1.0, 0.0}, {-1.0, 0.0}, 0.05, -0.02, -0.04},
                                 {{1.0, 0.0}, {-1.0, 0.0}, 0.95, 0.90, -0.03},
                                 {{2.3, 0.9}, {-0.5, -0.6}, -0.3, -0.38, -0.06},
                                 {{1.2, 0.2}, {-1.1, -0.1}, 0.7, -0.8, -0.05},
                                 {{1.2, 0.2}, {-1.1, -0.1}, 1.15, 0.8, -1e-5}};
  const cc::ContactLawParameters laws[] = {{1e3, 0.0, 0.0}, {1e3, 5e2, 50.0}, {1e3, 5e2, 0.2},
                                           {1e3, 0.0, 0.3, 1.0}, {1e3, 1e-3, 0.3, 1.0}, {1e3, 0.0, 0.3, 0.005},
                                           {1e3, 300.0, 0.3, 0.005}};
  double worstResidual = 0.0, worstTangent = 0.0;
  int compared = 0;
  for (const auto terms : {cc::TangentTerms::Consistent, cc::TangentTerms::PaperMainTerms})
    for (const auto& law : laws) {
      const cc::NodeToSegmentContact2D old(law, terms);
      const cc::NodeToFacetContact<cc::Line2Facet> now(law, terms);
      for (const auto& g : geometries)
        for (const double committedTraction : {0.0, 1.5, -0.7})
          for (const auto committedStatus : {ContactStatus::Open, ContactStatus::Stick, ContactStatus::Slip})
            for (const double secant : {0.0, 30.0, 1e6}) {
              const auto p = cc::SegmentProjection2D::evaluateAt({0.0, 0.0}, {{g.x1, g.x2}}, {g.xi});
              const Vector<2> slave = cc::add(p.position, cc::scaled(g.gap, p.normal));
              cc::ContactHistory<1> committed;
              if (committedStatus != ContactStatus::Open) {
                committed.segment = 4;
                committed.xi = {g.xiN};
                committed.tangentialTraction = {committedTraction};
                committed.status = committedStatus;
                committed.accumulatedSlip = 0.3;
              }
              const cc::SlipTangent slip = secant > 0.0 ? cc::SlipTangent::secantOf(secant) : cc::SlipTangent::consistent();
              const auto a = old.evaluate({slave, {{g.x1, g.x2}}}, 4, committed, 4.0, slip);
              const auto b = now.evaluate({slave, {{g.x1, g.x2}}}, 4, committed, 4.0, slip);
              ASSERT_EQ(a.status, b.status);
              EXPECT_EQ(a.trial.status, b.trial.status);
              EXPECT_EQ(a.trial.segment, b.trial.segment);
              EXPECT_NEAR(a.trial.xi[0], b.trial.xi[0], 1e-15);
              EXPECT_NEAR(a.trial.tangentialTraction[0], b.trial.tangentialTraction[0],
                          1e-14 * (1.0 + std::abs(a.trial.tangentialTraction[0])));
              EXPECT_NEAR(a.trial.accumulatedSlip, b.trial.accumulatedSlip, 1e-14);
              double rScale = 0.0, rDiff = 0.0;
              for (int i = 0; i < 6; ++i) {
                rScale = std::max(rScale, std::abs(a.residual[i]));
                rDiff = std::max(rDiff, std::abs(a.residual[i] - b.residual[i]));
              }
              cc::Matrix<6, 6> d = a.tangent;
              cc::addScaled(d, -1.0, b.tangent);
              const double kScale = cc::frobeniusNorm(a.tangent);
              const double rRel = rScale > 0.0 ? rDiff / rScale : rDiff;
              const double kRel = kScale > 0.0 ? cc::frobeniusNorm(d) / kScale : cc::frobeniusNorm(d);
              EXPECT_LT(rRel, 1e-13);
              EXPECT_LT(kRel, 1e-13);
              worstResidual = std::max(worstResidual, rRel);
              worstTangent = std::max(worstTangent, kRel);
              ++compared;
            }
    }
  std::printf("[ compare  ] %d evaluations: worst relative difference residual %.2e, tangent %.2e\n", compared,
              worstResidual, worstTangent);
}
