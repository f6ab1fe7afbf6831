#include "contact/NodeToFacetContact.hpp"
#include "contact/NodeToFacetTerms.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

namespace contessa::contact {

namespace {

using namespace terms;  // the element's named terms (NodeToFacetTerms.hpp)

/// The slip increment of the return mapping (eq. 20) and how it varies with ξ̄ and g_N: against the
/// committed ξ_n for a node in contact at the commit; for a node open at the commit, against the point
/// where it touched, ξ_0 + τ(ξ̄ − ξ_0), τ = g_N,0/(g_N,0 − g_N) (CommittedApproach).
template <int M>
Vector<M> slipIncrement(const Vector<M>& xi, double gap, const ContactHistory<M>& committed,
                        const CommittedApproach<M>& approach, TangentialLaw<M>& law) {
  if (committed.isInContact()) return subtract(xi, committed.xi);
  const Vector<M> path = subtract(xi, approach.xi);
  if (!(approach.gap > 0.0)) return path;  // touching at the commit: τ = 0
  const double closing = approach.gap - gap;  // > 0: g_N < 0 ≤ g_N,0
  const double tau = approach.gap / closing;
  law.slipScale = 1.0 - tau;
  law.slipPerGap = scaled(-approach.gap / (closing * closing), path);  // −(ξ̄ − ξ_0) ∂τ/∂g_N
  return scaled(1.0 - tau, path);
}

/// The Coulomb law at the projection ξ̄: the return mapping of eq. (20)–(23) against the committed history;
/// sets the status, tractions and trial history of `out`.
template <class Facet, class Result>
TangentialLaw<Facet::kSurfaceDim> applyTangentialLaw(const ContactLawParameters& parameters,
                                                     const CoulombReturnMapping<Facet::kSurfaceDim>& returnMapping,
                                                     const ProjectionResult<Facet>& p,
                                                     const ContactHistory<Facet::kSurfaceDim>& committed,
                                                     const CommittedApproach<Facet::kSurfaceDim>& approach, double tN,
                                                     double facetLength, SlipTangent slipTangent, Result& out) {
  constexpr int M = Facet::kSurfaceDim;
  TangentialLaw<M> law;
  if (parameters.isFrictionless()) {
    out.status = ContactStatus::Slip;  // free sliding, t_T ≡ 0
  } else if (!committed.isInContact() && !approach.known) {
    // First contact, approach unknown: ξ_n := ξ̄, t_T,n := 0, so Δξ ≡ 0 and t_T ≡ 0 in this increment.
    out.status = ContactStatus::Stick;
  } else {
    ReturnMappingInput<M> in;
    // The augmented Lagrangian's trial starts from the multiplier λ_Tα instead of t_Tα,n (eq. 15.2).
    in.committedTraction = parameters.isAugmented()     ? committed.tangentialMultiplier
                           : committed.isInContact() ? committed.tangentialTraction
                                                     : Vector<M>{};
    in.slipIncrement = slipIncrement(p.xi, out.gap, committed, approach, law);  // Δξ_{n+1}, eq. (20)
    in.metric = p.metric;
    in.normalTraction = tN;
    in.facetLength = facetLength;
    // The augmented Lagrangian's slip-tolerance ε_T follows λ_N, constant between updates (eq. 15.2).
    if (parameters.isAugmented()) in.frozenNormalTraction = committed.normalMultiplier;
    out.friction = returnMapping.map(in);  // eq. (20)–(23)
    out.status = out.friction.status;
    law.traction = out.friction.traction;
    law.dT_dXi = out.friction.dTraction_dSlipIncrement;
    if (out.status == ContactStatus::Slip && slipTangent.secant) {
      // A node in a slip cycle: the secant stiffness along its slip direction (see SlipTangent).
      Vector<M> s = out.friction.trialDirection;
      s = scaled(1.0 / norm(s), s);
      const double stick = out.friction.tangentialPenalty * dot(s, multiply(p.metric, s));
      const double along = dot(s, multiply(law.dT_dXi, s));
      addOuter(law.dT_dXi, std::min(slipTangent.stiffness, stick) - along, s, s);
    }
    law.dT_dMetric = out.friction.dTraction_dMetric;
    law.dT_dNormal = out.friction.dTraction_dNormalTraction;
    // eq. (7), backward Euler: g_T,n+1 = g_T,n + √(Δξ^α ā_αβ Δξ^β); committed only at commit().
    out.trial.accumulatedSlip =
        committed.accumulatedSlip + std::sqrt(dot(in.slipIncrement, multiply(p.metric, in.slipIncrement)));
  }
  out.tangentialTraction = law.traction;
  out.trial.tangentialTraction = law.traction;
  if (parameters.isAugmented()) out.trial.tangentialMultiplier = law.traction;  // the next λ_T (eq. 15.3)
  out.trial.status = out.status;
  return law;
}


/// The weight of the fade past a free edge, w = 1 − 3s² + 2s³ with s = d/reach (ContactPoint), and its
/// derivative ∂w/∂u (NodeToFacetContact.hpp; docs/theory-contact.md §3.2); nullopt on the facet (ξ̄ inside
/// its parent domain) or without a reach.
template <class Facet>
struct FreeEdgeFade {
  double weight = 1.0;
  typename Operators<Facet>::Column derivative{};  // ∂w/∂u
};

template <class Facet>
std::optional<FreeEdgeFade<Facet>> freeEdgeFade(const NodeToFacetGeometry<Facet>& x,
                                                const ProjectionResult<Facet>& p, double reach) {
  using Op = Operators<Facet>;
  constexpr int M = Facet::kSurfaceDim;
  if (!(reach > 0.0)) return std::nullopt;
  const auto toDomain = Facet::clampToDomain(p.xi);  // the closest point of the parent domain, ∂ξ_c/∂ξ̄
  const typename Facet::SurfaceCoords& clamped = toDomain.xi;
  if (clamped == p.xi) return std::nullopt;
  const auto c = Projection<Facet>::evaluateAt(x.slave, x.master, clamped);
  const typename Facet::Point v = subtract(p.position, c.position);
  const double d = norm(v);
  if (!(d > 0.0)) return std::nullopt;
  FreeEdgeFade<Facet> fade;
  const double s = d / reach;
  if (s >= 1.0) {
    fade.weight = 0.0;
    return fade;
  }
  fade.weight = 1.0 - s * s * (3.0 - 2.0 * s);
  const double dwdd = 6.0 * s * (s - 1.0) / reach;
  FacetKinematics<Facet> k;
  if (!k.build(p, x.master)) return fade;  // not reached: the element built it already
  const typename Facet::Point unit = scaled(1.0 / d, v);
  typename Op::Weights shapeDifference{};
  for (int i = 0; i < Facet::kNodes; ++i) shapeDifference[1 + i] = p.shape[i] - c.shape[i];
  typename Op::Column dd = Op::kron(shapeDifference, unit);
  for (int al = 0; al < M; ++al) {
    double along = dot(unit, p.covariantBasis[al]);
    for (int be = 0; be < M; ++be)
      if (toDomain.derivative(be, al) != 0.0) along -= toDomain.derivative(be, al) * dot(unit, c.covariantBasis[be]);
    addScaled(dd, along, k.Xi[al]);
  }
  fade.derivative = scaled(dwdd, dd);
  return fade;
}

}  // namespace

template <class Facet>
NodeToFacetContact<Facet>::NodeToFacetContact(const ContactLawParameters& parameters, TangentTerms terms)
    : parameters_(parameters),
      terms_(terms),
      normalLaw_(parameters.normalPenalty),
      returnMapping_(parameters.tangentialPenalty, parameters.frictionCoefficient, parameters.slipTolerance) {
  parameters_.validate();
}

template <class Facet>
typename NodeToFacetContact<Facet>::Result NodeToFacetContact<Facet>::evaluate(
    const Geometry& x, int facet, const ContactHistory<kSurfaceDim>& committed, double facetLength,
    SlipTangent slipTangent, const ContactPoint& point, const CommittedApproach<kSurfaceDim>& approach) const {
  Result out = evaluateUnfaded(x, facet, committed, facetLength, slipTangent, point, approach);
  if (out.status == ContactStatus::Open || point.kind != ContactPoint::Kind::Projection) return out;
  const auto fade = freeEdgeFade<Facet>(x, out.projection, point.freeEdgeReach);
  if (!fade) return out;
  const double w = fade->weight;
  out.freeEdgeWeight = w;
  out.pastFreeEdge = true;
  if (w == 0.0) {  // past the reach: open
    Result open;
    open.projection = out.projection;
    open.point = out.point;
    open.gap = out.gap;
    open.freeEdgeWeight = 0.0;
    open.pastFreeEdge = true;
    open.trial = out.trial;
    open.trial.tangentialTraction = {};
    open.trial.status = ContactStatus::Open;
    open.trial.normalMultiplier = 0.0;
    open.trial.tangentialMultiplier = {};
    open.trial.accumulatedSlip = committed.accumulatedSlip;
    return open;
  }
  // K = w K_c + r_c (∂w/∂u)ᵀ, r = w r_c
  for (int i = 0; i < kDofs; ++i)
    for (int j = 0; j < kDofs; ++j) out.tangent(i, j) = w * out.tangent(i, j) + out.residual[i] * fade->derivative[j];
  out.residual = scaled(w, out.residual);
  out.normalTraction *= w;
  out.tangentialTraction = scaled(w, out.tangentialTraction);
  return out;
}

template <class Facet>
typename NodeToFacetContact<Facet>::Result NodeToFacetContact<Facet>::evaluateUnfaded(
    const Geometry& x, int facet, const ContactHistory<kSurfaceDim>& committed, double facetLength,
    SlipTangent slipTangent, const ContactPoint& point, const CommittedApproach<kSurfaceDim>& approach) const {
  constexpr int M = kSurfaceDim;
  using Op = Operators<Facet>;
  using Column = typename Op::Column;

  if (committed.isInContact() && committed.segment != facet)
    throw std::logic_error("NodeToFacetContact: committed history is on facet " + std::to_string(committed.segment) +
                           ", not on facet " + std::to_string(facet) + "; map it with transferHistory first");

  Result out;
  out.point = point;
  // eq. (1)–(5): closest point, ā_α, ā_αβ, n̄, g_N (robust start and fallback on a curved facet).
  out.projection = Projection<Facet>().project(x.slave, x.master);
  const auto& p = out.projection;
  out.trial = committed;
  out.trial.segment = facet;
  out.trial.xi = p.xi;
  out.trial.tangentialTraction = {};
  out.trial.status = ContactStatus::Open;
  out.trial.normalMultiplier = 0.0;  // an open node's next multipliers (augmented Lagrangian)
  out.trial.tangentialMultiplier = {};
  out.gap = p.gap;
  if (!p.converged) return out;
  // The normal part: at the projection, or at a vertex or edge point of the facet (ContactPoint).
  std::optional<BoundaryPointKinematics<Facet>> boundary;
  if (point.kind != ContactPoint::Kind::Projection) {
    boundary.emplace(point, x.slave, x.master, p.normal);
    out.gap = boundary->gap;
  }
  const double lambdaN = parameters_.isAugmented() ? committed.normalMultiplier : 0.0;  // eq. (15.1)
  const bool active = normalLaw_.isActive(out.gap, lambdaN);
  // eq. (6): open, no force, no stiffness — but a node in an open/closed cycle gets the normal law's secant
  // k N Nᵀ in its tangent (SlipTangent::normalStiffness, NormalToggleDamping); its residual stays 0.
  if (!active && !(slipTangent.normalStiffness > 0.0)) return out;

  FacetKinematics<Facet> facetKinematics;
  if (!facetKinematics.build(p, x.master)) return out;  // the node sits at a focal point of the facet
  const auto& k = facetKinematics;
  const Column& N = boundary ? boundary->N : k.N;  // ∂g_N/∂u of the contact law's gap
  if (!active) {
    addOuter(out.tangent, slipTangent.normalStiffness, N, N);
    return out;
  }

  // ---- Contact law: eq. (16), then the return mapping of eq. (20)–(23) ------------------------------
  const double tN = normalLaw_.traction(out.gap, lambdaN);  // eq. (16) or (15.1), < 0
  const double epsN = normalLaw_.tractionDerivative(out.gap, lambdaN);
  out.normalTraction = tN;
  if (parameters_.isAugmented()) out.trial.normalMultiplier = tN;  // the next λ_N (eq. 15.3)
  const auto tangential =
      applyTangentialLaw<Facet>(parameters_, returnMapping_, p, committed, approach, tN, facetLength, slipTangent, out);

  // ---- Residual: r_c = t_N N + t_Tα Ξ^α --------------------------------------------------------------
  const Vector<M>& tT = tangential.traction;
  out.residual = scaled(tN, N);
  for (int al = 0; al < M; ++al) addScaled(out.residual, tT[al], k.Xi[al]);

  auto& K = out.tangent;
  addOuter(K, epsN, N, N);  // eq. (24): K_N = ε_N N Nᵀ

  if (terms_ == TangentTerms::PaperMainTerms) {
    // ∂ξ̄/∂u ≈ D^α, fixed metric: stick ∂t_α/∂Δξ^β = ε_T ā_αβ gives eq. (25) ε_T ā_αβ D^α D^βᵀ; slip gives
    // eq. (26): ∂t_α/∂t_N ε_N = −μ ε_N n^trial_α (t_N < 0; the paper counts the penetration positive) and
    // the eq. (27) term. With a slip tolerance the ∂t/∂t_N term also acts in stick (ε_T depends on t_N).
    for (int al = 0; al < M; ++al) {
      Column dt = scaled(tangential.dT_dNormal[al] * epsN, N);
      for (int be = 0; be < M; ++be) {
        addScaled(dt, tangential.dT_dXi(al, be) * tangential.slipScale, k.D[be]);
        addScaled(dt, tangential.dT_dXi(al, be) * tangential.slipPerGap[be], N);
      }
      addOuter(K, 1.0, k.D[al], dt);
    }
    return out;
  }

  // ---- Consistent tangent: K_c = ε_N N Nᵀ + t_N ∂²g_N/∂u² + Ξ^α (dt_Tα/du)ᵀ + t_Tα ∂²ξ̄^α/∂u² -------
  if (boundary)
    boundary->addGapCurvature(K, tN);  // (a) at the vertex or edge point
  else
    k.addGapCurvature(K, tN);          // (a) at the projection
  addTractionVariation<Facet>(K, k, tangential, N, epsN);  // (b)
  addProjectionCurvature<Facet>(K, k, tT);                 // (c)
  return out;
}

template <class Facet>
FacetGapVariation<Facet> facetGapVariation(const NodeToFacetGeometry<Facet>& x) {
  constexpr int M = Facet::kSurfaceDim;
  FacetGapVariation<Facet> out;
  out.projection = Projection<Facet>().project(x.slave, x.master);
  if (!out.projection.converged) return out;
  FacetKinematics<Facet> k;
  if (!k.build(out.projection, x.master)) return out;
  out.valid = true;
  out.gapFirst = k.N;
  k.addGapCurvature(out.gapSecond, 1.0);  // term (a) per unit t_N
  for (int al = 0; al < M; ++al) {
    out.xiFirst[al] = k.Xi[al];
    Vector<M> unit{};
    unit[al] = 1.0;
    addProjectionCurvature<Facet>(out.xiSecond[al], k, unit);  // term (c) with t_T = e_α
  }
  out.metricFirst = metricVariation<Facet>(k);
  return out;
}

#define CONTESSA_INSTANTIATE_NODE_TO_FACET_CONTACT(F) template class NodeToFacetContact<F>;
CONTESSA_FOR_EACH_FACET(CONTESSA_INSTANTIATE_NODE_TO_FACET_CONTACT)
#undef CONTESSA_INSTANTIATE_NODE_TO_FACET_CONTACT

template FacetGapVariation<Line2Facet> facetGapVariation<Line2Facet>(const NodeToFacetGeometry<Line2Facet>&);
template FacetGapVariation<Quad4Facet> facetGapVariation<Quad4Facet>(const NodeToFacetGeometry<Quad4Facet>&);
template FacetGapVariation<Line3Facet> facetGapVariation<Line3Facet>(const NodeToFacetGeometry<Line3Facet>&);
template FacetGapVariation<Tri3Facet> facetGapVariation<Tri3Facet>(const NodeToFacetGeometry<Tri3Facet>&);
template FacetGapVariation<Tri6Facet> facetGapVariation<Tri6Facet>(const NodeToFacetGeometry<Tri6Facet>&);
template FacetGapVariation<Quad8Facet> facetGapVariation<Quad8Facet>(const NodeToFacetGeometry<Quad8Facet>&);
template FacetGapVariation<Quad9Facet> facetGapVariation<Quad9Facet>(const NodeToFacetGeometry<Quad9Facet>&);

}  // namespace contessa::contact
