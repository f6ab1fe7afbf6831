#pragma once
// Shared tools of the contact element tests: dofs ↔ geometry, central-difference tangents, matrix
// measures and a dense solve for the small Newton demonstrations.
#include "contact/NodeToFacetContact.hpp"

#include <cmath>
#include <utility>

namespace contessa::contact::testing {

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
