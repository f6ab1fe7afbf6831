#pragma once
// Standard (displacement-only) total-Lagrangian solid kernel over any isoparametric reference
// element: f_int = Σ_gp Bᵀ P w j, K = Σ_gp Bᵀ A B w j. Quad4 is this with the bilinear quadrilateral;
// Hex8 will be this with a trilinear hexahedron. evaluate() returns InadmissibleDeformation when the
// material rejects F at a Gauss point or when the reference element itself has j ≤ 0 (clockwise
// node order or a degenerate element).
#include "mechanics/Element.hpp"
#include "mechanics/ReferenceElement.hpp"

namespace contessa::mechanics {

class DisplacementElement : public ElementKernel {
 public:
  int dimension() const override { return reference_.dimension(); }
  int numNodes() const override { return reference_.numNodes(); }

  ElementStatus evaluate(const double* X, const double* u, double* internal, const Material& material,
                         double* internalForce, double* stiffness) const override;
  ElementStatus averageCauchyStress(const double* X, const double* u, const double* internal,
                                    const Material& material, Tensor2& sigma) const override;

 protected:
  explicit DisplacementElement(const ReferenceElement& reference) : reference_(reference) {}

 private:
  const ReferenceElement& reference_;  ///< a shared immutable instance (static lifetime)
};

}  // namespace contessa::mechanics
