#include "mechanics/DenseSolve.hpp"

#include <cmath>
#include <utility>

namespace contessa::mechanics {

bool solveDenseInPlace(int n, double* A, int nrhs, double* B) {
  double maxAbs = 0.0;
  for (int k = 0; k < n * n; ++k) maxAbs = std::fmax(maxAbs, std::fabs(A[k]));
  if (!(maxAbs > 0.0) || !std::isfinite(maxAbs)) return false;
  const double tiny = 1e-14 * maxAbs;
  for (int c = 0; c < n; ++c) {
    int p = c;
    for (int r = c + 1; r < n; ++r)
      if (std::fabs(A[r * n + c]) > std::fabs(A[p * n + c])) p = r;
    if (!(std::fabs(A[p * n + c]) > tiny)) return false;
    if (p != c) {
      for (int k = 0; k < n; ++k) std::swap(A[c * n + k], A[p * n + k]);
      for (int k = 0; k < nrhs; ++k) std::swap(B[c * nrhs + k], B[p * nrhs + k]);
    }
    for (int r = c + 1; r < n; ++r) {
      const double factor = A[r * n + c] / A[c * n + c];
      if (factor == 0.0) continue;
      for (int k = c; k < n; ++k) A[r * n + k] -= factor * A[c * n + k];
      for (int k = 0; k < nrhs; ++k) B[r * nrhs + k] -= factor * B[c * nrhs + k];
    }
  }
  for (int c = n - 1; c >= 0; --c)
    for (int k = 0; k < nrhs; ++k) {
      double s = B[c * nrhs + k];
      for (int j = c + 1; j < n; ++j) s -= A[c * n + j] * B[j * nrhs + k];
      B[c * nrhs + k] = s / A[c * n + c];
    }
  return true;
}

}  // namespace contessa::mechanics
