#include "contact/ValleyBlend.hpp"

#include <algorithm>
#include <cmath>

namespace contessa::contact {

namespace {

/// The edges of a facet as (α, s): the nodes with ξ^α = s (2D: an end vertex; 3D: a side).
template <class Facet>
std::vector<int> edgeNodes(const MasterFacetNodes<Facet>& f, int alpha, double side) {
  std::vector<int> ids;
  for (int i = 0; i < Facet::kNodes; ++i)
    if (Facet::nodeCoords(i)[alpha] == side) ids.push_back(f.nodes[i]);
  std::sort(ids.begin(), ids.end());
  return ids;
}

/// ξ at the middle of the edge (α, s) of the parent domain [−1, 1]^M.
template <class Facet>
typename Facet::SurfaceCoords edgeMiddle(int alpha, double side) {
  typename Facet::SurfaceCoords xi{};
  xi[alpha] = side;
  return xi;
}

/// The partner's edge (α, s) holding the same nodes, if any.
template <class Facet>
std::optional<std::pair<int, double>> matchingEdge(const MasterFacetNodes<Facet>& f, const std::vector<int>& ids) {
  for (int alpha = 0; alpha < Facet::kSurfaceDim; ++alpha)
    for (double side : {-1.0, 1.0})
      if (edgeNodes(f, alpha, side) == ids) return std::make_pair(alpha, side);
  return std::nullopt;
}

/// Smootherstep S(t) = t³(10 − 15t + 6t²) and its first two derivatives in t.
struct Step {
  double value = 0.0, first = 0.0, second = 0.0;
};
Step smootherstep(double t) {
  if (t <= 0.0) return {0.0, 0.0, 0.0};
  if (t >= 1.0) return {1.0, 0.0, 0.0};
  return {t * t * t * (10.0 - 15.0 * t + 6.0 * t * t), 30.0 * t * t * (1.0 - t) * (1.0 - t),
          60.0 * t * (1.0 - t) * (1.0 - 2.0 * t)};
}

}  // namespace

template <class Facet>
std::optional<ValleyEdge> findValleyEdge(const typename Facet::Point& slave, std::size_t selected,
                                         const std::vector<MasterFacetNodes<Facet>>& candidates,
                                         const std::vector<MasterFacetNodes<Facet>>& reference, double slaveSize,
                                         const ValleyBlendOptions& options) {
  const auto& fa = candidates[selected];
  if (!(slaveSize > 0.0) || fa.id < 0 || static_cast<std::size_t>(fa.id) >= reference.size()) return std::nullopt;
  const Projection<Facet> projection;
  const auto pa = projection.project(slave, fa.x);
  if (!pa.converged) return std::nullopt;
  std::optional<ValleyEdge> best;
  double bestDistance = 0.0;
  for (int alpha = 0; alpha < Facet::kSurfaceDim; ++alpha)
    for (double side : {-1.0, 1.0}) {
      const std::vector<int> ids = edgeNodes(fa, alpha, side);
      for (std::size_t c = 0; c < candidates.size(); ++c) {
        const auto& fb = candidates[c];
        if (c == selected || fb.id < 0 || static_cast<std::size_t>(fb.id) >= reference.size()) continue;
        const auto across = matchingEdge(fb, ids);
        if (!across) continue;
        // A valley: the partner rises in front of facet a's tangent plane at the edge, by more than minAngle.
        const auto ea = Projection<Facet>::evaluateAt(slave, fa.x, edgeMiddle<Facet>(alpha, side));
        const auto eb = Projection<Facet>::evaluateAt(slave, fb.x, edgeMiddle<Facet>(across->first, across->second));
        const auto cb = Projection<Facet>::evaluateAt(slave, fb.x, Facet::center());
        const double chord = norm(subtract(ea.normal, eb.normal));  // 2 sin(θ/2)
        const double angle = 2.0 * std::asin(std::min(1.0, 0.5 * chord));
        if (!(dot(subtract(cb.position, ea.position), ea.normal) > 0.0) || !(angle > options.minAngle)) continue;
        const auto pb = projection.project(slave, fb.x);
        if (!pb.converged) continue;
        ValleyEdge e;
        e.a = selected;
        e.b = c;
        e.acrossA = alpha;
        e.sideA = side;
        e.acrossB = across->first;
        e.sideB = across->second;
        e.angle = angle;
        const auto lengthAcross = [&](const MasterFacetNodes<Facet>& f, int al) {
          const auto at = Projection<Facet>::evaluateAt(slave, reference[static_cast<std::size_t>(f.id)].x, Facet::center());
          return norm(at.covariantBasis[al]);
        };
        e.lengthA = lengthAcross(fa, alpha);
        e.lengthB = lengthAcross(fb, e.acrossB);
        e.band = std::min(options.bandWidth * slaveSize, options.maxFacetFraction * std::min(e.lengthA, e.lengthB));
        const double etaA = side * pa.xi[alpha] - 1.0, etaB = e.sideB * pb.xi[e.acrossB] - 1.0;
        const double z = 0.5 * (e.lengthA * etaA - e.lengthB * etaB);
        if (!(std::abs(z) < e.band) || (best && !(std::abs(z) < bestDistance))) continue;
        best = e;
        bestDistance = std::abs(z);
      }
    }
  return best;
}

template <class Facet>
ValleyBlendResult<Facet> evaluateValleyBlend(const PenaltyNormalLaw& law, const typename Facet::Point& slave,
                                             const MasterFacetNodes<Facet>& a, const MasterFacetNodes<Facet>& b,
                                             const ValleyEdge& edge) {
  constexpr int kDim = Facet::kSpaceDim;
  constexpr int kNodes = Facet::kNodes;
  using Variation = FacetGapVariation<Facet>;
  ValleyBlendResult<Facet> out;
  const Variation va = facetGapVariation<Facet>({slave, a.x});
  const Variation vb = facetGapVariation<Facet>({slave, b.x});
  if (!va.valid || !vb.valid) return out;

  // The union of the nodes: the slave, a's nodes, b's nodes not in a. blockOf[f][i]: the block of local
  // node i of facet f (block 0 is the slave node in both facets' element dofs).
  std::array<std::array<int, 1 + kNodes>, 2> blockOf{};
  int blocks = 1 + kNodes;
  for (int i = 0; i < kNodes; ++i) {
    blockOf[0][1 + i] = 1 + i;
    out.source[1 + i] = {0, i};
  }
  for (int j = 0; j < kNodes; ++j) {
    int shared = -1;
    for (int i = 0; i < kNodes && shared < 0; ++i)
      if (a.nodes[i] == b.nodes[j]) shared = 1 + i;
    if (shared < 0) {
      out.source[blocks] = {1, j};
      shared = blocks++;
    }
    blockOf[1][1 + j] = shared;
  }
  out.numBlocks = blocks;
  const int n = blocks * kDim;
  const auto dof = [&](int f, int elementDof) { return blockOf[f][elementDof / kDim] * kDim + elementDof % kDim; };
  using Column = std::vector<double>;
  using Square = std::vector<double>;
  const auto embed = [&](int f, const Vector<Variation::kDofs>& v, double s, Column& into) {
    for (int i = 0; i < Variation::kDofs; ++i) into[dof(f, i)] += s * v[i];
  };
  const auto embedMatrix = [&](int f, const Matrix<Variation::kDofs, Variation::kDofs>& m, double s, Square& into) {
    for (int i = 0; i < Variation::kDofs; ++i)
      for (int j = 0; j < Variation::kDofs; ++j) into[dof(f, i) * n + dof(f, j)] += s * m(i, j);
  };
  const auto outer = [&](Square& into, double s, const Column& x, const Column& y) {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) into[i * n + j] += s * x[i] * y[j];
  };

  // z = ½(ℓ_a η_a − ℓ_b η_b), η_f = s_f ξ̄_f^α − 1, and its derivatives.
  const double etaA = edge.sideA * va.projection.xi[edge.acrossA] - 1.0;
  const double etaB = edge.sideB * vb.projection.xi[edge.acrossB] - 1.0;
  const double z = 0.5 * (edge.lengthA * etaA - edge.lengthB * etaB);
  const double ca = 0.5 * edge.lengthA * edge.sideA, cb = -0.5 * edge.lengthB * edge.sideB;
  Column dz(n, 0.0);
  Square d2z(static_cast<std::size_t>(n) * n, 0.0);
  embed(0, va.xiFirst[edge.acrossA], ca, dz);
  embed(1, vb.xiFirst[edge.acrossB], cb, dz);
  embedMatrix(0, va.xiSecond[edge.acrossA], ca, d2z);
  embedMatrix(1, vb.xiSecond[edge.acrossB], cb, d2z);

  // w = S(t), t = z/(2b) + ½.
  const Step s = smootherstep(z / (2.0 * edge.band) + 0.5);
  const double w = s.value, wz = s.first / (2.0 * edge.band), wzz = s.second / (4.0 * edge.band * edge.band);
  out.weight = w;

  // g = g_a − w q, q = g_a − g_b; Q = ∂q/∂u.
  const double q = va.projection.gap - vb.projection.gap;
  out.gap = va.projection.gap - w * q;
  Column Q(n, 0.0), dg(n, 0.0);
  embed(0, va.gapFirst, 1.0, Q);
  embed(1, vb.gapFirst, -1.0, Q);
  embed(0, va.gapFirst, 1.0, dg);
  for (int i = 0; i < n; ++i) dg[i] -= w * Q[i] + q * wz * dz[i];
  // ∂²g = (1 − w) H_a + w H_b − w_z (Q ∂zᵀ + ∂z Qᵀ) − q (w_zz ∂z ∂zᵀ + w_z ∂²z)
  Square d2g(static_cast<std::size_t>(n) * n, 0.0);
  embedMatrix(0, va.gapSecond, 1.0 - w, d2g);
  embedMatrix(1, vb.gapSecond, w, d2g);
  outer(d2g, -wz, Q, dz);
  outer(d2g, -wz, dz, Q);
  outer(d2g, -q * wzz, dz, dz);
  for (std::size_t i = 0; i < d2g.size(); ++i) d2g[i] -= q * wz * d2z[i];

  out.normalTraction = law.traction(out.gap);
  const double epsN = law.tractionDerivative(out.gap);
  out.residual.assign(n, 0.0);
  out.tangent.assign(static_cast<std::size_t>(n) * n, 0.0);
  if (!law.isActive(out.gap)) return out;
  for (int i = 0; i < n; ++i) out.residual[i] = out.normalTraction * dg[i];
  outer(out.tangent, epsN, dg, dg);
  for (std::size_t i = 0; i < d2g.size(); ++i) out.tangent[i] += out.normalTraction * d2g[i];
  return out;
}

template std::optional<ValleyEdge> findValleyEdge<Line2Facet>(const Line2Facet::Point&, std::size_t,
                                                              const std::vector<MasterFacetNodes<Line2Facet>>&,
                                                              const std::vector<MasterFacetNodes<Line2Facet>>&, double,
                                                              const ValleyBlendOptions&);
template std::optional<ValleyEdge> findValleyEdge<Quad4Facet>(const Quad4Facet::Point&, std::size_t,
                                                              const std::vector<MasterFacetNodes<Quad4Facet>>&,
                                                              const std::vector<MasterFacetNodes<Quad4Facet>>&, double,
                                                              const ValleyBlendOptions&);
template ValleyBlendResult<Line2Facet> evaluateValleyBlend<Line2Facet>(const PenaltyNormalLaw&, const Line2Facet::Point&,
                                                                       const MasterFacetNodes<Line2Facet>&,
                                                                       const MasterFacetNodes<Line2Facet>&,
                                                                       const ValleyEdge&);
template ValleyBlendResult<Quad4Facet> evaluateValleyBlend<Quad4Facet>(const PenaltyNormalLaw&, const Quad4Facet::Point&,
                                                                       const MasterFacetNodes<Quad4Facet>&,
                                                                       const MasterFacetNodes<Quad4Facet>&,
                                                                       const ValleyEdge&);

}  // namespace contessa::contact
