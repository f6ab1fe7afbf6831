#pragma once
// "Q4": bilinear 4-node quadrilateral, total-Lagrangian, full 2 × 2 Gauss integration, plane strain.
// Locks in bending (parasitic shear) and near incompressibility; see Quad4Enhanced.
#include <string>

#include "mechanics/DisplacementElement.hpp"
#include "mechanics/ReferenceElement.hpp"

namespace contessa::mechanics {

/// Bilinear 4-node quadrilateral, nodes counter-clockwise at (ξ, η) = (−1,−1), (1,−1), (1,1), (−1,1);
/// N_a = ¼ (1 + ξ_a ξ)(1 + η_a η), 2 × 2 Gauss. One shared instance: bilinearQuadrilateral().
class BilinearQuadrilateral final : public ReferenceElement {
 public:
  BilinearQuadrilateral() : rule_(gaussLegendreRule(2, 2)) {}
  int dimension() const override { return 2; }
  int numNodes() const override { return 4; }
  void shapeGradients(const double* xi, double* dNdxi) const override;
  const std::vector<QuadraturePoint>& quadrature() const override { return rule_; }

 private:
  std::vector<QuadraturePoint> rule_;
};

const BilinearQuadrilateral& bilinearQuadrilateral();

class Quad4 final : public DisplacementElement {
 public:
  static constexpr const char* kName = "Q4";
  Quad4();
  std::string name() const override;
};

}  // namespace contessa::mechanics
