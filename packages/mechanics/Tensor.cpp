// Small 3 × 3 tensor algebra (see Tensor.hpp) for the 3D material interface and output stresses.
#include "mechanics/Tensor.hpp"

#include <cmath>

namespace contessa::mechanics {

Tensor2 identity2() { return identityMatrix<3>(); }

double determinant(const Tensor2& a) { return determinantOf<3>(a); }

Tensor2 inverse(const Tensor2& a) { return inverseOf<3>(a, determinant(a)); }

Tensor2 transpose(const Tensor2& a) { return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]}; }

Tensor2 multiply(const Tensor2& a, const Tensor2& b) {
  Tensor2 c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c[idx2(i, j)] += a[idx2(i, k)] * b[idx2(k, j)];
  return c;
}

double trace(const Tensor2& a) { return a[0] + a[4] + a[8]; }

double doubleContraction(const Tensor2& a, const Tensor2& b) {
  double s = 0.0;
  for (int n = 0; n < 9; ++n) s += a[n] * b[n];
  return s;
}

double frobeniusNorm(const Tensor2& a) { return std::sqrt(doubleContraction(a, a)); }

Tensor2 add(const Tensor2& a, const Tensor2& b) {
  Tensor2 c{};
  for (int n = 0; n < 9; ++n) c[n] = a[n] + b[n];
  return c;
}

Tensor2 scaled(double s, const Tensor2& a) {
  Tensor2 c{};
  for (int n = 0; n < 9; ++n) c[n] = s * a[n];
  return c;
}

}  // namespace contessa::mechanics
