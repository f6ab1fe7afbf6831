#pragma once
// Small fixed-size tensors for constitutive and element code: plain arrays, row-major.
// Matrix<D> and Tangent<D> are the D-dimensional second- and fourth-order tensors the element kernels
// work with (D = 2 is plane strain: only the in-plane components exist, F_33 = 1 is implied).
// Tensor2 and Tensor4 are their 3 × 3 cases, used by the 3D material interface and for output stresses.
#include <array>

namespace contessa::mechanics {

template <int D>
using Matrix = std::array<double, D * D>;  ///< A_iJ at index D·i + J
template <int D>
using Tangent = std::array<double, D * D * D * D>;  ///< A_iJkL at index D³·i + D²·J + D·k + L

using Tensor2 = Matrix<3>;   ///< A_iJ at index 3*i + J
using Tensor4 = Tangent<3>;  ///< A_iJkL at index 27*i + 9*J + 3*k + L

inline constexpr int idx2(int i, int j) { return 3 * i + j; }
inline constexpr int idx4(int i, int j, int k, int l) { return 27 * i + 9 * j + 3 * k + l; }

Tensor2 identity2();
double determinant(const Tensor2& a);
Tensor2 inverse(const Tensor2& a);  ///< assumes det != 0
Tensor2 transpose(const Tensor2& a);
Tensor2 multiply(const Tensor2& a, const Tensor2& b);  ///< a · b

double trace(const Tensor2& a);
double doubleContraction(const Tensor2& a, const Tensor2& b);  ///< a : b = a_iJ b_iJ
double frobeniusNorm(const Tensor2& a);                        ///< sqrt(a : a)
Tensor2 add(const Tensor2& a, const Tensor2& b);               ///< a + b
Tensor2 scaled(double s, const Tensor2& a);                    ///< s a

// ---- D-dimensional versions (D = 2, 3), inline: they run at every integration point. ----

template <int D>
constexpr Matrix<D> identityMatrix() {
  Matrix<D> a{};
  for (int i = 0; i < D; ++i) a[D * i + i] = 1.0;
  return a;
}

template <int D>
inline double determinantOf(const Matrix<D>& a) {
  static_assert(D == 2 || D == 3);
  if constexpr (D == 2) {
    return a[0] * a[3] - a[1] * a[2];
  } else {
    return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
           a[2] * (a[3] * a[7] - a[4] * a[6]);
  }
}

/// a⁻¹ given det a (adjugate over determinant); assumes det != 0.
template <int D>
inline Matrix<D> inverseOf(const Matrix<D>& a, double det) {
  static_assert(D == 2 || D == 3);
  const double inv = 1.0 / det;
  if constexpr (D == 2) {
    return {a[3] * inv, -a[1] * inv, -a[2] * inv, a[0] * inv};
  } else {
    return {(a[4] * a[8] - a[5] * a[7]) * inv, (a[2] * a[7] - a[1] * a[8]) * inv,
            (a[1] * a[5] - a[2] * a[4]) * inv, (a[5] * a[6] - a[3] * a[8]) * inv,
            (a[0] * a[8] - a[2] * a[6]) * inv, (a[2] * a[3] - a[0] * a[5]) * inv,
            (a[3] * a[7] - a[4] * a[6]) * inv, (a[1] * a[6] - a[0] * a[7]) * inv,
            (a[0] * a[4] - a[1] * a[3]) * inv};
  }
}

/// The 3 × 3 tensor of a plane-strain Matrix<2> (F_33 = `out`, the other out-of-plane entries 0);
/// a Matrix<3> is returned unchanged.
template <int D>
inline Tensor2 embedIn3D(const Matrix<D>& a, double out) {
  if constexpr (D == 3) {
    (void)out;
    return a;
  } else {
    return {a[0], a[1], 0.0, a[2], a[3], 0.0, 0.0, 0.0, out};
  }
}

}  // namespace contessa::mechanics
