#include "mechanics/Simplices.hpp"

#include "mechanics/DisplacementElement.hpp"

namespace contessa::mechanics {

std::unique_ptr<ElementKernel> makeTri3(const std::string& name) {
  return std::make_unique<DisplacementElement<LinearTriangle>>(name);
}
std::unique_ptr<ElementKernel> makeTri6(const std::string& name) {
  return std::make_unique<DisplacementElement<QuadraticTriangle>>(name);
}
std::unique_ptr<ElementKernel> makeTri3Axisymmetric(const std::string& name) {
  return std::make_unique<DisplacementElement<LinearTriangle3Points, AxisymmetricKinematics>>(name);
}
std::unique_ptr<ElementKernel> makeTri6Axisymmetric(const std::string& name) {
  return std::make_unique<DisplacementElement<QuadraticTriangle, AxisymmetricKinematics>>(name);
}
std::unique_ptr<ElementKernel> makeTet4(const std::string& name) {
  return std::make_unique<DisplacementElement<LinearTetrahedron>>(name);
}
std::unique_ptr<ElementKernel> makeTet10(const std::string& name) {
  return std::make_unique<DisplacementElement<QuadraticTetrahedron>>(name);
}

}  // namespace contessa::mechanics
