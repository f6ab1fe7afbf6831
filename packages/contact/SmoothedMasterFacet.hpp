#pragma once
// The C¹-smoothed 2D master segment of `Master Smoothing = Hermite` (docs/theory-contact.md §16): the segment x_a → x_b of a polyline master surface replaced by the cubic Hermite curve through
// x_a and x_b whose end tangents are the central differences of the neighbouring nodes (a Catmull–Rom
// segment). Neighbouring segments share their end points and their end tangents, so the surface and its
// normal are continuous across the master nodes: the smoothing of Wriggers, Krstulovic-Opara and Korelc
// (Acta Mech. 2001) and Padmanabhan and Laursen (FEAD 2001), with the tangents taken from the nodes
// rather than from averaged normals, so that x̄(ξ) stays linear in the nodal positions and the facet is one
// more traits class of MasterFacet.hpp (four nodes, cubic shape functions) for the unchanged projection and
// node-to-facet element (eq. 1–27).
//
// Why it matters (docs/verification-contact.md §8): on a faceted master the normal at a fixed point of
// space turns with the facet's nodes, so in gross slip under a convex slave a rotation of the master's
// surface about the slave's centre of curvature meets the contact pressure as a follower load, with the
// negative stiffness −(|F|/R)(I − r̂ r̂ᵀ) per contact node; on a smooth master that represents the circle the
// normal at a fixed point does not turn under that rotation (the curve maps onto itself) and the term is
// gone to the order of the interpolation error (what is left is the continuum's own term, §16).
#include "contact/MasterFacet.hpp"

#include <type_traits>

namespace contessa::contact {

/// Smoothed master segment in 2D, nodes [x_p, x_a, x_b, x_n]: the previous node, the segment's two ends
/// and the next node along the master surface (SmoothedMaster.cpp builds them from the side set's
/// segments; at a free end of the surface the missing neighbour is the end node itself). ξ ∈ [−1, 1] runs
/// from x_a to x_b, s = (1 + ξ)/2:
///   x̄(s) = h00 x_a + h01 x_b + h10 m_a + h11 m_b,   m_a = (x_b − x_p)/2,  m_b = (x_n − x_a)/2,
/// with the cubic Hermite basis h00 = 2s³ − 3s² + 1, h10 = s³ − 2s² + s, h01 = −2s³ + 3s², h11 = s³ − s²,
/// i.e. H_p = −h10/2, H_a = h00 − h11/2, H_b = h01 + h10/2, H_n = h11/2 (Σ H_i = 1). dx̄/ds at x_a is m_a
/// on this segment and on the previous one alike: C¹ across every interior node. Normal convention
/// SegmentFacet's (the master body on the left of x_a → x_b).
struct HermiteLine4Facet : SegmentFacet<4> {
  /// H_i as the combination of the Hermite basis (h00, h10, h01, h11) above.
  static constexpr std::array<std::array<double, 4>, kNodes> kBasis{{{0.0, -0.5, 0.0, 0.0},
                                                                    {1.0, 0.0, 0.0, -0.5},
                                                                    {0.0, 0.5, 1.0, 0.0},
                                                                    {0.0, 0.0, 0.0, 0.5}}};

  /// The k-th derivative in ξ of H_i: the basis' k-th s-derivatives times (ds/dξ)^k = 2^−k.
  static Vector<kNodes> derivative(double xi, int k) {
    const double s = 0.5 * (1.0 + xi);
    std::array<double, 4> h{};  // d^k/ds^k of h00, h10, h01, h11
    switch (k) {
      case 0: h = {2 * s * s * s - 3 * s * s + 1, s * s * s - 2 * s * s + s, -2 * s * s * s + 3 * s * s, s * s * s - s * s}; break;
      case 1: h = {6 * s * s - 6 * s, 3 * s * s - 4 * s + 1, -6 * s * s + 6 * s, 3 * s * s - 2 * s}; break;
      case 2: h = {12 * s - 6, 6 * s - 4, -12 * s + 6, 6 * s - 2}; break;
      default: h = {12.0, 6.0, -12.0, 6.0}; break;
    }
    const double scale = k == 0 ? 1.0 : k == 1 ? 0.5 : k == 2 ? 0.25 : 0.125;
    Vector<kNodes> out{};
    for (int i = 0; i < kNodes; ++i)
      for (int j = 0; j < 4; ++j) out[i] += scale * kBasis[i][j] * h[j];
    return out;
  }

  static Vector<kNodes> shapeFunctions(const SurfaceCoords& xi) { return derivative(xi[0], 0); }
  static First shapeDerivatives(const SurfaceCoords& xi) { return asFirst(derivative(xi[0], 1)); }
  static Second shapeSecondDerivatives(const SurfaceCoords& xi) { return asSecond(derivative(xi[0], 2)); }
  /// Cubic in ξ: constant third derivatives (the element's second variation of ξ̄ uses them, kCubic).
  static Third shapeThirdDerivatives(const SurfaceCoords& xi) { return asThird(derivative(xi[0], 3)); }

  /// The segment itself, x_a – x_b (the neighbours are not on its boundary).
  static constexpr std::array<std::array<int, 2>, 1> boundarySegments() { return {{{1, 2}}}; }
  /// Its chord: the projection's start points, the swept crossing test (SmoothedMaster.cpp).
  static constexpr int kPieces = 1;
  static constexpr std::array<std::array<int, kSpaceDim>, kPieces> flatPieces() { return {{{1, 2}}}; }

  /// The neighbours sit one parameter length beyond the ends (nominally: the curve does not pass them).
  static SurfaceCoords nodeCoords(int i) { return {2.0 * i - 3.0}; }
  static constexpr bool kAffine = false;
  static constexpr bool kCubic = true;
  /// 3 Gauss points (a master facet only; slave sides are never smoothed).
  static std::array<SurfaceRulePoint<1>, 3> quadrature() { return gaussRuleOnSquare<1, 3>(); }
};

/// Local index (in the facet's node order) of end `end` (0: ξ = −1, 1: ξ = +1) of a 2D master segment:
/// nodes 0 and 1 of Line2Facet and Line3Facet, 1 and 2 of HermiteLine4Facet.
template <class Facet>
constexpr int segmentEndNode(int end) {
  return std::is_same_v<Facet, HermiteLine4Facet> ? end + 1 : end;
}

}  // namespace contessa::contact
