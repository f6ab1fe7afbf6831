// The node-to-facet element's terms one by one (NodeToFacetTerms.hpp), each against central differences of
// the quantity it is the derivative of, on every facet family (Line2, Line3 in 2D; Quad4, Tri3, Tri6, Quad8,
// Quad9 in 3D) at a curved facet and a slave node off it (g_N ≠ 0, so the g_N terms count):
//  - the operators of eq. (26): N = ∂g_N/∂u and Ξ^α = ∂ξ̄^α/∂u, and the metric's variation dā_βγ;
//  - tangent term (a), ∂²g_N/∂u² (FacetKinematics::addGapCurvature), against differences of N, and the same
//    at an edge point and a vertex (BoundaryPointKinematics);
//  - tangent term (b), Ξ^α (dt_Tα/du)ᵀ (addTractionVariation), for a traction depending on Δξ, ā_βγ and t_N
//    through arbitrary partial derivatives, against differences of that traction;
//  - tangent term (c), ∂²ξ̄^β/∂u² (addProjectionCurvature with t_T = e_β), against differences of Ξ^β.
// The element tests (NodeToFacetContact*Test.cpp, NewFacetContactTest.cpp) check the sum; a wrong term is
// found here by name.
#include "ElementTestTools.hpp"

#include "contact/NodeToFacetTerms.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <type_traits>

namespace {

namespace terms = cc::terms;
using cc::add;
using cc::addOuter;
using cc::ContactPoint;
using cc::Line2Facet;
using cc::Line3Facet;
using cc::Matrix;
using cc::NodeToFacetGeometry;
using cc::Projection;
using cc::ProjectionResult;
using cc::Quad4Facet;
using cc::Quad8Facet;
using cc::Quad9Facet;
using cc::scaled;
using cc::Tri3Facet;
using cc::Tri6Facet;
using ct::kDofs;

constexpr double kStep = 1e-6;
constexpr double kTolerance = 1e-6;  // relative to the largest entry of the analytic operator

template <class Facet>
using Column = Vector<kDofs<Facet>>;
template <class Facet>
using Square = Matrix<kDofs<Facet>, kDofs<Facet>>;

/// A curved facet (a sag on segments, a warp on faces; the straight and flat families stay affine) and a
/// slave node 0.07 off it, above an interior point away from the centre.
template <class Facet>
NodeToFacetGeometry<Facet> curvedCase() {
  NodeToFacetGeometry<Facet> g;
  typename Facet::SurfaceCoords centre{};
  for (int i = 0; i < Facet::kNodes; ++i) {
    const auto xi = Facet::nodeCoords(i);
    for (int a = 0; a < Facet::kSurfaceDim; ++a) centre[a] += xi[a] / Facet::kNodes;
    if constexpr (Facet::kSurfaceDim == 1) {
      g.master[i] = {0.3 + 1.1 * xi[0] + 0.05 * xi[0] * xi[0], 0.2 * (1.0 - xi[0] * xi[0]) + 0.1 * xi[0]};
    } else {
      g.master[i] = {0.2 + 1.1 * xi[0] + 0.25 * xi[1], -0.1 + 0.15 * xi[0] + 0.95 * xi[1],
                     0.2 * (0.5 - xi[0] * xi[0] - 0.7 * xi[1] * xi[1] + 0.3 * xi[0] * xi[1]) + 0.1 * xi[0]};
    }
  }
  auto target = centre;
  const auto corner = Facet::nodeCoords(0);
  for (int a = 0; a < Facet::kSurfaceDim; ++a) target[a] = 0.7 * centre[a] + 0.3 * corner[a];
  const auto at = Projection<Facet>::evaluateAt(g.master[0], g.master, target);
  g.slave = add(at.position, scaled(0.07, at.normal));
  return g;
}

/// The projection of the slave node of dofs `u` and the element's kinematics there (both must exist).
template <class Facet>
struct Evaluated {
  ProjectionResult<Facet> p;
  terms::FacetKinematics<Facet> k;
};

template <class Facet>
Evaluated<Facet> evaluate(const Column<Facet>& u) {
  const auto g = ct::fromDofs<Facet>(u);
  Evaluated<Facet> e;
  e.p = Projection<Facet>().project(g.slave, g.master);
  EXPECT_TRUE(e.p.converged);
  EXPECT_TRUE(e.k.build(e.p, g.master));
  return e;
}

/// Central differences of a scalar function of the dofs: its gradient.
template <class Facet>
Column<Facet> gradientOf(const std::function<double(const Column<Facet>&)>& f, const Column<Facet>& u) {
  Column<Facet> d{};
  for (int j = 0; j < kDofs<Facet>; ++j) {
    auto plus = u, minus = u;
    plus[j] += kStep;
    minus[j] -= kStep;
    d[j] = (f(plus) - f(minus)) / (2.0 * kStep);
  }
  return d;
}

/// Central differences of a column function of the dofs: K(:, j) = ∂f/∂u_j.
template <class Facet>
Square<Facet> jacobianOf(const std::function<Column<Facet>(const Column<Facet>&)>& f, const Column<Facet>& u) {
  Square<Facet> d{};
  for (int j = 0; j < kDofs<Facet>; ++j) {
    auto plus = u, minus = u;
    plus[j] += kStep;
    minus[j] -= kStep;
    const auto fp = f(plus), fm = f(minus);
    for (int i = 0; i < kDofs<Facet>; ++i) d(i, j) = (fp[i] - fm[i]) / (2.0 * kStep);
  }
  return d;
}

template <class Facet>
double relativeDifference(const Column<Facet>& analytic, const Column<Facet>& differences) {
  double scale = 0.0, worst = 0.0;
  for (int i = 0; i < kDofs<Facet>; ++i) {
    scale = std::max(scale, std::abs(analytic[i]));
    worst = std::max(worst, std::abs(analytic[i] - differences[i]));
  }
  return worst / scale;
}

template <class Facet>
double relativeDifference(const Square<Facet>& analytic, const Square<Facet>& differences) {
  double scale = 0.0, worst = 0.0;
  for (int i = 0; i < kDofs<Facet>; ++i)
    for (int j = 0; j < kDofs<Facet>; ++j) {
      scale = std::max(scale, std::abs(analytic(i, j)));
      worst = std::max(worst, std::abs(analytic(i, j) - differences(i, j)));
    }
  return worst / scale;
}

template <class Facet>
class NodeToFacetTerms : public ::testing::Test {};

using AllFacetTypes =
    ::testing::Types<Line2Facet, Line3Facet, Quad4Facet, Tri3Facet, Tri6Facet, Quad8Facet, Quad9Facet>;
struct AllFacetNames {
  template <class T>
  static std::string GetName(int i) {
    if (std::is_same_v<T, Line2Facet>) return "Line2";
    if (std::is_same_v<T, Quad4Facet>) return "Quad4";
    return ct::FacetTypeName::GetName<T>(i);
  }
};
TYPED_TEST_SUITE(NodeToFacetTerms, AllFacetTypes, AllFacetNames);

}  // namespace

// eq. (26)'s operators: N = ∂g_N/∂u and Ξ^α = ∂ξ̄^α/∂u (the exact variation of the projection).
TYPED_TEST(NodeToFacetTerms, GapAndProjectionOperatorsAreTheDerivativesOfGapAndProjection) {
  using Facet = TypeParam;
  const auto u = ct::toDofs(curvedCase<Facet>());
  const auto e = evaluate<Facet>(u);
  EXPECT_NE(e.p.gap, 0.0);
  const auto dGap = gradientOf<Facet>([](const Column<Facet>& v) { return evaluate<Facet>(v).p.gap; }, u);
  EXPECT_LT(relativeDifference<Facet>(e.k.N, dGap), kTolerance);
  for (int al = 0; al < Facet::kSurfaceDim; ++al) {
    const auto dXi = gradientOf<Facet>([al](const Column<Facet>& v) { return evaluate<Facet>(v).p.xi[al]; }, u);
    EXPECT_LT(relativeDifference<Facet>(e.k.Xi[al], dXi), kTolerance) << "alpha " << al;
  }
}

// dā_βγ (metricVariation): the variation of the metric at the moving projection, fixed ξ and ξ̄'s motion.
TYPED_TEST(NodeToFacetTerms, MetricVariationIsTheDerivativeOfTheMetricAtTheProjection) {
  using Facet = TypeParam;
  const auto u = ct::toDofs(curvedCase<Facet>());
  const auto dMetric = terms::metricVariation<Facet>(evaluate<Facet>(u).k);
  for (int be = 0; be < Facet::kSurfaceDim; ++be)
    for (int ga = 0; ga < Facet::kSurfaceDim; ++ga) {
      const auto d = gradientOf<Facet>(
          [be, ga](const Column<Facet>& v) { return evaluate<Facet>(v).p.metric(be, ga); }, u);
      EXPECT_LT(relativeDifference<Facet>(dMetric[be][ga], d), kTolerance) << "beta " << be << " gamma " << ga;
    }
}

// Tangent term (a) at the projection: ∂²g_N/∂u² against differences of N.
TYPED_TEST(NodeToFacetTerms, GapCurvatureIsTheDerivativeOfTheGapOperator) {
  using Facet = TypeParam;
  const auto u = ct::toDofs(curvedCase<Facet>());
  Square<Facet> K{};
  evaluate<Facet>(u).k.addGapCurvature(K, 1.0);
  const auto d = jacobianOf<Facet>([](const Column<Facet>& v) { return evaluate<Facet>(v).k.N; }, u);
  EXPECT_LT(relativeDifference<Facet>(K, d), kTolerance);
}

// Tangent term (a) at an edge point and at a vertex of the facet: ∂²g_N/∂u² of g_N = ±‖x^k − x_b‖.
TYPED_TEST(NodeToFacetTerms, BoundaryPointGapCurvatureIsTheDerivativeOfItsGapOperator) {
  using Facet = TypeParam;
  const auto u = ct::toDofs(curvedCase<Facet>());
  for (const ContactPoint& point : {ContactPoint::vertex(0, 1.0), ContactPoint::edge(0, 1, -1.0)}) {
    if (Facet::kSurfaceDim == 1 && point.kind == ContactPoint::Kind::Edge) continue;  // a segment has no edge
    const auto kinematics = [&point](const Column<Facet>& v) {
      const auto g = ct::fromDofs<Facet>(v);
      return terms::BoundaryPointKinematics<Facet>(point, g.slave, g.master, g.slave);
    };
    Square<Facet> K{};
    kinematics(u).addGapCurvature(K, 1.0);
    const auto d = jacobianOf<Facet>([&](const Column<Facet>& v) { return kinematics(v).N; }, u);
    EXPECT_LT(relativeDifference<Facet>(K, d), kTolerance) << (point.kind == ContactPoint::Kind::Edge ? "edge" : "vertex");
  }
}

// Tangent term (b): Ξ^α (dt_Tα/du)ᵀ for t_α(u) = C_αβ Δξ^β + D_α^βγ ā_βγ + e_α t_N with
// Δξ^β = s (ξ̄^β − ξ_0^β) + q^β g_N and t_N = ε_N g_N: the partial derivatives of the law (TangentialLaw)
// are C, D, e, s and q, and addTractionVariation must chain them with Ξ, dā and N.
TYPED_TEST(NodeToFacetTerms, TractionVariationChainsTheLawsPartialsWithTheKinematics) {
  using Facet = TypeParam;
  constexpr int M = Facet::kSurfaceDim;
  const double epsN = 3.0;
  terms::TangentialLaw<M> law;
  law.slipScale = 0.8;
  for (int al = 0; al < M; ++al) {
    law.dT_dNormal[al] = 0.3 - 0.5 * al;
    law.slipPerGap[al] = 0.2 + 0.1 * al;
    for (int be = 0; be < M; ++be) {
      law.dT_dXi(al, be) = al == be ? 2.0 : 0.4;
      for (int ga = 0; ga < M; ++ga) law.dT_dMetric[al](be, ga) = 0.1 * (1 + al) - 0.07 * be + 0.05 * ga;
    }
  }
  const Vector<M> xi0{};
  const auto traction = [&](const Column<Facet>& v, int al) {
    const auto e = evaluate<Facet>(v);
    double t = law.dT_dNormal[al] * epsN * e.p.gap;
    for (int be = 0; be < M; ++be) {
      const double slip = law.slipScale * (e.p.xi[be] - xi0[be]) + law.slipPerGap[be] * e.p.gap;
      t += law.dT_dXi(al, be) * slip;
      for (int ga = 0; ga < M; ++ga) t += law.dT_dMetric[al](be, ga) * e.p.metric(be, ga);
    }
    return t;
  };
  const auto u = ct::toDofs(curvedCase<Facet>());
  const auto k = evaluate<Facet>(u).k;
  Square<Facet> K{}, expected{};
  terms::addTractionVariation<Facet>(K, k, law, k.N, epsN);
  for (int al = 0; al < M; ++al) {
    const auto dt = gradientOf<Facet>([&](const Column<Facet>& v) { return traction(v, al); }, u);
    addOuter(expected, 1.0, k.Xi[al], dt);
  }
  EXPECT_LT(relativeDifference<Facet>(K, expected), kTolerance);
}

// Tangent term (c): with t_T = e_β, addProjectionCurvature adds ∂²ξ̄^β/∂u², the derivative of Ξ^β.
TYPED_TEST(NodeToFacetTerms, ProjectionCurvatureIsTheDerivativeOfTheProjectionOperator) {
  using Facet = TypeParam;
  constexpr int M = Facet::kSurfaceDim;
  const auto u = ct::toDofs(curvedCase<Facet>());
  const auto k = evaluate<Facet>(u).k;
  for (int be = 0; be < M; ++be) {
    Vector<M> unit{};
    unit[be] = 1.0;
    Square<Facet> K{};
    terms::addProjectionCurvature<Facet>(K, k, unit);
    const auto d = jacobianOf<Facet>([be](const Column<Facet>& v) { return evaluate<Facet>(v).k.Xi[be]; }, u);
    EXPECT_LT(relativeDifference<Facet>(K, d), kTolerance) << "beta " << be;
  }
}
