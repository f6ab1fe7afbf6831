#pragma once
// A solid element kernel: local internal force and tangent only (the model assembles). Kernels are
// stateless; per-element internal variables (the enhanced-strain parameters α) live in the model
// with a committed and a trial copy.
#include <memory>
#include <string>
#include <vector>

#include "mechanics/Material.hpp"
#include "mechanics/Tensor.hpp"

namespace contessa::mechanics {

enum class ElementStatus { Ok, InadmissibleDeformation, InternalSolveFailed };

class ElementKernel {
 public:
  virtual ~ElementKernel() = default;
  virtual std::string name() const = 0;
  virtual int dimension() const = 0;
  virtual int numNodes() const = 0;
  int numDofs() const { return dimension() * numNodes(); }
  /// Internal (condensed) variables per element, e.g. 4 enhanced-strain parameters.
  virtual int numInternalVariables() const { return 0; }

  /// Internal force f_int = ∫ Bᵀ P dV (size numDofs, node-major: u_x0 u_y0 u_x1 ...) and, when
  /// `stiffness` is not null, the consistent tangent ∂f_int/∂u (numDofs², row-major).
  /// X: reference coordinates (numNodes × dimension), u: displacements (same layout).
  /// internal: in = starting guess, out = converged internal variables (may be null when none).
  /// Plane strain, unit thickness.
  virtual ElementStatus evaluate(const double* X, const double* u, double* internal,
                                 const Material& material, double* internalForce,
                                 double* stiffness) const = 0;

  /// Cauchy stress averaged over the integration points (3 × 3; plane strain includes σ_zz).
  virtual ElementStatus averageCauchyStress(const double* X, const double* u, const double* internal,
                                            const Material& material, Tensor2& sigma) const = 0;
};

/// Creates element kernels by the deck's "Element" name: "Q4" (bilinear, 2 × 2 Gauss) and
/// "Q4 Enhanced" (Simo–Armero enhanced assumed strain, 4 modes, condensed).
class ElementFactory {
 public:
  static std::vector<std::string> names();
  /// Throws InputError (naming `where` and listing the known names) for an unknown name.
  static std::unique_ptr<ElementKernel> create(const std::string& name, const std::string& where);
};

/// Von Mises equivalent stress of a 3 × 3 Cauchy stress.
double vonMises(const Tensor2& sigma);

}  // namespace contessa::mechanics
