#pragma once
// The enhanced modes of the enhanced assumed strain method (Simo & Armero 1992, IJNME 33:1413), as
// compile-time traits for EnhancedStrainElement. A modes class provides
//
//   static constexpr int kPseudoNodes;   // M: D·M enhanced parameters
//   static void gradients(const double* xi, double j0OverJ, const Matrix<D>& J0inv, double* g);
//
// and the enhanced displacement gradient is H̃_iJ = Σ_β α_(β,i) g_β,J (β < M, α_(β,i) at index D·β + i):
// each mode pattern enters every formula exactly like an extra node with reference gradient g_β and
// "displacement" α_β, which is how the kernel treats it (SolidOperators.hpp).
#include "mechanics/Tensor.hpp"

namespace contessa::mechanics {

/// Simo–Armero form H̃ = (j0 / j(ξ)) α̂(ξ) J0⁻¹ with α̂_iβ = ξ_β α_(β,i): for every parent direction β
/// the parent gradient of the Wilson bubble 1 − ξ_β² (up to a factor absorbed in α), mapped like
/// GRAD u = (∂u/∂ξ) J⁻¹ but with J0 = ∂X/∂ξ at the element centre, j0 = det J0. So
/// g_β,J = (j0 / j) ξ_β (J0⁻¹)_βJ, D² parameters (4 for Quad4, 9 for a Hex8 of this type).
/// Since dV = j dξ, ∫ H̃ dV = j0 (∫ α̂ dξ) J0⁻¹ = 0 (α̂ is odd in ξ_β) on any element shape: H̃ does
/// no work on a constant stress, which is what makes the patch test pass.
template <int D>
struct WilsonBubbleModes {
  static constexpr int kPseudoNodes = D;
  static void gradients(const double* xi, double j0OverJ, const Matrix<D>& J0inv, double* g) {
    for (int beta = 0; beta < D; ++beta)
      for (int J = 0; J < D; ++J) g[D * beta + J] = j0OverJ * xi[beta] * J0inv[D * beta + J];
  }
};

}  // namespace contessa::mechanics
