#include "mechanics/EnhancedStrainElement.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "mechanics/DenseSolve.hpp"
#include "mechanics/EnhancedStrain.hpp"
#include "mechanics/SolidOperators.hpp"

namespace contessa::mechanics {
namespace {

// Local Newton stopping rules. R_α is converged when ‖R_α‖ ≤ kResidualTolerance · s, where
// s = Σ_gp ‖P‖ Σ_m ‖G_m‖ w j bounds the size of the terms summed into R_α (so the test is
// independent of units and of the load level). The condensed tangent is exact only at R_α = 0, and
// an α error δα shows up as K_uα δα in f_int, hence the tight value: Newton converges
// quadratically, so it costs at most one extra iteration. Two fallbacks end the iteration at the
// round-off floor: a Newton step negligible against the element size, or a residual that is small
// and no longer decreasing (quadratic convergence would have reduced it by orders of magnitude).
constexpr double kResidualTolerance = 1e-13;
constexpr double kStagnationTolerance = 1e-9;
constexpr double kStepTolerance = 1e-14;

struct EnhancedPoint {
  PointGeometry geometry;
  EnhancedModes modes;
  Tensor2 compatibleF{};  ///< I + GRAD u
};

/// Geometry, enhanced modes and compatible F at every quadrature point; false for a bad reference
/// element. `volume` = Σ w j.
bool preparePoints(const ReferenceElement& ref, const double* X, const double* u,
                   std::vector<EnhancedPoint>& points, double& volume) {
  const int dim = ref.dimension(), nn = ref.numNodes();
  std::vector<PointGeometry> geometry;
  if (!referenceGeometry(ref, X, geometry)) return false;
  const double centre[3] = {0.0, 0.0, 0.0};
  const Tensor2 J0 = parentJacobian(ref, centre, X);
  const double j0 = determinant(J0);
  if (!(j0 > 0.0)) return false;
  const Tensor2 J0inv = inverse(J0);
  const auto& rule = ref.quadrature();
  points.resize(rule.size());
  volume = 0.0;
  for (std::size_t q = 0; q < rule.size(); ++q) {
    EnhancedPoint& p = points[q];
    p.geometry = geometry[q];
    p.modes = enhancedModes(dim, rule[q].xi.data(), J0inv, j0 / p.geometry.detJ);
    p.compatibleF = add(identity2(), displacementGradient(dim, nn, p.geometry, u));
    volume += p.geometry.weightedVolume;
  }
  return true;
}

/// Residuals and tangents at fixed α. The u blocks are only formed when requested.
struct LocalSystem {
  int nd = 0, nm = 0;
  std::array<double, kMaxEnhancedModes> Ra{};
  std::array<double, kMaxEnhancedModes * kMaxEnhancedModes> Kaa{};
  double scale = 0.0;
  std::vector<double> Ru, Kuu, Kua, Kau;

  LocalSystem(int numDofs, int numModes) : nd(numDofs), nm(numModes) {}

  bool integrate(int dim, int nn, const std::vector<EnhancedPoint>& points, const Material& material,
                 const double* alpha, bool force, bool tangent) {
    Ra.fill(0.0);
    Kaa.fill(0.0);
    scale = 0.0;
    Ru.assign(force ? nd : 0, 0.0);
    Kuu.assign(tangent ? nd * nd : 0, 0.0);
    Kua.assign(tangent ? nd * nm : 0, 0.0);
    Kau.assign(tangent ? nm * nd : 0, 0.0);
    Tensor2 P{};
    Tensor4 A{};
    for (const EnhancedPoint& p : points) {
      const PointGeometry& g = p.geometry;
      const Tensor2 F = add(p.compatibleF, enhancedGradient(p.modes, alpha));
      if (!material.firstPiolaKirchhoff(F, P, &A)) return false;
      addEnhancedResidual(p.modes, P, g.weightedVolume, Ra.data());
      addEnhancedStiffness(dim, p.modes, A, g.weightedVolume, Kaa.data());
      scale += frobeniusNorm(P) * p.modes.normSum * g.weightedVolume;
      if (force) addInternalForce(dim, nn, g, P, Ru.data());
      if (tangent) {
        addMaterialStiffness(dim, nn, g, A, Kuu.data());
        addCouplingStiffness(dim, nn, g, p.modes, A, Kua.data(), Kau.data());
      }
    }
    return true;
  }
};

double norm(const double* v, int n) {
  double s = 0.0;
  for (int k = 0; k < n; ++k) s += v[k] * v[k];
  return std::sqrt(s);
}

}  // namespace

ElementStatus EnhancedStrainElement::evaluate(const double* X, const double* u, double* internal,
                                              const Material& material, double* internalForce,
                                              double* stiffness) const {
  const int dim = dimension(), nn = numNodes(), nd = numDofs(), nm = numInternalVariables();
  std::vector<EnhancedPoint> points;
  double volume = 0.0;
  if (!preparePoints(reference_, X, u, points, volume)) return ElementStatus::InadmissibleDeformation;
  const double length = std::pow(volume, 1.0 / dim);  // α has units of length (α̂ J0⁻¹ is a gradient)

  std::array<double, kMaxEnhancedModes> alpha{}, step{};
  if (internal) std::copy(internal, internal + nm, alpha.begin());
  LocalSystem sys(nd, nm);
  bool converged = false;
  double previousNorm = HUGE_VAL;
  for (int iter = 0; iter < kMaxLocalIterations && !converged; ++iter) {
    if (!sys.integrate(dim, nn, points, material, alpha.data(), internalForce != nullptr, stiffness != nullptr)) {
      // Inadmissible at the starting guess: the deformation itself is bad. After a Newton step:
      // the step overshot, so halve it and try again.
      if (iter == 0) return ElementStatus::InadmissibleDeformation;
      for (int m = 0; m < nm; ++m) {
        step[m] *= 0.5;
        alpha[m] -= step[m];
      }
      continue;
    }
    const double rNorm = norm(sys.Ra.data(), nm);
    if (!std::isfinite(rNorm)) return ElementStatus::InternalSolveFailed;
    if (rNorm <= kResidualTolerance * sys.scale ||
        (rNorm <= kStagnationTolerance * sys.scale && rNorm > 0.5 * previousNorm)) {
      converged = true;
      break;
    }
    // Newton step K_αα Δα = −R_α.
    std::array<double, kMaxEnhancedModes * kMaxEnhancedModes> Kaa = sys.Kaa;
    for (int m = 0; m < nm; ++m) step[m] = -sys.Ra[m];
    if (!solveDenseInPlace(nm, Kaa.data(), 1, step.data())) return ElementStatus::InternalSolveFailed;
    if (norm(step.data(), nm) <= kStepTolerance * (norm(alpha.data(), nm) + length)) {
      converged = true;  // the current α is already exact to round-off; outputs below are consistent
      break;
    }
    for (int m = 0; m < nm; ++m) alpha[m] += step[m];
    previousNorm = rNorm;
  }
  if (!converged) return ElementStatus::InternalSolveFailed;

  if (internalForce) std::copy(sys.Ru.begin(), sys.Ru.end(), internalForce);
  if (stiffness) {
    // Static condensation: K = K_uu − K_uα Z with K_αα Z = K_αu.
    std::array<double, kMaxEnhancedModes * kMaxEnhancedModes> Kaa = sys.Kaa;
    std::vector<double> Z = sys.Kau;
    if (!solveDenseInPlace(nm, Kaa.data(), nd, Z.data())) return ElementStatus::InternalSolveFailed;
    for (int r = 0; r < nd; ++r)
      for (int c = 0; c < nd; ++c) {
        double s = 0.0;
        for (int m = 0; m < nm; ++m) s += sys.Kua[r * nm + m] * Z[m * nd + c];
        stiffness[r * nd + c] = sys.Kuu[r * nd + c] - s;
      }
  }
  if (internal) std::copy(alpha.begin(), alpha.begin() + nm, internal);
  return ElementStatus::Ok;
}

ElementStatus EnhancedStrainElement::averageCauchyStress(const double* X, const double* u, const double* internal,
                                                         const Material& material, Tensor2& sigma) const {
  const int nm = numInternalVariables();
  std::array<double, kMaxEnhancedModes> alpha{};
  if (internal) {
    std::copy(internal, internal + nm, alpha.begin());
  } else {
    const ElementStatus status = evaluate(X, u, alpha.data(), material, nullptr, nullptr);
    if (status != ElementStatus::Ok) return status;
  }
  std::vector<EnhancedPoint> points;
  double volume = 0.0;
  if (!preparePoints(reference_, X, u, points, volume)) return ElementStatus::InadmissibleDeformation;
  sigma = Tensor2{};
  Tensor2 s{};
  for (const EnhancedPoint& p : points) {
    if (!material.cauchyStress(add(p.compatibleF, enhancedGradient(p.modes, alpha.data())), s))
      return ElementStatus::InadmissibleDeformation;
    sigma = add(sigma, s);
  }
  sigma = scaled(1.0 / static_cast<double>(points.size()), sigma);
  return ElementStatus::Ok;
}

}  // namespace contessa::mechanics
