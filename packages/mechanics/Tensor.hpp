#pragma once
// Small fixed-size tensors for constitutive and element code: plain arrays, row-major, 3 × 3 always
// (plane strain embeds the 2D deformation with F_33 = 1), so 2D and 3D share one material code.
#include <array>

namespace contessa::mechanics {

using Tensor2 = std::array<double, 9>;   ///< A_iJ at index 3*i + J
using Tensor4 = std::array<double, 81>;  ///< A_iJkL at index 27*i + 9*J + 3*k + L

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

}  // namespace contessa::mechanics
