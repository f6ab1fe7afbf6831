#pragma once
// Gaussian elimination with partial pivoting for the small element-local systems (K_αα ≤ 9 × 9),
// sizes fixed at compile time so the loops unroll and nothing is allocated.
#include <cmath>
#include <utility>

namespace contessa::mechanics {

/// Solves A X = B in place: A (N × N, row-major) is destroyed, B (N × R, row-major) becomes X.
/// False when a pivot is zero or negligible (≤ 1e-14 · max |A_ij|) or not finite.
template <int N, int R>
bool solveDenseInPlace(double* A, double* B) {
  double maxAbs = 0.0;  // NaN entries are skipped here (as fmax would) and fail the pivot test below
  for (int k = 0; k < N * N; ++k)
    if (std::fabs(A[k]) > maxAbs) maxAbs = std::fabs(A[k]);
  if (!(maxAbs > 0.0) || !std::isfinite(maxAbs)) return false;
  const double tiny = 1e-14 * maxAbs;
  double inversePivot[N];  // one division per column, multiplications elsewhere
  for (int c = 0; c < N; ++c) {
    int p = c;
    for (int r = c + 1; r < N; ++r)
      if (std::fabs(A[r * N + c]) > std::fabs(A[p * N + c])) p = r;
    if (!(std::fabs(A[p * N + c]) > tiny)) return false;
    if (p != c) {
      for (int k = 0; k < N; ++k) std::swap(A[c * N + k], A[p * N + k]);
      for (int k = 0; k < R; ++k) std::swap(B[c * R + k], B[p * R + k]);
    }
    inversePivot[c] = 1.0 / A[c * N + c];
    for (int r = c + 1; r < N; ++r) {
      const double factor = A[r * N + c] * inversePivot[c];
      if (factor == 0.0) continue;
      for (int k = c; k < N; ++k) A[r * N + k] -= factor * A[c * N + k];
      for (int k = 0; k < R; ++k) B[r * R + k] -= factor * B[c * R + k];
    }
  }
  for (int c = N - 1; c >= 0; --c)
    for (int k = 0; k < R; ++k) {
      double s = B[c * R + k];
      for (int j = c + 1; j < N; ++j) s -= A[c * N + j] * B[j * R + k];
      B[c * R + k] = s * inversePivot[c];
    }
  return true;
}

}  // namespace contessa::mechanics
