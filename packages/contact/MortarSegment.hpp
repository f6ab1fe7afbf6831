#pragma once
// The mortar integral of one slave segment against one master segment (2D): segmentation and the
// weighted gaps g̃_a = ∫ N_a g dΓ of its two slave nodes over the part of the slave segment the master
// segment covers (theory-contact.md, "Mortar", eq. M1–M4). Written once as a template on the number type
// and evaluated with nested dual numbers (MortarDual.hpp) for the exact gradient and Hessian with respect
// to the twelve nodal coordinates: the clip points and the slave normal depend on the nodes, and that
// dependence is differentiated too, with no hand-derived formula.
//
// Normals (theory-contact §13, M1′): each slave node k has the averaged unit normal n_k, the normalised sum
// of the unit normals of its (one or two) slave segments, and a slave point ξ the interpolated normal
// n(ξ) = N_0 n_0 + N_1 n_1 (Yang, Laursen & Meng 2005; Popp, Gee & Wall 2009). A master node maps to the
// slave point whose normal passes through it (a quadratic in ξ): that is the segmentation. On a flat slave
// surface every n_k is the segment normal and this is the projection along n_s (Puso & Laursen 2004 §3);
// on a curved one the neighbouring slave segments see the master without gap or overlap (with the
// segment normals, the master near a slave node is seen twice or not at all). The gap itself is measured
// along the master segment's normal (M3′, MortarSegment.cpp says why). The nodal normals depend on the
// neighbouring slave nodes, so a segment pair depends on six nodes: its two slave nodes, its two master
// nodes, and the slave nodes beyond each end.
#include <array>
#include <vector>

#include "contact/MortarSlipVariation.hpp"
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
  /// Weighted slip increments Δũ_a = ∫ N_a t_m · (Δx_s(ξ) − Δx_m(η(ξ))) dΓ_0 (eq. M9), when the committed
  /// positions are given (friction), else 0.
  std::array<T, 2> weightedSlip{};
  /// With committed positions and derivatives (T a HessianDual): the virtual slips (MortarSlipVariation.hpp).
  SlipVariationSum<T> slipVariation;
};

/// The committed positions of the pair's slave and master nodes (entries 0–7 of SegmentPairCoordinates):
/// where the material points were at the last converged state, for the slip increments.
using SegmentPairCommitted = std::array<double, 8>;

/// The number of coordinates a segment pair depends on: six nodes, two coordinates each.
constexpr int kMortarPairCoordinates = 12;

/// The coordinates of a segment pair, in the order of the derivatives: slave node 0, slave node 1
/// (the slave side's orientation: its normal, the right of the direction 0 → 1, points out of the slave
/// body), master node 0, master node 1 (likewise out of the master body), then the slave node beyond
/// slave node 0 and the one beyond slave node 1 (zero and unused where MortarSlaveNeighbours says none).
template <class T>
using SegmentPairCoordinates = std::array<T, kMortarPairCoordinates>;

/// The slave segments beyond the pair's slave segment, which enter the nodal normals: per end a, 0 when
/// slave node a ends the slave surface (its normal is the segment's), else ±1, the sign that makes
/// σ_0 (s_0 − y_0), resp. σ_1 (y_1 − s_1), the neighbour segment's direction 0 → 1 as stored (y_a the
/// neighbour node's coordinates, entries 8–9 and 10–11).
struct MortarSlaveNeighbours {
  std::array<int, 2> orientation{0, 0};
};

/// The integral over the overlap (eq. M1–M4), exact for the linear gap and shape functions (2-point Gauss).
/// The measure is the slave segment's reference length L_0 (dΓ_0 = L_0 dξ): the weighted gaps are then
/// per reference length, as the node-to-segment force is the traction times the reference tributary
/// length, and a uniform gap g gives g̃_a = g A_a exactly (the patch test).
template <class T>
MortarPairGaps<T> integrateSegmentPair(const SegmentPairCoordinates<T>& x, double referenceLength,
                                       const MortarSlaveNeighbours& neighbours,
                                       const SegmentPairCommitted* committed = nullptr);

/// Weighted gaps with their gradient and Hessian with respect to the twelve coordinates.
struct MortarPairDerivatives {
  bool overlaps = false;
  std::array<double, 2> weightedGap{};
  std::array<double, 2> mortarLength{};
  std::array<std::array<double, kMortarPairCoordinates>, 2> gradient{};  ///< ∂g̃_a/∂x_i
  std::array<std::array<double, kMortarPairCoordinates * kMortarPairCoordinates>, 2> hessian{};  ///< ∂²g̃_a/∂x_i∂x_j, row-major
  std::array<double, 2> weightedSlip{};  ///< Δũ_a (with committed positions)
  std::array<std::array<double, kMortarPairCoordinates>, 2> slipGradient{};  ///< ∂Δũ_a/∂x_i
  std::array<std::array<double, kMortarPairCoordinates * kMortarPairCoordinates>, 2> slipHessian{};
  /// With committed positions: the virtual slips B_a = ∂Δũ_a/∂x at a frozen segmentation (the D and M
  /// matrices, what the tangential traction works on) and ∂B_a,i/∂x_j, row-major, not symmetric (eq. M11″).
  std::vector<std::array<double, kMortarPairCoordinates>> slipVariation;
  std::vector<std::array<double, kMortarPairCoordinates * kMortarPairCoordinates>> slipVariationGradient;
};

/// A 2D pair kernel's results `g` on HessianDual<V> numbers (per slave slot a of Slots: the weighted gap, the
/// mortar length and the scalar slip along t_m; the virtual slips with `committed`) into `out` as values,
/// gradients and Hessians over the C coordinates: MortarPairDerivatives and MortarQuadraticSegmentDerivatives.
template <int Slots, int C, int V, class Integrated, class Derivatives>
void extractSegmentPairDerivatives(const Integrated& g, const KernelVariables<C>& variables, bool committed,
                                   Derivatives& out) {
  out.overlaps = g.overlaps;
  for (int a = 0; a < Slots; ++a) {
    out.weightedGap[a] = g.weightedGap[a].v;
    out.mortarLength[a] = g.mortarLength[a].v;
    out.weightedSlip[a] = g.weightedSlip[a].v;
    variables.extract(g.weightedGap[a], out.gradient[a], out.hessian[a]);
    variables.extract(g.weightedSlip[a], out.slipGradient[a], out.slipHessian[a]);
  }
  if (committed) extractSlipVariation<C, V>(g.slipVariation, variables, Slots, 1, out.slipVariation, out.slipVariationGradient);
}

/// The pair's weighted gaps (values only: open nodes, predicted states).
MortarPairGaps<double> segmentPairGaps(const SegmentPairCoordinates<double>& x, double referenceLength,
                                       const MortarSlaveNeighbours& neighbours = {},
                                       const SegmentPairCommitted* committed = nullptr);
/// The pair's weighted gaps differentiated twice (closed nodes: residual and tangent), by the gradient-
/// and-Hessian numbers of MortarDual.hpp (HessianDual). With `masterMotion` (a rigid master: ∂x/∂λ of its
/// four coordinates, entries 4–7), the master's coordinates are not unknowns and are differentiated
/// along that motion only: entry 4 of the gradients and Hessians holds the derivatives along the motion,
/// entries 5–7 are zero (the interface's ∂r/∂λ contracts the master's entries with the motion; nothing
/// else reads them).
MortarPairDerivatives segmentPairDerivatives(const SegmentPairCoordinates<double>& x, double referenceLength,
                                             const MortarSlaveNeighbours& neighbours = {},
                                             const SegmentPairCommitted* committed = nullptr,
                                             const double* masterMotion = nullptr);

}  // namespace contessa::contact
