#pragma once
// Small-strain isotropic linear elasticity, σ = λ tr(ε) I + 2 μ ε with ε = sym(F − I). Geometrically
// linear: not frame indifferent under finite rotations, which is why isSmallStrain() is true.
#include <memory>
#include <string>

#include "mechanics/IsotropicElasticity.hpp"
#include "mechanics/Material.hpp"

namespace contessa::mechanics {

class LinearElastic final : public Material {
 public:
  static constexpr const char* kModelName = "Linear Elastic";
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  static std::unique_ptr<Material> create(const Teuchos::ParameterList& params, const std::string& where);

  explicit LinearElastic(const LameConstants& lame) : lame_(lame) {}
  const LameConstants& lame() const { return lame_; }

  bool firstPiolaKirchhoff(const Tensor2& F, Tensor2& P, Tensor4* A) const override;
  bool isSmallStrain() const override { return true; }

 private:
  LameConstants lame_;
};

}  // namespace contessa::mechanics
