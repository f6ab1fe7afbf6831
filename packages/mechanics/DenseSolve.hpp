#pragma once
// Dense solvers for the small element-local systems (K_αα ≤ 9 × 9), sizes fixed at compile time so
// the loops unroll and nothing is allocated: Gaussian elimination with partial pivoting for any
// matrix, and LDLᵀ without pivoting for the symmetric positive definite ones (half the operations,
// and a Schur complement that stays symmetric; Golub & Van Loan, Matrix Computations, §4.1–4.2).
#include <algorithm>
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

/// LDLᵀ of a symmetric positive definite A (N × N, row-major; only the lower triangle is read), in
/// place: L (unit diagonal implied) strictly below the diagonal, D on it. No pivoting, which is
/// backward stable when every pivot is positive (Golub & Van Loan §4.2.3), so the factorisation is
/// refused — false, A then undefined — as soon as a pivot is not > 1e-14 · max |A_ij| (A indefinite,
/// or singular to working precision) or not finite: the caller then pivots (solveDenseInPlace).
template <int N>
bool factorPositiveDefinite(double* A) {
  double maxAbs = 0.0;
  for (int r = 0; r < N; ++r)
    for (int c = 0; c <= r; ++c)
      if (std::fabs(A[r * N + c]) > maxAbs) maxAbs = std::fabs(A[r * N + c]);
  if (!(maxAbs > 0.0) || !std::isfinite(maxAbs)) return false;
  const double tiny = 1e-14 * maxAbs;
  for (int j = 0; j < N; ++j) {
    double ld[N];  // L_jk d_k, k < j
    double d = A[j * N + j];
    for (int k = 0; k < j; ++k) {
      ld[k] = A[j * N + k] * A[k * N + k];
      d -= A[j * N + k] * ld[k];
    }
    if (!(d > tiny) || !std::isfinite(d)) return false;
    A[j * N + j] = d;
    const double inverse = 1.0 / d;
    for (int i = j + 1; i < N; ++i) {
      double s = A[i * N + j];
      for (int k = 0; k < j; ++k) s -= A[i * N + k] * ld[k];
      A[i * N + j] = s * inverse;
    }
  }
  return true;
}

/// B ← L⁻¹ B with the unit lower L of factorPositiveDefinite (B: N × R, row-major).
template <int N, int R>
void forwardSubstitute(const double* LD, double* B) {
  for (int i = 1; i < N; ++i)
    for (int k = 0; k < i; ++k) {
      const double l = LD[i * N + k];
      for (int c = 0; c < R; ++c) B[i * R + c] -= l * B[k * R + c];
    }
}

/// B ← L⁻ᵀ B (B: N × R, row-major).
template <int N, int R>
void backSubstitute(const double* LD, double* B) {
  for (int i = N - 2; i >= 0; --i)
    for (int k = i + 1; k < N; ++k) {
      const double l = LD[k * N + i];
      for (int c = 0; c < R; ++c) B[i * R + c] -= l * B[k * R + c];
    }
}

/// Solves A X = B in place for a symmetric A (N × N, row-major, both triangles given; destroyed),
/// B (N × R) becoming X: LDLᵀ when A is positive definite, else Gaussian elimination with partial
/// pivoting on the copy kept for that. False when both refuse (A singular to working precision).
template <int N, int R>
bool solveSymmetricInPlace(double* A, double* B) {
  double copy[N * N];
  std::copy(A, A + N * N, copy);
  if (!factorPositiveDefinite<N>(A)) return solveDenseInPlace<N, R>(copy, B);
  forwardSubstitute<N, R>(A, B);
  for (int i = 0; i < N; ++i) {
    const double inverse = 1.0 / A[i * N + i];
    for (int c = 0; c < R; ++c) B[i * R + c] *= inverse;
  }
  backSubstitute<N, R>(A, B);
  return true;
}

}  // namespace contessa::mechanics
