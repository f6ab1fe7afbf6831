#pragma once
// The mortar integral of one slave segment against one master segment (2D): segmentation and the
// weighted gaps g̃_a = ∫ N_a g dΓ of its two slave nodes over the part of the slave segment the master
// segment covers (theory-contact.md, "Mortar", eq. M1–M4). Written once as a template on the number type
// and evaluated with nested dual numbers (MortarDual.hpp) for the exact gradient and Hessian with respect
// to the eight nodal coordinates: the clip points and the slave normal depend on the nodes, and that
// dependence is differentiated too, with no hand-derived formula.
//
// Segmentation along the slave segment's own normal (piecewise constant over the slave surface): every
// point of the slave segment is projected along n_s onto the master line, so the master segment's nodes
// map to slave coordinates ξ by orthogonal projection on the slave line (an affine map between the
// lines), and the segment pair is clipped in ξ ∈ [0, 1] (Puso & Laursen 2004 §3; Yang, Laursen & Meng
// 2005 use the averaged nodal normals instead, which coincide with it on a flat interface).
#include <array>

#include "contact/SmallMatrix.hpp"

namespace contessa::contact {

/// Which pairs count: the master segment must face the slave (n_m · n_s ≤ −kMortarMinFacing, n_m pointing
/// out of the master body) and lie within one segment size of the slave segment (neither far behind it,
/// which would be the other side of a thin body, nor far in front, where it carries no force).
constexpr double kMortarMinFacing = 0.5;
/// Clip points within this fraction of the slave segment of one of its ends are taken at the end.
constexpr double kMortarSnap = 1e-9;

/// Weighted gaps of the two slave nodes of one segment pair, and the mortar lengths ∫ N_a dΓ_0 over the
/// overlap (their sum is the overlap's reference length).
template <class T>
struct MortarPairGaps {
  bool overlaps = false;
  std::array<T, 2> weightedGap{};
  std::array<T, 2> mortarLength{};
};

/// The coordinates of a segment pair, in the order of the derivatives: slave node 0, slave node 1
/// (the slave side's orientation: its normal, the right of the direction 0 → 1, points out of the slave
/// body), master node 0, master node 1 (likewise out of the master body).
template <class T>
using SegmentPairCoordinates = std::array<T, 8>;

/// The integral over the overlap (eq. M1–M4), exact for the linear gap and shape functions (2-point Gauss).
/// The measure is the slave segment's reference length L_0 (dΓ_0 = L_0 dξ): the weighted gaps are then
/// per reference length, as the node-to-segment force is the traction times the reference tributary
/// length, and a uniform gap g gives g̃_a = g A_a exactly (the patch test).
template <class T>
MortarPairGaps<T> integrateSegmentPair(const SegmentPairCoordinates<T>& x, double referenceLength);

/// Weighted gaps with their gradient and Hessian with respect to the eight coordinates.
struct MortarPairDerivatives {
  bool overlaps = false;
  std::array<double, 2> weightedGap{};
  std::array<double, 2> mortarLength{};
  std::array<std::array<double, 8>, 2> gradient{};       ///< ∂g̃_a/∂x_i
  std::array<std::array<double, 64>, 2> hessian{};       ///< ∂²g̃_a/∂x_i∂x_j, row-major
};

/// The pair's weighted gaps (values only: open nodes, predicted states).
MortarPairGaps<double> segmentPairGaps(const SegmentPairCoordinates<double>& x, double referenceLength);
/// The pair's weighted gaps differentiated twice (closed nodes: residual and tangent).
MortarPairDerivatives segmentPairDerivatives(const SegmentPairCoordinates<double>& x, double referenceLength);

}  // namespace contessa::contact
