#pragma once
// Gaussian elimination with partial pivoting for the small element-local systems (K_αα ≤ 9 × 9).

namespace contessa::mechanics {

/// Solves A X = B in place: A (n × n, row-major) is destroyed, B (n × nrhs, row-major) becomes X.
/// False when a pivot is zero or negligible (≤ 1e-14 · max |A_ij|) or not finite.
bool solveDenseInPlace(int n, double* A, int nrhs, double* B);

}  // namespace contessa::mechanics
