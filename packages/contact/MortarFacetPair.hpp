#pragma once
// The mortar integral of one slave facet against one master facet (3D; 3- and 4-node facets): the
// segmentation and the weighted gaps g̃_a = ∫ N_a g dA of the slave facet's nodes over the part of the
// slave facet the master facet covers (theory-contact.md §13, "3D segmentation", eq. M13–M17). As the 2D
// segment pair (MortarSegment.hpp), written once as a template on the number type and evaluated with
// nested dual numbers (MortarDual.hpp) for the exact gradient and Hessian with respect to the 24 nodal
// coordinates: the projection plane, the clip polygon's vertices, the Gauss points' parametric
// coordinates on both facets and the master normal all depend on the nodes, and that dependence is
// differentiated to round-off (the full linearisation of the segmentation, Popp et al. 2010), with no
// hand-derived formula.
//
// Segmentation (Puso & Laursen 2004 §3): both facets are projected along the slave facet's normal n_0 at
// its centre onto the plane through its centre, the projected master polygon clips the projected slave
// polygon (MortarClipping.hpp), and the clip polygon is cut into triangles about its vertex centroid. A
// Gauss point p of a triangle maps back to the slave point x_s(ξ) and the master point x_m(η) whose
// projections are p; the gap is measured along the master's outward normal there, g = (x_s − x_m) · n_m
// (as in 2D, MortarSegment.cpp says why). The plane's normal is the slave facet's own, not the average
// of its nodes' averaged normals: a pair then depends on its own eight nodes only (theory-contact §13
// discusses what this changes on curved faces).
#include <array>
#include <vector>

#include "contact/MortarSlipVariation.hpp"

namespace contessa::contact {

/// A 3D pair's coordinates: slave nodes 0–3 then master nodes 0–3, three coordinates each (a 3-node
/// facet's fourth node's entries are zero and unused). Each facet is ordered so that its right-hand
/// normal points out of its body: the slave's towards the master, the master's towards the slave.
constexpr int kMortarFacetNodes = 4;
constexpr int kMortarFacetPairCoordinates = 3 * 2 * kMortarFacetNodes;
template <class T>
using FacetPairCoordinates = std::array<T, kMortarFacetPairCoordinates>;

/// The node counts of the pair's slave and master facets (3: Tri3, 4: Quad4).
struct MortarFacetPairShape {
  int slaveNodes = 4;
  int masterNodes = 4;
  /// A quadratic slave face's flat pieces' reference measures (a triangle piece's area, a 4-node piece's
  /// three Jacobian coefficients: mortarFacetPieceMeasures), each piece's own dA_0 / dA
  /// (MortarQuadraticFacetPair.hpp, eq. M20); unused for 3- and 4-node faces.
  std::array<double, 12> slavePieceAreas{};
};

/// The committed positions of the pair's slave and master nodes, in the layout of FacetPairCoordinates:
/// where the material points were at the last converged state, the start of the slip increments (eq. M9′).
using FacetPairCommitted = std::array<double, kMortarFacetPairCoordinates>;

/// Weighted gaps of the slave facet's nodes and their mortar areas ∫ N_a dA_0 over the overlap.
template <class T>
struct MortarFacetPairGaps {
  bool overlaps = false;
  std::array<T, kMortarFacetNodes> weightedGap{};
  std::array<T, kMortarFacetNodes> mortarArea{};
  /// Weighted slip increments Δũ_a = ∫ N_a (I − n_m ⊗ n_m)(Δx_s(ξ) − Δx_m(η)) dA_0 (eq. M9′), a 3-vector
  /// in the master's tangent plane at each Gauss point, when the committed positions are given (friction),
  /// else 0. The interface takes its components in the slave node's tangent basis (MortarSlipBasis.hpp).
  std::array<std::array<T, 3>, kMortarFacetNodes> weightedSlip{};
  /// With committed positions and derivatives (T a HessianDual): the virtual slips δũ_a (the mortar
  /// matrices applied to a virtual displacement) and their first derivatives (MortarSlipVariation.hpp).
  SlipVariationSum<T> slipVariation;
};

/// The integral over the overlap (eq. M13–M17). The measure is the slave facet's reference area: the
/// current projected area scaled by A_0 / A_projected(slave facet), so that, as in 2D, the weighted gaps
/// are per reference area and a uniform gap g gives g̃_a = g A_a exactly (the patch test).
template <class T>
MortarFacetPairGaps<T> integrateFacetPair(const FacetPairCoordinates<T>& x, double referenceArea,
                                          const MortarFacetPairShape& shape,
                                          const FacetPairCommitted* committed = nullptr);

/// Weighted gaps with their gradient and Hessian with respect to the 24 coordinates.
struct MortarFacetPairDerivatives {
  static constexpr int kCoordinates = kMortarFacetPairCoordinates;
  bool overlaps = false;
  std::array<double, kMortarFacetNodes> weightedGap{};
  std::array<double, kMortarFacetNodes> mortarArea{};
  std::array<std::array<double, kCoordinates>, kMortarFacetNodes> gradient{};
  std::array<std::array<double, kCoordinates * kCoordinates>, kMortarFacetNodes> hessian{};  ///< row-major
  /// With committed positions (friction): Δũ_a's components c (index 3 a + c), their gradients and
  /// Hessians; empty without (a frictionless pair carries no slip derivatives).
  std::array<std::array<double, 3>, kMortarFacetNodes> weightedSlip{};
  std::vector<std::array<double, kCoordinates>> slipGradient;
  std::vector<std::array<double, kCoordinates * kCoordinates>> slipHessian;
  /// With committed positions: the virtual slips' components (index 3 a + c), B_ac = ∂Δũ_ac/∂x at a frozen
  /// segmentation (the D and M matrices: what the tangential traction works on, the residual's), and their
  /// derivatives ∂B_ac,i/∂x_j, row-major, not symmetric (MortarSlipVariation.hpp, eq. M11″).
  std::vector<std::array<double, kCoordinates>> slipVariation;
  std::vector<std::array<double, kCoordinates * kCoordinates>> slipVariationGradient;
};

/// The pair's weighted gaps (values only).
MortarFacetPairGaps<double> facetPairGaps(const FacetPairCoordinates<double>& x, double referenceArea,
                                          const MortarFacetPairShape& shape = {},
                                          const FacetPairCommitted* committed = nullptr);
/// The pair's weighted gaps differentiated twice (MortarDual.hpp's HessianDual). With `masterMotion` (a
/// rigid master: ∂x/∂λ of its twelve coordinates, entries 12–23), the master is differentiated along that
/// motion only: entry 12 holds the derivatives along it, entries 13–23 are zero (as 2D's
/// segmentPairDerivatives).
MortarFacetPairDerivatives facetPairDerivatives(const FacetPairCoordinates<double>& x, double referenceArea,
                                                const MortarFacetPairShape& shape = {},
                                                const double* masterMotion = nullptr,
                                                const FacetPairCommitted* committed = nullptr);
/// The same, written into `out` (every field): a kept record (MortarInterface's, one per pair) filled in
/// place instead of a returned 18 KB one copied into it.
void facetPairDerivatives(const FacetPairCoordinates<double>& x, double referenceArea, const MortarFacetPairShape& shape,
                          const double* masterMotion, const FacetPairCommitted* committed,
                          MortarFacetPairDerivatives& out);

}  // namespace contessa::contact
