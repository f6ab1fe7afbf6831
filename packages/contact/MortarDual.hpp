#pragma once
// Forward-mode dual numbers for the mortar kernels: a value of type T and N partial derivatives of type T.
// With T = double they carry a gradient; nested, Dual<Dual<double, N>, N>, they carry the gradient and the
// Hessian, so the weighted gaps of a slave × master segment pair (MortarSegment.hpp) are differentiated
// twice, exactly to round-off, including the dependence of the clip points and the normal on the nodes.
// mechanics/ShapeFunctions.hpp has a smaller dual (no division, no square root, not nestable) and contact
// may not include mechanics (docs/architecture.md, package order), hence this one.
#include <array>
#include <type_traits>
#include <vector>
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

/// A number with its gradient and Hessian over N variables, the Hessian's upper triangle stored once
/// (packed row by row: (i, j ≥ i) at i N − i (i − 1)/2 + j − i). Carries what Dual<Dual<double, N>, N>
/// carries, without its duplicate gradient (v.d and d[·].v) and its duplicate Hessian half: a product costs
/// about N²/2 multiply-adds of four terms against the nested duals' N² of inner dual products, and a
/// quotient or square root applies the chain rule once (f', f'') instead of differentiating the inner
/// operations again. Constants (doubles mixed in) scale or shift without forming a number.
template <int N>
struct HessianDual {
  static constexpr int kPacked = N * (N + 1) / 2;
  double v;
  std::array<double, N> g;
  std::array<double, kPacked> h;
  HessianDual() : HessianDual(0.0) {}
  HessianDual(double value) : v(value) {  // NOLINT(google-explicit-constructor): constants mix freely
    g.fill(0.0);
    h.fill(0.0);
  }
  /// The operations' results, every derivative written next: not zeroed first.
  struct Unset {};
  HessianDual(double value, Unset) : v(value) {}  // NOLINT(cppcoreguidelines-pro-type-member-init)

  static constexpr int packed(int i, int j) { return i * N - i * (i - 1) / 2 + (j - i); }
  double gradient(int i) const { return g[i]; }
  double hessian(int i, int j) const { return i <= j ? h[packed(i, j)] : h[packed(j, i)]; }
};

template <int N>
double valueOf(const HessianDual<N>& x) {
  return x.v;
}

namespace hessian_dual_detail {
/// r.g = fa a.g + fb b.g, r.h = fa a.h + fb b.h + c (a.g ⊗ b.g + b.g ⊗ a.g): the second-order chain rule of
/// r = f(a, b) with f's first derivatives (fa, fb) and mixed second derivative c (∂²f/∂a² = ∂²f/∂b² = 0).
template <int N>
void combine(HessianDual<N>& r, const HessianDual<N>& a, double fa, const HessianDual<N>& b, double fb, double c) {
  for (int i = 0; i < N; ++i) r.g[i] = fa * a.g[i] + fb * b.g[i];
  int k = 0;
  for (int i = 0; i < N; ++i) {
    const double ai = c * a.g[i], bi = c * b.g[i];
    for (int j = i; j < N; ++j, ++k) r.h[k] = fa * a.h[k] + fb * b.h[k] + ai * b.g[j] + bi * a.g[j];
  }
}
/// r = f(a) with f'(a) = d1, f''(a) = d2.
template <int N>
HessianDual<N> apply(const HessianDual<N>& a, double value, double d1, double d2) {
  HessianDual<N> r(value, typename HessianDual<N>::Unset{});
  for (int i = 0; i < N; ++i) r.g[i] = d1 * a.g[i];
  int k = 0;
  for (int i = 0; i < N; ++i) {
    const double ai = d2 * a.g[i];
    for (int j = i; j < N; ++j, ++k) r.h[k] = d1 * a.h[k] + ai * a.g[j];
  }
  return r;
}
}  // namespace hessian_dual_detail

template <int N>
HessianDual<N> operator+(const HessianDual<N>& a, const HessianDual<N>& b) {
  HessianDual<N> r(a.v + b.v, typename HessianDual<N>::Unset{});
  for (int i = 0; i < N; ++i) r.g[i] = a.g[i] + b.g[i];
  for (int k = 0; k < HessianDual<N>::kPacked; ++k) r.h[k] = a.h[k] + b.h[k];
  return r;
}
template <int N>
HessianDual<N> operator-(const HessianDual<N>& a, const HessianDual<N>& b) {
  HessianDual<N> r(a.v - b.v, typename HessianDual<N>::Unset{});
  for (int i = 0; i < N; ++i) r.g[i] = a.g[i] - b.g[i];
  for (int k = 0; k < HessianDual<N>::kPacked; ++k) r.h[k] = a.h[k] - b.h[k];
  return r;
}
template <int N>
HessianDual<N> operator-(const HessianDual<N>& a) {
  HessianDual<N> r(-a.v, typename HessianDual<N>::Unset{});
  for (int i = 0; i < N; ++i) r.g[i] = -a.g[i];
  for (int k = 0; k < HessianDual<N>::kPacked; ++k) r.h[k] = -a.h[k];
  return r;
}
template <int N>
HessianDual<N> operator*(const HessianDual<N>& a, const HessianDual<N>& b) {
  HessianDual<N> r(a.v * b.v, typename HessianDual<N>::Unset{});
  hessian_dual_detail::combine(r, a, b.v, b, a.v, 1.0);
  return r;
}
/// q = a / b: from a = q b, q'' = (a'' − q b'' − q' ⊗ b' − b' ⊗ q') / b. The value and the gradient are
/// rounded as Dual's (divided, not multiplied by 1/b): the residual, −p ∇g̃, is then the nested duals' to
/// the bit, and the finite-difference checks of the tangent see the same residuals.
template <int N>
HessianDual<N> operator/(const HessianDual<N>& a, const HessianDual<N>& b) {
  const double inverse = 1.0 / b.v;
  HessianDual<N> r(a.v / b.v, typename HessianDual<N>::Unset{});
  for (int i = 0; i < N; ++i) r.g[i] = (a.g[i] - r.v * b.g[i]) / b.v;
  int k = 0;
  for (int i = 0; i < N; ++i)
    for (int j = i; j < N; ++j, ++k)
      r.h[k] = (a.h[k] - r.v * b.h[k] - r.g[i] * b.g[j] - b.g[i] * r.g[j]) * inverse;
  return r;
}
template <int N>
HessianDual<N> sqrt(const HessianDual<N>& a) {
  const double s = std::sqrt(a.v);
  HessianDual<N> r = hessian_dual_detail::apply(a, s, 0.5 / s, -0.25 / (a.v * s));
  for (int i = 0; i < N; ++i) r.g[i] = a.g[i] / (2.0 * s);  // rounded as Dual's (operator/ says why)
  return r;
}

// Mixed with plain doubles: shifts and scalings, no product of derivatives.
template <int N>
HessianDual<N> operator+(const HessianDual<N>& a, double b) {
  HessianDual<N> r = a;
  r.v += b;
  return r;
}
template <int N>
HessianDual<N> operator+(double a, const HessianDual<N>& b) { return b + a; }
template <int N>
HessianDual<N> operator-(const HessianDual<N>& a, double b) { return a + (-b); }
template <int N>
HessianDual<N> operator-(double a, const HessianDual<N>& b) {
  HessianDual<N> r = -b;
  r.v += a;
  return r;
}
template <int N>
HessianDual<N> operator*(const HessianDual<N>& a, double b) {
  HessianDual<N> r(a.v * b, typename HessianDual<N>::Unset{});
  for (int i = 0; i < N; ++i) r.g[i] = a.g[i] * b;
  for (int k = 0; k < HessianDual<N>::kPacked; ++k) r.h[k] = a.h[k] * b;
  return r;
}
template <int N>
HessianDual<N> operator*(double a, const HessianDual<N>& b) { return b * a; }
template <int N>
HessianDual<N> operator/(const HessianDual<N>& a, double b) {
  HessianDual<N> r(a.v / b, typename HessianDual<N>::Unset{});
  for (int i = 0; i < N; ++i) r.g[i] = a.g[i] / b;
  for (int k = 0; k < HessianDual<N>::kPacked; ++k) r.h[k] = a.h[k] / b;
  return r;
}
/// a / b = a f(b), f(x) = 1/x: f' = −1/x², f'' = 2/x³.
template <int N>
HessianDual<N> operator/(double a, const HessianDual<N>& b) {
  const double inverse = 1.0 / b.v;
  HessianDual<N> r = hessian_dual_detail::apply(b, a / b.v, -a * inverse * inverse, 2.0 * a * inverse * inverse * inverse);
  for (int i = 0; i < N; ++i) r.g[i] = -(r.v * b.g[i]) / b.v;  // rounded as Dual's (operator/ says why)
  return r;
}

/// Whether a number carries no derivative: a double always; a HessianDual whose gradient and Hessian are
/// zero (a rigid body's edge vectors under a translation, a parallelogram's twist), which a kernel may then
/// multiply as a double.
inline bool hasNoDerivatives(double) { return true; }
template <int N>
bool hasNoDerivatives(const HessianDual<N>& x) {
  for (double d : x.g)
    if (d != 0.0) return false;
  for (double d : x.h)
    if (d != 0.0) return false;
  return true;
}
template <class T, int N>
bool hasNoDerivatives(const Dual<T, N>&) {
  return false;  // not looked into: multiplied as it is
}

/// x with its value replaced by `value` (a double is `value` itself): a kernel that differentiates a
/// quantity through a cheaper formula keeps the value of the formula its doubles use, to the bit.
inline double withValue(double, double value) { return value; }
template <class T>
T withValue(T x, double value) {
  x.v = value;
  return x;
}

/// The independent variable x_i of N: value x, gradient e_i, Hessian 0.
template <int N>
HessianDual<N> hessianVariable(double x, int i) {
  HessianDual<N> r(x);
  r.g[i] = 1.0;
  return r;
}

/// Which variable each of a kernel's C coordinates is: its own (variable[i] ≥ 0), or, for a rigid body's
/// coordinates (variable[i] < 0), the one variable of the body's motion, the last of V, along which
/// coordinate i moves by motion[i]. A rigid master's coordinates are not unknowns: the tangent needs no
/// derivative in them, and ∂r/∂λ only the derivative along the motion (the load factor's), so V = the
/// own coordinates + 1 instead of C (2D: 9 instead of 12; 3D: 13 instead of 24), and the Hessian's cost
/// goes with V².
template <int C>
struct KernelVariables {
  std::array<int, C> variable{};
  std::array<double, C> motion{};
  /// The coordinate whose entries receive the derivatives along the motion (the other rigid ones get 0).
  int motionEntry = -1;

  template <int V>
  std::array<HessianDual<V>, C> seed(const std::array<double, C>& x) const {
    std::array<HessianDual<V>, C> out;
    for (int i = 0; i < C; ++i) {
      out[i] = HessianDual<V>(x[i]);
      if (variable[i] >= 0)
        out[i].g[variable[i]] = 1.0;
      else
        out[i].g[V - 1] = motion[i];
    }
    return out;
  }
  /// f's gradient and Hessian (row-major, C × C) over the coordinates.
  template <int V>
  void extract(const HessianDual<V>& f, std::array<double, C>& gradient, std::array<double, C * C>& hessian) const {
    std::array<int, C> at{};
    for (int i = 0; i < C; ++i) at[i] = variable[i] >= 0 ? variable[i] : (i == motionEntry ? V - 1 : -1);
    for (int i = 0; i < C; ++i) {
      gradient[i] = at[i] < 0 ? 0.0 : f.gradient(at[i]);
      for (int j = 0; j < C; ++j) hessian[i * C + j] = at[i] < 0 || at[j] < 0 ? 0.0 : f.hessian(at[i], at[j]);
    }
  }
};

/// Every coordinate its own variable.
template <int C>
KernelVariables<C> ownVariables() {
  KernelVariables<C> v;
  for (int i = 0; i < C; ++i) v.variable[i] = i;
  return v;
}
/// The coordinates [first, first + count) those of a rigid body moving by motion (count entries): its
/// derivatives along the motion in entry `first`; the others their own variables, in order.
template <int C>
KernelVariables<C> rigidBodyVariables(int first, int count, const double* motion) {
  KernelVariables<C> v;
  int next = 0;
  for (int i = 0; i < C; ++i) {
    const bool rigid = i >= first && i < first + count;
    v.variable[i] = rigid ? -1 : next++;
    v.motion[i] = rigid ? motion[i - first] : 0.0;
  }
  v.motionEntry = first;
  return v;
}

/// Whether a rigid body's motion is zero (count entries): a motionless rigid master (the block's base),
/// whose coordinates then carry no derivative at all.
inline bool motionless(const double* motion, int count) {
  for (int i = 0; i < count; ++i)
    if (motion[i] != 0.0) return false;
  return true;
}
/// The coordinates [first, first + count) those of a motionless rigid body: no variable of theirs (the
/// others their own, in order), V = C − count. The entries of a moving body's motion variable would hold
/// the derivatives along a zero motion, zeros: they are zeros here too, and every other entry is computed
/// by the same operations on the same numbers (a HessianDual's entries do not mix variables), so the
/// derivatives are the same to the bit, at (V/(V + 1))² of the Hessians' cost.
template <int C>
KernelVariables<C> motionlessBodyVariables(int first, int count) {
  const std::array<double, C> zero{};
  KernelVariables<C> v = rigidBodyVariables<C>(first, count, zero.data());
  v.motionEntry = -1;
  return v;
}

/// A friction pair kernel's results `g` (overlaps and, per slave slot, the weighted gap, mortar area and weighted
/// slip increment's three components, on HessianDual numbers) into `out` as values, gradients and Hessians over
/// the coordinates (the fields of MortarFacetPairDerivatives and MortarQuadraticPairDerivatives alike).
template <int Slots, int C, class Integrated, class Derivatives>
void extractGapsAndSlips(const Integrated& g, const KernelVariables<C>& variables, Derivatives& out) {
  out.overlaps = g.overlaps;
  out.slipGradient.resize(3 * Slots);
  out.slipHessian.resize(3 * Slots);
  for (int a = 0; a < Slots; ++a) {
    out.weightedGap[a] = g.weightedGap[a].v;
    out.mortarArea[a] = g.mortarArea[a].v;
    variables.extract(g.weightedGap[a], out.gradient[a], out.hessian[a]);
    for (int c = 0; c < 3; ++c) {
      out.weightedSlip[a][c] = g.weightedSlip[a][c].v;
      variables.extract(g.weightedSlip[a][c], out.slipGradient[3 * a + c], out.slipHessian[3 * a + c]);
    }
  }
}

/// A pair kernel's weighted gaps differentiated twice: `integrate` (the kernel on HessianDual coordinates,
/// returning overlaps, weightedGap and mortarArea per slave slot) evaluated with every coordinate its own
/// variable, or, given a rigid master's motion (its entries from FirstMaster on), with the master along that
/// motion only (KernelVariables). Written into `out` (overlaps, weightedGap, mortarArea, gradient and
/// hessian, every entry): a caller that keeps its records (MortarInterface's per pair, 18 KB in 3D) fills
/// them in place instead of copying a returned one.
template <int FirstMaster, class Derivatives, std::size_t N, class Integrate>
void differentiatePairKernelInto(Derivatives& out, const std::array<double, N>& x, const double* masterMotion,
                                 Integrate integrate) {
  constexpr int C = static_cast<int>(N);
  const auto differentiate = [&](auto variablesTag, const KernelVariables<C>& variables) {
    constexpr int V = decltype(variablesTag)::value;
    // A HessianDual<36> holds 703 doubles: the seeded coordinates live on the heap.
    std::vector<std::array<HessianDual<V>, C>> seeded(1, variables.template seed<V>(x));
    const auto g = integrate(seeded[0]);
    out.overlaps = g.overlaps;
    for (std::size_t a = 0; a < out.weightedGap.size(); ++a) {
      out.weightedGap[a] = g.weightedGap[a].v;
      out.mortarArea[a] = g.mortarArea[a].v;
      variables.extract(g.weightedGap[a], out.gradient[a], out.hessian[a]);
    }
  };
  if (masterMotion == nullptr) return differentiate(std::integral_constant<int, C>{}, ownVariables<C>());
  if (motionless(masterMotion, FirstMaster))
    return differentiate(std::integral_constant<int, FirstMaster>{}, motionlessBodyVariables<C>(FirstMaster, FirstMaster));
  differentiate(std::integral_constant<int, FirstMaster + 1>{}, rigidBodyVariables<C>(FirstMaster, FirstMaster, masterMotion));
}
/// The same, returned (the other fields of Derivatives value-initialised).
template <class Derivatives, int FirstMaster, std::size_t N, class Integrate>
Derivatives differentiatePairKernel(const std::array<double, N>& x, const double* masterMotion, Integrate integrate) {
  Derivatives out;
  differentiatePairKernelInto<FirstMaster>(out, x, masterMotion, integrate);
  return out;
}

}  // namespace contessa::contact
