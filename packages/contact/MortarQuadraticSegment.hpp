#pragma once
// The 2D mortar integral of a segment pair with a 3-node segment on either side (Line3: the sides of Tri6,
// Q8 and Q9 cells), the other side a Line2 or a Line3: theory-contact.md §13.2, "Quadratic segments" (eq.
// M18–M20 in 2D). The construction of the 3D quadratic faces (MortarQuadraticFacetPair.hpp), one idea for
// both dimensions:
//
// Segmentation on flat pieces: a Line3 is cut at its mid-edge node into its two chords (Line3Facet's
// flatPieces, corner–mid and mid–corner), a Line2 is its own piece. Each slave piece is paired with each
// master piece as the linear kernel pairs two segments (MortarSegment.hpp, eq. M2): the master piece's ends
// are projected onto the slave chord along the chord's normal, the clip is where they meet [0, 1]. A Gauss
// point of the clip maps affinely to the slave's parent coordinate ξ, and its projection along the same
// normal onto the master chord affinely to the master's η. There the quadratic geometry is evaluated,
// x_s(ξ) = Σ N_a(ξ) x_a, x_m(η), the master's unit normal n_m(η) and tangent t_m(η), and the gap
// g = (x_s − x_m) · n_m (along the master's normal, as M3′) is weighted with the slave piece's hat
// functions Φ_a (1 − l and l on a piece), which are non-negative and a partition of unity: the nodal
// lengths A_a = ∫ Φ_a dΓ_0 are l_0/2, (l_0 + l_1)/2, l_1/2 (the chords' reference lengths), all positive,
// where the quadratic N_a give the corner L/6 and the mid-edge node 2L/3 (still positive in 2D, but a
// positive gap then does not give a positive weighted gap at every node: N_corner < 0 on part of the
// segment). The virtual work Σ_a p_a δg̃_a = ∫ (Σ_a p_a Φ_a) Σ_b N_b δx_b · n_m dΓ_0 puts on each node the
// consistent load of the interpolated pressure: a uniform pressure gives L/6, 2L/3, L/6 on a straight
// slave segment, the loads under which a Q8 or Q9 cell has a uniform stress (the patch test).
//
// As MortarSegment, written once on the number type and differentiated twice with nested dual numbers over
// the pair's twelve coordinates. No averaged nodal normals (the linear 2D kernel's M1′): each slave piece
// projects along its own normal, as the 3D pieces do.
#include <array>
#include <vector>

#include "contact/MortarFacetPair.hpp"  // MortarFacetPairShape
#include "contact/MortarSlipVariation.hpp"

namespace contessa::contact {

/// Node slots per side: a Line3's three (corner 0, corner 1, mid-edge node, as Line3Facet); a Line2 leaves
/// the third unused.
constexpr int kQuadraticSegmentNodes = 3;
constexpr int kQuadraticSegmentPairCoordinates = 2 * 2 * kQuadraticSegmentNodes;
/// The pair's coordinates: the slave segment's nodes (slots 0–2), then the master's (slots 3–5), x and y
/// each; both sides oriented as Line2Facet (the body on the left of the direction node 0 → node 1).
template <class T>
using QuadraticSegmentPairCoordinates = std::array<T, kQuadraticSegmentPairCoordinates>;
/// The committed positions of the pair's nodes in that layout (friction: the slip increments' start).
using QuadraticSegmentPairCommitted = std::array<double, kQuadraticSegmentPairCoordinates>;

/// The flat pieces of a segment of `nodes` nodes: 2 for a Line3, 1 for a Line2; a slave segment's reference
/// measures (InterfaceSpec::slaveFacetMeasures) are its pieces' reference lengths.
constexpr int mortarSegmentPieces(int nodes) { return nodes == 3 ? 2 : 1; }

template <class T>
struct MortarQuadraticSegmentGaps {
  bool overlaps = false;
  std::array<T, kQuadraticSegmentNodes> weightedGap{};   ///< g̃_a = ∫ Φ_a g dΓ_0
  std::array<T, kQuadraticSegmentNodes> mortarLength{};  ///< ∫ Φ_a dΓ_0 over the overlap
  /// Weighted slip increments Δũ_a = ∫ Φ_a t_m(η) · (Δx_s(ξ) − Δx_m(η)) dΓ_0 (eq. M9 on the quadratic
  /// segments), when the committed positions are given (friction), else 0.
  std::array<T, kQuadraticSegmentNodes> weightedSlip{};
  SlipVariationSum<T> slipVariation;  ///< with committed positions and derivatives (eq. M11″)
};

/// The integral over the overlap. `shape`: the node counts of the slave and master segments (2 or 3) and,
/// in slavePieceAreas, the slave pieces' reference lengths (dΓ_0 = l_0 dl on a piece, l ∈ [0, 1]).
template <class T>
MortarQuadraticSegmentGaps<T> integrateQuadraticSegmentPair(const QuadraticSegmentPairCoordinates<T>& x,
                                                            const MortarFacetPairShape& shape,
                                                            const QuadraticSegmentPairCommitted* committed = nullptr);

/// The weighted gaps and slips with their gradients and Hessians over the twelve coordinates.
struct MortarQuadraticSegmentDerivatives {
  static constexpr int kCoordinates = kQuadraticSegmentPairCoordinates;
  bool overlaps = false;
  std::array<double, kQuadraticSegmentNodes> weightedGap{};
  std::array<double, kQuadraticSegmentNodes> mortarLength{};
  std::array<std::array<double, kCoordinates>, kQuadraticSegmentNodes> gradient{};
  std::array<std::array<double, kCoordinates * kCoordinates>, kQuadraticSegmentNodes> hessian{};  ///< row-major
  std::array<double, kQuadraticSegmentNodes> weightedSlip{};  ///< with committed positions
  std::array<std::array<double, kCoordinates>, kQuadraticSegmentNodes> slipGradient{};
  std::array<std::array<double, kCoordinates * kCoordinates>, kQuadraticSegmentNodes> slipHessian{};
  /// With committed positions: the virtual slips B_a and ∂B_a,i/∂x_j, row-major (MortarSlipVariation.hpp).
  std::vector<std::array<double, kCoordinates>> slipVariation;
  std::vector<std::array<double, kCoordinates * kCoordinates>> slipVariationGradient;
};

/// The pair's values (open nodes, predicted states).
MortarQuadraticSegmentGaps<double> quadraticSegmentPairGaps(const QuadraticSegmentPairCoordinates<double>& x,
                                                            const MortarFacetPairShape& shape,
                                                            const QuadraticSegmentPairCommitted* committed = nullptr);
/// The pair differentiated twice; with `masterMotion` (a rigid master's ∂x/∂λ, its six entries) only along
/// that motion in the master's coordinates (entry 6 holds those derivatives, 7–11 are zero), as
/// segmentPairDerivatives.
MortarQuadraticSegmentDerivatives quadraticSegmentPairDerivatives(const QuadraticSegmentPairCoordinates<double>& x,
                                                                  const MortarFacetPairShape& shape,
                                                                  const QuadraticSegmentPairCommitted* committed = nullptr,
                                                                  const double* masterMotion = nullptr);

/// A segment's nodes (2 or 3 of them, x and y), Line3 ordered as Line3Facet.
using MortarSegmentNodes = std::array<std::array<double, 2>, kQuadraticSegmentNodes>;
/// The local nodes (the ends) of piece i of a segment of `nodes` nodes: a Line3's corner–mid and mid–corner.
std::array<int, 2> mortarSegmentPieceNodes(int nodes, int i);
/// A slave segment's pieces' reference lengths (mortarSegmentPieces(nodes) of them).
std::array<double, 2> mortarSegmentPieceLengths(const MortarSegmentNodes& x, int nodes);
/// Its nodes' mortar lengths ∫ Φ_a dΓ_0 over the whole segment: half of each piece's length at each of its
/// ends (the A_a of p_a = ε_N ⟨−g̃_a⟩ / A_a).
std::array<double, kQuadraticSegmentNodes> mortarSegmentNodeLengths(const MortarSegmentNodes& x, int nodes);

}  // namespace contessa::contact
