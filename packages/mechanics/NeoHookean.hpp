#pragma once
// Compressible Neo-Hookean law, W = μ/2 (tr C − 3) − μ ln J + λ/2 (ln J)² (Bonet & Wood, Nonlinear
// Continuum Mechanics for FEA, 2nd ed., eq. 6.27; Simo & Pister 1984). Reduces to linear elasticity
// with the same λ, μ for small strains; W → ∞ as J → 0, so inverted states are rejected.
#include <memory>
#include <string>

#include "mechanics/IsotropicElasticity.hpp"
#include "mechanics/Material.hpp"

namespace contessa::mechanics {

class NeoHookean final : public MaterialLaw<NeoHookean> {
 public:
  static constexpr const char* kModelName = "Neo-Hookean";
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  static std::unique_ptr<Material> create(const Teuchos::ParameterList& params, const std::string& where);

  explicit NeoHookean(const LameConstants& lame) : lame_(lame) {}
  const LameConstants& lame() const { return lame_; }

  /// P(F) and A = ∂P/∂F (when not null) in D dimensions (D = 2: plane strain, in-plane blocks).
  template <int D>
  bool stress(const Matrix<D>& F, Matrix<D>& P, Tangent<D>* A) const;

 private:
  LameConstants lame_;
};

extern template class MaterialLaw<NeoHookean>;

}  // namespace contessa::mechanics
