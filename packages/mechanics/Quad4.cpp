#include "mechanics/Quad4.hpp"

namespace contessa::mechanics {

void BilinearQuadrilateral::shapeGradients(const double* xi, double* dNdxi) const {
  static const double kNodeXi[4] = {-1.0, 1.0, 1.0, -1.0};
  static const double kNodeEta[4] = {-1.0, -1.0, 1.0, 1.0};
  for (int a = 0; a < 4; ++a) {
    dNdxi[2 * a] = 0.25 * kNodeXi[a] * (1.0 + kNodeEta[a] * xi[1]);
    dNdxi[2 * a + 1] = 0.25 * kNodeEta[a] * (1.0 + kNodeXi[a] * xi[0]);
  }
}

const BilinearQuadrilateral& bilinearQuadrilateral() {
  static const BilinearQuadrilateral instance;
  return instance;
}

Quad4::Quad4() : DisplacementElement(bilinearQuadrilateral()) {}

std::string Quad4::name() const { return kName; }

}  // namespace contessa::mechanics
