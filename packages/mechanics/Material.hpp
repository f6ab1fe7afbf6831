#pragma once
// A hyperelastic (or small-strain elastic) material law: stress and its tangent from the
// deformation gradient. One class per law; created by name through MaterialFactory.
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "mechanics/Tensor.hpp"

namespace contessa::mechanics {

class Material {
 public:
  virtual ~Material() = default;

  /// First Piola–Kirchhoff stress P(F) and, when A is not null, the tangent A = ∂P/∂F.
  /// Returns false when F is inadmissible for the law (det F ≤ 0 for finite-strain laws).
  /// Small-strain laws return P = σ(ε), ε = sym(F − I), and A = the elasticity tensor.
  virtual bool firstPiolaKirchhoff(const Tensor2& F, Tensor2& P, Tensor4* A) const = 0;

  /// Cauchy stress σ = P Fᵀ / det F (small-strain laws: σ = P). False when F is inadmissible.
  virtual bool cauchyStress(const Tensor2& F, Tensor2& sigma) const;

  /// True for geometrically linear laws (the element then uses the small-strain kinematics).
  virtual bool isSmallStrain() const { return false; }
};

/// Creates materials by the deck's "Model" name. Each law publishes its valid parameters.
class MaterialFactory {
 public:
  /// Registered model names, e.g. "Saint Venant-Kirchhoff", "Neo-Hookean", "Linear Elastic".
  static std::vector<std::string> names();
  /// Valid parameters of one model (with docs and defaults), including "Model" itself.
  /// Throws InputError listing the known names for an unknown model.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters(const std::string& model);
  /// Creates from a validated list (with "Model"); `where` names the deck path for error messages.
  static std::unique_ptr<Material> create(const Teuchos::ParameterList& params, const std::string& where);
};

}  // namespace contessa::mechanics
