#include "mechanics/Wedges.hpp"

#include "mechanics/DisplacementElement.hpp"

namespace contessa::mechanics {

std::unique_ptr<ElementKernel> makeWedge6(const std::string& name) {
  return std::make_unique<DisplacementElement<LinearWedge>>(name);
}
std::unique_ptr<ElementKernel> makeWedge15(const std::string& name) {
  return std::make_unique<DisplacementElement<QuadraticWedge>>(name);
}

}  // namespace contessa::mechanics
