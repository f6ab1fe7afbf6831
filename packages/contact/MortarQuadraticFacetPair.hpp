#pragma once
// The 3D mortar integral of a facet pair with a quadratic face on either side: a 6-node triangle (Tet10 and
// Wedge15 faces), an 8-node serendipity quadrilateral (Hex20, Wedge15) or a 9-node Lagrange one (Hex27);
// the other side Tri3, Quad4 or quadratic: theory-contact.md §13, "Quadratic faces" (eq. M18–M20).
//
// Segmentation on flat pieces (Puso, Laursen & Solberg 2008 §3): a quadratic face is cut into flat pieces
// through its nodes — a Tri6 into its four triangles (corner–mid–mid three times and the middle one,
// Tri6Facet::flatPieces), a Quad8 into its four corner triangles and the quadrilateral of its mid-edge
// nodes (Quad8Facet::tributaryPieces), a Quad9 into its four quarters (corner, mid, centre, mid) — and each
// slave piece is projected, clipped and triangulated against each master piece exactly as a linear facet
// pair (MortarFacetPair.hpp, eq. M13–M15; a 4-node piece as a Quad4). A Gauss point maps back to the
// pieces' local coordinates and from them, affinely, to the parent coordinates ξ of the slave face and η
// of the master face. There the quadratic geometry is evaluated, x_s(ξ) = Σ N_a(ξ) x_a, x_m(η), n_m(η),
// so that the nodal forces are the consistent loads ∫ N_a p dA of the face the element sees (a Tri6's
// corners take none of a uniform pressure, a Quad8's corners −A/12), and the gap g = (x_s − x_m) · n_m is
// weighted with the pieces' linear (3-node piece) or bilinear (4-node piece) functions Φ_a (eq. M18),
// which are non-negative — a positive gap everywhere gives a positive weighted gap, which the quadratic
// N_a and the modified quadratic bases of Popp et al. 2012, negative in parts of the face, do not — and
// whose nodal areas ∫ Φ_a dA are positive at every node (flat faces: Tri6 A/12 and A/4, Quad8 A/24 and
// 5A/24, Quad9 A/16, A/8 and A/4 at a corner, a mid-edge node, the centre); a standard basis gives 0 at a
// Tri6 corner and −A/12 at a Quad8 corner, where a penalty pressure ε g̃_a / A_a could not be formed. Φ is
// a partition of unity, so Σ_a Φ_a p_a reproduces a uniform pressure.
//
// As MortarFacetPair, written once on the number type and differentiated twice with nested dual numbers
// over the pair's coordinates: Slots node slots per side (6 when the larger face is a Tri6, 8 a Quad8,
// 9 a Quad9; a smaller face leaves the last slots unused).
#include <array>
#include <vector>

#include "contact/MortarFacetPair.hpp"  // MortarFacetPairShape

namespace contessa::contact {

/// Node slots per side of a pair whose larger face is a Tri6 (the Tri3 and Quad4 sides leave the last
/// unused); the 8- and 9-slot layouts take Quad8 and Quad9 faces.
constexpr int kQuadraticFacetNodes = 6;
/// The most nodes a mortar face has (a Quad9) and the most reference measures of its flat pieces (a Quad9's
/// four 4-node pieces, three each: mortarFaceMeasures).
constexpr int kMaxMortarFaceNodes = 9;
constexpr int kMaxMortarFaceMeasures = 12;
constexpr int kQuadraticFacetPairCoordinates = 3 * 2 * kQuadraticFacetNodes;
template <class T, int Slots = kQuadraticFacetNodes>
using QuadraticFacetPairCoordinates = std::array<T, 3 * 2 * Slots>;

/// The committed positions of the pair's nodes, in the layout of QuadraticFacetPairCoordinates: where the
/// material points were at the last converged state, the start of the slip increments (eq. M9′, M21).
template <int Slots>
using QuadraticFacetPairCommitted = std::array<double, 3 * 2 * Slots>;

template <class T, int Slots = kQuadraticFacetNodes>
struct MortarQuadraticFacetPairGaps {
  bool overlaps = false;
  std::array<T, Slots> weightedGap{};  ///< g̃_a = ∫ Φ_a g dA_0 (eq. M19)
  std::array<T, Slots> mortarArea{};   ///< ∫ Φ_a dA_0 over the overlap
  /// Weighted slip increments Δũ_a = ∫ Φ_a (I − n_m ⊗ n_m)(Δx_s(ξ) − Δx_m(η)) dA_0 (eq. M21), with the
  /// weights of the weighted gaps, a 3-vector per node, when the committed positions are given (friction),
  /// else 0; as MortarFacetPairGaps::weightedSlip.
  std::array<std::array<T, 3>, Slots> weightedSlip{};
  /// With committed positions and derivatives: the virtual slips (MortarSlipVariation.hpp, eq. M11″).
  SlipVariationSum<T> slipVariation;
};

/// The integral over the overlap. The measure is the reference one, as the linear kernel's A_0 / A_projected
/// (eq. M17): for a quadratic slave face per flat piece (shape.slavePieceAreas, mortarFacetPieceMeasures), a
/// triangle's reference area over its current one, a 4-node piece's reference Jacobian J_0(l) over its
/// current one J(l) at the point (eq. M20); for a 3- or 4-node slave face referenceArea (its area, a Quad4's
/// |d_1 × d_2| / 2) over the current one.
template <class T, int Slots>
MortarQuadraticFacetPairGaps<T, Slots> integrateQuadraticFacetPair(const QuadraticFacetPairCoordinates<T, Slots>& x,
                                                                   double referenceArea, const MortarFacetPairShape& shape,
                                                                   const QuadraticFacetPairCommitted<Slots>* committed = nullptr);

template <int Slots>
struct MortarQuadraticPairDerivatives {
  static constexpr int kCoordinates = 3 * 2 * Slots;
  bool overlaps = false;
  std::array<double, Slots> weightedGap{};
  std::array<double, Slots> mortarArea{};
  std::array<std::array<double, kCoordinates>, Slots> gradient{};
  std::array<std::array<double, kCoordinates * kCoordinates>, Slots> hessian{};  ///< row-major
  /// With committed positions (friction): Δũ_a's components c (index 3 a + c), their gradients and
  /// Hessians; empty without (a frictionless pair carries no slip derivatives).
  std::array<std::array<double, 3>, Slots> weightedSlip{};
  std::vector<std::array<double, kCoordinates>> slipGradient;
  std::vector<std::array<double, kCoordinates * kCoordinates>> slipHessian;
  /// The virtual slips and their derivatives, as MortarFacetPairDerivatives'.
  std::vector<std::array<double, kCoordinates>> slipVariation;
  std::vector<std::array<double, kCoordinates * kCoordinates>> slipVariationGradient;
};
using MortarQuadraticFacetPairDerivatives = MortarQuadraticPairDerivatives<kQuadraticFacetNodes>;

/// The pair's weighted gaps (values only); overloads of MortarFacetPair's on the quadratic layouts (6, 8
/// and 9 slots). With `committed` (friction) the weighted slip increments too.
MortarQuadraticFacetPairGaps<double, 6> facetPairGaps(const QuadraticFacetPairCoordinates<double, 6>& x,
                                                      double referenceArea, const MortarFacetPairShape& shape,
                                                      const QuadraticFacetPairCommitted<6>* committed = nullptr);
MortarQuadraticFacetPairGaps<double, 8> facetPairGaps(const QuadraticFacetPairCoordinates<double, 8>& x,
                                                      double referenceArea, const MortarFacetPairShape& shape,
                                                      const QuadraticFacetPairCommitted<8>* committed = nullptr);
MortarQuadraticFacetPairGaps<double, 9> facetPairGaps(const QuadraticFacetPairCoordinates<double, 9>& x,
                                                      double referenceArea, const MortarFacetPairShape& shape,
                                                      const QuadraticFacetPairCommitted<9>* committed = nullptr);
/// The pair's weighted gaps differentiated twice; with masterMotion (a rigid master's ∂x/∂λ, its 3 × Slots
/// entries) only along that motion in the master's coordinates (MortarFacetPair.hpp says why); with
/// `committed` (friction) the slip increments' too.
MortarQuadraticPairDerivatives<6> facetPairDerivatives(const QuadraticFacetPairCoordinates<double, 6>& x,
                                                       double referenceArea, const MortarFacetPairShape& shape,
                                                       const double* masterMotion = nullptr,
                                                       const QuadraticFacetPairCommitted<6>* committed = nullptr);
MortarQuadraticPairDerivatives<8> facetPairDerivatives(const QuadraticFacetPairCoordinates<double, 8>& x,
                                                       double referenceArea, const MortarFacetPairShape& shape,
                                                       const double* masterMotion = nullptr,
                                                       const QuadraticFacetPairCommitted<8>* committed = nullptr);
MortarQuadraticPairDerivatives<9> facetPairDerivatives(const QuadraticFacetPairCoordinates<double, 9>& x,
                                                       double referenceArea, const MortarFacetPairShape& shape,
                                                       const double* masterMotion = nullptr,
                                                       const QuadraticFacetPairCommitted<9>* committed = nullptr);

/// The node slots a pair of faces of these node counts takes (6, 8 or 9: the larger face's, a Quad8 with
/// a Quad9 9).
constexpr int quadraticPairSlots(int slaveNodes, int masterNodes) {
  return slaveNodes > masterNodes ? slaveNodes : masterNodes;
}
/// The flat pieces of a face of `nodes` nodes (1 for a Tri3 or Quad4, 4 for a Tri6 or Quad9, 5 for a
/// Quad8).
constexpr int mortarFacePieces(int nodes) { return nodes == 6 || nodes == 9 ? 4 : nodes == 8 ? 5 : 1; }
/// The reference measures the deck stores per slave face (InterfaceSpec::slaveFacetMeasures): one for a
/// linear face (its area); for a quadratic face a triangle piece's area and a 4-node piece's three Jacobian
/// coefficients (eq. M20): 4 for a Tri6, 4 + 3 for a Quad8, 4 × 3 for a Quad9.
constexpr int mortarFaceMeasures(int nodes) { return nodes == 6 ? 4 : nodes == 8 ? 7 : nodes == 9 ? 12 : 1; }

/// A face's nodes (3, 4, 6, 8 or 9 of them; Tri6 ordered as Tri6Facet: corners, then mid-edge 0–1, 1–2,
/// 2–0; Quad8 and Quad9 as Quad9Facet: corners, mid-edge 0–1, 1–2, 2–3, 3–0, then the centre).
using MortarFaceNodes = std::array<std::array<double, 3>, kMaxMortarFaceNodes>;
/// A slave face's reference measure for the kernels: the summed areas of its flat pieces (a Tri3's area,
/// a Quad4's |d_1 × d_2| / 2, a quadratic face's pieces').
double mortarFacetReferenceArea(const MortarFaceNodes& x, int nodes);
/// A quadratic face's reference measures, mortarFaceMeasures(nodes) of them in the kernel's order of its
/// pieces: a triangle piece's area; a 4-node piece's projected Jacobian J(l) = (x_,l1 × x_,l2) · n_0 =
/// j_0 + j_1 l_1 + j_2 l_2 on [−1, 1]² as (j_0, j_1, j_2) (affine in l for a bilinear piece). A 3- or 4-node
/// face's area first.
std::array<double, kMaxMortarFaceMeasures> mortarFacetPieceMeasures(const MortarFaceNodes& x, int nodes);
/// A face's flat piece: its node count (3 or 4) and the face's local nodes, counter-clockwise about the
/// face's normal (a Tri3 or Quad4 is its own one piece; the quadratic faces' pieces as described above).
struct MortarFacePiece {
  int count = 0;
  std::array<int, 4> node{};
};
/// Piece i (0 ≤ i < mortarFacePieces(nodes)) of a face of `nodes` nodes, in the order of its measures.
MortarFacePiece mortarFacePiece(int nodes, int i);
/// Its nodes' mortar areas ∫ Φ_a dA_0 over the whole face (the A_a of p_a = ε_N ⟨−g̃_a⟩ / A_a), integrated
/// as the kernel does on the flat pieces.
std::array<double, kMaxMortarFaceNodes> mortarFacetNodeAreas(const MortarFaceNodes& x, int nodes);

}  // namespace contessa::contact
