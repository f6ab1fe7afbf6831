#pragma once
// The 4-node quadrilateral: its reference element (BilinearQuadrilateral) and the two kernels built on
// it, "Q4" (DisplacementElement: full 2 × 2 Gauss, locks in bending and near incompressibility) and
// "Q4 Enhanced" (EnhancedStrainElement with the 4 Simo–Armero modes: exact for pure bending of
// rectangles, free of volumetric locking in the small-strain limit). Plane strain, and both revolved
// about the y axis: "Q4 Axisymmetric" and "Q4 Enhanced Axisymmetric" (Kinematics.hpp).
#include <array>
#include <memory>
#include <string>

#include "mechanics/Element.hpp"
#include "mechanics/ReferenceElement.hpp"

namespace contessa::mechanics {

/// Bilinear 4-node quadrilateral, nodes counter-clockwise at (ξ, η) = (−1,−1), (1,−1), (1,1), (−1,1);
/// N_a = ¼ (1 + ξ_a ξ)(1 + η_a η), 2 × 2 Gauss.
struct BilinearQuadrilateral {
  static constexpr int kDimension = 2, kNodes = 4, kPoints = 4;
  static std::array<QuadraturePoint<2>, kPoints> quadrature() { return gaussLegendreRule<2, 2>(); }
  static void shapeGradients(const double* xi, double* dNdxi);
  static void shapeValues(const double* xi, double* N);  ///< N_a at ξ (the axisymmetric radius, N_a / R)
  static std::array<std::array<double, 2>, kNodes> parentNodes() { return {{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}}; }
};

/// The kernels, under the name the registry (ElementFactory.cpp) gives them.
std::unique_ptr<ElementKernel> makeQuad4(const std::string& name);
std::unique_ptr<ElementKernel> makeQuad4Enhanced(const std::string& name);
std::unique_ptr<ElementKernel> makeQuad4Axisymmetric(const std::string& name);
std::unique_ptr<ElementKernel> makeQuad4EnhancedAxisymmetric(const std::string& name);

}  // namespace contessa::mechanics
