#pragma once
// Forward-mode dual numbers for the mortar kernels: a value of type T and N partial derivatives of type T.
// With T = double they carry a gradient; nested, Dual<Dual<double, N>, N>, they carry the gradient and the
// Hessian, so the weighted gaps of a slave × master segment pair (MortarSegment.hpp) are differentiated
// twice, exactly to round-off, including the dependence of the clip points and the normal on the nodes.
// mechanics/ShapeFunctions.hpp has a smaller dual (no division, no square root, not nestable) and contact
// may not include mechanics (docs/architecture.md, package order), hence this one.
#include <array>
#include <cmath>

namespace contessa::contact {

template <class T, int N>
struct Dual {
  T v{};
  std::array<T, N> d{};
  Dual() = default;
  Dual(double value) : v(value) {}  // NOLINT(google-explicit-constructor): constants mix freely
  Dual(const T& value, const std::array<T, N>& partials) : v(value), d(partials) {}
};

/// The value of a number at the innermost level (a double stays a double).
inline double valueOf(double x) { return x; }
template <class T, int N>
double valueOf(const Dual<T, N>& x) {
  return valueOf(x.v);
}

template <class T, int N>
Dual<T, N> operator+(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r(a.v + b.v, {});
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] + b.d[i];
  return r;
}
template <class T, int N>
Dual<T, N> operator-(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r(a.v - b.v, {});
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] - b.d[i];
  return r;
}
template <class T, int N>
Dual<T, N> operator-(const Dual<T, N>& a) {
  Dual<T, N> r(-a.v, {});
  for (int i = 0; i < N; ++i) r.d[i] = -a.d[i];
  return r;
}
template <class T, int N>
Dual<T, N> operator*(const Dual<T, N>& a, const Dual<T, N>& b) {
  Dual<T, N> r(a.v * b.v, {});
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] * b.v + a.v * b.d[i];
  return r;
}
template <class T, int N>
Dual<T, N> operator/(const Dual<T, N>& a, const Dual<T, N>& b) {
  const T q = a.v / b.v;
  Dual<T, N> r(q, {});
  for (int i = 0; i < N; ++i) r.d[i] = (a.d[i] - q * b.d[i]) / b.v;
  return r;
}
template <class T, int N>
Dual<T, N> sqrt(const Dual<T, N>& a) {
  using std::sqrt;
  const T s = sqrt(a.v);
  Dual<T, N> r(s, {});
  for (int i = 0; i < N; ++i) r.d[i] = a.d[i] / (2.0 * s);
  return r;
}

// Mixed with plain doubles (constants of the kernels).
template <class T, int N>
Dual<T, N> operator+(double a, const Dual<T, N>& b) { return Dual<T, N>(a) + b; }
template <class T, int N>
Dual<T, N> operator+(const Dual<T, N>& a, double b) { return a + Dual<T, N>(b); }
template <class T, int N>
Dual<T, N> operator-(double a, const Dual<T, N>& b) { return Dual<T, N>(a) - b; }
template <class T, int N>
Dual<T, N> operator-(const Dual<T, N>& a, double b) { return a - Dual<T, N>(b); }
template <class T, int N>
Dual<T, N> operator*(double a, const Dual<T, N>& b) { return Dual<T, N>(a) * b; }
template <class T, int N>
Dual<T, N> operator*(const Dual<T, N>& a, double b) { return a * Dual<T, N>(b); }
template <class T, int N>
Dual<T, N> operator/(const Dual<T, N>& a, double b) { return a / Dual<T, N>(b); }
template <class T, int N>
Dual<T, N> operator/(double a, const Dual<T, N>& b) { return Dual<T, N>(a) / b; }

/// A number whose value is x and whose first and second derivatives are seeded along variable i (of
/// N): the independent variable x_i of a twice-differentiated function.
template <int N>
Dual<Dual<double, N>, N> secondOrderVariable(double x, int i) {
  Dual<Dual<double, N>, N> r(x);
  r.v.d[i] = 1.0;
  r.d[i].v = 1.0;
  return r;
}

}  // namespace contessa::contact
