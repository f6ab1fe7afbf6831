#pragma once
// Small fixed-size vectors and dense matrices for the local contact kernels (no Eigen, no heap).
// Contact kernels live at one slave node at a time (6 dofs in 2D, 15 in 3D), so everything fits on the
// stack; the assembly scatters these blocks into Tpetra storage elsewhere.
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>

namespace contessa::contact {

/// Column vector of N doubles.
template <int N>
using Vector = std::array<double, static_cast<std::size_t>(N)>;

/// Blocks template argument deduction (the vector size follows from the matrix argument).
template <class T>
struct NonDeduced {
  using type = T;
};
template <class T>
using NonDeducedT = typename NonDeduced<T>::type;

/// Dense R × C matrix stored row-major in a std::array.
template <int R, int C>
struct Matrix {
  static constexpr int kRows = R;
  static constexpr int kCols = C;
  std::array<double, static_cast<std::size_t>(R * C)> entries{};

  double& operator()(int i, int j) { return entries[static_cast<std::size_t>(i * C + j)]; }
  double operator()(int i, int j) const { return entries[static_cast<std::size_t>(i * C + j)]; }
};

template <std::size_t N>
double dot(const std::array<double, N>& a, const std::array<double, N>& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < N; ++i) s += a[i] * b[i];
  return s;
}

template <std::size_t N>
double norm(const std::array<double, N>& a) {
  return std::sqrt(dot(a, a));
}

template <std::size_t N>
std::array<double, N> add(const std::array<double, N>& a, const std::array<double, N>& b) {
  std::array<double, N> c{};
  for (std::size_t i = 0; i < N; ++i) c[i] = a[i] + b[i];
  return c;
}

template <std::size_t N>
std::array<double, N> subtract(const std::array<double, N>& a, const std::array<double, N>& b) {
  std::array<double, N> c{};
  for (std::size_t i = 0; i < N; ++i) c[i] = a[i] - b[i];
  return c;
}

template <std::size_t N>
std::array<double, N> scaled(double s, const std::array<double, N>& a) {
  std::array<double, N> c{};
  for (std::size_t i = 0; i < N; ++i) c[i] = s * a[i];
  return c;
}

/// y += s x
template <std::size_t N>
void addScaled(std::array<double, N>& y, double s, const std::array<double, N>& x) {
  for (std::size_t i = 0; i < N; ++i) y[i] += s * x[i];
}

/// A += s x yᵀ (rows from x, columns from y).
template <int R, int C>
void addOuter(Matrix<R, C>& a, double s, const NonDeducedT<Vector<R>>& x, const NonDeducedT<Vector<C>>& y) {
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j) a(i, j) += s * x[i] * y[j];
}

/// A += s B
template <int R, int C>
void addScaled(Matrix<R, C>& a, double s, const Matrix<R, C>& b) {
  for (std::size_t k = 0; k < a.entries.size(); ++k) a.entries[k] += s * b.entries[k];
}

template <int R, int C>
Matrix<C, R> transpose(const Matrix<R, C>& a) {
  Matrix<C, R> t;
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j) t(j, i) = a(i, j);
  return t;
}

template <int R, int K, int C>
Matrix<R, C> multiply(const Matrix<R, K>& a, const Matrix<K, C>& b) {
  Matrix<R, C> c;
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j) {
      double s = 0.0;
      for (int k = 0; k < K; ++k) s += a(i, k) * b(k, j);
      c(i, j) = s;
    }
  return c;
}

template <int R, int C>
Vector<R> multiply(const Matrix<R, C>& a, const NonDeducedT<Vector<C>>& x) {
  Vector<R> y{};
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j) y[i] += a(i, j) * x[j];
  return y;
}

template <int R, int C>
Matrix<R, C> scaled(double s, const Matrix<R, C>& a) {
  Matrix<R, C> b;
  for (std::size_t k = 0; k < a.entries.size(); ++k) b.entries[k] = s * a.entries[k];
  return b;
}

/// Frobenius norm.
template <int R, int C>
double frobeniusNorm(const Matrix<R, C>& a) {
  double s = 0.0;
  for (double v : a.entries) s += v * v;
  return std::sqrt(s);
}

template <int N>
Matrix<N, N> identityMatrix() {
  Matrix<N, N> m;
  for (int i = 0; i < N; ++i) m(i, i) = 1.0;
  return m;
}

template <int N>
double determinant(const Matrix<N, N>& a) {
  static_assert(N >= 1 && N <= 3, "determinant: only 1x1, 2x2 and 3x3 are needed for surface metrics");
  if constexpr (N == 1) {
    return a(0, 0);
  } else if constexpr (N == 2) {
    return a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0);
  } else {
    return a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)) - a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0)) +
           a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0));
  }
}

/// Inverse of a 1×1 or 2×2 matrix (surface metrics a_αβ and Newton Jacobians in ξ^α). Assumes det ≠ 0.
template <int N>
Matrix<N, N> inverse(const Matrix<N, N>& a) {
  static_assert(N == 1 || N == 2, "inverse: surface quantities have one or two coordinates");
  Matrix<N, N> inv;
  const double det = determinant(a);
  assert(det != 0.0);
  if constexpr (N == 1) {
    inv(0, 0) = 1.0 / det;
  } else {
    inv(0, 0) = a(1, 1) / det;
    inv(0, 1) = -a(0, 1) / det;
    inv(1, 0) = -a(1, 0) / det;
    inv(1, 1) = a(0, 0) / det;
  }
  return inv;
}

inline Vector<3> cross(const Vector<3>& a, const Vector<3>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace contessa::contact
