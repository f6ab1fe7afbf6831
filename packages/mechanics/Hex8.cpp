#include "mechanics/Hex8.hpp"

#include "mechanics/DisplacementElement.hpp"
#include "mechanics/EnhancedStrain.hpp"
#include "mechanics/EnhancedStrainElement.hpp"

namespace contessa::mechanics {

void TrilinearHexahedron::shapeGradients(const double* xi, double* dNdxi) {
  static const double kNode[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                     {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  for (int a = 0; a < 8; ++a) {
    const double f[3] = {1.0 + kNode[a][0] * xi[0], 1.0 + kNode[a][1] * xi[1], 1.0 + kNode[a][2] * xi[2]};
    dNdxi[3 * a] = 0.125 * kNode[a][0] * f[1] * f[2];
    dNdxi[3 * a + 1] = 0.125 * kNode[a][1] * f[0] * f[2];
    dNdxi[3 * a + 2] = 0.125 * kNode[a][2] * f[0] * f[1];
  }
}

std::unique_ptr<ElementKernel> makeHex8(const std::string& name) {
  return std::make_unique<DisplacementElement<TrilinearHexahedron>>(name);
}

std::unique_ptr<ElementKernel> makeHex8Enhanced(const std::string& name) {
  return std::make_unique<EnhancedStrainElement<TrilinearHexahedron, WilsonBubbleModes<3>>>(name);
}

}  // namespace contessa::mechanics
