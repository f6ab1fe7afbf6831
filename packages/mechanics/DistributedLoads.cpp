#include "mechanics/DistributedLoads.hpp"

#include <array>
#include <cmath>

#include "mechanics/ReferenceElement.hpp"

namespace contessa::mechanics {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A multilinear cell of parametric dimension M (a 2-node edge, a 4-node quadrilateral, an 8-node
// hexahedron) with its nodes in Exodus order: the corners of [−1, 1]^M, the first two coordinates
// going round counter-clockwise, the third one (if any) −1 for the first four nodes and +1 after.
template <int M>
struct MultilinearCell {
  static constexpr int kNodes = 1 << M;
  static double corner(int a, int i) {
    static const double kCyclic[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    if (M == 1) return a == 0 ? -1.0 : 1.0;
    if (i < 2) return kCyclic[a % 4][i];
    return a < 4 ? -1.0 : 1.0;
  }
  std::array<double, kNodes> N{};      ///< shape functions at a point
  std::array<double, kNodes * M> dN{};  ///< ∂N_a/∂ξ_m at M·a + m

  explicit MultilinearCell(const std::array<double, M>& xi) {
    for (int a = 0; a < kNodes; ++a) {
      std::array<double, M> factor{};
      for (int i = 0; i < M; ++i) factor[i] = 0.5 * (1.0 + corner(a, i) * xi[i]);
      N[a] = 1.0;
      for (int i = 0; i < M; ++i) N[a] *= factor[i];
      for (int m = 0; m < M; ++m) {
        double d = 0.5 * corner(a, m);
        for (int i = 0; i < M; ++i)
          if (i != m) d *= factor[i];
        dN[M * a + m] = d;
      }
    }
  }

  /// Σ_a N_a x_a (D components).
  template <int D>
  std::array<double, D> point(const double* x) const {
    std::array<double, D> p{};
    for (int a = 0; a < kNodes; ++a)
      for (int i = 0; i < D; ++i) p[i] += N[a] * x[D * a + i];
    return p;
  }
  /// The tangents ∂x/∂ξ_m = Σ_a ∂N_a/∂ξ_m x_a, g[m][i].
  template <int D>
  std::array<std::array<double, D>, M> tangents(const double* x) const {
    std::array<std::array<double, D>, M> g{};
    for (int a = 0; a < kNodes; ++a)
      for (int m = 0; m < M; ++m)
        for (int i = 0; i < D; ++i) g[m][i] += dN[M * a + m] * x[D * a + i];
    return g;
  }
};

int permutationSign(int i, int j, int k) { return (i - j) * (j - k) * (k - i) / 2; }  // ε_ijk for 0..2

// The facet geometry, the one dimension-specific piece (theory-solids eq. 8.1): the area vector
// a = n |∂x/∂ξ| (per unit parent measure) from the facet's tangents, outward for an Exodus side,
// and its derivative ∂a_i/∂g_mj.
template <int D>
std::array<double, D> areaVector(const std::array<std::array<double, D>, D - 1>& g) {
  if constexpr (D == 2) {
    return {g[0][1], -g[0][0]};  // the tangent turned clockwise
  } else {
    return {g[0][1] * g[1][2] - g[0][2] * g[1][1], g[0][2] * g[1][0] - g[0][0] * g[1][2],
            g[0][0] * g[1][1] - g[0][1] * g[1][0]};  // g_0 × g_1
  }
}

template <int D>
std::array<std::array<double, D * D>, D - 1> areaVectorDerivative(const std::array<std::array<double, D>, D - 1>& g) {
  std::array<std::array<double, D * D>, D - 1> d{};
  if constexpr (D == 2) {
    d[0] = {0.0, 1.0, -1.0, 0.0};
  } else {
    // ∂(g_0 × g_1)_i/∂g_0j = ε_ijk g_1k and ∂(g_0 × g_1)_i/∂g_1k = ε_ijk g_0j.
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) {
          d[0][3 * i + j] += permutationSign(i, j, k) * g[1][k];
          d[1][3 * i + k] += permutationSign(i, j, k) * g[0][j];
        }
  }
  return d;
}

template <int D>
double norm(const std::array<double, D>& v) {
  double s = 0.0;
  for (double c : v) s += c * c;
  return std::sqrt(s);
}

}  // namespace

double RevolvedMeasure::weight(const double* x) const { return 2.0 * kPi * x[0]; }
void RevolvedMeasure::gradient(const double*, double* dwdx) const {
  dwdx[0] = 2.0 * kPi;
  dwdx[1] = 0.0;
}

template <int D>
void followerPressure(const double* x, double p, const LoadMeasure& measure, double* force, double* stiffness) {
  constexpr int M = D - 1, K = 1 << M, n = D * K;
  for (int r = 0; r < n; ++r) force[r] = 0.0;
  if (stiffness)
    for (int r = 0; r < n * n; ++r) stiffness[r] = 0.0;
  // Two Gauss points per direction integrate N_a a exactly (degree ≤ 2 per direction), also with w = 2πr.
  for (const auto& q : gaussLegendreRule<M, 2>()) {
    const MultilinearCell<M> cell(q.xi);
    const auto g = cell.template tangents<D>(x);
    const auto xq = cell.template point<D>(x);
    const auto area = areaVector<D>(g);
    const double w = measure.weight(xq.data());
    const double s = -p * q.weight;
    // eq. (8.2): f_a = −p Σ_q N_a w a (the outward area vector a = n da/dξ).
    for (int a = 0; a < K; ++a)
      for (int i = 0; i < D; ++i) force[D * a + i] += s * w * cell.N[a] * area[i];
    if (!stiffness) continue;
    // eq. (8.4): ∂f_ai/∂x_bj = −p Σ_q N_a (w Σ_m ∂N_b/∂ξ_m ∂a_i/∂g_mj + a_i ∂w/∂x_j N_b).
    const auto dArea = areaVectorDerivative<D>(g);
    std::array<double, D> dw{};
    measure.gradient(xq.data(), dw.data());
    for (int b = 0; b < K; ++b) {
      std::array<double, D * D> column{};  // ∂(w a_i)/∂x_bj
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) {
          double v = area[i] * dw[j] * cell.N[b];
          for (int m = 0; m < M; ++m) v += w * cell.dN[M * b + m] * dArea[m][D * i + j];
          column[D * i + j] = v;
        }
      for (int a = 0; a < K; ++a)
        for (int i = 0; i < D; ++i)
          for (int j = 0; j < D; ++j) stiffness[(D * a + i) * n + D * b + j] += s * cell.N[a] * column[D * i + j];
    }
  }
}

template <int D>
void facetTraction(const double* X, const double* t, const LoadMeasure& measure, double* force) {
  constexpr int M = D - 1, K = 1 << M;
  for (int r = 0; r < D * K; ++r) force[r] = 0.0;
  for (const auto& q : gaussLegendreRule<M, 2>()) {
    const MultilinearCell<M> cell(q.xi);
    const auto Xq = cell.template point<D>(X);
    // eq. (8.5): dA = |a(X)| dξ.
    const double dA = q.weight * measure.weight(Xq.data()) * norm<D>(areaVector<D>(cell.template tangents<D>(X)));
    for (int a = 0; a < K; ++a)
      for (int i = 0; i < D; ++i) force[D * a + i] += dA * cell.N[a] * t[i];
  }
}

namespace {
// det ∂X/∂ξ of a cell at one point (the columns are the tangents).
template <int D>
double cellJacobian(const std::array<std::array<double, D>, D>& g) {
  if constexpr (D == 2) {
    return g[0][0] * g[1][1] - g[0][1] * g[1][0];
  } else {
    return g[0][0] * (g[1][1] * g[2][2] - g[1][2] * g[2][1]) - g[1][0] * (g[0][1] * g[2][2] - g[0][2] * g[2][1]) +
           g[2][0] * (g[0][1] * g[1][2] - g[0][2] * g[1][1]);
  }
}
}  // namespace

template <int D>
void bodyForce(const double* X, const double* b, const LoadMeasure& measure, double* force) {
  constexpr int K = 1 << D;
  for (int r = 0; r < D * K; ++r) force[r] = 0.0;
  for (const auto& q : gaussLegendreRule<D, 2>()) {
    const MultilinearCell<D> cell(q.xi);
    const auto Xq = cell.template point<D>(X);
    // eq. (8.6): dV = det(∂X/∂ξ) dξ.
    const double dV = q.weight * measure.weight(Xq.data()) * cellJacobian<D>(cell.template tangents<D>(X));
    for (int a = 0; a < K; ++a)
      for (int i = 0; i < D; ++i) force[D * a + i] += dV * cell.N[a] * b[i];
  }
}

template <int D>
double facetMeasure(const double* X, const LoadMeasure& measure) {
  double total = 0.0;
  for (const auto& q : gaussLegendreRule<D - 1, 2>()) {
    const MultilinearCell<D - 1> cell(q.xi);
    const auto Xq = cell.template point<D>(X);
    total += q.weight * measure.weight(Xq.data()) * norm<D>(areaVector<D>(cell.template tangents<D>(X)));
  }
  return total;
}

template <int D>
double cellMeasure(const double* X, const LoadMeasure& measure) {
  double total = 0.0;
  for (const auto& q : gaussLegendreRule<D, 2>()) {
    const MultilinearCell<D> cell(q.xi);
    const auto Xq = cell.template point<D>(X);
    total += q.weight * measure.weight(Xq.data()) * cellJacobian<D>(cell.template tangents<D>(X));
  }
  return total;
}

template void followerPressure<2>(const double*, double, const LoadMeasure&, double*, double*);
template void followerPressure<3>(const double*, double, const LoadMeasure&, double*, double*);
template void facetTraction<2>(const double*, const double*, const LoadMeasure&, double*);
template void facetTraction<3>(const double*, const double*, const LoadMeasure&, double*);
template void bodyForce<2>(const double*, const double*, const LoadMeasure&, double*);
template void bodyForce<3>(const double*, const double*, const LoadMeasure&, double*);
template double facetMeasure<2>(const double*, const LoadMeasure&);
template double facetMeasure<3>(const double*, const LoadMeasure&);
template double cellMeasure<2>(const double*, const LoadMeasure&);
template double cellMeasure<3>(const double*, const LoadMeasure&);

}  // namespace contessa::mechanics
