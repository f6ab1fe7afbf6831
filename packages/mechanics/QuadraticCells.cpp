#include "mechanics/QuadraticCells.hpp"

#include "mechanics/DisplacementElement.hpp"

namespace contessa::mechanics {

std::unique_ptr<ElementKernel> makeQ8(const std::string& name) {
  return std::make_unique<DisplacementElement<SerendipityQuadrilateral>>(name);
}
std::unique_ptr<ElementKernel> makeQ9(const std::string& name) {
  return std::make_unique<DisplacementElement<LagrangeQuadrilateral>>(name);
}
std::unique_ptr<ElementKernel> makeQ8Axisymmetric(const std::string& name) {
  return std::make_unique<DisplacementElement<SerendipityQuadrilateral, AxisymmetricKinematics>>(name);
}
std::unique_ptr<ElementKernel> makeQ9Axisymmetric(const std::string& name) {
  return std::make_unique<DisplacementElement<LagrangeQuadrilateral, AxisymmetricKinematics>>(name);
}
std::unique_ptr<ElementKernel> makeHex20(const std::string& name) {
  return std::make_unique<DisplacementElement<SerendipityHexahedron>>(name);
}
std::unique_ptr<ElementKernel> makeHex27(const std::string& name) {
  return std::make_unique<DisplacementElement<LagrangeHexahedron>>(name);
}

}  // namespace contessa::mechanics
