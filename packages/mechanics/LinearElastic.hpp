#pragma once
// Small-strain isotropic linear elasticity, σ = λ tr(ε) I + 2 μ ε with ε = sym(F − I). Geometrically
// linear: not frame indifferent under finite rotations, which is why isSmallStrain() is true.
#include <memory>
#include <string>

#include "mechanics/IsotropicElasticity.hpp"
#include "mechanics/Material.hpp"

namespace contessa::mechanics {

class LinearElastic final : public MaterialLaw<LinearElastic> {
 public:
  static constexpr const char* kModelName = "Linear Elastic";
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  static std::unique_ptr<Material> create(const Teuchos::ParameterList& params, const std::string& where);

  explicit LinearElastic(const LameConstants& lame) : lame_(lame) {}
  const LameConstants& lame() const { return lame_; }

  /// P(F) and A = ∂P/∂F (when not null) in D dimensions (D = 2: plane strain, in-plane blocks).
  template <int D>
  bool stress(const Matrix<D>& F, Matrix<D>& P, Tangent<D>* A) const;
  bool isSmallStrain() const override { return true; }

 private:
  LameConstants lame_;
};

extern template class MaterialLaw<LinearElastic>;

}  // namespace contessa::mechanics
