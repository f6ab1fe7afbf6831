#pragma once
// Shape functions written once, differentiated exactly: each reference element of the element families
// (Simplices.hpp, QuadraticCells.hpp, Wedges.hpp) writes its N_a(ξ) as a template on the number type, and
// ShapeFromValues evaluates it with doubles for N_a and with dual numbers (value + D partials, forward-mode
// differentiation) for ∂N_a/∂ξ. The gradients are then exact to round-off by construction, with no
// hand-derived formula to get wrong; they are computed once per element (SolidOperators.hpp), never in the
// residual or Jacobian loops, so the dual arithmetic costs nothing that matters.
#include <array>

namespace contessa::mechanics {

/// A value and its D partial derivatives.
template <int D>
struct Dual {
  double v = 0.0;
  std::array<double, D> d{};
  Dual() = default;
  Dual(double value) : v(value) {}  // NOLINT(google-explicit-constructor): constants mix freely
};

template <int D>
inline Dual<D> operator+(const Dual<D>& a, const Dual<D>& b) {
  Dual<D> r(a.v + b.v);
  for (int i = 0; i < D; ++i) r.d[i] = a.d[i] + b.d[i];
  return r;
}
template <int D>
inline Dual<D> operator-(const Dual<D>& a, const Dual<D>& b) {
  Dual<D> r(a.v - b.v);
  for (int i = 0; i < D; ++i) r.d[i] = a.d[i] - b.d[i];
  return r;
}
template <int D>
inline Dual<D> operator*(const Dual<D>& a, const Dual<D>& b) {
  Dual<D> r(a.v * b.v);
  for (int i = 0; i < D; ++i) r.d[i] = a.d[i] * b.v + a.v * b.d[i];
  return r;
}
template <int D>
inline Dual<D> operator+(double a, const Dual<D>& b) { return Dual<D>(a) + b; }
template <int D>
inline Dual<D> operator+(const Dual<D>& a, double b) { return a + Dual<D>(b); }
template <int D>
inline Dual<D> operator-(double a, const Dual<D>& b) { return Dual<D>(a) - b; }
template <int D>
inline Dual<D> operator-(const Dual<D>& a, double b) { return a - Dual<D>(b); }
template <int D>
inline Dual<D> operator*(double a, const Dual<D>& b) { return Dual<D>(a) * b; }
template <int D>
inline Dual<D> operator*(const Dual<D>& a, double b) { return a * Dual<D>(b); }

/// shapeValues and shapeGradients (the ReferenceElement.hpp interface) of a Shape that provides
///   template <class T> static void values(const T* xi, T* N);   // N_a(ξ), a < kNodes
template <class Shape, int D, int N>
struct ShapeFromValues {
  static void shapeValues(const double* xi, double* values) { Shape::values(xi, values); }
  /// ∂N_a/∂ξ_β at D·a + β.
  static void shapeGradients(const double* xi, double* dNdxi) {
    std::array<Dual<D>, D> x;
    for (int b = 0; b < D; ++b) {
      x[b] = Dual<D>(xi[b]);
      x[b].d[b] = 1.0;
    }
    std::array<Dual<D>, N> n;
    Shape::values(x.data(), n.data());
    for (int a = 0; a < N; ++a)
      for (int b = 0; b < D; ++b) dNdxi[D * a + b] = n[a].d[b];
  }
};

}  // namespace contessa::mechanics
