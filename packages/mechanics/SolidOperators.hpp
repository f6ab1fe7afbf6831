#pragma once
// Total-Lagrangian operators of the solid kernels, with sizes fixed at compile time (dimension D and
// number of gradient vectors), and the reference geometry each element computes once.
//
// The operators work on lists of reference gradients g_a (D components each): the shape-function
// gradients ∂N_a/∂X of the nodes, and for the enhanced element also the gradients of its enhanced
// modes, which enter every formula exactly like D extra nodes (EnhancedStrain.hpp). In 2D (plane
// strain) all indices run over the two in-plane components only.
#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "mechanics/Element.hpp"
#include "mechanics/Tensor.hpp"

namespace contessa::mechanics {

/// H_iJ += Σ_a v_ai g_aJ over `Count` gradients g (Count × D, row a) and vectors v (Count × D):
/// the displacement gradient GRAD u for nodal displacements v and g = ∂N/∂X.
template <int D, int Count>
inline void addGradient(const double* g, const double* v, Matrix<D>& H) {
  for (int a = 0; a < Count; ++a)
    for (int i = 0; i < D; ++i)
      for (int J = 0; J < D; ++J) H[D * i + J] += v[D * a + i] * g[D * a + J];
}

/// r_ai += P_iJ g_aJ · wj for a < Count: the discrete ∫ Bᵀ P dV (wj = integration weight × det J).
template <int D, int Count>
inline void addDivergence(const double* g, const Matrix<D>& P, double wj, double* r) {
  for (int a = 0; a < Count; ++a)
    for (int i = 0; i < D; ++i) {
      double s = 0.0;
      for (int J = 0; J < D; ++J) s += P[D * i + J] * g[D * a + J];
      r[D * a + i] += s * wj;
    }
}

/// At[i][J][L][k] = A_iJkL · wj: A scaled by the point's weight with its last two indices swapped, so
/// that the tangent's column loops run over contiguous k (the two components of a row entry pair in 2D)
/// and vectorise without shuffles.
template <int D>
inline void swapLastIndicesScaled(const Tangent<D>& A, double wj, double (&At)[D][D][D][D]) {
  for (int i = 0; i < D; ++i)
    for (int J = 0; J < D; ++J)
      for (int k = 0; k < D; ++k)
        for (int L = 0; L < D; ++L) At[i][J][L][k] = A[((D * i + J) * D + k) * D + L] * wj;
}

/// AN[L][k] = Σ_J g_aJ At[i][J][L][k], row (a, i)'s contraction of g_a into A before the columns are
/// swept. (The sum starts from its first term rather than from 0.0, which the compiler may not do for
/// us: x + 0.0 is not x for x = −0.0.)
template <int D>
inline void contractRow(const double* ga, const double (&Ati)[D][D][D], double (&AN)[D][D]) {
  for (int L = 0; L < D; ++L)
    for (int k = 0; k < D; ++k) {
      double s = ga[0] * Ati[0][L][k];
      for (int J = 1; J < D; ++J) s += ga[J] * Ati[J][L][k];
      AN[L][k] = s;
    }
}

/// Two doubles operated on at once (GCC's vector extension: SSE2 on x86-64, NEON on arm64). Element by
/// element the arithmetic is the scalar code's, in the same order, so the results are the same bits.
using DoublePair = double __attribute__((vector_size(2 * sizeof(double))));

/// A_iJkL · wj with its last two indices swapped, at [i][J][(D·L + k) / 2][(D·L + k) % 2] (the D²-th
/// entry of an odd D² is a zero pad): each (i, J) slice is a run over (L, k) in pairs, so that a row's
/// contraction (contractRowInPairs) is D² / 2 vector multiply-adds per J.
template <int D>
struct SwappedTangent {
  static constexpr int kPairs = (D * D + 1) / 2;
  DoublePair slice[D][D][kPairs];

  SwappedTangent(const Tangent<D>& A, double wj) {
    for (int i = 0; i < D; ++i)
      for (int J = 0; J < D; ++J) {
        slice[i][J][kPairs - 1] = DoublePair{};
        for (int k = 0; k < D; ++k)
          for (int L = 0; L < D; ++L) {
            const int n = D * L + k;
            slice[i][J][n / 2][n % 2] = A[((D * i + J) * D + k) * D + L] * wj;
          }
      }
  }
};

/// AN[L][k] = Σ_J g_aJ At_iJkL (At: A · wj, indices swapped), row (a, i)'s contraction of g_a into A
/// before the columns are swept, two (L, k) at a time: the scalar form, D³ multiply-adds over D-long
/// runs, stayed scalar and was a third of the 3D tangent's instructions (issue 23, fifth round). (The
/// sum starts from its first term rather than from 0.0, which the compiler may not do for us: x + 0.0
/// is not x for x = −0.0.)
template <int D>
inline void contractRowInPairs(const double* ga, const SwappedTangent<D>& At, int i, double (&AN)[D][D]) {
  constexpr int P = SwappedTangent<D>::kPairs;
  DoublePair s[P];
  const DoublePair g0 = {ga[0], ga[0]};
  for (int p = 0; p < P; ++p) s[p] = g0 * At.slice[i][0][p];
  for (int J = 1; J < D; ++J) {
    const DoublePair gJ = {ga[J], ga[J]};
    for (int p = 0; p < P; ++p) s[p] += gJ * At.slice[i][J][p];
  }
  for (int n = 0; n < D * D; ++n) AN[n / D][n % D] = s[n / 2][n % 2];
}

/// K_(ai),(bk) += g_aJ A_iJkL h_bL · wj for a < Rows, b < Cols, into K with leading dimension `ld`
/// (row D·a + i, column D·b + k). With g = h = ∂N/∂X this is K_uu, material and geometric stiffness
/// together since A = ∂P/∂F. No symmetry of A is assumed. K must not overlap g, h or A (it never
/// does: K is the caller's output block), which lets the compiler keep the row sums in registers.
template <int D, int Rows, int Cols>
inline void addTangent(const double* g, const double* h, const Tangent<D>& A, double wj, double* __restrict K, int ld) {
  double At[D][D][D][D];
  swapLastIndicesScaled<D>(A, wj, At);
  for (int a = 0; a < Rows; ++a)
    for (int i = 0; i < D; ++i) {
      double AN[D][D];  // Σ_J g_aJ A_iJkL · wj, indexed [L][k]
      contractRow<D>(g + D * a, At[i], AN);
      double* row = K + static_cast<std::size_t>(D * a + i) * ld;
      for (int b = 0; b < Cols; ++b)
        for (int k = 0; k < D; ++k) {
          double s = AN[0][k] * h[D * b];
          for (int L = 1; L < D; ++L) s += AN[L][k] * h[D * b + L];
          row[D * b + k] += s;
        }
    }
}

/// The rows D·a + i of addTangent's K with h = g, over the columns of the blocks b ≥ a only, At being
/// A · wj with its last two indices swapped (as in addTangent). `a` is a template parameter so that
/// every column loop has a length known at compile time and is unrolled and vectorised as addTangent's
/// are (with a run-time start the triangle saved only 14 % of the instructions for Hex8 Enhanced).
template <int D, int Count, bool kAssign, int a>
inline void addUpperRowBlock(const double* g, const SwappedTangent<D>& At, double* __restrict K, int ld) {
  for (int i = 0; i < D; ++i) {
    double AN[D][D];  // Σ_J g_aJ A_iJkL · wj, indexed [L][k]
    contractRowInPairs<D>(g + D * a, At, i, AN);
    double* row = K + static_cast<std::size_t>(D * a + i) * ld;
    for (int b = a; b < Count; ++b)
      for (int k = 0; k < D; ++k) {
        double s = AN[0][k] * g[D * b];
        for (int L = 1; L < D; ++L) s += AN[L][k] * g[D * b + L];
        if constexpr (kAssign)
          row[D * b + k] = s;
        else
          row[D * b + k] += s;
      }
  }
}

template <int D, int Count, bool kAssign, int... a>
inline void addUpperRowBlocks(const double* g, const SwappedTangent<D>& At, double* __restrict K, int ld,
                              std::integer_sequence<int, a...>) {
  (addUpperRowBlock<D, Count, kAssign, a>(g, At, K, ld), ...);
}

/// addTangent with h = g and Rows = Cols = Count when A has major symmetry (A_iJkL = A_kLiJ: a law
/// with a stored energy, Material::tangentIsSymmetric), so that K is symmetric: only the blocks b ≥ a
/// are accumulated (the diagonal blocks whole), 60 % of addTangent's multiplications for the 11
/// gradients of Hex8 Enhanced; mirrorUpperTriangle completes K once after the last point. With
/// `first`, the blocks are assigned instead of added to (the first point: K need not be zeroed).
template <int D, int Count>
inline void addSymmetricTangent(const double* g, const Tangent<D>& A, double wj, double* __restrict K, int ld,
                                bool first) {
  const SwappedTangent<D> At(A, wj);
  if (first)
    addUpperRowBlocks<D, Count, true>(g, At, K, ld, std::make_integer_sequence<int, Count>{});
  else
    addUpperRowBlocks<D, Count, false>(g, At, K, ld, std::make_integer_sequence<int, Count>{});
}

/// K_cr = K_rc for c > r: completes a symmetric n × n K (leading dimension `ld`) from its upper
/// triangle, which holds every block that addSymmetricTangent builds (the diagonal blocks' own lower
/// halves are overwritten too, so that K comes out exactly symmetric).
template <int n>
inline void mirrorUpperTriangle(double* K, int ld) {
  for (int r = 0; r < n; ++r)
    for (int c = r + 1; c < n; ++c) K[static_cast<std::size_t>(c) * ld + r] = K[static_cast<std::size_t>(r) * ld + c];
}

/// Frobenius norm of a D × D matrix.
template <int D>
inline double normOf(const Matrix<D>& a) {
  double s = 0.0;
  for (double v : a) s += v * v;
  return std::sqrt(s);
}

/// Parent Jacobian J_Jβ = ∂X_J/∂ξ_β = Σ_a X_aJ ∂N_a/∂ξ_β at ξ. X: Shape::kNodes × D, node-major.
template <class Shape>
Matrix<Shape::kDimension> parentJacobian(const double* xi, const double* X) {
  constexpr int D = Shape::kDimension, N = Shape::kNodes;
  std::array<double, N * D> dNdxi{};
  Shape::shapeGradients(xi, dNdxi.data());
  Matrix<D> J{};
  for (int Jr = 0; Jr < D; ++Jr)
    for (int b = 0; b < D; ++b) {
      double s = 0.0;
      for (int a = 0; a < N; ++a) s += X[D * a + Jr] * dNdxi[D * a + b];
      J[D * Jr + b] = s;
    }
  return J;
}

/// Hoop coefficients c_a = N_a / R of Count shape functions at Q points (axisymmetric kinematics,
/// Kinematics.hpp); nothing is stored, and at() is null, when the kinematics has no hoop strain.
template <int Count, int Q, bool Stored>
struct HoopCoefficients {
  const double* at(int) const { return nullptr; }
  double* at(int) { return nullptr; }
};
template <int Count, int Q>
struct HoopCoefficients<Count, Q, true> {
  std::array<std::array<double, Count>, Q> c{};
  const double* at(int q) const { return c[q].data(); }
  double* at(int q) { return c[q].data(); }
};

/// Reference geometry of one element at its integration points: what every residual and Jacobian
/// needs from X, computed once (ElementKernel::referenceGeometry).
template <class Shape, bool Hoop = false>
struct ReferenceGeometry {
  static constexpr int D = Shape::kDimension, N = Shape::kNodes, Q = Shape::kPoints;
  std::array<std::array<double, N * D>, Q> dNdX{};  ///< ∂N_a/∂X_J at D·a + J
  std::array<double, Q> detJ{};                     ///< j = det ∂X/∂ξ
  std::array<double, Q> weightedVolume{};           ///< w · j (unit thickness in 2D; × 2πR revolved)
  HoopCoefficients<N, Q, Hoop> hoop;                ///< N_a / R (revolved only)
};

/// ∂N_a/∂X_J = ∂N_a/∂ξ_β (J⁻¹)_βJ, j and w j at every integration point, and what the Kinematics
/// (Kinematics.hpp) adds: the axisymmetric 2πR and N_a / R. False when some j ≤ 0 (nodes not
/// counter-clockwise, or a degenerate element), or the kinematics refuses a point (R ≤ 0): the
/// reference configuration cannot be integrated.
template <class Shape, class Kinematics, bool Hoop>
bool computeReferenceGeometry(const double* X, ReferenceGeometry<Shape, Hoop>& g) {
  constexpr int D = Shape::kDimension, N = Shape::kNodes, Q = Shape::kPoints;
  static_assert(Hoop == Kinematics::kHoop);
  const auto rule = Shape::quadrature();
  for (int q = 0; q < Q; ++q) {
    const Matrix<D> J = parentJacobian<Shape>(rule[q].xi.data(), X);
    g.detJ[q] = determinantOf<D>(J);
    if (!(g.detJ[q] > 0.0)) return false;
    g.weightedVolume[q] = rule[q].weight * g.detJ[q];
    if (!Kinematics::template revolve<Shape>(rule[q].xi.data(), X, g.weightedVolume[q], g.hoop.at(q))) return false;
    const Matrix<D> Jinv = inverseOf<D>(J, g.detJ[q]);
    std::array<double, N * D> dNdxi{};
    Shape::shapeGradients(rule[q].xi.data(), dNdxi.data());
    for (int a = 0; a < N; ++a)
      for (int Jc = 0; Jc < D; ++Jc) {
        double s = 0.0;
        for (int b = 0; b < D; ++b) s += dNdxi[D * a + b] * Jinv[D * b + Jc];
        g.dNdX[q][D * a + Jc] = s;
      }
  }
  return true;
}

/// The reference geometry of a set of elements, as one kernel computed it (PerElement is the
/// kernel's own record). Elements whose geometry cannot be integrated are kept, marked invalid:
/// evaluating them reports InadmissibleDeformation.
template <class PerElement>
class ElementGeometrySet final : public ElementGeometry {
 public:
  explicit ElementGeometrySet(int count) : elements_(count), valid_(count, 0) {}
  int size() const override { return static_cast<int>(elements_.size()); }
  bool valid(int e) const { return valid_[e] != 0; }
  const PerElement& operator[](int e) const { return elements_[e]; }
  PerElement& record(int e) { return elements_[e]; }
  void setValid(int e, bool v) { valid_[e] = v ? 1 : 0; }

 private:
  std::vector<PerElement> elements_;
  std::vector<char> valid_;
};

}  // namespace contessa::mechanics
