#pragma once
// A solid element kernel: local internal force and tangent only (the model assembles). Kernels hold
// no per-element data themselves: what depends only on the reference configuration is computed once
// per element into an ElementGeometry (referenceGeometry), and what changes with the solution (the
// enhanced-strain parameters α and the data that warm-start their local solve) is the element's
// state, kept by the model in a committed and a trial copy.
#include <memory>
#include <string>
#include <vector>

#include "mechanics/Material.hpp"
#include "mechanics/Tensor.hpp"

namespace contessa::mechanics {

enum class ElementStatus { Ok, InadmissibleDeformation, InternalSolveFailed };

/// Reference geometry of a set of elements of one kernel (shape-function gradients ∂N/∂X and
/// integration weights × det J at every integration point, and what else the kernel precomputes).
/// Opaque: only the kernel that made it reads it.
class ElementGeometry {
 public:
  virtual ~ElementGeometry() = default;
  virtual int size() const = 0;  ///< number of elements
};

class ElementKernel {
 public:
  virtual ~ElementKernel() = default;
  virtual std::string name() const = 0;
  virtual int dimension() const = 0;
  virtual int numNodes() const = 0;
  int numDofs() const { return dimension() * numNodes(); }
  /// True for a 2D kernel of a solid of revolution about the y axis (r = x, z = y): its forces are
  /// those of the full circumference and its stress's zz component is the hoop stress σ_θθ.
  virtual bool axisymmetric() const { return false; }
  /// Parent (reference-element) coordinates ξ of the nodes, numNodes × dimension, node-major: where the
  /// kernel's shape functions are 1 (tests map them into distorted elements of every family).
  virtual std::vector<double> parentNodeCoordinates() const = 0;
  /// Internal (condensed) variables per element, e.g. 4 (Q4) or 9 (Hex8) enhanced-strain parameters.
  virtual int numInternalVariables() const { return 0; }
  /// Values of the element state: the internal variables first, then what the kernel keeps to
  /// start its next local solve closer to the solution (the enhanced element's warm start). Held by
  /// the model like the internal variables (trial and committed copies); all zero initially.
  virtual int numStateValues() const { return numInternalVariables(); }

  /// Reference geometry of `count` elements with reference coordinates X (count × numNodes ×
  /// dimension, node-major). An element with det ∂X/∂ξ ≤ 0 at an integration point (clockwise nodes
  /// or degenerate) is kept and reports InadmissibleDeformation whenever it is evaluated.
  virtual std::unique_ptr<ElementGeometry> referenceGeometry(int count, const double* X) const = 0;

  /// Internal force f_int = ∫ Bᵀ P dV (size numDofs, node-major: u_x0 u_y0 u_x1 ...) and, when
  /// `stiffness` is not null, the consistent tangent ∂f_int/∂u (numDofs², row-major), of element
  /// `element` of `geometry` at displacements u (numNodes × dimension). `internalForce` may be null.
  /// state (numStateValues, may be null when numInternalVariables() is 0): in = the last state, out =
  /// updated (left unchanged on failure). Plane strain, unit thickness in 2D; the full 3 × 3 F in 3D;
  /// axisymmetric kernels integrate over the full circumference (2π R).
  virtual ElementStatus evaluate(const ElementGeometry& geometry, int element, const double* u, double* state,
                                 const Material& material, double* internalForce, double* stiffness) const = 0;

  /// Cauchy stress averaged over the integration points (3 × 3; plane strain includes σ_zz) with the
  /// internal variables `internal` (the first numInternalVariables() values of a state; null: solved
  /// for at u from zero).
  virtual ElementStatus averageCauchyStress(const ElementGeometry& geometry, int element, const double* u,
                                            const double* internal, const Material& material,
                                            Tensor2& sigma) const = 0;

  /// One element given by its reference coordinates X (numNodes × dimension): its geometry is
  /// computed on the spot (tests and tools; the model precomputes it). `internal`: the internal
  /// variables only (in = starting guess, null = 0; out = converged values, unchanged on failure);
  /// no warm start beyond that.
  ElementStatus evaluate(const double* X, const double* u, double* internal, const Material& material,
                         double* internalForce, double* stiffness) const;
  ElementStatus averageCauchyStress(const double* X, const double* u, const double* internal,
                                    const Material& material, Tensor2& sigma) const;
};

/// Creates element kernels by the deck's "Element" name (ElementFactory.cpp lists them all): "Q4"
/// (bilinear, 2 × 2 Gauss), "Q4 Enhanced"
/// (Simo–Armero enhanced assumed strain, 4 modes, condensed), and their 3D counterparts "Hex8"
/// (trilinear, 2 × 2 × 2 Gauss) and "Hex8 Enhanced" (9 modes, condensed); "Q4 Axisymmetric" and "Q4
/// Enhanced Axisymmetric" revolve the 2D ones about the y axis (Kinematics.hpp).
class ElementFactory {
 public:
  static std::vector<std::string> names();
  /// Throws InputError (naming `where` and listing the known names) for an unknown name.
  static std::unique_ptr<ElementKernel> create(const std::string& name, const std::string& where);
};

/// Von Mises equivalent stress of a 3 × 3 Cauchy stress.
double vonMises(const Tensor2& sigma);

}  // namespace contessa::mechanics
