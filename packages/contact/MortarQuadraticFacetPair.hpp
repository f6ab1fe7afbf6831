#pragma once
// The 3D mortar integral of a facet pair with a 6-node triangle on either side (Tet10 and Wedge15 faces;
// the other side Tri3, Quad4 or Tri6): theory-contact.md §13, "Quadratic faces" (eq. M18–M20).
//
// Segmentation on flat pieces (Puso, Laursen & Solberg 2008 §3): a Tri6 is cut into its four flat
// triangles (corner–mid–mid three times and the middle one, Tri6Facet::flatPieces); each slave piece is
// projected, clipped and triangulated against each master piece exactly as a linear facet pair
// (MortarFacetPair.hpp, eq. M13–M15). A Gauss point maps back to the pieces' local coordinates and from
// them, affinely, to the parent coordinates ξ of the slave face and η of the master face. There the
// quadratic geometry is evaluated, x_s(ξ) = Σ N_a(ξ) x_a, x_m(η), n_m(η), so that the nodal forces are the
// consistent loads ∫ N_a p dA of the face the element sees (a Tri6's corners take none of a uniform
// pressure), and the gap g = (x_s − x_m) · n_m is weighted with the pieces' linear functions Φ_a (eq. M18:
// on each flat piece the hat functions of its three nodes), which are non-negative — a positive gap
// everywhere gives a positive weighted gap, which the quadratic N_a and the modified quadratic bases of
// Popp et al. 2012, negative in parts of the face, do not — and whose nodal areas ∫ Φ_a dA are A/12 at a
// corner and A/4 at a mid-edge node of a flat face (the standard basis gives 0 at a corner: a penalty
// pressure ε g̃_a / A_a could not be formed). Φ is a partition of unity, so Σ_a Φ_a p_a reproduces a
// uniform pressure.
//
// As MortarFacetPair, written once on the number type and differentiated twice with nested dual numbers
// over the pair's 36 coordinates (6 slave and 6 master nodes).
#include <array>

#include "contact/MortarFacetPair.hpp"  // MortarFacetPairShape

namespace contessa::contact {

/// Node slots per side of a quadratic pair (a Tri6's six; Tri3 and Quad4 sides leave the last unused).
constexpr int kQuadraticFacetNodes = 6;
constexpr int kQuadraticFacetPairCoordinates = 3 * 2 * kQuadraticFacetNodes;
template <class T>
using QuadraticFacetPairCoordinates = std::array<T, kQuadraticFacetPairCoordinates>;

template <class T>
struct MortarQuadraticFacetPairGaps {
  bool overlaps = false;
  std::array<T, kQuadraticFacetNodes> weightedGap{};  ///< g̃_a = ∫ Φ_a g dA_0 (eq. M19)
  std::array<T, kQuadraticFacetNodes> mortarArea{};   ///< ∫ Φ_a dA_0 over the overlap
};

/// The integral over the overlap. The measure is the reference one, as the linear kernel's A_0 / A_projected
/// (eq. M17): for a 6-node slave face per flat piece, shape.slavePieceAreas (mortarFacetPieceAreas) over the
/// current piece's area; for a 3- or 4-node slave face referenceArea (its area, a Quad4's |d_1 × d_2| / 2)
/// over the current one.
template <class T>
MortarQuadraticFacetPairGaps<T> integrateQuadraticFacetPair(const QuadraticFacetPairCoordinates<T>& x,
                                                            double referenceArea, const MortarFacetPairShape& shape);

struct MortarQuadraticFacetPairDerivatives {
  static constexpr int kCoordinates = kQuadraticFacetPairCoordinates;
  bool overlaps = false;
  std::array<double, kQuadraticFacetNodes> weightedGap{};
  std::array<double, kQuadraticFacetNodes> mortarArea{};
  std::array<std::array<double, kCoordinates>, kQuadraticFacetNodes> gradient{};
  std::array<std::array<double, kCoordinates * kCoordinates>, kQuadraticFacetNodes> hessian{};  ///< row-major
};

/// The pair's weighted gaps (values only); overloads of MortarFacetPair's on the quadratic layout.
MortarQuadraticFacetPairGaps<double> facetPairGaps(const QuadraticFacetPairCoordinates<double>& x,
                                                   double referenceArea, const MortarFacetPairShape& shape);
/// The pair's weighted gaps differentiated twice; with masterMotion (a rigid master's ∂x/∂λ, its 18
/// entries) only along that motion in the master's coordinates (MortarFacetPair.hpp says why).
MortarQuadraticFacetPairDerivatives facetPairDerivatives(const QuadraticFacetPairCoordinates<double>& x,
                                                         double referenceArea, const MortarFacetPairShape& shape,
                                                         const double* masterMotion = nullptr);

/// A face's nodes (3, 4 or 6 of them, Tri6 ordered as Tri6Facet: corners, then mid-edge 0–1, 1–2, 2–0).
using MortarFaceNodes = std::array<std::array<double, 3>, kQuadraticFacetNodes>;
/// A slave face's reference measure for the kernels: the summed areas of its flat pieces (a Tri3's area,
/// a Quad4's |d_1 × d_2| / 2, a Tri6's four triangles).
double mortarFacetReferenceArea(const MortarFaceNodes& x, int nodes);
/// A 6-node face's four flat pieces' areas (Tri6Facet::flatPieces order; a 3- or 4-node face's area first).
std::array<double, 4> mortarFacetPieceAreas(const MortarFaceNodes& x, int nodes);
/// Its nodes' mortar areas ∫ Φ_a dA_0 over the whole face (the A_a of p_a = ε_N ⟨−g̃_a⟩ / A_a), integrated
/// as the kernel does on the flat pieces.
std::array<double, kQuadraticFacetNodes> mortarFacetNodeAreas(const MortarFaceNodes& x, int nodes);

}  // namespace contessa::contact
