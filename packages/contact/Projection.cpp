#include "contact/Projection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace contessa::contact {

namespace {

/// Barycentric weights of the point of segment [a, b] closest to x.
template <std::size_t D>
std::array<double, 2> closestOnSegment(const std::array<double, D>& x, const std::array<double, D>& a,
                                       const std::array<double, D>& b) {
  const auto e = subtract(b, a);
  const double length2 = dot(e, e);
  const double t = length2 > 0.0 ? std::clamp(dot(subtract(x, a), e) / length2, 0.0, 1.0) : 0.0;
  return {1.0 - t, t};
}

/// Barycentric weights of the point of a flat piece (segment or triangle) closest to x, clamped to it.
template <std::size_t D, std::size_t K>
std::array<double, K> closestOnPiece(const std::array<double, D>& x, const std::array<std::array<double, D>, K>& v) {
  if constexpr (K == 2) {
    return closestOnSegment(x, v[0], v[1]);
  } else {
    static_assert(K == 3, "flat pieces are segments or triangles");
    // Unconstrained: x − v0 ≈ s e1 + t e2 in the least-squares sense (the triangle's plane).
    const auto e1 = subtract(v[1], v[0]);
    const auto e2 = subtract(v[2], v[0]);
    const auto r = subtract(x, v[0]);
    Matrix<2, 2> g;
    g(0, 0) = dot(e1, e1);
    g(0, 1) = g(1, 0) = dot(e1, e2);
    g(1, 1) = dot(e2, e2);
    if (determinant(g) > 0.0) {
      const Vector<2> st = multiply(inverse(g), Vector<2>{dot(r, e1), dot(r, e2)});
      if (st[0] >= 0.0 && st[1] >= 0.0 && st[0] + st[1] <= 1.0) return {1.0 - st[0] - st[1], st[0], st[1]};
    }
    // Outside (or a degenerate triangle): the closest point lies on an edge.
    std::array<double, 3> best{1.0, 0.0, 0.0};
    double bestDistance = std::numeric_limits<double>::infinity();
    for (int edge = 0; edge < 3; ++edge) {
      const int i = edge, j = (edge + 1) % 3;
      const auto w = closestOnSegment(x, v[i], v[j]);
      const auto point = add(scaled(w[0], v[i]), scaled(w[1], v[j]));
      const double distance = norm(subtract(x, point));
      if (distance < bestDistance) {
        bestDistance = distance;
        best = {0.0, 0.0, 0.0};
        best[i] = w[0];
        best[j] = w[1];
      }
    }
    return best;
  }
}

}  // namespace

template <class Facet>
ProjectionResult<Facet> Projection<Facet>::evaluateAt(const Point& slave, const NodeCoords& master,
                                                      const SurfaceCoords& xi) {
  constexpr int nXi = Facet::kSurfaceDim;
  ProjectionResult<Facet> p;
  p.xi = xi;
  p.shape = Facet::shapeFunctions(xi);
  const auto dH = Facet::shapeDerivatives(xi);
  // Positions relative to the facet's first node (Σ H_i = 1, Σ H_i,α = 0): x̄ = x_1 + Σ H_i (x_i − x_1),
  // ā_α = Σ H_i,α (x_i − x_1), g_N = ((x^k − x_1) − Σ H_i (x_i − x_1))·n̄. In absolute coordinates Σ H_i
  // is 1 only to round-off, so a slave node flush with a flat facet far from the origin got a gap of
  // ±ulp(|x|) instead of 0, and a penalty of 1e8 turned that into a residual no Newton tolerance meets
  // (a flush start at λ = 0, issue 22). Relative to x_1, a flat facet and a node in its plane give 0.
  const Point& origin = master[0];
  Point offset{};
  for (int i = 1; i < Facet::kNodes; ++i) {
    const Point relative = subtract(master[i], origin);
    addScaled(offset, p.shape[i], relative);
    // eq. (2)–(3): ā_α = ∂x̄/∂ξ^α = Σ_i H_i,α x_i
    for (int alpha = 0; alpha < nXi; ++alpha) addScaled(p.covariantBasis[alpha], dH(i, alpha), relative);
  }
  p.position = add(origin, offset);
  for (int alpha = 0; alpha < nXi; ++alpha)
    for (int beta = 0; beta < nXi; ++beta) p.metric(alpha, beta) = dot(p.covariantBasis[alpha], p.covariantBasis[beta]);
  if (determinant(p.metric) <= 0.0) return p;  // degenerate facet (zero length/area): no geometry, not converged
  p.inverseMetric = inverse(p.metric);
  for (int alpha = 0; alpha < nXi; ++alpha)
    for (int beta = 0; beta < nXi; ++beta)
      addScaled(p.contravariantBasis[alpha], p.inverseMetric(alpha, beta), p.covariantBasis[beta]);
  p.normal = Facet::unitNormal(p.covariantBasis);          // eq. (5)
  p.gap = dot(subtract(subtract(slave, origin), offset), p.normal);  // eq. (4)
  return p;
}

template <class Facet>
std::vector<typename Facet::SurfaceCoords> Projection<Facet>::startCandidates(const Point& slave,
                                                                              const NodeCoords& master) {
  std::vector<SurfaceCoords> starts{Facet::center()};
  for (const auto& piece : Facet::flatPieces()) {
    std::array<Point, Facet::kSpaceDim> vertices{};
    for (int v = 0; v < Facet::kSpaceDim; ++v) vertices[v] = master[piece[v]];
    const auto weights = closestOnPiece(slave, vertices);
    SurfaceCoords xi{};
    for (int v = 0; v < Facet::kSpaceDim; ++v) addScaled(xi, weights[v], Facet::nodeCoords(piece[v]));
    starts.push_back(xi);
  }
  // Closest on the facet first (the flat pieces' points are near the facet, not on it when it is warped).
  std::vector<double> distance;
  for (const auto& xi : starts) distance.push_back(norm(subtract(slave, evaluateAt(slave, master, xi).position)));
  std::vector<std::size_t> order(starts.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return distance[a] < distance[b]; });
  std::vector<SurfaceCoords> sorted;
  for (std::size_t i : order) sorted.push_back(starts[i]);
  return sorted;
}

template <class Facet>
ProjectionResult<Facet> Projection<Facet>::project(const Point& slave, const NodeCoords& master) const {
  if constexpr (Facet::kAffine) {
    return project(slave, master, Facet::center());
  } else {
    ProjectionResult<Facet> best;
    int tried = 0;
    for (const SurfaceCoords& start : startCandidates(slave, master)) {
      ProjectionResult<Facet> p = project(slave, master, start);
      if (++tried == 1) best = p;  // reported when no start converges
      if (!p.converged) continue;
      best = p;
      break;  // the closest start converged: its stationary point of φ is the projection
    }
    best.starts = tried;
    return best;
  }
}

template <class Facet>
ProjectionResult<Facet> Projection<Facet>::project(const Point& slave, const NodeCoords& master,
                                                   const SurfaceCoords& start) const {
  constexpr int nXi = Facet::kSurfaceDim;
  // A step never exceeds the width of the parent domain, so Newton on a curved facet cannot run off along
  // its unbounded bilinear extension (not needed where the step is exact, Facet::kAffine).
  constexpr double kMaxStep = 2.0;
  constexpr int kMaxHalvings = 30;
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
    Vector<nXi> step = multiply(inverse(definite ? negJacobian : p.metric), residual);
    double stepNorm = 0.0;
    for (int alpha = 0; alpha < nXi; ++alpha) stepNorm = std::max(stepNorm, std::abs(step[alpha]));
    if (!std::isfinite(stepNorm)) return p;
    const double newtonStepNorm = stepNorm;  // convergence is judged on the full step, not a damped one
    if constexpr (Facet::kAffine) {
      for (int alpha = 0; alpha < nXi; ++alpha) xi[alpha] += step[alpha];
      p = evaluateAt(slave, master, xi);
    } else {
      if (stepNorm > kMaxStep) {
        step = scaled(kMaxStep / stepNorm, step);
        stepNorm = kMaxStep;
      }
      // Backtracking on φ = ½‖x^k − x̄‖²; below the tolerance the step is taken as it is (φ is flat to
      // round-off there and cannot judge it).
      const double phi = dot(distance, distance);
      ProjectionResult<Facet> next;
      for (int halving = 0;; ++halving) {
        SurfaceCoords trial = xi;
        for (int alpha = 0; alpha < nXi; ++alpha) trial[alpha] += step[alpha];
        next = evaluateAt(slave, master, trial);
        const Point d = subtract(slave, next.position);
        if (dot(d, d) <= phi || stepNorm <= options_.tolerance || halving == kMaxHalvings) {
          xi = trial;
          break;
        }
        step = scaled(0.5, step);
        stepNorm *= 0.5;
      }
      p = next;
    }
    p.iterations = iteration;
    if (newtonStepNorm <= options_.tolerance) {
      p.converged = true;
      return p;
    }
  }
  return p;
}

#define CONTESSA_INSTANTIATE_PROJECTION(F) template class Projection<F>;
CONTESSA_FOR_EACH_FACET(CONTESSA_INSTANTIATE_PROJECTION)
#undef CONTESSA_INSTANTIATE_PROJECTION

}  // namespace contessa::contact
