#pragma once
// The 8-node hexahedron: its reference element (TrilinearHexahedron) and the two kernels built on it,
// "Hex8" (DisplacementElement: full 2 × 2 × 2 Gauss, locks in bending and near incompressibility) and
// "Hex8 Enhanced" (EnhancedStrainElement with the 9 Simo–Armero modes: exact in pure bending of
// rectangular bricks). The same kernel templates as Quad4.hpp; only the traits are 3D.
#include <array>
#include <memory>
#include <string>

#include "mechanics/Element.hpp"
#include "mechanics/ReferenceElement.hpp"

namespace contessa::mechanics {

/// Trilinear 8-node hexahedron in the Exodus HEX8 node order: nodes 0–3 counter-clockwise (seen
/// from +ζ) on the face ζ = −1 at (ξ, η) = (−1,−1), (1,−1), (1,1), (−1,1), nodes 4–7 above them on
/// ζ = +1; N_a = ⅛ (1 + ξ_a ξ)(1 + η_a η)(1 + ζ_a ζ), 2 × 2 × 2 Gauss.
struct TrilinearHexahedron {
  static constexpr int kDimension = 3, kNodes = 8, kPoints = 8;
  static std::array<QuadraturePoint<3>, kPoints> quadrature() { return gaussLegendreRule<3, 2>(); }
  static void shapeGradients(const double* xi, double* dNdxi);
  static std::array<std::array<double, 3>, kNodes> parentNodes() {
    return {{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}}};
  }
};

/// The kernels, under the name the registry (ElementFactory.cpp) gives them.
std::unique_ptr<ElementKernel> makeHex8(const std::string& name);
std::unique_ptr<ElementKernel> makeHex8Enhanced(const std::string& name);

}  // namespace contessa::mechanics
