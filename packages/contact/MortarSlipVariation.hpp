#pragma once
// The virtual slip of a mortar slave node: the mortar matrices D and M applied to a virtual displacement,
// δũ_a = ∫ w_a P (δx_s(ξ) − δx_m(η)) dA_0, at the current segmentation, and its derivative with respect to
// the coordinates (theory-contact.md §13, eq. M11″). The frictional residual is the work of the nodal
// tangential tractions on it, r_T = Σ_a t_a · δũ_a (Gitterle, Popp, Gee & Wall 2010; Puso & Laursen 2004
// §4: the tractions act on the mortar-projected virtual displacements), not the gradient of the weighted
// slip increment Δũ_a itself: Δũ_a = B_a(x) · (x − x_n) (the slip's integrand is linear in the nodes'
// current positions, with the segmentation, the weights and P from the current geometry), so its
// gradient B_a + (∂B_a/∂x) · (x − x_n) adds to the virtual slip B_a a term of the order of the increment's
// slip: the change of the overlap, of the Gauss points' ξ, η, of the measure and of n_m times the slip.
// Where the overlap shrinks (a slave facet sliding past a master's free edge) that term pulls the
// friction force below μ F_N by a fraction of the order of the increment's slip over the facet size.
//
// With the kernels' HessianDual numbers T (the seeded coordinates' gradients are the seeds ∂x_i/∂v), at
// each Gauss point:
//   J_d[v] = Σ_terms sign σ_t ∂x_(t,d)/∂v,    the point x_s(ξ) − x_m(η) differentiated at fixed ξ, η,
//   q_c[v] = Σ_d R_cd J_d[v],                 R the rows of P = I − n_m ⊗ n_m (2D: the tangent t_m),
//   B_ac[v] += W_a q_c[v],                    W_a the Gauss point's weight times the node's weight,
// and the first derivatives of each over the variables (σ_t, R and W_a depend on the geometry; the seeds
// are constants). Only first derivatives: the tangent K_T = Σ_a [B_a ⊗ ∂t_a/∂x + t_a · ∂B_a/∂x] needs no
// Hessian of a slip.
#include <array>
#include <vector>

#include "contact/MortarDual.hpp"

namespace contessa::contact {

/// A number's value and gradient (the first-order part of a HessianDual), as MortarDual.hpp's Dual.
template <int V>
using FirstOrder = Dual<double, V>;
template <int V>
FirstOrder<V> firstOrder(const HessianDual<V>& x) {
  return FirstOrder<V>(x.v, x.g);
}

/// The number of variables V of a HessianDual<V>.
template <class T>
struct HessianDualVariables;
template <int V>
struct HessianDualVariables<HessianDual<V>> {
  static constexpr int value = V;
};
template <class T>
constexpr int kVariables = HessianDualVariables<T>::value;

/// The virtual slips of a pair's weight slots summed over its Gauss points: nothing for values (T double,
/// no derivative wanted), value and gradient over the V variables for HessianDual<V>.
template <class T>
struct SlipVariationSum {
  template <class... Args>
  void add(const Args&...) {}
};

template <int V>
struct SlipVariationSum<HessianDual<V>> {
  using H = HessianDual<V>;
  /// One term σ_t x_t of the point x_s(ξ) − x_m(η): its shape value and node's Dim seeded coordinates.
  struct Term {
    const H* shape;
    std::array<const H*, 3> coordinate;  ///< the node's first Dim coordinates
    double sign;
  };
  int slots = 0;
  int rows = 0;
  std::vector<double> value;     ///< B_ac[v] at ((a rows + c) V + v)
  std::vector<double> gradient;  ///< ∂B_ac[v]/∂w at ((a rows + c) V + v) V + w

  /// One Gauss point: the slots' weights W_a (`slotCount` of them, in a pair of `totalSlots`), the rows
  /// R_c (Rows × Dim first-order numbers) and the point's terms.
  template <int Dim, int Rows>
  void add(int totalSlots, const H* weights, int slotCount, const std::array<std::array<FirstOrder<V>, Dim>, Rows>& r,
           const Term* terms, int termCount) {
    if (value.empty()) {
      slots = totalSlots;
      rows = Rows;
      value.assign(static_cast<std::size_t>(slots) * rows * V, 0.0);
      gradient.assign(static_cast<std::size_t>(slots) * rows * V * V, 0.0);
    }
    // J_d and ∂J_d (the seeds are constants: only the shape values carry derivatives).
    std::array<std::array<double, V>, Dim> j{};
    std::vector<double> dj(static_cast<std::size_t>(Dim) * V * V, 0.0);
    for (int t = 0; t < termCount; ++t) {
      const Term& term = terms[t];
      const double s = term.sign * term.shape->v;
      for (int d = 0; d < Dim; ++d) {
        const std::array<double, V>& seed = term.coordinate[d]->g;
        for (int v = 0; v < V; ++v) {
          if (seed[v] == 0.0) continue;
          j[d][v] += s * seed[v];
          double* row = &dj[(static_cast<std::size_t>(d) * V + v) * V];
          const double sv = term.sign * seed[v];
          for (int w = 0; w < V; ++w) row[w] += sv * term.shape->g[w];
        }
      }
    }
    // q_c and ∂q_c.
    std::array<std::array<double, V>, Rows> q{};
    std::vector<double> dq(static_cast<std::size_t>(Rows) * V * V, 0.0);
    for (int c = 0; c < Rows; ++c)
      for (int d = 0; d < Dim; ++d) {
        const FirstOrder<V>& rcd = r[c][d];
        for (int v = 0; v < V; ++v) {
          const double jv = j[d][v];
          q[c][v] += rcd.v * jv;
          double* row = &dq[(static_cast<std::size_t>(c) * V + v) * V];
          const double* djRow = &dj[(static_cast<std::size_t>(d) * V + v) * V];
          for (int w = 0; w < V; ++w) row[w] += rcd.d[w] * jv + rcd.v * djRow[w];
        }
      }
    // B_ac += W_a q_c.
    for (int a = 0; a < slotCount; ++a) {
      const H& wa = weights[a];
      for (int c = 0; c < Rows; ++c) {
        const std::size_t base = static_cast<std::size_t>(a * rows + c) * V;
        for (int v = 0; v < V; ++v) {
          const double qv = q[c][v];
          value[base + v] += wa.v * qv;
          double* row = &gradient[(base + v) * V];
          const double* dqRow = &dq[(static_cast<std::size_t>(c) * V + v) * V];
          for (int w = 0; w < V; ++w) row[w] += wa.g[w] * qv + wa.v * dqRow[w];
        }
      }
    }
  }
};

/// The rows of P = I − n ⊗ n (3D: the slip's part in the master's tangent plane) as first-order numbers.
template <int V>
std::array<std::array<FirstOrder<V>, 3>, 3> tangentialProjectorRows(const std::array<FirstOrder<V>, 3>& n) {
  std::array<std::array<FirstOrder<V>, 3>, 3> p{};
  for (int c = 0; c < 3; ++c)
    for (int d = 0; d < 3; ++d) {
      p[c][d].v = (c == d ? 1.0 : 0.0) - n[c].v * n[d].v;
      for (int w = 0; w < V; ++w) p[c][d].d[w] = -(n[c].d[w] * n[d].v + n[c].v * n[d].d[w]);
    }
  return p;
}

/// The variable holding coordinate i's derivatives (KernelVariables::extract's map), −1 for none.
template <int C>
int variableOfCoordinate(const KernelVariables<C>& variables, int i, int V) {
  return variables.variable[i] >= 0 ? variables.variable[i] : (i == variables.motionEntry ? V - 1 : -1);
}

/// The summed virtual slips over the coordinates (as KernelVariables::extract): for each slot a and row c
/// (entry a rows + c), B over the coordinates and ∂B_i/∂x_j row-major (i the virtual displacement's
/// coordinate, j the geometry's; not symmetric).
template <int C, int V>
void extractSlipVariation(const SlipVariationSum<HessianDual<V>>& s, const KernelVariables<C>& variables, int slots,
                          int rows, std::vector<std::array<double, C>>& value,
                          std::vector<std::array<double, C * C>>& gradient) {
  value.assign(static_cast<std::size_t>(slots) * rows, std::array<double, C>{});
  gradient.assign(static_cast<std::size_t>(slots) * rows, std::array<double, C * C>{});
  if (s.value.empty()) return;  // no Gauss point (no overlap)
  std::array<int, C> at{};
  for (int i = 0; i < C; ++i) at[i] = variableOfCoordinate(variables, i, V);
  for (int e = 0; e < slots * rows; ++e) {
    const std::size_t base = static_cast<std::size_t>(e) * V;
    for (int i = 0; i < C; ++i) {
      if (at[i] < 0) continue;
      value[e][i] = s.value[base + at[i]];
      for (int j = 0; j < C; ++j)
        if (at[j] >= 0) gradient[e][i * C + j] = s.gradient[(base + at[i]) * V + at[j]];
    }
  }
}

}  // namespace contessa::contact
