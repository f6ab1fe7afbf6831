#pragma once
// The "G" operators of the enhanced assumed strain method (Simo & Armero 1992, IJNME 33:1413):
// the enhanced displacement gradient H̃ = Σ_m α_m G_m added to GRAD u, and its contributions to the
// residuals and tangents. Dimension-generic: dim² modes (4 for Quad4, 9 for Hex8).
#include <array>

#include "mechanics/ReferenceElement.hpp"
#include "mechanics/SolidOperators.hpp"
#include "mechanics/Tensor.hpp"

namespace contessa::mechanics {

inline constexpr int kMaxEnhancedModes = kMaxDimension * kMaxDimension;

/// The G_m at one integration point.
struct EnhancedModes {
  int count = 0;
  std::array<Tensor2, kMaxEnhancedModes> G{};
  double normSum = 0.0;  ///< Σ_m ‖G_m‖, a magnitude for relative tolerances
};

/// Simo–Armero (1992) form H̃ = (j0 / j(ξ)) α̂(ξ) J0⁻¹ with α̂_iβ = α_m ξ_β, m = dim·i + β;
/// J0 = ∂X/∂ξ at the element centre, j0 = det J0. In 2D α̂ = [[ξ α1, η α2], [ξ α3, η α4]]: the
/// parent gradients of the Wilson bubbles 1 − ξ², 1 − η², mapped like GRAD u = (∂u/∂ξ) J⁻¹ but
/// with the constant J0. Since dV = j dξ, ∫ H̃ dV = j0 (∫ α̂ dξ) J0⁻¹ = 0 (α̂ is odd in ξ_β) on any
/// element shape: H̃ does no work on a constant stress, which is what makes the patch test pass.
EnhancedModes enhancedModes(int dimension, const double* xi, const Tensor2& J0inv, double j0OverJ);

/// H̃ = Σ_m α_m G_m.
Tensor2 enhancedGradient(const EnhancedModes& modes, const double* alpha);

/// R_α,m += G_m : P · w j.
void addEnhancedResidual(const EnhancedModes& modes, const Tensor2& P, double weightedVolume, double* Ralpha);

/// K_αα,mn += G_m : A : G_n · w j  (count × count, row-major).
void addEnhancedStiffness(int dimension, const EnhancedModes& modes, const Tensor4& A, double weightedVolume,
                          double* Kaa);

/// Coupling blocks K_uα,(ai)m = ∂R_u,ai/∂α_m += ∂N_a/∂X_J A_iJkL G_m,kL · w j (numDofs × count) and
/// K_αu,m(bk) = ∂R_α,m/∂u_bk += G_m,iJ A_iJkL ∂N_b/∂X_L · w j (count × numDofs). Kept separate
/// rather than assuming major symmetry of A.
void addCouplingStiffness(int dimension, int numNodes, const PointGeometry& g, const EnhancedModes& modes,
                          const Tensor4& A, double* Kua, double* Kau);

}  // namespace contessa::mechanics
