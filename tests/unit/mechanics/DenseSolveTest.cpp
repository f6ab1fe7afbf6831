// The element-local dense solvers (DenseSolve.hpp): LDLᵀ of a symmetric positive definite matrix
// against Gaussian elimination with partial pivoting, and its refusal of an indefinite one, where
// solveSymmetricInPlace must still solve by pivoting.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>

#include "mechanics/DenseSolve.hpp"

namespace contessa::mechanics::test {
namespace {

constexpr int N = 9, R = 4;

/// A symmetric 9 × 9 matrix Bᵀ B + shift I (B random): positive definite for shift > 0, indefinite
/// for a shift between minus the largest and minus the smallest eigenvalue of Bᵀ B.
std::array<double, N * N> symmetricMatrix(unsigned seed, double shift) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  std::array<double, N * N> B{}, A{};
  for (double& b : B) b = dist(gen);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j) {
      double s = i == j ? shift : 0.0;
      for (int k = 0; k < N; ++k) s += B[k * N + i] * B[k * N + j];
      A[i * N + j] = s;
    }
  return A;
}

std::array<double, N * R> rightHandSides() {
  std::array<double, N * R> b{};
  for (int k = 0; k < N * R; ++k) b[k] = std::sin(1.0 + k);
  return b;
}

/// max |A X − B| / max |B|.
double residual(const std::array<double, N * N>& A, const std::array<double, N * R>& X, const std::array<double, N * R>& B) {
  double r = 0.0, b = 0.0;
  for (int i = 0; i < N; ++i)
    for (int c = 0; c < R; ++c) {
      double s = -B[i * R + c];
      for (int k = 0; k < N; ++k) s += A[i * N + k] * X[k * R + c];
      r = std::max(r, std::fabs(s));
      b = std::max(b, std::fabs(B[i * R + c]));
    }
  return r / b;
}

TEST(DenseSolve, LdltOfPositiveDefiniteMatrixSolvesLikeGaussianElimination) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const auto A = symmetricMatrix(seed, 0.1);
    auto LD = A;
    ASSERT_TRUE(factorPositiveDefinite<N>(LD.data()));
    auto xs = rightHandSides(), xg = rightHandSides();
    auto copy = A;
    ASSERT_TRUE((solveSymmetricInPlace<N, R>(copy.data(), xs.data())));
    copy = A;
    ASSERT_TRUE((solveDenseInPlace<N, R>(copy.data(), xg.data())));
    EXPECT_LT(residual(A, xs, rightHandSides()), 1e-12);
    double diff = 0.0, size = 0.0;
    for (int k = 0; k < N * R; ++k) diff = std::max(diff, std::fabs(xs[k] - xg[k])), size = std::max(size, std::fabs(xg[k]));
    EXPECT_LT(diff, 1e-11 * size) << "seed " << seed;
  }
}

TEST(DenseSolve, IndefiniteMatrixIsRefusedByLdltAndSolvedByPivoting) {
  // Bᵀ B − 2 I has eigenvalues of both signs: those of Bᵀ B (B with entries of variance 1/3) spread
  // from near 0 to about 4 N / 3 = 12. LDLᵀ without pivoting then meets a pivot ≤ 0.
  const auto A = symmetricMatrix(5, -2.0);
  auto LD = A;
  EXPECT_FALSE(factorPositiveDefinite<N>(LD.data()));
  auto x = rightHandSides();
  auto copy = A;
  ASSERT_TRUE((solveSymmetricInPlace<N, R>(copy.data(), x.data())));
  EXPECT_LT(residual(A, x, rightHandSides()), 1e-10);
}

TEST(DenseSolve, SingularMatrixIsRefused) {
  std::array<double, N * N> A{};
  for (int i = 0; i < N - 1; ++i) A[i * N + i] = 1.0;  // the last row and column zero
  auto x = rightHandSides();
  auto copy = A;
  EXPECT_FALSE(factorPositiveDefinite<N>(copy.data()));
  copy = A;
  EXPECT_FALSE((solveSymmetricInPlace<N, R>(copy.data(), x.data())));
}

}  // namespace
}  // namespace contessa::mechanics::test
