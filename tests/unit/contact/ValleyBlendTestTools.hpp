#pragma once
// What the valley-blend tests share (ValleyBlendTest, ValleyBlendFrictionTest): the two valleys they blend
// over, 2D and 3D, and the perturbation of one degree of freedom of the blend's union of facet nodes.
#include <array>
#include <vector>

#include "contact/ValleyBlend.hpp"

namespace contessa::contact::testing {

namespace cc = contessa::contact;

template <class Facet>
using Facets = std::vector<cc::MasterFacetNodes<Facet>>;

template <class Facet>
cc::MasterFacetNodes<Facet> facet(int id, std::array<int, Facet::kNodes> nodes,
                                  std::array<typename Facet::Point, Facet::kNodes> x) {
  cc::MasterFacetNodes<Facet> f;
  f.id = id;
  f.nodes = nodes;
  f.x = x;
  return f;
}

// 2D valley at the origin: a rises to the left, b to the right (slope `rise`), body below (n̄ ≈ +y).
inline Facets<cc::Line2Facet> valley2D(double rise) {
  return {facet<cc::Line2Facet>(0, {10, 11}, {{{0.0, 0.0}, {-1.0, rise}}}),
          facet<cc::Line2Facet>(1, {12, 10}, {{{1.0, rise}, {0.0, 0.0}}})};
}

// 3D valley along the y axis, faces 1 x 1 (a: x < 0, b: x > 0) rising by `rise` at their far sides; `warp`
// lifts one far corner of b (a warped face). Body below (n̄ ≈ +z).
inline Facets<cc::Quad4Facet> valley3D(double rise, double warp, bool rotated = false) {
  using P = cc::Quad4Facet::Point;
  if (rotated)  // b's nodes numbered from another corner: the edge lies at ξ² = −1 on b
    return {facet<cc::Quad4Facet>(0, {20, 21, 22, 23}, {P{-1.0, 0.0, rise}, P{0.0, 0.0, 0.0}, P{0.0, 1.0, 0.0}, P{-1.0, 1.0, rise}}),
            facet<cc::Quad4Facet>(1, {22, 21, 24, 25}, {P{0.0, 1.0, 0.0}, P{0.0, 0.0, 0.0}, P{1.0, 0.0, rise}, P{1.0, 1.0, rise + warp}})};
  return {facet<cc::Quad4Facet>(0, {20, 21, 22, 23}, {P{-1.0, 0.0, rise}, P{0.0, 0.0, 0.0}, P{0.0, 1.0, 0.0}, P{-1.0, 1.0, rise}}),
          facet<cc::Quad4Facet>(1, {21, 24, 25, 22}, {P{0.0, 0.0, 0.0}, P{1.0, 0.0, rise}, P{1.0, 1.0, rise + warp}, P{0.0, 1.0, 0.0}})};
}

/// Moves dof `d` of the blend's union by h in both facets (a shared node moves in both).
template <class Facet>
void perturb(typename Facet::Point& slave, Facets<Facet>& facets, const cc::ValleyBlendResult<Facet>& r,
             const cc::ValleyEdge& e, int d, double h) {
  constexpr int kDim = Facet::kSpaceDim;
  const int block = d / kDim, c = d % kDim;
  if (block == 0) {
    slave[c] += h;
    return;
  }
  const auto [f, i] = r.source[block];
  const std::size_t from = f == 0 ? e.a : e.b, other = f == 0 ? e.b : e.a;
  const int id = facets[from].nodes[i];
  facets[from].x[i][c] += h;
  for (int j = 0; j < Facet::kNodes; ++j)
    if (facets[other].nodes[j] == id) facets[other].x[j][c] += h;
}

}  // namespace contessa::contact::testing
