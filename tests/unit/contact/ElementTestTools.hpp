#pragma once
// The contact element tests' fixture (Line2 and Quad4 facets alike): dofs ↔ geometry, central-difference
// tangents and their comparison with the element's, the slip-tolerance laws every facet is checked
// with, matrix measures and a dense solve for the small Newton demonstrations.
#include "contact/NodeToFacetContact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>
#include <utility>

namespace contessa::contact::testing {

/// The three contact laws the element tests run each case with: ε_N = 1e3, ε_T = 5e2; stick with μ = 100,
/// slip with μ = 0.2 (against the committed tractions each test sets).
struct Law {
  const char* name;
  ContactLawParameters parameters;
};
inline const Law kLaws[] = {{"frictionless", {1e3, 0.0, 0.0}}, {"stick", {1e3, 5e2, 100.0}}, {"slip", {1e3, 5e2, 0.2}}};

/// The facet types beyond Line2 and Quad4, for typed tests, and their names in the tests' names.
using NewFacetTypes = ::testing::Types<Line3Facet, Tri3Facet, Tri6Facet, Quad8Facet, Quad9Facet>;
struct FacetTypeName {
  template <class T>
  static std::string GetName(int) {
    if (std::is_same_v<T, Line3Facet>) return "Line3";
    if (std::is_same_v<T, Tri3Facet>) return "Tri3";
    if (std::is_same_v<T, Tri6Facet>) return "Tri6";
    if (std::is_same_v<T, Quad8Facet>) return "Quad8";
    return "Quad9";
  }
};


/// The central-difference step of the tangent checks, and the relative difference they accept.
constexpr double kFdStep = 1e-6;
constexpr double kFdTolerance = 1e-6;

template <class Facet>
constexpr int kDofs = Facet::kSpaceDim * (1 + Facet::kNodes);

template <class Facet>
NodeToFacetGeometry<Facet> fromDofs(const Vector<kDofs<Facet>>& x) {
  NodeToFacetGeometry<Facet> g;
  for (int c = 0; c < Facet::kSpaceDim; ++c) g.slave[c] = x[c];
  for (int i = 0; i < Facet::kNodes; ++i)
    for (int c = 0; c < Facet::kSpaceDim; ++c) g.master[i][c] = x[(1 + i) * Facet::kSpaceDim + c];
  return g;
}

template <class Facet>
Vector<kDofs<Facet>> toDofs(const NodeToFacetGeometry<Facet>& g) {
  Vector<kDofs<Facet>> x{};
  for (int c = 0; c < Facet::kSpaceDim; ++c) x[c] = g.slave[c];
  for (int i = 0; i < Facet::kNodes; ++i)
    for (int c = 0; c < Facet::kSpaceDim; ++c) x[(1 + i) * Facet::kSpaceDim + c] = g.master[i][c];
  return x;
}

/// Central differences of the residual: K_FD(:, j) = (r(x + h e_j) − r(x − h e_j)) / 2h.
template <class Facet>
Matrix<kDofs<Facet>, kDofs<Facet>> finiteDifferenceTangent(const NodeToFacetContact<Facet>& element,
                                                             const NodeToFacetGeometry<Facet>& g, int facet,
                                                             const ContactHistory<Facet::kSurfaceDim>& committed,
                                                             double h, double facetLength = 0.0,
                                                             const ContactPoint& point = ContactPoint::projection(),
                                                             const CommittedApproach<Facet::kSurfaceDim>& approach = {}) {
  constexpr int n = kDofs<Facet>;
  Matrix<n, n> k;
  const auto x = toDofs(g);
  for (int j = 0; j < n; ++j) {
    auto plus = x;
    auto minus = x;
    plus[j] += h;
    minus[j] -= h;
    const auto rp = element.evaluate(fromDofs<Facet>(plus), facet, committed, facetLength, SlipTangent::consistent(),
                                     point, approach).residual;
    const auto rm = element.evaluate(fromDofs<Facet>(minus), facet, committed, facetLength, SlipTangent::consistent(),
                                     point, approach).residual;
    for (int i = 0; i < n; ++i) k(i, j) = (rp[i] - rm[i]) / (2.0 * h);
  }
  return k;
}

/// The 3D element tests' 4-node faces on (0,0)–(2,2): flat in z = 0, and warped off that plane.
using Quad4Face = std::array<Vector<3>, 4>;
inline const Quad4Face kFlatFace{{{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {2.0, 2.0, 0.0}, {0.0, 2.0, 0.0}}};
inline const Quad4Face kWarpedFace{{{0.0, 0.0, 0.0}, {2.0, 0.1, 0.4}, {2.2, 2.0, -0.1}, {-0.1, 1.9, 0.3}}};

/// A committed state in contact on `facet` at ξ_n with traction t_n (stick unless said), and the slip
/// accumulated so far.
template <int S>
ContactHistory<S> committedHistory(int facet, Vector<S> xi, Vector<S> traction,
                                   ContactStatus status = ContactStatus::Stick, double slip = 0.0) {
  return {facet, xi, traction, status, slip};  // ContactHistory's members in their declared order
}

/// `check(law, element)` for each law of `laws` (anything with a `parameters` member) with its element on
/// Facet, in order.
template <class Facet, class Laws, class Check>
void forEachLaw(const Laws& laws, Check check) {
  for (const auto& law : laws) {
    const NodeToFacetContact<Facet> element(law.parameters);
    check(law, element);
  }
}

/// The 3D tangent checks past a face's boundary: `check(law, element, committed, faceName, face)` for every
/// law of kLaws on the flat and the warped face, from a committed stick state at ξ_n = (0.8, 0.1) on facet 3
/// with t_n = (0.02, −0.01); the worst of what `check` returns (relative errors).
template <class Check>
double worstOverLawsAndFaces(Check check) {
  double worst = 0.0;
  const auto committed = committedHistory<2>(3, {0.8, 0.1}, {0.02, -0.01});
  forEachLaw<Quad4Facet>(kLaws, [&](const Law& law, const NodeToFacetContact<Quad4Facet>& element) {
    for (const auto& [name, face] : {std::pair{"flat", kFlatFace}, std::pair{"warped", kWarpedFace}})
      worst = std::max(worst, check(law, element, committed, std::string(name), face));
  });
  return worst;
}

/// The laws of the slip-tolerance tangent checks: ε_T = μ|t_N|/(s L) with its ∂t_T/∂t_N term, stick
/// (s = 1: s L = 4 exceeds every slip of the configurations) and slip (s = 0.005), capped or not.
struct SlipToleranceCase {
  const char* name;
  ContactLawParameters parameters;
  ContactStatus expected;
};
inline const SlipToleranceCase kSlipToleranceCases[] = {
    {"stick", {1e3, 0.0, 0.3, 1.0}, ContactStatus::Stick},
    {"stick_capped", {1e3, 1e-3, 0.3, 1.0}, ContactStatus::Stick},
    {"slip", {1e3, 0.0, 0.3, 0.005}, ContactStatus::Slip},
    {"slip_capped", {1e3, 300.0, 0.3, 0.005}, ContactStatus::Slip},
};
/// The facet length L of those checks.
constexpr double kSlipToleranceFacetLength = 4.0;

/// The element's tangential penalty under a slip-tolerance law at penetration `gap`: μ ε_N |g_N|/(s L),
/// capped by the law's ε_T when it has one.
inline void expectSlipTolerancePenalty(double tangentialPenalty, const SlipToleranceCase& c, double gap) {
  const double pressurePenalty = 0.3 * 1e3 * std::abs(gap) / (c.parameters.slipTolerance * kSlipToleranceFacetLength);
  const double cap = c.parameters.tangentialPenalty;
  EXPECT_NEAR(tangentialPenalty, cap > 0.0 ? std::min(cap, pressurePenalty) : pressurePenalty, 1e-9 * pressurePenalty);
}

template <int N>
double relativeDifference(const Matrix<N, N>& a, const Matrix<N, N>& b);

/// An element's tangent against central differences: the relative difference ‖K − K_FD‖/‖K_FD‖,
/// printed with its label and expected below `tolerance`.
template <int N>
double expectTangentClose(const Matrix<N, N>& tangent, const Matrix<N, N>& fd, double tolerance, const std::string& label) {
  const double error = relativeDifference(tangent, fd);
  std::printf("[ FD       ] %-44s ‖K − K_FD‖/‖K_FD‖ = %.2e\n", label.c_str(), error);
  EXPECT_LT(error, tolerance) << label;
  return error;
}

/// The consistent tangent of the element at `point` of facet 3 (no facet length) against central
/// differences of its residual, labelled `what`: the relative difference, expected below kFdTolerance.
template <class Facet>
double expectTangentAtPointClose(const NodeToFacetContact<Facet>& element, const NodeToFacetGeometry<Facet>& g,
                                 const ContactHistory<Facet::kSurfaceDim>& committed, const ContactPoint& point,
                                 const std::string& what) {
  const auto r = element.evaluate(g, 3, committed, 0.0, SlipTangent::consistent(), point);
  return expectTangentClose(r.tangent, finiteDifferenceTangent(element, g, 3, committed, kFdStep, 0.0, point),
                            kFdTolerance, what);
}

/// Several such comparisons, the worst kept.
struct TangentCheck {
  double tolerance;
  double worst = 0.0;
  template <int N>
  void expectClose(const Matrix<N, N>& tangent, const Matrix<N, N>& fd, const std::string& label) {
    worst = std::max(worst, expectTangentClose(tangent, fd, tolerance, label));
  }
  void printWorst(const char* what) const { std::printf("[ FD       ] %s: worst relative error %.2e\n", what, worst); }
};

/// The slip-tolerance tangent check of a facet: every law of kSlipToleranceCases at each configuration
/// (a `name` and a penetration `gap`), at that penetration and at 2.5e-4 of it (a nearly unloaded node).
/// `inContactAt(configuration, g_N)` gives the geometry and the committed history there (on its facet),
/// the status is the law's, the tangential penalty μ ε_N |g_N|/(s L) (capped), and the tangent that of
/// central differences with a step well below the penetration, to `tolerance`.
template <class Facet, class Configurations, class InContactAt>
void checkSlipToleranceTangents(const Configurations& configurations, const InContactAt& inContactAt, double tolerance,
                                const std::string& label) {
  TangentCheck check{tolerance};
  for (const SlipToleranceCase& c : kSlipToleranceCases) {
    const NodeToFacetContact<Facet> element(c.parameters);
    for (const double gapScale : {1.0, 2.5e-4}) {
      for (const auto& conf : configurations) {
        SCOPED_TRACE(std::string(c.name) + " / " + conf.name + " / gap x " + std::to_string(gapScale));
        const double gap = conf.gap * gapScale;
        const auto [g, committed] = inContactAt(conf, gap);
        const auto r = element.evaluate(g, committed.segment, committed, kSlipToleranceFacetLength);
        ASSERT_EQ(r.status, c.expected);
        expectSlipTolerancePenalty(r.friction.tangentialPenalty, c, gap);
        const double h = 1e-3 * std::min(1e-3, std::abs(gap));  // the FD must not open the contact
        check.expectClose(r.tangent,
                          finiteDifferenceTangent(element, g, committed.segment, committed, h, kSlipToleranceFacetLength),
                          "slip tolerance " + std::string(c.name) + " " + conf.name + " g_N = " + std::to_string(gap));
      }
    }
  }
  check.printWorst((label + " slip tolerance").c_str());
}

template <int N>
double relativeDifference(const Matrix<N, N>& a, const Matrix<N, N>& b) {
  Matrix<N, N> d = a;
  addScaled(d, -1.0, b);
  return frobeniusNorm(d) / frobeniusNorm(b);
}

template <int N>
double asymmetry(const Matrix<N, N>& a) {
  Matrix<N, N> d = a;
  addScaled(d, -1.0, transpose(a));
  return frobeniusNorm(d) / frobeniusNorm(a);
}

/// Gaussian elimination with partial pivoting.
template <int N>
Vector<N> solve(Matrix<N, N> a, Vector<N> b) {
  for (int c = 0; c < N; ++c) {
    int pivot = c;
    for (int r = c + 1; r < N; ++r)
      if (std::abs(a(r, c)) > std::abs(a(pivot, c))) pivot = r;
    for (int k = 0; k < N; ++k) std::swap(a(c, k), a(pivot, k));
    std::swap(b[c], b[pivot]);
    for (int r = c + 1; r < N; ++r) {
      const double f = a(r, c) / a(c, c);
      for (int k = c; k < N; ++k) a(r, k) -= f * a(c, k);
      b[r] -= f * b[c];
    }
  }
  Vector<N> x{};
  for (int r = N - 1; r >= 0; --r) {
    double s = b[r];
    for (int k = r + 1; k < N; ++k) s -= a(r, k) * x[k];
    x[r] = s / a(r, r);
  }
  return x;
}

}  // namespace contessa::contact::testing

// The names every element test writes with: cc for the contact package, ct for this fixture, and the
// status and vector types each of them uses.
namespace cc = contessa::contact;
namespace ct = contessa::contact::testing;
using cc::ContactStatus;
using cc::Vector;
