#include "mechanics/Quad4.hpp"

#include "mechanics/DisplacementElement.hpp"
#include "mechanics/EnhancedStrain.hpp"
#include "mechanics/EnhancedStrainElement.hpp"

namespace contessa::mechanics {

void BilinearQuadrilateral::shapeGradients(const double* xi, double* dNdxi) {
  static const double kNodeXi[4] = {-1.0, 1.0, 1.0, -1.0};
  static const double kNodeEta[4] = {-1.0, -1.0, 1.0, 1.0};
  for (int a = 0; a < 4; ++a) {
    dNdxi[2 * a] = 0.25 * kNodeXi[a] * (1.0 + kNodeEta[a] * xi[1]);
    dNdxi[2 * a + 1] = 0.25 * kNodeEta[a] * (1.0 + kNodeXi[a] * xi[0]);
  }
}

void BilinearQuadrilateral::shapeValues(const double* xi, double* N) {
  static const double kNodeXi[4] = {-1.0, 1.0, 1.0, -1.0};
  static const double kNodeEta[4] = {-1.0, -1.0, 1.0, 1.0};
  for (int a = 0; a < 4; ++a) N[a] = 0.25 * (1.0 + kNodeXi[a] * xi[0]) * (1.0 + kNodeEta[a] * xi[1]);
}

std::unique_ptr<ElementKernel> makeQuad4(const std::string& name) {
  return std::make_unique<DisplacementElement<BilinearQuadrilateral>>(name);
}

std::unique_ptr<ElementKernel> makeQuad4Enhanced(const std::string& name) {
  return std::make_unique<EnhancedStrainElement<BilinearQuadrilateral, WilsonBubbleModes<2>>>(name);
}

std::unique_ptr<ElementKernel> makeQuad4Axisymmetric(const std::string& name) {
  return std::make_unique<DisplacementElement<BilinearQuadrilateral, AxisymmetricKinematics>>(name);
}

std::unique_ptr<ElementKernel> makeQuad4EnhancedAxisymmetric(const std::string& name) {
  return std::make_unique<EnhancedStrainElement<BilinearQuadrilateral, WilsonBubbleModes<2>, AxisymmetricKinematics>>(name);
}

}  // namespace contessa::mechanics
