#include "contact/Projection.hpp"

#include <algorithm>
#include <cmath>

namespace contessa::contact {

template <class Facet>
ProjectionResult<Facet> Projection<Facet>::evaluateAt(const Point& slave, const NodeCoords& master,
                                                      const SurfaceCoords& xi) {
  constexpr int nXi = Facet::kSurfaceDim;
  ProjectionResult<Facet> p;
  p.xi = xi;
  p.shape = Facet::shapeFunctions(xi);
  const auto dH = Facet::shapeDerivatives(xi);
  for (int i = 0; i < Facet::kNodes; ++i) {
    addScaled(p.position, p.shape[i], master[i]);
    // eq. (2)–(3): ā_α = ∂x̄/∂ξ^α = Σ_i H_i,α x_i
    for (int alpha = 0; alpha < nXi; ++alpha) addScaled(p.covariantBasis[alpha], dH(i, alpha), master[i]);
  }
  for (int alpha = 0; alpha < nXi; ++alpha)
    for (int beta = 0; beta < nXi; ++beta) p.metric(alpha, beta) = dot(p.covariantBasis[alpha], p.covariantBasis[beta]);
  if (determinant(p.metric) <= 0.0) return p;  // degenerate facet (zero length/area): no geometry, not converged
  p.inverseMetric = inverse(p.metric);
  for (int alpha = 0; alpha < nXi; ++alpha)
    for (int beta = 0; beta < nXi; ++beta)
      addScaled(p.contravariantBasis[alpha], p.inverseMetric(alpha, beta), p.covariantBasis[beta]);
  p.normal = Facet::unitNormal(p.covariantBasis);          // eq. (5)
  p.gap = dot(subtract(slave, p.position), p.normal);      // eq. (4)
  return p;
}

template <class Facet>
ProjectionResult<Facet> Projection<Facet>::project(const Point& slave, const NodeCoords& master,
                                                   const SurfaceCoords& start) const {
  constexpr int nXi = Facet::kSurfaceDim;
  SurfaceCoords xi = start;
  ProjectionResult<Facet> p = evaluateAt(slave, master, xi);
  for (int iteration = 1; iteration <= options_.maxIterations; ++iteration) {
    if (determinant(p.metric) <= 0.0) return p;
    const Point distance = subtract(slave, p.position);
    // r_α = (x^k − x̄)·ā_α, eq. (1) times ‖x^k − x̄‖
    Vector<nXi> residual{};
    for (int alpha = 0; alpha < nXi; ++alpha) residual[alpha] = dot(distance, p.covariantBasis[alpha]);
    // −∂r_α/∂ξ^β = ā_αβ − (x^k − x̄)·x̄,αβ
    Matrix<nXi, nXi> negJacobian = p.metric;
    const auto d2H = Facet::shapeSecondDerivatives(xi);
    for (int i = 0; i < Facet::kNodes; ++i) {
      const double projected = dot(distance, master[i]);
      for (int alpha = 0; alpha < nXi; ++alpha)
        for (int beta = 0; beta < nXi; ++beta) negJacobian(alpha, beta) -= d2H[i](alpha, beta) * projected;
    }
    const bool definite = negJacobian(0, 0) > 0.0 && determinant(negJacobian) > 0.0;
    const Vector<nXi> step = multiply(inverse(definite ? negJacobian : p.metric), residual);
    double stepNorm = 0.0;
    for (int alpha = 0; alpha < nXi; ++alpha) {
      xi[alpha] += step[alpha];
      stepNorm = std::max(stepNorm, std::abs(step[alpha]));
    }
    p = evaluateAt(slave, master, xi);
    p.iterations = iteration;
    if (stepNorm <= options_.tolerance) {
      p.converged = true;
      return p;
    }
    if (!std::isfinite(stepNorm)) return p;
  }
  return p;
}

template class Projection<Line2Facet>;
template class Projection<Quad4Facet>;

}  // namespace contessa::contact
