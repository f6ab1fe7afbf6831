#pragma once
// Enhanced assumed strain solid kernel (Simo & Armero 1992, IJNME 33:1413) over a reference element
// Shape and its enhanced modes Modes (EnhancedStrain.hpp): F = I + GRAD u + H̃(α), with the element
// parameters α condensed out at every evaluation by a local Newton solve of R_α(u, α) = 0. "Q4
// Enhanced" is this with the bilinear quadrilateral and its 4 Wilson-bubble modes, "Hex8 Enhanced"
// the same template with the trilinear hexahedron and its 9 modes (Hex8.hpp). With the axisymmetric
// Kinematics ("Q4 Enhanced Axisymmetric"), the modes enhance the in-plane gradient only: the hoop
// stretch stays 1 + u_r / R (Simo & Armero's axisymmetric version, §5 of their paper).
//
// Lean by construction (docs/theory-solids.md §4): sizes are compile-time constants; per element,
// ∂N/∂X, the mode gradients g_β, w j and the tolerance scales are precomputed (Geometry); the modes
// are handled as D extra "nodes", so R_u, R_α and all four tangent blocks come from the same two
// operators; one material call per local iteration evaluates every Gauss point; the local solve
// starts from the last converged α moved along dα/du (the warm start, state layout below).
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "mechanics/DenseSolve.hpp"
#include "mechanics/EnhancedStrain.hpp"
#include "mechanics/KernelIsa.hpp"
#include "mechanics/Kinematics.hpp"
#include "mechanics/ShapeKernel.hpp"
#include "mechanics/SolidOperators.hpp"

namespace contessa::mechanics {

template <class Shape, class Modes, class Kinematics = PlanarKinematics<Shape::kDimension>>
class EnhancedStrainElement final : public ShapeKernel<Shape, Kinematics::kHoop> {
 public:
  static constexpr int D = Shape::kDimension, N = Shape::kNodes, Q = Shape::kPoints;
  static constexpr int MD = Kinematics::kMaterialDimension;  ///< the law's F is MD × MD
  static constexpr int M = Modes::kPseudoNodes;  ///< mode "nodes", D parameters each
  static constexpr int ND = D * N, NA = D * M, NE = ND + NA, G = N + M;
  /// State: α (NA values, α_(β,i) at D·β + i), then the displacements u_α at which α was converged
  /// (ND), then dα/du = −K_αα⁻¹ K_αu from the last tangent evaluation (NA × ND, row-major).
  static constexpr int kStateAlpha = 0, kStateDisplacement = NA, kStateSensitivity = NA + ND;
  static constexpr int kStateSize = NA + ND + NA * ND;
  static constexpr int kMaxLocalIterations = 25;

  /// What an evaluation needs from the reference configuration, computed once per element.
  struct Geometry {
    std::array<std::array<double, G * D>, Q> gradients{};  ///< ∂N_a/∂X_J (a < N), then g_β,J
    std::array<double, Q> weightedVolume{};                ///< w j (× 2πR revolved)
    HoopCoefficients<G, Q, Kinematics::kHoop> hoop;        ///< N_a / R for the nodes, 0 for the modes
    std::array<double, Q> modeNormSum{};                   ///< Σ_m ‖G_m‖ (Frobenius) over the NA modes
    double length = 0.0;                                   ///< V^(1/D): α has units of length
  };
  using GeometrySet = ElementGeometrySet<Geometry>;

  explicit EnhancedStrainElement(std::string name) : ShapeKernel<Shape, Kinematics::kHoop>(std::move(name)) {}
  int numInternalVariables() const override { return NA; }
  int numStateValues() const override { return kStateSize; }

  std::unique_ptr<ElementGeometry> referenceGeometry(int count, const double* X) const override {
    auto set = std::make_unique<GeometrySet>(count);
    for (int e = 0; e < count; ++e) set->setValid(e, computeGeometry(X + ND * e, set->record(e)));
    return set;
  }

  using ElementKernel::averageCauchyStress;
  using ElementKernel::evaluate;

  /// f_int = R_u(u, α*) and K = K_uu − K_uα K_αα⁻¹ K_αu at the converged α*, which is the exact
  /// derivative of u ↦ R_u(u, α*(u)) because R_α(u, α*(u)) = 0. The local Newton starts from the
  /// state's α + dα/du (u − u_α) (a first-order prediction; from the state's α itself if that start
  /// fails). Returns InternalSolveFailed when the local Newton does not converge in
  /// kMaxLocalIterations or K_αα is singular.
  ElementStatus evaluate(const ElementGeometry& geometry, int element, const double* u, double* state,
                         const Material& material, double* internalForce, double* stiffness) const override {
#if CONTESSA_KERNEL_AVX2
    if constexpr (kDispatched)
      if (kernelIsa() == KernelIsa::Avx2)
        return evaluateAvx2(geometry, element, u, state, material, internalForce, stiffness);
#endif
    return evaluateHere(geometry, element, u, state, material, internalForce, stiffness);
  }

  ElementStatus averageCauchyStress(const ElementGeometry& geometry, int element, const double* u,
                                    const double* internal, const Material& material,
                                    Tensor2& sigma) const override {
    const auto& set = static_cast<const GeometrySet&>(geometry);
    if (!set.valid(element)) return ElementStatus::InadmissibleDeformation;
    const Geometry& g = set[element];
    Alpha alpha{};
    if (internal) {
      std::copy(internal, internal + NA, alpha.begin());
    } else {
      std::array<double, kStateSize> state{};
      const ElementStatus status = evaluate(geometry, element, u, state.data(), material, nullptr, nullptr);
      if (status != ElementStatus::Ok) return status;
      std::copy(state.begin() + kStateAlpha, state.begin() + kStateAlpha + NA, alpha.begin());
    }
    sigma = Tensor2{};
    Tensor2 s{};
    for (int q = 0; q < Q; ++q) {
      // Output only: the 3 × 3 path of the law (plane strain: F_33 = 1), which gives σ_zz (σ_θθ) too.
      if (!material.cauchyStress(Kinematics::threeByThree(enhancedGradient(g, q, compatibleGradient(g, q, u), alpha)), s))
        return ElementStatus::InadmissibleDeformation;
      sigma = add(sigma, s);
    }
    sigma = scaled(1.0 / Q, sigma);
    return ElementStatus::Ok;
  }

 private:
  using Alpha = std::array<double, NA>;
  /// F, P and A at every integration point for the current α.
  struct PointStates {
    std::array<Matrix<MD>, Q> F, P;
    std::array<Tangent<MD>, Q> A;
  };

  // Local Newton stopping rules. R_α is converged when ‖R_α‖ ≤ kResidualTolerance · s, where
  // s = Σ_gp ‖P‖ Σ_m ‖G_m‖ w j bounds the size of the terms summed into R_α (so the test is
  // independent of units and of the load level). The condensed tangent is exact only at R_α = 0, and
  // an α error δα shows up as K_uα δα in f_int, hence the tight value: Newton converges
  // quadratically, so it costs at most one extra iteration. Two fallbacks end the iteration at the
  // round-off floor: a Newton step negligible against the element size, or a residual that is small
  // and no longer decreasing (quadratic convergence would have reduced it by orders of magnitude).
  static constexpr double kResidualTolerance = 1e-13;
  // The half tangent and LDLᵀ (condensedTangent) for a symmetric material tangent: measured in
  // instructions per Jacobian (bench/README.md, issue 23 third round), Hex8 Enhanced 139 000 → 111 747,
  // but Q4 Enhanced 8 477 → 10 246 (its 12 × 12 blocks are too small for the halving to outweigh the
  // mirroring and the triangular loops), so 3D only; the revolved 2D kinematics never takes it.
  static constexpr bool kSymmetricPathPays = D == 3 && !Kinematics::kHoop;
  // Hex8 Enhanced (3D, planar) is also compiled for AVX2 and chosen at run time (KernelIsa.hpp):
  // about 4× the 2D kernel's work per element, and the largest phase of the 3D tube (issue 23, sixth
  // round). The 2D kernels stay in the generic instruction set only.
  static constexpr bool kDispatched = D == 3 && !Kinematics::kHoop;
  static constexpr double kStagnationTolerance = 1e-9;
  static constexpr double kStepTolerance = 1e-14;

  /// The evaluation itself, in the instruction set of the code around it (evaluate dispatches).
  ElementStatus evaluateHere(const ElementGeometry& geometry, int element, const double* u, double* state,
                             const Material& material, double* internalForce, double* stiffness) const {
    const auto& set = static_cast<const GeometrySet&>(geometry);
    if (!set.valid(element)) return ElementStatus::InadmissibleDeformation;
    const Geometry& g = set[element];
    std::array<Matrix<MD>, Q> Fc;  // I + GRAD u, fixed during the local solve
    for (int q = 0; q < Q; ++q) Fc[q] = compatibleGradient(g, q, u);

    Alpha alpha{}, shift{};
    if (state) {
      std::copy(state + kStateAlpha, state + kStateAlpha + NA, alpha.begin());
      // Warm start: α moves with u like dα/du (from the last tangent), so predict it to first order.
      // Exactly α when u has not changed since α was converged (a Jacobian after its residual).
      const double* uAlpha = state + kStateDisplacement;
      const double* dAlphadU = state + kStateSensitivity;
      for (int c = 0; c < ND; ++c) {
        const double du = u[c] - uAlpha[c];
        if (du == 0.0) continue;
        for (int m = 0; m < NA; ++m) shift[m] += dAlphadU[m * ND + c] * du;
      }
    }
    PointStates s;
    Alpha solution = alpha;
    for (int m = 0; m < NA; ++m) solution[m] += shift[m];
    const bool tangent = stiffness != nullptr;
    ElementStatus status = solveLocal(g, Fc, material, tangent, solution, s);
    if (status != ElementStatus::Ok && shift != Alpha{}) {
      // The prediction overshot (an inadmissible start or no convergence): start where we would
      // without it.
      solution = alpha;
      status = solveLocal(g, Fc, material, tangent, solution, s);
    }
    if (status != ElementStatus::Ok) return status;

    if (internalForce) {
      std::fill(internalForce, internalForce + ND, 0.0);
      for (int q = 0; q < Q; ++q)
        Kinematics::template addDivergence<N>(g.gradients[q].data(), g.hoop.at(q), s.P[q], g.weightedVolume[q],
                                              internalForce);
    }
    std::array<double, NA * ND> W;  // K_αα⁻¹ K_αu, written whole by the condensation (not zeroed: a residual pass never uses it)
    if (stiffness && !condensedTangent(g, s, kSymmetricPathPays && material.tangentIsSymmetric(), stiffness, W))
      return ElementStatus::InternalSolveFailed;
    if (state) {
      std::copy(solution.begin(), solution.end(), state + kStateAlpha);
      std::copy(u, u + ND, state + kStateDisplacement);
      if (stiffness)
        for (int k = 0; k < NA * ND; ++k) state[kStateSensitivity + k] = -W[k];  // dα/du = −K_αα⁻¹ K_αu
    }
    return ElementStatus::Ok;
  }

#if CONTESSA_KERNEL_AVX2
  /// evaluateHere compiled for AVX2, with every call but the law's inlined (KernelIsa.hpp).
  CONTESSA_TARGET_AVX2 ElementStatus evaluateAvx2(const ElementGeometry& geometry, int element, const double* u,
                                                        double* state, const Material& material, double* internalForce,
                                                        double* stiffness) const {
    return evaluateHere(geometry, element, u, state, material, internalForce, stiffness);
  }
#endif

  static bool computeGeometry(const double* X, Geometry& g) {
    ReferenceGeometry<Shape, Kinematics::kHoop> reference;
    if (!computeReferenceGeometry<Shape, Kinematics>(X, reference)) return false;
    const double centre[D] = {};
    const Matrix<D> J0 = parentJacobian<Shape>(centre, X);
    const double j0 = determinantOf<D>(J0);
    if (!(j0 > 0.0)) return false;
    const Matrix<D> J0inv = inverseOf<D>(J0, j0);
    const auto rule = Shape::quadrature();
    double volume = 0.0;
    for (int q = 0; q < Q; ++q) {
      std::copy(reference.dNdX[q].begin(), reference.dNdX[q].end(), g.gradients[q].begin());
      double* modes = g.gradients[q].data() + ND;
      // The modes' scale j0 / j makes ∫ H̃ dV vanish (EnhancedStrain.hpp); revolved, dV = 2π R j dξ, so
      // the scale is j0 R0 / (j R) (R0: the radius at the centre) and the patch test still holds.
      const double measureRatio = j0 * Kinematics::template measureFactor<Shape>(centre, X) /
                                  (reference.detJ[q] * Kinematics::template measureFactor<Shape>(rule[q].xi.data(), X));
      Modes::gradients(rule[q].xi.data(), measureRatio, J0inv, modes);
      // Each of the NA modes G_m, m = (β, i), has the single non-zero row g_β: ‖G_m‖ = |g_β|.
      double sum = 0.0;
      for (int beta = 0; beta < M; ++beta) {
        double n2 = 0.0;
        for (int J = 0; J < D; ++J) n2 += modes[D * beta + J] * modes[D * beta + J];
        sum += D * std::sqrt(n2);
      }
      g.modeNormSum[q] = sum;
      g.weightedVolume[q] = reference.weightedVolume[q];
      if constexpr (Kinematics::kHoop) std::copy(reference.hoop.at(q), reference.hoop.at(q) + N, g.hoop.at(q));
      volume += g.weightedVolume[q];
    }
    g.length = std::pow(volume, 1.0 / D);
    return true;
  }

  /// K = K_uu − K_uα W with W = K_αα⁻¹ K_αu, from the extended tangent at α* (all four blocks at
  /// once: nodes and modes are one list of gradients). With a symmetric material tangent only the upper
  /// blocks are built and condensed by LDLᵀ (condenseSymmetric). False when K_αα is singular.
  bool condensedTangent(const Geometry& g, const PointStates& s, bool symmetric, double* K,
                        std::array<double, NA * ND>& W) const {
    std::array<double, NE * NE> Ke;  // the symmetric path fills its upper triangle at the first point
    if constexpr (kSymmetricPathPays) {
      if (symmetric) {
        for (int q = 0; q < Q; ++q)
          Kinematics::template addSymmetricTangent<G>(g.gradients[q].data(), g.hoop.at(q), s.A[q], g.weightedVolume[q],
                                                      Ke.data(), NE, q == 0);
        return condenseSymmetric(Ke, K, W);
      }
    }
    Ke.fill(0.0);
    for (int q = 0; q < Q; ++q)
      Kinematics::template addTangent<G, G>(g.gradients[q].data(), g.hoop.at(q), g.gradients[q].data(), g.hoop.at(q),
                                            s.A[q], g.weightedVolume[q], Ke.data(), NE);
    return condenseGeneral(Ke, K, W);
  }

  /// Static condensation by Gaussian elimination with partial pivoting: K_αα W = K_αu, then
  /// K = K_uu − K_uα W. Ke whole.
  static bool condenseGeneral(const std::array<double, NE * NE>& Ke, double* K, std::array<double, NA * ND>& W) {
    std::array<double, NA * NA> Kaa;
    for (int m = 0; m < NA; ++m) {
      for (int n = 0; n < NA; ++n) Kaa[m * NA + n] = Ke[(ND + m) * NE + ND + n];
      for (int c = 0; c < ND; ++c) W[m * ND + c] = Ke[(ND + m) * NE + c];
    }
    if (!solveDenseInPlace<NA, ND>(Kaa.data(), W.data())) return false;
    for (int r = 0; r < ND; ++r)
      for (int c = 0; c < ND; ++c) {
        double sum = 0.0;
        for (int m = 0; m < NA; ++m) sum += Ke[r * NE + ND + m] * W[m * ND + c];
        K[r * ND + c] = Ke[r * NE + c] - sum;
      }
    return true;
  }

  /// Static condensation of a symmetric Ke given by its upper triangle (addSymmetricTangent): with
  /// K_αα = L D Lᵀ and Y = L⁻¹ K_αu, K = K_uu − Yᵀ D⁻¹ Y (symmetric) and W = L⁻ᵀ D⁻¹ Y: the
  /// triangular solves replace the pivoting elimination with 24 right-hand sides; when K_αα is not
  /// positive definite (LDLᵀ refuses), Ke is completed and condenseGeneral pivots.
  static bool condenseSymmetric(std::array<double, NE * NE>& Ke, double* K, std::array<double, NA * ND>& W) {
    std::array<double, NA * NA> Kaa;
    for (int m = 0; m < NA; ++m)
      for (int n = 0; n <= m; ++n) Kaa[m * NA + n] = Ke[(ND + n) * NE + ND + m];
    if (!factorPositiveDefinite<NA>(Kaa.data())) {
      mirrorUpperTriangle<NE>(Ke.data(), NE);
      return condenseGeneral(Ke, K, W);
    }
    std::array<double, NA * ND> Y;  // K_αu, from the upper block K_uα
    for (int m = 0; m < NA; ++m)
      for (int c = 0; c < ND; ++c) Y[m * ND + c] = Ke[c * NE + ND + m];
    forwardSubstitute<NA, ND>(Kaa.data(), Y.data());
    for (int m = 0; m < NA; ++m) {
      const double inverse = 1.0 / Kaa[m * NA + m];
      for (int c = 0; c < ND; ++c) W[m * ND + c] = Y[m * ND + c] * inverse;
    }
    schurRowBlocks(Ke, Y, W, K, std::make_integer_sequence<int, N>{});
    mirrorUpperTriangle<ND>(K, ND);
    backSubstitute<NA, ND>(Kaa.data(), W.data());
    return true;
  }

  /// K_rc = Ke_rc − Σ_m Y_mr W_mc over the row block of node a (rows D·a .. D·a + D − 1), columns from
  /// D·a on: the blocks b ≥ a, which mirrorUpperTriangle completes. `a` is a template parameter so
  /// that every column loop has a length known at compile time and vectorises (whole rows cost 5 184
  /// multiply-adds for Hex8 Enhanced, these 2 916; a run-time start cost more instructions than the
  /// operations it saved, issue 23 third round).
  template <int a>
  static void schurRowBlock(const std::array<double, NE * NE>& Ke, const std::array<double, NA * ND>& Y,
                            const std::array<double, NA * ND>& W, double* K) {
    for (int r = D * a; r < D * a + D; ++r) {
      double* row = K + r * ND;
      for (int c = D * a; c < ND; ++c) row[c] = Ke[r * NE + c];
      for (int m = 0; m < NA; ++m) {
        const double y = Y[m * ND + r];
        for (int c = D * a; c < ND; ++c) row[c] -= y * W[m * ND + c];
      }
    }
  }
  template <int... a>
  static void schurRowBlocks(const std::array<double, NE * NE>& Ke, const std::array<double, NA * ND>& Y,
                             const std::array<double, NA * ND>& W, double* K, std::integer_sequence<int, a...>) {
    (schurRowBlock<a>(Ke, Y, W, K), ...);
  }

  static Matrix<MD> compatibleGradient(const Geometry& g, int q, const double* u) {
    Matrix<MD> H{};
    Kinematics::template addGradient<N>(g.gradients[q].data(), g.hoop.at(q), u, H);
    for (int i = 0; i < MD; ++i) H[MD * i + i] += 1.0;
    return H;
  }

  /// F = (I + GRAD u) + H̃(α).
  static Matrix<MD> enhancedGradient(const Geometry& g, int q, const Matrix<MD>& compatible, const Alpha& alpha) {
    Matrix<MD> H{};
    Kinematics::template addGradient<M>(g.gradients[q].data() + ND, nullptr, alpha.data(), H);
    for (int n = 0; n < MD * MD; ++n) H[n] += compatible[n];
    return H;
  }

  template <int n>
  static double norm(const double* v) {
    double s = 0.0;
    for (int k = 0; k < n; ++k) s += v[k] * v[k];
    return std::sqrt(s);
  }

  /// K_αα Δα = −R_α (`step` holds −R_α on entry, Δα on exit); LDLᵀ for a symmetric material tangent.
  static bool localNewtonStep(const Geometry& g, const PointStates& s, bool symmetric, std::array<double, NA * NA>& Kaa,
                              Alpha& step) {
    if constexpr (kSymmetricPathPays) {
      if (symmetric) {
        for (int q = 0; q < Q; ++q)
          Kinematics::template addSymmetricTangent<M>(g.gradients[q].data() + ND, nullptr, s.A[q], g.weightedVolume[q],
                                                      Kaa.data(), NA, q == 0);
        mirrorUpperTriangle<NA>(Kaa.data(), NA);
        return solveSymmetricInPlace<NA, 1>(Kaa.data(), step.data());
      }
    }
    for (int q = 0; q < Q; ++q) {
      const double* modes = g.gradients[q].data() + ND;
      Kinematics::template addTangent<M, M>(modes, nullptr, modes, nullptr, s.A[q], g.weightedVolume[q], Kaa.data(), NA);
    }
    return solveDenseInPlace<NA, 1>(Kaa.data(), step.data());
  }

  /// Local Newton on R_α(u, α) = 0 from `alpha`; on success `alpha` is the solution and `s` holds F
  /// and P there, and A too when `tangent` (a Jacobian evaluation). Without `tangent` (a residual) A is
  /// evaluated only where a Newton step needs it, not at the iterate that passes the convergence test:
  /// that saves one of the law's tangents per residual evaluation (issue 23, fifth round), and P is the
  /// same either way (the same F), so the iterates are too.
  ElementStatus solveLocal(const Geometry& g, const std::array<Matrix<MD>, Q>& Fc, const Material& material,
                           bool tangent, Alpha& alpha, PointStates& s) const {
    Alpha step{};
    double previousNorm = HUGE_VAL;
    for (int iter = 0; iter < kMaxLocalIterations; ++iter) {
      for (int q = 0; q < Q; ++q) s.F[q] = enhancedGradient(g, q, Fc[q], alpha);
      if (!material.firstPiolaKirchhoffAtPoints(Q, s.F.data(), s.P.data(), tangent ? s.A.data() : nullptr)) {
        // Inadmissible at the starting guess: the deformation (or the start) is bad. After a Newton
        // step: the step overshot, so halve it and try again.
        if (iter == 0) return ElementStatus::InadmissibleDeformation;
        for (int m = 0; m < NA; ++m) {
          step[m] *= 0.5;
          alpha[m] -= step[m];
        }
        continue;
      }
      Alpha R{};
      double scale = 0.0;
      for (int q = 0; q < Q; ++q) {
        Kinematics::template addDivergence<M>(g.gradients[q].data() + ND, nullptr, s.P[q], g.weightedVolume[q], R.data());
        scale += normOf<MD>(s.P[q]) * g.modeNormSum[q] * g.weightedVolume[q];
      }
      const double rNorm = norm<NA>(R.data());
      if (!std::isfinite(rNorm)) return ElementStatus::InternalSolveFailed;
      if (rNorm <= kResidualTolerance * scale ||
          (rNorm <= kStagnationTolerance * scale && rNorm > 0.5 * previousNorm))
        return ElementStatus::Ok;
      // Newton step K_αα Δα = −R_α (A at this α first, if the residual pass has not evaluated it).
      if (!tangent && !material.firstPiolaKirchhoffAtPoints(Q, s.F.data(), s.P.data(), s.A.data()))
        return ElementStatus::InternalSolveFailed;  // cannot happen: P was admissible at this F
      std::array<double, NA * NA> Kaa{};
      for (int m = 0; m < NA; ++m) step[m] = -R[m];
      if (!localNewtonStep(g, s, kSymmetricPathPays && material.tangentIsSymmetric(), Kaa, step))
        return ElementStatus::InternalSolveFailed;
      // The current α is already exact to round-off; F, P, A in s belong to it.
      if (norm<NA>(step.data()) <= kStepTolerance * (norm<NA>(alpha.data()) + g.length)) return ElementStatus::Ok;
      for (int m = 0; m < NA; ++m) alpha[m] += step[m];
      previousNorm = rNorm;
    }
    return ElementStatus::InternalSolveFailed;
  }
};

}  // namespace contessa::mechanics
