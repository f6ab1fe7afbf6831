#pragma once
// Enhanced assumed strain solid kernel (Simo & Armero 1992, IJNME 33:1413) over any isoparametric
// reference element: F = I + GRAD u + H̃(α), with the element parameters α condensed out at every
// evaluate() by a local Newton solve of R_α(u, α) = 0. Quad4Enhanced is this with the bilinear
// quadrilateral (4 modes); Hex8 will give 9 modes with no change here.
#include "mechanics/Element.hpp"
#include "mechanics/ReferenceElement.hpp"

namespace contessa::mechanics {

class EnhancedStrainElement : public ElementKernel {
 public:
  int dimension() const override { return reference_.dimension(); }
  int numNodes() const override { return reference_.numNodes(); }
  int numInternalVariables() const override { return dimension() * dimension(); }

  /// `internal` (α): in = starting guess (null = 0), out = converged α (left unchanged on failure).
  /// f_int = R_u(u, α*) and K = K_uu − K_uα K_αα⁻¹ K_αu at the converged α*, which is the exact
  /// derivative of u ↦ R_u(u, α*(u)) because R_α(u, α*(u)) = 0. Returns InternalSolveFailed when
  /// the local Newton does not converge in kMaxLocalIterations or K_αα is singular.
  ElementStatus evaluate(const double* X, const double* u, double* internal, const Material& material,
                         double* internalForce, double* stiffness) const override;
  /// Uses `internal` as the converged α (null: solves for it from 0).
  ElementStatus averageCauchyStress(const double* X, const double* u, const double* internal,
                                    const Material& material, Tensor2& sigma) const override;

  static constexpr int kMaxLocalIterations = 25;

 protected:
  explicit EnhancedStrainElement(const ReferenceElement& reference) : reference_(reference) {}

 private:
  const ReferenceElement& reference_;  ///< a shared immutable instance (static lifetime)
};

}  // namespace contessa::mechanics
