#pragma once
// Total-Lagrangian "B" operators, written for any dimension and node count (Quad4 now, Hex8 later).
// Tensors stay 3 × 3: in 2D the indices J, L of ∂N/∂X run over the first two components only, and
// the padding (F_33 = 1, F_3J = F_i3 = 0) is what makes the 3D material code plane strain.
#include <array>
#include <vector>

#include "mechanics/ReferenceElement.hpp"
#include "mechanics/Tensor.hpp"

namespace contessa::mechanics {

/// Reference geometry at one integration point.
struct PointGeometry {
  std::array<double, kMaxNodes * kMaxDimension> dNdX{};  ///< ∂N_a/∂X_J at index dimension·a + J
  double detJ = 0.0;                                      ///< j = det ∂X/∂ξ
  double weightedVolume = 0.0;                            ///< w · j (unit thickness in 2D)
};

/// Parent Jacobian J_Jβ = ∂X_J/∂ξ_β at ξ, padded to 3 × 3 with ones on the unused diagonal so that
/// det and inverse are those of the dim × dim block. X: numNodes × dimension, node-major.
Tensor2 parentJacobian(const ReferenceElement& ref, const double* xi, const double* X);

/// Geometry at every quadrature point of `ref`. False when some j ≤ 0 (nodes not counter-clockwise
/// or a degenerate element): the reference configuration cannot be integrated.
bool referenceGeometry(const ReferenceElement& ref, const double* X, std::vector<PointGeometry>& points);

/// GRAD u_iJ = Σ_a u_ai ∂N_a/∂X_J (3 × 3, zero padding).
Tensor2 displacementGradient(int dimension, int numNodes, const PointGeometry& g, const double* u);

/// f_ai += P_iJ ∂N_a/∂X_J · w j   (the discrete ∫ Bᵀ P dV).
void addInternalForce(int dimension, int numNodes, const PointGeometry& g, const Tensor2& P, double* f);

/// K_ai,bk += ∂N_a/∂X_J A_iJkL ∂N_b/∂X_L · w j  (material and geometric stiffness together, since
/// A = ∂P/∂F); K is numDofs × numDofs row-major.
void addMaterialStiffness(int dimension, int numNodes, const PointGeometry& g, const Tensor4& A, double* K);

}  // namespace contessa::mechanics
