#pragma once
// The node-to-facet penalty contact element with Coulomb friction, for any master facet of
// MasterFacet.hpp: one slave node k and the kNodes nodes of its master facet, kDofs = kSpaceDim·(1 + kNodes)
// dofs ordered [x^k, x_1, …, x_kNodes] (2D node-to-segment: 6 dofs; 3D node-to-face on a 4-node face: 15).
// It returns the contact residual and its consistent tangent for the current positions x = X + u and
// the committed history, in the paper's surface notation (eq. 1–9, 14–27).
#include "contact/ContactLawParameters.hpp"
#include "contact/CoulombReturnMapping.hpp"
#include "contact/PenaltyNormalLaw.hpp"
#include "contact/Projection.hpp"

namespace contessa::contact {

/// Current positions of the slave node and of the master facet's nodes, in the facet's node order (see
/// the facet for the orientation that makes n̄ the outward normal of the master body).
template <class Facet>
struct NodeToFacetGeometry {
  typename Facet::Point slave{};
  std::array<typename Facet::Point, Facet::kNodes> master{};
};

/// Which tangent to build. Consistent is the exact derivative of the residual (quadratic Newton);
/// PaperMainTerms keeps only eq. (24)–(26), for comparison and verification.
enum class TangentTerms { Consistent, PaperMainTerms };

/// The tangential stiffness of a slipping node along its slip direction. Consistent: eq. (27) (zero along
/// the slip, the stick stiffness across it). Secant: a given stiffness along the slip instead, for a node
/// whose slip direction flips between Newton iterates (SlipReversalDamping): the secant of the traction
/// between the two states of the cycle, so the step lands between them, in the stick range, instead of
/// jumping across it. The residual, hence the converged answer, is the same either way.
///
/// The stiffness is ∂t_T/∂ξ along the slip in the facet's coordinates: with the slip direction
/// s_α = n^trial_α/|n^trial| (covariant components normalised in the parent coordinates; s_1 = ±1 with one
/// surface coordinate, where the stiffness is ∂t_T1/∂ξ̄), ∂t_α/∂Δξ^β becomes
///   ∂t_α/∂Δξ^β + (k − s_γ ∂t_γ/∂Δξ^δ s_δ) s_α s_β,   k = min(stiffness, ε_T s_γ ā_γδ s_δ),
/// capped by the stick stiffness along the same direction.
///
/// `normalStiffness` > 0: an open node's tangent k N Nᵀ (N = ∂g_N/∂u) instead of none, for a node that cycles
/// between open and closed (NormalToggleDamping: the secant of t_N between the two states); its residual stays
/// 0. Unused for a node in contact.
struct SlipTangent {
  bool secant = false;
  double stiffness = 0.0;  ///< ∂t_T/∂ξ along the slip used when `secant`
  double normalStiffness = 0.0;  ///< k of an open node's tangent k N Nᵀ (0: none, the consistent tangent)

  static SlipTangent consistent() { return {}; }
  static SlipTangent secantOf(double stiffness) { return {true, stiffness}; }
  /// Whether the tangent differs from the residual's derivative somewhere.
  bool damped() const { return secant || normalStiffness > 0.0; }
};

/// Where the slave node touches its facet (FacetSelection): at the closest point ξ̄ of eq. (1)–(3), or,
/// when the node lies past the facet's boundary and the closest point of the master surface is a vertex
/// or an edge point of it (a node under a valley or in a concave corner of the master; a node on a line
/// of master nodes sits there), at that vertex or edge point x_b. The normal part of the contact then
/// uses g_N = ±‖x^k − x_b‖ and n̄ = ±(x^k − x_b)/‖x^k − x_b‖ (docs/theory-contact.md §3 and §6.4), which
/// join the neighbouring facets' gaps and normals continuously; evaluated on one facet extended instead,
/// the force turned between the two facets' normals where the choice of facet flipped, and Newton cycled
/// on a node at rest exactly on the line (issue 22).
///
/// Past a free boundary (a projection outside the facet's parent domain that the selector kept on the
/// facet, FacetSelectorOptions::freeEdgeTolerance), the whole contact force fades to zero over
/// `freeEdgeReach` (0: no fade): r = w(d) r_c with the C1 weight
///   w = 1 − 3s² + 2s³,   s = min(d / freeEdgeReach, 1),   d = ‖x̄(ξ̄) − x̄(clamp(ξ̄))‖,
/// so a node carried past the edge by the deformation loses its force continuously instead of being cut
/// off (a node row on a punch's edge stalled Newton, issue 22); docs/theory-contact.md §3.1.
struct ContactPoint {
  enum class Kind { Projection, Vertex, Edge };
  Kind kind = Kind::Projection;
  std::array<int, 2> nodes{-1, -1};  ///< Vertex: nodes[0]; Edge: its two nodes (local indices in the facet)
  double side = 1.0;                 ///< sign of g_N: +1 in front of the master surface, −1 behind it
  double freeEdgeReach = 0.0;        ///< Projection: the length over which the force fades past the facet

  static ContactPoint projection(double freeEdgeReach = 0.0) { return {Kind::Projection, {-1, -1}, 1.0, freeEdgeReach}; }
  static ContactPoint vertex(int node, double side) { return {Kind::Vertex, {node, -1}, side}; }
  static ContactPoint edge(int a, int b, double side) { return {Kind::Edge, {a, b}, side}; }
};

/// Where a slave node that is open at the last commit was, relative to the facet it now touches, at that
/// commit: its gap g_N,0 and the parameter ξ_0 of its projection on the facet's committed position
/// (ContactInterface measures them). Such a node closes during the increment; taking its path relative to
/// the master as straight from (ξ_0, g_N,0) to the current (ξ̄, g_N), it touched the facet at the fraction
///   τ = g_N,0 / (g_N,0 − g_N)   (the closure fraction β^k of eq. 10; τ = 0 when g_N,0 ≤ 0)
/// at the point ξ_0 + τ (ξ̄ − ξ_0). That point is its stick reference: the return mapping of eq. (20)–(23)
/// runs with t_T,n = 0 and Δξ = (1 − τ)(ξ̄ − ξ_0), so friction acts from the first touch and the answer
/// does not depend on how far into the step the node closed (docs/theory-contact.md §5.2). Not known (the
/// node has no committed state, or no master was in reach at the commit): the reference is the current ξ̄
/// and the node carries no tangential traction in this increment.
template <int M>
struct CommittedApproach {
  bool known = false;
  double gap = 0.0;  ///< g_N,0 at the commit (finite)
  Vector<M> xi{};    ///< ξ_0: the committed slave position projected on the facet's committed position

  static CommittedApproach at(double gap, const Vector<M>& xi) { return {true, gap, xi}; }
};

template <class Facet>
struct NodeToFacetResult {
  static constexpr int kSurfaceDim = Facet::kSurfaceDim;
  static constexpr int kDofs = Facet::kSpaceDim * (1 + Facet::kNodes);

  ProjectionResult<Facet> projection{};        ///< ξ̄, ā_α, ā_αβ, n̄, g_N on the facet (unclamped)
  /// Where the node touches the facet, as given to evaluate: each kind (and each vertex or edge) is its own
  /// smooth branch of the residual; a switch between them is a kink (the Jacobian check's SlaveNodeChange).
  ContactPoint point{};
  double gap = 0.0;                            ///< g_N of the contact law: the projection's, or at the vertex/edge
  ContactStatus status = ContactStatus::Open;  ///< Open, Stick or Slip at this iterate
  double normalTraction = 0.0;                 ///< t_N = ε_N g_N, eq. (16), times freeEdgeWeight
  Vector<kSurfaceDim> tangentialTraction{};    ///< t_Tα, covariant, eq. (22), times freeEdgeWeight
  double freeEdgeWeight = 1.0;                 ///< w of the fade past a free edge (ContactPoint); 1 on the facet
  /// ξ̄ past a free edge, the fade applied: w is C1 only (w'' jumps from 0 to −6/reach² at the edge), so
  /// crossing the edge is a kink of the residual's second derivative (the Jacobian check tells it apart).
  bool pastFreeEdge = false;
  ReturnMappingResult<kSurfaceDim> friction{}; ///< trial state of eq. (20)–(23), when evaluated
  Vector<kDofs> residual{};                    ///< r_c = t_N ∂g_N/∂u + t_Tα ∂ξ̄^α/∂u
  Matrix<kDofs, kDofs> tangent{};              ///< K_c = ∂r_c/∂u
  ContactHistory<kSurfaceDim> trial{};         ///< trial history to store for this slave node

  /// Force exerted by the contact on the slave node, −r_c[0..kSpaceDim); along +n̄ when penetrating.
  typename Facet::Point slaveForce() const {
    typename Facet::Point f{};
    for (int c = 0; c < Facet::kSpaceDim; ++c) f[c] = -residual[c];
    return f;
  }
};

/// Node-to-facet contact element.
///
/// Kinematics (eq. 1–5 at the converged projection, where x^k − x̄ = g_N n̄). With the operators
/// (each a kDofs column: a slave block, then one block per master node i; H_i = H_i(ξ̄))
///   N   = [ n̄;   −H_i n̄ ]        T_α = [ ā_α; −H_i ā_α ]        D^α = ā^αβ T_β         (eq. 26)
///   N̄_α = [ 0;  H_i,α n̄ ]        (N̄_α·δu = n̄·δā_α at fixed ξ: the master nodes tilt the facet)
/// and the curvature b̄_αβ = x̄,αβ·n̄, the exact first variations are
///   ∂g_N/∂u = N,     ∂ξ̄^α/∂u = Ξ^α = (A⁻¹)^αβ (T_β + g_N N̄_β),     A_αβ = ā_αβ − g_N b̄_αβ.
/// (Straight segment: b̄ = 0, Ξ = D + g_N ā^11 N̄_1; flat parallelogram: b̄ = 0 too; a warped 4-node face
/// has b̄_12 ≠ 0.)
///
/// Residual (virtual work of the tractions of eq. 14, 16, 22: t_T·δg_T = t_Tα ā^α·ā_β δξ^β = t_Tα δξ^α):
///   r_c = t_N N + t_Tα Ξ^α.
/// It is added to the internal forces: R(u) = f_int + r_c − f_ext, K = ∂R/∂u. Since t_N < 0 in contact,
/// the force on the slave node, −r_c = ε_N|g_N| n̄ + …, pushes it out.
///
/// Tangent (docs/theory-contact.md §6 has the derivation):
///   K_c = ε_N N Nᵀ + t_N ∂²g_N/∂u² + Ξ^α (dt_Tα/du)ᵀ + t_Tα ∂²ξ̄^α/∂u²,
/// where dt_Tα/du is the return mapping's linearisation (∂t/∂Δξ, ∂t/∂ā_βγ, ∂t/∂t_N) chained with Ξ, the
/// total variation of ā_βγ and ε_N N. TangentTerms::PaperMainTerms keeps ε_N N Nᵀ + D^α (∂t_α/∂Δξ^β D^β +
/// ∂t_α/∂t_N ε_N N)ᵀ only, which is eq. (24) + (25) in stick and (24) + (26) in slip.
///
/// At a vertex or edge point x_b (ContactPoint), the normal part uses the operator N_b = [n̄_b; −h_i n̄_b]
/// of the point's weights h_i (1 at the vertex; 1 − t and t on the edge x_i → x_j) and
///   ∂²g_N/∂u² = (1/g_N) [ (r ⊗ I)ᵀ(r ⊗ I) − N_b N_bᵀ − F F ᵀ/‖e‖² ],   r = [1, −h_i],
/// with, on an edge e = x_j − x_i, F = ∂(d·e)/∂u = r ⊗ e + [−1 at i, 1 at j] ⊗ d, d = x^k − x_b (the edge
/// point moves along the edge as the node moves: the last term; none at a vertex). The tangential part
/// stays that of the facet, at its projection ξ̄ on the facet's extension, with t_N from g_N at x_b.
///
/// History: the element reads the committed history of the node on THIS facet (after a facet change,
/// first map it with transferHistory) and returns the trial history. A node whose committed status is
/// Open is a first contact: its stick reference point is where it touched the facet (CommittedApproach):
/// Δξ = (1 − τ)(ξ̄ − ξ_0) with τ(g_N) of eq. (10), whose variation adds to ∂Δξ/∂u = Ξ the terms
///   ∂Δξ^β/∂u = (1 − τ) Ξ^β − (ξ̄^β − ξ_0^β) g_N,0/(g_N,0 − g_N)² N
/// (N the contact law's ∂g_N/∂u). Without an approach the reference is the current ξ̄ (no traction).
///
/// Past a free edge (ContactPoint::freeEdgeReach > 0 and ξ̄ outside the parent domain) the result is faded:
///   r = w r_c,   K = w K_c + r_c (∂w/∂u)ᵀ,   ∂w/∂u = w'(s)/reach · v̂·∂v/∂u,   v = x̄(ξ̄) − x̄(ξ_c),
///   ∂v/∂u = ā_α(ξ̄) Ξ^α − Σ_{α free} ā_α(ξ_c) Ξ^α + [0, H_i(ξ̄) − H_i(ξ_c)] ⊗ I
/// (ξ_c = clamp(ξ̄): its clamped components are constant, its free ones follow ξ̄). w = 0: open. The trial
/// history keeps the law's unweighted traction (the state of the return mapping).
template <class Facet>
class NodeToFacetContact {
 public:
  static constexpr int kSurfaceDim = Facet::kSurfaceDim;
  static constexpr int kDofs = Facet::kSpaceDim * (1 + Facet::kNodes);
  using Geometry = NodeToFacetGeometry<Facet>;
  using Result = NodeToFacetResult<Facet>;

  explicit NodeToFacetContact(const ContactLawParameters& parameters, TangentTerms terms = TangentTerms::Consistent);

  /// Residual, tangent and trial history for the current positions `x` on master facet `facet`.
  /// `facetLength` is L_k, the mean size of the slave facets at the node (reference configuration): the
  /// length the slip tolerance refers to (ε_T = μ|t_N|/(s L_k), ContactLawParameters); unused when s = 0.
  /// `point`: where on the facet the node touches (the selector's choice; ContactPoint). `approach`: for a
  /// node open at the commit, where it was at the commit (CommittedApproach); unused otherwise.
  Result evaluate(const Geometry& x, int facet, const ContactHistory<kSurfaceDim>& committed,
                  double facetLength = 0.0, SlipTangent slipTangent = SlipTangent::consistent(),
                  const ContactPoint& point = ContactPoint::projection(),
                  const CommittedApproach<kSurfaceDim>& approach = {}) const;

  const ContactLawParameters& parameters() const { return parameters_; }

 private:
  /// evaluate without the fade past a free edge.
  Result evaluateUnfaded(const Geometry& x, int facet, const ContactHistory<kSurfaceDim>& committed,
                         double facetLength, SlipTangent slipTangent, const ContactPoint& point,
                         const CommittedApproach<kSurfaceDim>& approach) const;

  ContactLawParameters parameters_;
  TangentTerms terms_;
  PenaltyNormalLaw normalLaw_;
  CoulombReturnMapping<kSurfaceDim> returnMapping_;
};

/// A slave node's gap on one facet (its projection ξ̄ of eq. 1–4, on the facet or its extension) with the
/// exact first and second derivatives of g_N and ξ̄ in the element dofs [x^k, x_1, …, x_n] (§6.1 of
/// docs/theory-contact.md: ∂g_N/∂u = N, ∂ξ̄^α/∂u = Ξ^α, ∂²g_N/∂u² of term (a), ∂²ξ̄^α/∂u² of term (c)),
/// and the first derivative of the metric ā_βγ at ξ̄ (term (b)):
/// what an element built on two facets at once (ValleyBlend) is made of. `valid` is false when the
/// projection did not converge or the node sits at a focal point of the facet.
template <class Facet>
struct FacetGapVariation {
  static constexpr int kSurfaceDim = Facet::kSurfaceDim;
  static constexpr int kDofs = Facet::kSpaceDim * (1 + Facet::kNodes);
  bool valid = false;
  ProjectionResult<Facet> projection{};
  Vector<kDofs> gapFirst{};                               ///< ∂g_N/∂u
  Matrix<kDofs, kDofs> gapSecond{};                       ///< ∂²g_N/∂u²
  std::array<Vector<kDofs>, kSurfaceDim> xiFirst{};       ///< ∂ξ̄^α/∂u
  std::array<Matrix<kDofs, kDofs>, kSurfaceDim> xiSecond{};  ///< ∂²ξ̄^α/∂u²
  /// ∂ā_βγ/∂u of the metric at ξ̄ (term (b) of §6.1): [0, H_i,β] ⊗ ā_γ + [0, H_i,γ] ⊗ ā_β + (Γ_βεγ + Γ_γεβ) Ξ^ε
  std::array<std::array<Vector<kDofs>, kSurfaceDim>, kSurfaceDim> metricFirst{};
};

template <class Facet>
FacetGapVariation<Facet> facetGapVariation(const NodeToFacetGeometry<Facet>& x);

#define CONTESSA_EXTERN_NODE_TO_FACET_CONTACT(F) extern template class NodeToFacetContact<F>;
CONTESSA_FOR_EACH_FACET(CONTESSA_EXTERN_NODE_TO_FACET_CONTACT)
#undef CONTESSA_EXTERN_NODE_TO_FACET_CONTACT

}  // namespace contessa::contact
