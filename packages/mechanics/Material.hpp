#pragma once
// A hyperelastic (or small-strain elastic) material law: stress and its tangent from the
// deformation gradient. One class per law; created by name through MaterialFactory.
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "mechanics/KernelIsa.hpp"
#include "mechanics/Tensor.hpp"

namespace contessa::mechanics {

class Material {
 public:
  virtual ~Material() = default;

  /// First Piola–Kirchhoff stress P(F) and, when A is not null, the tangent A = ∂P/∂F, in 3D at one
  /// point. Returns false when F is inadmissible for the law (det F ≤ 0 for finite-strain laws).
  /// Small-strain laws return P = σ(ε), ε = sym(F − I), and A = the elasticity tensor.
  virtual bool firstPiolaKirchhoff(const Tensor2& F, Tensor2& P, Tensor4* A) const = 0;

  /// The same at `count` points at once: the element kernels' entry, one virtual call per element
  /// and local iteration instead of one per Gauss point. A may be null. False if any point is
  /// inadmissible (P and A are then undefined).
  /// D = 2 is plane strain: F is the in-plane block of the deformation gradient (F_33 = 1 and
  /// F_i3 = F_3J = 0 implied), P and A are the in-plane blocks (A_iJkL with all four indices in the
  /// plane, the only components a 2D element contracts). P_33 does no work in plane strain and is
  /// not returned; output stresses come from cauchyStress on the 3 × 3 F.
  /// The defaults evaluate the 3D point function (embedding F in 3 × 3 for D = 2), so any law works
  /// in both dimensions; the laws of this package override them with their D-dimensional formula
  /// (MaterialLaw below).
  virtual bool firstPiolaKirchhoffAtPoints(int count, const Matrix<2>* F, Matrix<2>* P, Tangent<2>* A) const;
  virtual bool firstPiolaKirchhoffAtPoints(int count, const Matrix<3>* F, Matrix<3>* P, Tangent<3>* A) const;

  /// Cauchy stress σ = P Fᵀ / det F (small-strain laws: σ = P). False when F is inadmissible.
  virtual bool cauchyStress(const Tensor2& F, Tensor2& sigma) const;

  /// True for geometrically linear laws (the element then uses the small-strain kinematics).
  virtual bool isSmallStrain() const { return false; }

  /// True when A has major symmetry at every F, A_iJkL = A_kLiJ: a law with a stored energy W, for
  /// which A = ∂²W/∂F∂F. Hex8 Enhanced then builds only half of its tangent and condenses it
  /// with LDLᵀ (EnhancedStrainElement.hpp, kSymmetricPathPays). False unless a law says so.
  virtual bool tangentIsSymmetric() const { return false; }
};

/// Implements every Material entry from one dimension-general formula,
///   template <int D> bool Law::stress(const Matrix<D>& F, Matrix<D>& P, Tangent<D>* A) const,
/// evaluated with D = 3 in 3D and with D = 2 on the in-plane block in plane strain. That is exact for
/// the isotropic laws here: with F = diag(F_2D, 1) every in-plane component of P and A is the
/// D = 2 formula (e.g. det F = det F_2D, F⁻¹ = diag(F_2D⁻¹, 1), tr E = tr E_2D since E_33 = 0).
/// A law defines stress<D> in its .cpp file and instantiates MaterialLaw<Law> there (its header
/// declares the instantiation extern), so the point loops are compiled with the formula inlined.
template <class Law>
class MaterialLaw : public Material {
 public:
  bool firstPiolaKirchhoff(const Tensor2& F, Tensor2& P, Tensor4* A) const final {
    return law().template stress<3>(F, P, A);
  }
  bool firstPiolaKirchhoffAtPoints(int count, const Matrix<2>* F, Matrix<2>* P, Tangent<2>* A) const final {
    return atPoints<2>(count, F, P, A);
  }
  bool firstPiolaKirchhoffAtPoints(int count, const Matrix<3>* F, Matrix<3>* P, Tangent<3>* A) const final {
#if CONTESSA_KERNEL_AVX2
    // The 3D point loop is dispatched like Hex8 Enhanced's evaluation (KernelIsa.hpp), which calls it
    // through this virtual function and so could not inline it into its own AVX2 code: the law was
    // a quarter of that kernel's instructions, in SSE2 (bench/README.md, issue 23 seventh round).
    if (kernelIsa() == KernelIsa::Avx2) return atPointsAvx2(count, F, P, A);
#endif
    return atPoints<3>(count, F, P, A);
  }
  /// Every law of this package derives P from a stored energy (the small-strain one for Linear
  /// Elastic): MaterialTest checks the symmetry of each law's A.
  bool tangentIsSymmetric() const override { return true; }

 private:
  const Law& law() const { return static_cast<const Law&>(*this); }
  template <int D>
  bool atPoints(int count, const Matrix<D>* F, Matrix<D>* P, Tangent<D>* A) const {
    for (int q = 0; q < count; ++q)
      if (!law().template stress<D>(F[q], P[q], A ? A + q : nullptr)) return false;
    return true;
  }
#if CONTESSA_KERNEL_AVX2
  // The same loop for AVX2, the law's formula inlined into it; the same bits as atPoints<3> (no
  // fused multiply-adds: the target has none, and the laws' files are compiled without contraction).
  CONTESSA_TARGET_AVX2 bool atPointsAvx2(int count, const Matrix<3>* F, Matrix<3>* P, Tangent<3>* A) const {
    for (int q = 0; q < count; ++q)
      if (!law().template stress<3>(F[q], P[q], A ? A + q : nullptr)) return false;
    return true;
  }
#endif
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
