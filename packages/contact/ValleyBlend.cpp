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

namespace {

/// The union of the two facets' nodes, the blended element's dofs: the slave, a's nodes, b's nodes not in
/// a. blockOf[f][i]: the block of local node i of facet f (block 0 is the slave node in both facets'
/// element dofs). Columns and squares over the union are std::vector (row-major squares).
template <class Facet>
struct UnionDofs {
  static constexpr int kDim = Facet::kSpaceDim;
  static constexpr int kNodes = Facet::kNodes;
  static constexpr int kFacetDofs = kDim * (1 + kNodes);
  using Column = std::vector<double>;
  using Square = std::vector<double>;
  std::array<std::array<int, 1 + kNodes>, 2> blockOf{};
  int n = 0;

  UnionDofs(const MasterFacetNodes<Facet>& a, const MasterFacetNodes<Facet>& b, ValleyBlendResult<Facet>& out) {
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
    n = blocks * kDim;
  }
  int dof(int f, int elementDof) const { return blockOf[f][elementDof / kDim] * kDim + elementDof % kDim; }
  Column column() const { return Column(n, 0.0); }
  Square square() const { return Square(static_cast<std::size_t>(n) * n, 0.0); }
  /// into += s v, v over facet f's element dofs
  void embed(int f, const Vector<kFacetDofs>& v, double s, Column& into) const {
    for (int i = 0; i < kFacetDofs; ++i) into[dof(f, i)] += s * v[i];
  }
  void embedMatrix(int f, const Matrix<kFacetDofs, kFacetDofs>& m, double s, Square& into) const {
    for (int i = 0; i < kFacetDofs; ++i)
      for (int j = 0; j < kFacetDofs; ++j) into[dof(f, i) * n + dof(f, j)] += s * m(i, j);
  }
  /// into += s x yᵀ
  void outer(Square& into, double s, const Column& x, const Column& y) const {
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) into[i * n + j] += s * x[i] * y[j];
  }
};

/// What the friction part needs of the normal blend: w and its derivatives (∂w = w_z ∂z, ∂²w = w_zz ∂z ∂zᵀ +
/// w_z ∂²z), ∂g and ε_N.
struct BlendWeight {
  double w = 0.0, wz = 0.0, wzz = 0.0, epsN = 0.0;
  const std::vector<double>* dz = nullptr;
  const std::vector<double>* d2z = nullptr;
  const std::vector<double>* dg = nullptr;
};

/// The slip increment Δξ̃ of the return mapping and how it varies (∂Δξ̃ = slipScale ∂ξ̃ + slipPerGap ∂g), as
/// NodeToFacetContact's for one facet: against ξ_n in contact at the commit; for a first contact against
/// the point it touched, ξ̃_0 + τ(ξ̃ − ξ̃_0), τ = g_0/(g_0 − g) (§5.2).
template <int M>
struct SlipIncrement {
  Vector<M> value{};
  double slipScale = 1.0;
  Vector<M> slipPerGap{};
};

template <int M>
SlipIncrement<M> slipIncrementOf(const Vector<M>& xi, double gap, const ContactHistory<M>& committed,
                                 const CommittedApproach<M>& approach) {
  SlipIncrement<M> s;
  if (committed.isInContact()) {
    s.value = subtract(xi, committed.xi);
    return s;
  }
  const Vector<M> path = subtract(xi, approach.xi);
  s.value = path;
  if (!(approach.gap > 0.0)) return s;
  const double closing = approach.gap - gap;
  const double tau = approach.gap / closing;
  s.slipScale = 1.0 - tau;
  s.slipPerGap = scaled(-approach.gap / (closing * closing), path);
  s.value = scaled(1.0 - tau, path);
  return s;
}

/// Coulomb friction in the blend (ValleyFriction): ξ̃, Ā and their derivatives over the union, one return
/// mapping, r_T = t_α ∂ξ̃^α, K_T = ∂ξ̃^α ⊗ ∂t_α + t_α ∂²ξ̃^α.
template <class Facet>
void addFriction(const ValleyFriction<Facet>& friction, const MasterFacetNodes<Facet>& a, const MasterFacetNodes<Facet>& b,
                 const ValleyEdge& edge, const UnionDofs<Facet>& dofs, const FacetGapVariation<Facet>& va,
                 const FacetGapVariation<Facet>& vb, const BlendWeight& bw, ValleyBlendResult<Facet>& out) {
  constexpr int M = Facet::kSurfaceDim;
  using Column = std::vector<double>;
  const int n = dofs.n;
  const ValleyChart<Facet> chart = valleyChart<Facet>(a, b, edge);
  const Matrix<M, M> Jinv = inverse(chart.J);
  const double w = bw.w;
  Column dw = *bw.dz;
  for (double& v : dw) v *= bw.wz;
  // ξ̃ = ξ̄_a + w D, D = U(ξ̄_b) − ξ̄_a; ∂ξ̃^α = Ξ_a^α + w G^α + D^α ∂w, G^α = J^α_β Ξ_b^β − Ξ_a^α.
  const Vector<M> D = subtract(chart.map(vb.projection.xi), va.projection.xi);
  const Vector<M> xi = add(va.projection.xi, scaled(w, D));
  std::array<Column, M> G, dxi;
  for (int al = 0; al < M; ++al) {
    G[al] = dofs.column();
    dofs.embed(0, va.xiFirst[al], -1.0, G[al]);
    for (int be = 0; be < M; ++be) dofs.embed(1, vb.xiFirst[be], chart.J(al, be), G[al]);
    dxi[al] = dofs.column();
    dofs.embed(0, va.xiFirst[al], 1.0, dxi[al]);
    for (int i = 0; i < n; ++i) dxi[al][i] += w * G[al][i] + D[al] * dw[i];
  }
  // Ā = (1 − w) ā_a + w B, B = J⁻ᵀ ā_b J⁻¹; ∂Ā = (1 − w) ∂ā_a + w J⁻ᵀ ∂ā_b J⁻¹ + (B − ā_a) ∂w.
  const Matrix<M, M> B = multiply(transpose(Jinv), multiply(vb.projection.metric, Jinv));
  Matrix<M, M> metric{};
  std::array<std::array<Column, M>, M> dMetric;
  for (int be = 0; be < M; ++be)
    for (int ga = 0; ga < M; ++ga) {
      metric(be, ga) = (1.0 - w) * va.projection.metric(be, ga) + w * B(be, ga);
      auto& d = dMetric[be][ga];
      d = dofs.column();
      dofs.embed(0, va.metricFirst[be][ga], 1.0 - w, d);
      for (int de = 0; de < M; ++de)
        for (int ep = 0; ep < M; ++ep) dofs.embed(1, vb.metricFirst[de][ep], w * Jinv(de, be) * Jinv(ep, ga), d);
      for (int i = 0; i < n; ++i) d[i] += (B(be, ga) - va.projection.metric(be, ga)) * dw[i];
    }
  out.frictional = true;
  out.chartXi = xi;
  out.chartMetric = metric;
  out.trial = friction.committed;
  out.trial.segment = a.id;
  out.trial.xi = xi;
  out.trial.normalMultiplier = 0.0;
  out.trial.tangentialMultiplier = {};
  if (!friction.committed.isInContact() && !friction.approach.known) {  // first contact, approach unknown
    out.status = out.trial.status = ContactStatus::Stick;  // ξ_n := ξ̃, t_T ≡ 0 in this increment
    out.trial.tangentialTraction = {};
    return;
  }
  // One return mapping, eq. (20)–(23), in a's chart.
  const ContactLawParameters& law = *friction.law;
  const SlipIncrement<M> slip = slipIncrementOf(xi, out.gap, friction.committed, friction.approach);
  ReturnMappingInput<M> in;
  in.committedTraction = friction.committed.isInContact() ? friction.committed.tangentialTraction : Vector<M>{};
  in.slipIncrement = slip.value;
  in.metric = metric;
  in.normalTraction = out.normalTraction;
  in.facetLength = friction.facetLength;
  out.friction = CoulombReturnMapping<M>(law.tangentialPenalty, law.frictionCoefficient, law.slipTolerance).map(in);
  const auto& rm = out.friction;
  out.status = out.trial.status = rm.status;
  out.traction = out.trial.tangentialTraction = rm.traction;
  // eq. (7), backward Euler, in the chart's metric
  out.trial.accumulatedSlip =
      friction.committed.accumulatedSlip + std::sqrt(dot(slip.value, multiply(metric, slip.value)));
  for (int al = 0; al < M; ++al) {
    // ∂t_α = ∂t_α/∂Δξ̃^β (slipScale ∂ξ̃^β + slipPerGap^β ∂g) + ∂t_α/∂Ā_βγ ∂Ā_βγ + ∂t_α/∂t_N ε_N ∂g
    Column dt = dofs.column();
    double perGap = rm.dTraction_dNormalTraction[al] * bw.epsN;
    for (int be = 0; be < M; ++be) {
      perGap += rm.dTraction_dSlipIncrement(al, be) * slip.slipPerGap[be];
      for (int i = 0; i < n; ++i) dt[i] += rm.dTraction_dSlipIncrement(al, be) * slip.slipScale * dxi[be][i];
      for (int ga = 0; ga < M; ++ga)
        for (int i = 0; i < n; ++i) dt[i] += rm.dTraction_dMetric[al](be, ga) * dMetric[be][ga][i];
    }
    for (int i = 0; i < n; ++i) dt[i] += perGap * (*bw.dg)[i];
    for (int i = 0; i < n; ++i) out.residual[i] += rm.traction[al] * dxi[al][i];
    dofs.outer(out.tangent, 1.0, dxi[al], dt);
    // t_α ∂²ξ̃^α = t_α [(1 − w) ∂²ξ̄_a^α + w J^α_β ∂²ξ̄_b^β + G^α ∂wᵀ + ∂w G^αᵀ + D^α ∂²w]
    const double t = rm.traction[al];
    if (t == 0.0) continue;
    dofs.embedMatrix(0, va.xiSecond[al], t * (1.0 - w), out.tangent);
    for (int be = 0; be < M; ++be) dofs.embedMatrix(1, vb.xiSecond[be], t * w * chart.J(al, be), out.tangent);
    dofs.outer(out.tangent, t, G[al], dw);
    dofs.outer(out.tangent, t, dw, G[al]);
    dofs.outer(out.tangent, t * D[al] * bw.wzz, *bw.dz, *bw.dz);
    for (std::size_t i = 0; i < out.tangent.size(); ++i) out.tangent[i] += t * D[al] * bw.wz * (*bw.d2z)[i];
  }
}

}  // namespace

template <class Facet>
ValleyBlendResult<Facet> evaluateValleyBlend(const PenaltyNormalLaw& law, const typename Facet::Point& slave,
                                             const MasterFacetNodes<Facet>& a, const MasterFacetNodes<Facet>& b,
                                             const ValleyEdge& edge, const ValleyFriction<Facet>& friction) {
  using Variation = FacetGapVariation<Facet>;
  ValleyBlendResult<Facet> out;
  const Variation va = facetGapVariation<Facet>({slave, a.x});
  const Variation vb = facetGapVariation<Facet>({slave, b.x});
  if (!va.valid || !vb.valid) return out;
  const UnionDofs<Facet> dofs(a, b, out);
  const int n = dofs.n;

  // z = ½(ℓ_a η_a − ℓ_b η_b), η_f = s_f ξ̄_f^α − 1, and its derivatives.
  const double etaA = edge.sideA * va.projection.xi[edge.acrossA] - 1.0;
  const double etaB = edge.sideB * vb.projection.xi[edge.acrossB] - 1.0;
  const double z = 0.5 * (edge.lengthA * etaA - edge.lengthB * etaB);
  const double ca = 0.5 * edge.lengthA * edge.sideA, cb = -0.5 * edge.lengthB * edge.sideB;
  auto dz = dofs.column();
  auto d2z = dofs.square();
  dofs.embed(0, va.xiFirst[edge.acrossA], ca, dz);
  dofs.embed(1, vb.xiFirst[edge.acrossB], cb, dz);
  dofs.embedMatrix(0, va.xiSecond[edge.acrossA], ca, d2z);
  dofs.embedMatrix(1, vb.xiSecond[edge.acrossB], cb, d2z);

  // w = S(t), t = z/(2b) + ½.
  const Step s = smootherstep(z / (2.0 * edge.band) + 0.5);
  const double w = s.value, wz = s.first / (2.0 * edge.band), wzz = s.second / (4.0 * edge.band * edge.band);
  out.weight = w;

  // g = g_a − w q, q = g_a − g_b; Q = ∂q/∂u.
  const double q = va.projection.gap - vb.projection.gap;
  out.gap = va.projection.gap - w * q;
  auto Q = dofs.column(), dg = dofs.column();
  dofs.embed(0, va.gapFirst, 1.0, Q);
  dofs.embed(1, vb.gapFirst, -1.0, Q);
  dofs.embed(0, va.gapFirst, 1.0, dg);
  for (int i = 0; i < n; ++i) dg[i] -= w * Q[i] + q * wz * dz[i];
  // ∂²g = (1 − w) H_a + w H_b − w_z (Q ∂zᵀ + ∂z Qᵀ) − q (w_zz ∂z ∂zᵀ + w_z ∂²z)
  auto d2g = dofs.square();
  dofs.embedMatrix(0, va.gapSecond, 1.0 - w, d2g);
  dofs.embedMatrix(1, vb.gapSecond, w, d2g);
  dofs.outer(d2g, -wz, Q, dz);
  dofs.outer(d2g, -wz, dz, Q);
  dofs.outer(d2g, -q * wzz, dz, dz);
  for (std::size_t i = 0; i < d2g.size(); ++i) d2g[i] -= q * wz * d2z[i];

  out.normalTraction = law.traction(out.gap);
  const double epsN = law.tractionDerivative(out.gap);
  out.residual.assign(n, 0.0);
  out.tangent.assign(static_cast<std::size_t>(n) * n, 0.0);
  if (!law.isActive(out.gap)) return out;
  out.status = ContactStatus::Slip;  // frictionless: free sliding
  for (int i = 0; i < n; ++i) out.residual[i] = out.normalTraction * dg[i];
  dofs.outer(out.tangent, epsN, dg, dg);
  for (std::size_t i = 0; i < d2g.size(); ++i) out.tangent[i] += out.normalTraction * d2g[i];
  if (friction.law == nullptr) return out;
  BlendWeight bw;
  bw.w = w;
  bw.wz = wz;
  bw.wzz = wzz;
  bw.epsN = epsN;
  bw.dz = &dz;
  bw.d2z = &d2z;
  bw.dg = &dg;
  addFriction(friction, a, b, edge, dofs, va, vb, bw, out);
  return out;
}

template <class Facet>
ValleyChart<Facet> valleyChart(const MasterFacetNodes<Facet>& a, const MasterFacetNodes<Facet>& b, const ValleyEdge& edge) {
  ValleyChart<Facet> u;
  // Across: η_a = −(ℓ_b/ℓ_a) η_b, η_f = s_f ξ^α_f − 1.
  const double ratio = edge.lengthB / edge.lengthA;
  u.J(edge.acrossA, edge.acrossB) = -edge.sideA * edge.sideB * ratio;
  u.c[edge.acrossA] = edge.sideA * (1.0 + ratio);
  if constexpr (Facet::kSurfaceDim == 2) {
    // Along: the edge's two nodes keep their places (their coordinates ±1 on each facet).
    const int alongA = 1 - edge.acrossA, alongB = 1 - edge.acrossB;
    std::array<double, 2> onA{}, onB{};
    int found = 0;
    for (int i = 0; i < Facet::kNodes && found < 2; ++i) {
      if (Facet::nodeCoords(i)[edge.acrossA] != edge.sideA) continue;
      for (int j = 0; j < Facet::kNodes; ++j)
        if (b.nodes[j] == a.nodes[i]) {
          onA[found] = Facet::nodeCoords(i)[alongA];
          onB[found] = Facet::nodeCoords(j)[alongB];
          ++found;
        }
    }
    const double scale = found == 2 ? (onA[0] - onA[1]) / (onB[0] - onB[1]) : 1.0;
    u.J(alongA, alongB) = scale;
    u.c[alongA] = onA[0] - scale * onB[0];
  }
  return u;
}

template <class Facet>
std::optional<typename Facet::SurfaceCoords> valleyChartPoint(const typename Facet::Point& slave,
                                                             const MasterFacetNodes<Facet>& a,
                                                             const MasterFacetNodes<Facet>& b, const ValleyEdge& edge) {
  const Projection<Facet> projection;
  const auto pa = projection.project(slave, a.x), pb = projection.project(slave, b.x);
  if (!pa.converged || !pb.converged) return std::nullopt;
  const double etaA = edge.sideA * pa.xi[edge.acrossA] - 1.0, etaB = edge.sideB * pb.xi[edge.acrossB] - 1.0;
  const double z = 0.5 * (edge.lengthA * etaA - edge.lengthB * etaB);
  const double w = smootherstep(z / (2.0 * edge.band) + 0.5).value;
  return add(scaled(1.0 - w, pa.xi), scaled(w, valleyChart<Facet>(a, b, edge).map(pb.xi)));
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
                                                                       const ValleyEdge&,
                                                                       const ValleyFriction<Line2Facet>&);
template ValleyBlendResult<Quad4Facet> evaluateValleyBlend<Quad4Facet>(const PenaltyNormalLaw&, const Quad4Facet::Point&,
                                                                       const MasterFacetNodes<Quad4Facet>&,
                                                                       const MasterFacetNodes<Quad4Facet>&,
                                                                       const ValleyEdge&,
                                                                       const ValleyFriction<Quad4Facet>&);

template ValleyChart<Line2Facet> valleyChart<Line2Facet>(const MasterFacetNodes<Line2Facet>&,
                                                         const MasterFacetNodes<Line2Facet>&, const ValleyEdge&);
template ValleyChart<Quad4Facet> valleyChart<Quad4Facet>(const MasterFacetNodes<Quad4Facet>&,
                                                         const MasterFacetNodes<Quad4Facet>&, const ValleyEdge&);
template std::optional<Line2Facet::SurfaceCoords> valleyChartPoint<Line2Facet>(const Line2Facet::Point&,
                                                                               const MasterFacetNodes<Line2Facet>&,
                                                                               const MasterFacetNodes<Line2Facet>&,
                                                                               const ValleyEdge&);
template std::optional<Quad4Facet::SurfaceCoords> valleyChartPoint<Quad4Facet>(const Quad4Facet::Point&,
                                                                               const MasterFacetNodes<Quad4Facet>&,
                                                                               const MasterFacetNodes<Quad4Facet>&,
                                                                               const ValleyEdge&);

}  // namespace contessa::contact
