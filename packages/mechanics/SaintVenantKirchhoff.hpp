#pragma once
// Saint Venant–Kirchhoff: the linear isotropic law between the Green–Lagrange strain and the
// second Piola–Kirchhoff stress (Holzapfel, Nonlinear Solid Mechanics, 2000, eq. 6.151). Fine for
// large rotations with small strains; unstable in strong compression (use Neo-Hookean there).
#include <memory>
#include <string>

#include "mechanics/IsotropicElasticity.hpp"
#include "mechanics/Material.hpp"

namespace contessa::mechanics {

class SaintVenantKirchhoff final : public MaterialLaw<SaintVenantKirchhoff> {
 public:
  static constexpr const char* kModelName = "Saint Venant-Kirchhoff";
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  static std::unique_ptr<Material> create(const Teuchos::ParameterList& params, const std::string& where);

  explicit SaintVenantKirchhoff(const LameConstants& lame) : lame_(lame) {}
  const LameConstants& lame() const { return lame_; }

  /// P(F) and A = ∂P/∂F (when not null) in D dimensions (D = 2: plane strain, in-plane blocks).
  template <int D>
  bool stress(const Matrix<D>& F, Matrix<D>& P, Tangent<D>* A) const;

 private:
  LameConstants lame_;
};

extern template class MaterialLaw<SaintVenantKirchhoff>;

}  // namespace contessa::mechanics
