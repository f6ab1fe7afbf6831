#pragma once
// How the element DOFs become the deformation gradient a material sees, and how stress comes back as
// nodal forces: the one place where plane strain, 3D and axisymmetry differ inside the solid kernels
// (DisplacementElement, EnhancedStrainElement take one of these as a template parameter).
//
//   PlanarKinematics<D>    D = 2 plane strain (F_33 = 1 implied) or D = 3: the law works on the
//                          D × D gradient, GRAD u = Σ_a u_a ⊗ ∂N_a/∂X.
//   AxisymmetricKinematics a 2D mesh in the (r, z) = (x, y) half plane, revolved about the y axis: the
//                          law works on the 3 × 3 gradient diag-block (F_rz block, F_θθ) with the hoop
//                          stretch F_θθ = 1 + u_r / R (R = Σ N_a X_a,r, the reference radius), and every
//                          integral runs over the full circumference, dV = 2π R dA (Hughes, The Finite
//                          Element Method, §2.12; Zienkiewicz & Taylor vol. 1, ch. 6).
//
// An operator takes a list of Count gradient vectors g_a (D components each) and, for axisymmetry,
// their hoop coefficients c_a = N_a / R (null: none, as for the enhanced modes, which carry no hoop
// strain). The planar operators are the ones in SolidOperators.hpp, unchanged.
#include <array>
#include <cmath>

#include "mechanics/SolidOperators.hpp"
#include "mechanics/Tensor.hpp"

namespace contessa::mechanics {

template <int D>
struct PlanarKinematics {
  static constexpr int kDimension = D;          ///< displacement components per node
  static constexpr int kMaterialDimension = D;  ///< the law is evaluated on a kMaterialDimension² F
  static constexpr bool kHoop = false;

  /// The point ξ of a Shape element with reference coordinates X: the scale of its integration weight
  /// w j and the hoop coefficients of its shape functions. Nothing in the plane; always valid.
  template <class Shape>
  static bool revolve(const double* /*xi*/, const double* /*X*/, double& /*weightedVolume*/, double* /*hoop*/) {
    return true;
  }
  /// The factor of dV / (j dξ) at ξ: 1 in the plane.
  template <class Shape>
  static double measureFactor(const double* /*xi*/, const double* /*X*/) {
    return 1.0;
  }
  /// H += Σ_a v_a ⊗ g_a.
  template <int Count>
  static void addGradient(const double* g, const double* /*hoop*/, const double* v, Matrix<D>& H) {
    mechanics::addGradient<D, Count>(g, v, H);
  }
  /// r_a += P g_a · wj.
  template <int Count>
  static void addDivergence(const double* g, const double* /*hoop*/, const Matrix<D>& P, double wj, double* r) {
    mechanics::addDivergence<D, Count>(g, P, wj, r);
  }
  /// K_(ai),(bk) += g_aJ A_iJkL h_bL · wj.
  template <int Rows, int Cols>
  static void addTangent(const double* g, const double* /*hoopG*/, const double* h, const double* /*hoopH*/,
                         const Tangent<D>& A, double wj, double* K, int ld) {
    mechanics::addTangent<D, Rows, Cols>(g, h, A, wj, K, ld);
  }
  /// addTangent with h = g for a major-symmetric A: the blocks b ≥ a only (mirrorUpperTriangle completes K),
  /// assigned instead of added at the `first` point.
  template <int Count>
  static void addSymmetricTangent(const double* g, const double* /*hoop*/, const Tangent<D>& A, double wj, double* K,
                                  int ld, bool first) {
    mechanics::addSymmetricTangent<D, Count>(g, A, wj, K, ld, first);
  }
  /// The 3 × 3 F for output stresses (plane strain: F_33 = 1).
  static Tensor2 threeByThree(const Matrix<D>& F) { return embedIn3D<D>(F, 1.0); }
};

struct AxisymmetricKinematics {
  static constexpr int kDimension = 2, kMaterialDimension = 3;
  static constexpr bool kHoop = true;
  static constexpr int kHoopIndex = 8;  ///< θθ in a Matrix<3> (row-major index 3·2 + 2)

  /// dV = 2π R w j and c_a = N_a / R at ξ. False when R ≤ 0 (the element reaches the axis' other side,
  /// or lies on it): such an element cannot be revolved.
  template <class Shape>
  static bool revolve(const double* xi, const double* X, double& weightedVolume, double* hoop) {
    std::array<double, Shape::kNodes> N{};
    Shape::shapeValues(xi, N.data());
    const double R = radius<Shape>(N.data(), X);
    if (!(R > 0.0)) return false;
    weightedVolume *= 2.0 * M_PI * R;
    for (int a = 0; a < Shape::kNodes; ++a) hoop[a] = N[a] / R;
    return true;
  }
  /// The factor of dV / (j dξ) at ξ, up to the constant 2π: the reference radius R.
  template <class Shape>
  static double measureFactor(const double* xi, const double* X) {
    std::array<double, Shape::kNodes> N{};
    Shape::shapeValues(xi, N.data());
    return radius<Shape>(N.data(), X);
  }
  /// The in-plane block H_ij += Σ_a v_ai g_aj and the hoop term H_θθ += Σ_a c_a v_a,r.
  template <int Count>
  static void addGradient(const double* g, const double* hoop, const double* v, Matrix<3>& H) {
    for (int a = 0; a < Count; ++a)
      for (int i = 0; i < 2; ++i)
        for (int J = 0; J < 2; ++J) H[3 * i + J] += v[2 * a + i] * g[2 * a + J];
    if (hoop)
      for (int a = 0; a < Count; ++a) H[kHoopIndex] += hoop[a] * v[2 * a];
  }
  /// r_ai += P_iJ g_aJ · wj (in-plane) and r_a,r += P_θθ c_a · wj: the virtual hoop strain δu_r / R.
  template <int Count>
  static void addDivergence(const double* g, const double* hoop, const Matrix<3>& P, double wj, double* r) {
    mechanics::addDivergence<2, Count>(g, inPlane(P), wj, r);
    if (hoop)
      for (int a = 0; a < Count; ++a) r[2 * a] += P[kHoopIndex] * hoop[a] * wj;
  }
  /// The derivative of addDivergence: the in-plane block of A between in-plane gradients, plus the
  /// couplings through the hoop strain (A_θθkL, A_iJθθ and A_θθθθ).
  template <int Rows, int Cols>
  static void addTangent(const double* g, const double* hoopG, const double* h, const double* hoopH,
                         const Tangent<3>& A, double wj, double* K, int ld) {
    Tangent<2> planar;
    for (int i = 0; i < 2; ++i)
      for (int J = 0; J < 2; ++J)
        for (int k = 0; k < 2; ++k)
          for (int L = 0; L < 2; ++L) planar[8 * i + 4 * J + 2 * k + L] = A[idx4(i, J, k, L)];
    mechanics::addTangent<2, Rows, Cols>(g, h, planar, wj, K, ld);
    if (hoopG)  // row (a, r): c_a A_θθkL h_bL
      for (int a = 0; a < Rows; ++a) {
        double* row = K + static_cast<std::size_t>(2 * a) * ld;
        for (int b = 0; b < Cols; ++b)
          for (int k = 0; k < 2; ++k) {
            double s = 0.0;
            for (int L = 0; L < 2; ++L) s += A[idx4(2, 2, k, L)] * h[2 * b + L];
            row[2 * b + k] += hoopG[a] * s * wj;
          }
      }
    if (hoopH)  // column (b, r): g_aJ A_iJθθ c_b
      for (int a = 0; a < Rows; ++a)
        for (int i = 0; i < 2; ++i) {
          double s = 0.0;
          for (int J = 0; J < 2; ++J) s += g[2 * a + J] * A[idx4(i, J, 2, 2)];
          double* row = K + static_cast<std::size_t>(2 * a + i) * ld;
          for (int b = 0; b < Cols; ++b) row[2 * b] += s * hoopH[b] * wj;
        }
    if (hoopG && hoopH)
      for (int a = 0; a < Rows; ++a)
        for (int b = 0; b < Cols; ++b)
          K[static_cast<std::size_t>(2 * a) * ld + 2 * b] += hoopG[a] * A[idx4(2, 2, 2, 2)] * hoopH[b] * wj;
  }
  static Tensor2 threeByThree(const Matrix<3>& F) { return F; }

 private:
  template <class Shape>
  static double radius(const double* N, const double* X) {
    double R = 0.0;
    for (int a = 0; a < Shape::kNodes; ++a) R += N[a] * X[2 * a];
    return R;
  }
  static Matrix<2> inPlane(const Matrix<3>& P) { return {P[0], P[1], P[3], P[4]}; }
};

}  // namespace contessa::mechanics
