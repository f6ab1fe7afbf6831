// The master facets of the simplex and quadratic cell families (Line3Facet, Tri3Facet, Tri6Facet,
// Quad8Facet, Quad9Facet; MasterFacet.hpp) through the unchanged projection and node-to-facet element:
//  - the traits: H_i(ξ_j) = δ_ij, Σ H_i = 1, and every derivative order against central differences of the
//    order below (the third derivatives of the 8- and 9-node faces included);
//  - the projection on curved facets that represent a parabola (2D) or a paraboloid (3D) exactly: a node
//    placed on the normal line of a surface point projects on that point, with the analytic gap and normal;
//  - the element's consistent tangent against central differences of its residual, in normal contact,
//    stick and slip, on curved and warped facets (the Quad4 test's cases), for every facet type.
#include "ElementTestTools.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>


namespace {

/// The curved reference surface each facet type samples: y = c x² in 2D, z = c (x² + y²) in 3D (c = 0 for
/// the flat Tri3 facet). A quadratic facet whose nodes lie on it with their in-plane coordinates affine in ξ
/// represents it exactly.
template <class Facet>
constexpr double kCurvature = Facet::kAffine ? 0.0 : 0.15;

template <class Facet>
typename Facet::Point onSurface(const Vector<Facet::kSurfaceDim>& in) {
  typename Facet::Point x{};
  for (int a = 0; a < Facet::kSurfaceDim; ++a) {
    x[a] = in[a];
    x[Facet::kSpaceDim - 1] += kCurvature<Facet> * in[a] * in[a];
  }
  return x;
}

/// In-plane position of parent point ξ: an affine, non-orthogonal map (a skewed facet of size ≈ 2).
template <class Facet>
Vector<Facet::kSurfaceDim> inPlane(const Vector<Facet::kSurfaceDim>& xi) {
  if constexpr (Facet::kSurfaceDim == 1) {
    return {0.3 + 1.1 * xi[0]};
  } else {
    return {0.2 + 1.1 * xi[0] + 0.25 * xi[1], -0.1 + 0.15 * xi[0] + 0.95 * xi[1]};
  }
}

/// The surface's unit normal at parent point ξ, from its exact tangents ∂x/∂ξ^α = Σ_a J_aα (e_a + 2c in_a e_d)
/// (J the constant in-plane Jacobian), oriented as the facets' normals (Facet::unitNormal, eq. 5).
template <class Facet>
typename Facet::Point surfaceNormal(const Vector<Facet::kSurfaceDim>& xi) {
  constexpr int M = Facet::kSurfaceDim;
  const auto in = inPlane<Facet>(xi);
  const auto origin = inPlane<Facet>(Vector<M>{});
  std::array<typename Facet::Point, M> a{};
  for (int al = 0; al < M; ++al) {
    Vector<M> unit{};
    unit[al] = 1.0;
    const auto column = cc::subtract(inPlane<Facet>(unit), origin);
    for (int c = 0; c < M; ++c) {
      a[al][c] += column[c];
      a[al][Facet::kSpaceDim - 1] += 2.0 * kCurvature<Facet> * in[c] * column[c];
    }
  }
  return Facet::unitNormal(a);
}

/// The facet's nodes on the surface (curved), optionally moved off it by a fixed pseudo-random warp.
template <class Facet>
std::array<typename Facet::Point, Facet::kNodes> curvedFacet(double warp) {
  std::array<typename Facet::Point, Facet::kNodes> x{};
  for (int i = 0; i < Facet::kNodes; ++i) {
    x[i] = onSurface<Facet>(inPlane<Facet>(Facet::nodeCoords(i)));
    for (int c = 0; c < Facet::kSpaceDim; ++c) x[i][c] += warp * std::sin(1.7 * i + 2.3 * c + 0.4);
  }
  return x;
}

template <class Facet>
class FacetFamilies : public ::testing::Test {};

TYPED_TEST_SUITE(FacetFamilies, ct::NewFacetTypes, ct::FacetTypeName);

/// Interior points of the parent domain (inside the unit triangle for the triangular facets).
template <class Facet>
std::vector<Vector<Facet::kSurfaceDim>> samplePoints() {
  if constexpr (Facet::kSurfaceDim == 1) {
    return {{-0.7}, {0.05}, {0.9}};
  } else if constexpr (Facet::kNodes == 3 || Facet::kNodes == 6) {
    return {{0.2, 0.3}, {0.6, 0.1}, {0.1, 0.75}};
  } else {
    return {{0.05, -0.03}, {0.9, 0.2}, {-0.6, 0.7}, {0.93, -0.95}};
  }
}

}  // namespace

TYPED_TEST(FacetFamilies, ShapeFunctionsInterpolateAndSumToOne) {
  using Facet = TypeParam;
  for (int j = 0; j < Facet::kNodes; ++j) {
    const auto h = Facet::shapeFunctions(Facet::nodeCoords(j));
    for (int i = 0; i < Facet::kNodes; ++i) EXPECT_NEAR(h[i], i == j ? 1.0 : 0.0, 1e-15) << i << " at node " << j;
    EXPECT_TRUE(Facet::contains(Facet::nodeCoords(j), 1e-14));
  }
  for (const auto& xi : samplePoints<Facet>()) {
    double sum = 0.0;
    for (double h : Facet::shapeFunctions(xi)) sum += h;
    EXPECT_NEAR(sum, 1.0, 1e-14);
  }
  EXPECT_TRUE(Facet::contains(Facet::center(), 0.0));
}

TYPED_TEST(FacetFamilies, DerivativesMatchCentralDifferences) {
  using Facet = TypeParam;
  constexpr int M = Facet::kSurfaceDim;
  const double h = 1e-6;
  double worst = 0.0;
  for (const auto& xi : samplePoints<Facet>()) {
    const auto d1 = Facet::shapeDerivatives(xi);
    const auto d2 = Facet::shapeSecondDerivatives(xi);
    for (int be = 0; be < M; ++be) {
      auto plus = xi, minus = xi;
      plus[be] += h;
      minus[be] -= h;
      const auto hp = Facet::shapeFunctions(plus), hm = Facet::shapeFunctions(minus);
      const auto dp = Facet::shapeDerivatives(plus), dm = Facet::shapeDerivatives(minus);
      const auto sp = Facet::shapeSecondDerivatives(plus), sm = Facet::shapeSecondDerivatives(minus);
      for (int i = 0; i < Facet::kNodes; ++i) {
        const double first = (hp[i] - hm[i]) / (2 * h);
        EXPECT_NEAR(d1(i, be), first, 1e-8);
        worst = std::max(worst, std::abs(d1(i, be) - first));
        for (int al = 0; al < M; ++al) {
          const double second = (dp(i, al) - dm(i, al)) / (2 * h);
          EXPECT_NEAR(d2[i](al, be), second, 1e-8);
          worst = std::max(worst, std::abs(d2[i](al, be) - second));
          for (int ga = 0; ga < M; ++ga) {
            const double third = (sp[i](al, ga) - sm[i](al, ga)) / (2 * h);
            double exact = 0.0;
            if constexpr (Facet::kCubic) exact = Facet::shapeThirdDerivatives(xi)[i][al](ga, be);
            EXPECT_NEAR(exact, third, 1e-8) << "H_" << i << "," << al << ga << be;
            worst = std::max(worst, std::abs(exact - third));
          }
        }
      }
    }
  }
  std::printf("[ FD       ] shape derivatives of orders 1-3: worst absolute error %.2e\n", worst);
}

// A node on the normal line of a point of the exact parabola/paraboloid, inside the radius of curvature
// (1/(2c) ≈ 3.3; a flat plane for Tri3), projects on that point: ξ̄ recovered, g_N and n̄ the surface's
// (eq. 1-5), from the robust starts of Projection::project, on both sides of the facet.
TYPED_TEST(FacetFamilies, ProjectionOnACurvedFacetFindsTheClosestPoint) {
  using Facet = TypeParam;
  const auto facet = curvedFacet<Facet>(0.0);
  const cc::Projection<Facet> projection;
  for (const auto& xi : samplePoints<Facet>()) {
    const auto in = inPlane<Facet>(xi);
    const auto n = surfaceNormal<Facet>(xi);
    for (double gap : {0.4, -0.25, 1e-3}) {
      const auto slave = cc::add(onSurface<Facet>(in), cc::scaled(gap, n));
      const auto p = projection.project(slave, facet);
      ASSERT_TRUE(p.converged);
      for (int a = 0; a < Facet::kSurfaceDim; ++a) EXPECT_NEAR(p.xi[a], xi[a], 1e-12);
      EXPECT_NEAR(p.gap, gap, 1e-12);
      EXPECT_NEAR(cc::dot(p.normal, n), 1.0, 1e-13);
      if (!Facet::kAffine) {
        // The facet is curved: its normal varies over it (it is not its flat pieces' normal).
        const auto centre = cc::Projection<Facet>::evaluateAt(slave, facet, Facet::center());
        EXPECT_LT(cc::dot(centre.normal, p.normal), 1.0 - 1e-4);
      }
    }
  }
}

namespace {

struct LawCase {
  const char* law;
  cc::ContactLawParameters parameters;
  ContactStatus expected;
};

// ε_N = 1e3, ε_T = 5e2; stick: μ = 100; slip: μ = 0.2 (the Quad4 test's cases).
const LawCase kLaws[] = {
    {"normal_only", {1e3, 0.0, 0.0}, ContactStatus::Slip},
    {"stick", {1e3, 5e2, 100.0}, ContactStatus::Stick},
    {"slip", {1e3, 5e2, 0.2}, ContactStatus::Slip},
};

}  // namespace

// The consistent tangent (NodeToFacetContact.hpp) against central differences of the residual, on the
// curved facet and on it warped off the surface, at interior points and near a corner, with a committed
// ξ_n away from ξ̄ (the stick and slip terms, the metric's variation, the projection's second variation and,
// on the 8- and 9-node faces, their third derivatives x̄,αβγ all contribute).
TYPED_TEST(FacetFamilies, ConsistentTangentMatchesCentralDifferences) {
  using Facet = TypeParam;
  constexpr int M = Facet::kSurfaceDim;
  double worst = 0.0;
  ct::forEachLaw<Facet>(kLaws, [&](const LawCase& law, const cc::NodeToFacetContact<Facet>& element) {
    for (double warp : {0.0, 0.08}) {
      const auto facet = curvedFacet<Facet>(warp);
      for (const auto& xi : samplePoints<Facet>()) {
        SCOPED_TRACE(std::string(law.law) + " warp " + std::to_string(warp) + " at " + std::to_string(xi[0]));
        const auto at = cc::Projection<Facet>::evaluateAt(typename Facet::Point{}, facet, xi);
        const double gap = -0.05;
        const cc::NodeToFacetGeometry<Facet> g{cc::add(at.position, cc::scaled(gap, at.normal)), facet};
        cc::ContactHistory<M> committed;
        committed.segment = 3;
        for (int a = 0; a < M; ++a) {
          committed.xi[a] = xi[a] - 0.07 + 0.03 * a;
          committed.tangentialTraction[a] = a == 0 ? 1.5 : -0.8;
        }
        committed.status = ContactStatus::Stick;
        const auto r = element.evaluate(g, 3, committed);
        ASSERT_TRUE(r.projection.converged);
        ASSERT_EQ(r.status, law.expected);
        for (int a = 0; a < M; ++a) EXPECT_NEAR(r.projection.xi[a], xi[a], 1e-11);
        const auto fd = ct::finiteDifferenceTangent(element, g, 3, committed, 1e-6);
        const double error = ct::relativeDifference(r.tangent, fd);
        EXPECT_LT(error, 1e-6);
        worst = std::max(worst, error);
      }
    }
  });
  std::printf("[ FD       ] %d-node facet: worst ‖K − K_FD‖/‖K_FD‖ = %.2e\n", Facet::kNodes, worst);
}
