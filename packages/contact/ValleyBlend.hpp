#pragma once
// Contact of a slave node within a band around a valley edge of the master surface, evaluated on the two
// facets sharing the edge at once (issue 22, point 3; docs/theory-contact.md §6.5).
//
// Under a valley (the two facets' normals turned towards each other by θ) the node-to-facet force points
// along n̄_a on one facet and along n̄_b on the other; the region between, where the edge itself is the
// closest point (§6.4), is only |g_N| θ wide. A node pressed into the valley is pushed across it by the
// tangential part ε_N |g_N| θ of the force, and a Newton step, which sees no contact stiffness along a
// facet, jumps over that region to the other facet and back (the 3D half ring on a line of base nodes:
// ±0.00056 mm across a region 1.3e-6 mm wide). Here the gap turns smoothly from one facet's to the other's
// over a band of half-width b around the edge, wider than such a step:
//
//   g = (1 − w) g_a + w g_b,   w = S(t),  t = clamp(z/(2b) + ½, 0, 1),  S(t) = t³(10 − 15t + 6t²),
//   z = ½ (ℓ_a η_a − ℓ_b η_b),  η_f = s_f ξ̄_f^α_f − 1,
//
// g_f and ξ̄_f the node's gap and projection on facet f or its extension (eq. 1–4), the edge at
// ξ^α_f = s_f on facet f (η_f > 0 past it), ℓ_f the facet's length per unit ξ across the edge (‖ā_α_f‖ at
// its centre in the committed configuration: constant within an increment), so z is the node's distance
// across the edge, positive towards b. S is C² (S′ = S″ = 0 at both ends): at |z| = b the element is the
// single facet's, with its residual and tangent. The force is t_N ∂g/∂u, the tangent ε_N ∂g ∂gᵀ + t_N ∂²g,
// both exact (ValleyBlendResult). With Coulomb friction (penalty) the slip is blended with the same w in one
// chart of both facets, under one return mapping (ValleyFriction).
//
// Where: the selected facet's edges that another candidate facet holds (2D: a shared vertex; 3D: a shared
// edge), where the two facets form a valley (the partner's centre in front of the facet's tangent plane at
// the edge, normals θ > minAngle apart) and |z| < b; the nearest such edge. Flat and convex edges are left
// alone: coplanar masters and convex ridges are evaluated as before.
#include <cstddef>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

#include "contact/NodeToFacetContact.hpp"

namespace contessa::contact {

/// The facets the blend is written and verified for: linear segments and quadrilaterals, whose edges are
/// the sides ξ^α = ±1 of the parent square. Triangles (edges ξ^α = 0 and ξ^1 + ξ^2 = 1) and the
/// quadratic facets (curved edges) are not blended: their valley nodes keep the facet selection's contact.
template <class Facet>
inline constexpr bool kValleyBlendable = std::is_same_v<Facet, Line2Facet> || std::is_same_v<Facet, Quad4Facet>;

struct ValleyBlendOptions {
  /// b = bandWidth × L_k (L_k: the slave facets' size at the node, as the free-edge reach), capped by
  /// maxFacetFraction × min(ℓ_a, ℓ_b) (a quarter of the smaller facet's width across the edge) so that the
  /// band never reaches another edge. 1e-2: see docs/theory-contact.md §6.5 (a Newton step's swing on the
  /// half ring is 3.5e-4 L_k; b = 1e-2 L_k holds it 30 times).
  double bandWidth = 1e-2;
  /// Edges flatter than this [rad] are not blended (coplanar facets: exactly as before).
  double minAngle = 1e-3;
  double maxFacetFraction = 0.5;
};

/// A valley edge near a slave node: candidates a (the selected facet) and b share it.
struct ValleyEdge {
  std::size_t a = 0, b = 0;          ///< positions in the candidate list
  int acrossA = 0, acrossB = 0;      ///< α_f: the surface coordinate across the edge on each facet
  double sideA = 1.0, sideB = 1.0;   ///< s_f: the edge lies at ξ^α_f = s_f
  double lengthA = 0.0, lengthB = 0.0;  ///< ℓ_f
  double band = 0.0;                 ///< b
  double angle = 0.0;                ///< θ between the two facets' normals at the edge (current configuration)
};

/// The nearest valley edge of candidate `selected` within the band around `slave`, if any. `reference`
/// holds the committed facets by facet id (ℓ_f is measured there); `slaveSize` is L_k.
template <class Facet>
std::optional<ValleyEdge> findValleyEdge(const typename Facet::Point& slave, std::size_t selected,
                                         const std::vector<MasterFacetNodes<Facet>>& candidates,
                                         const std::vector<MasterFacetNodes<Facet>>& reference, double slaveSize,
                                         const ValleyBlendOptions& options = {});

/// The blend's surface chart: facet a's parent coordinates, facet b's mapped into them by unfolding b about
/// the shared edge, ξ_a = U(ξ_b) = c + J ξ_b (across the edge η_a = −(ℓ_b/ℓ_a) η_b, along it the edge's own
/// parametrisation, ±1): an isometry between flat rectangular facets, and the map HistoryTransfer applies
/// to a point carried across the edge. Constant within an increment (ℓ_f: committed configuration).
template <class Facet>
struct ValleyChart {
  static constexpr int M = Facet::kSurfaceDim;
  Matrix<M, M> J{};
  Vector<M> c{};
  Vector<M> map(const Vector<M>& xiB) const { return add(c, multiply(J, xiB)); }
};

template <class Facet>
ValleyChart<Facet> valleyChart(const MasterFacetNodes<Facet>& a, const MasterFacetNodes<Facet>& b, const ValleyEdge& edge);

/// Coulomb friction in the blend (docs/theory-contact.md §6.5): one contact point in facet a's chart,
///   ξ̃ = (1 − w) ξ̄_a + w U(ξ̄_b),   Ā = (1 − w) ā_a + w J⁻ᵀ ā_b J⁻¹   (the metric in that chart),
/// one return mapping (eq. 20–23) of t_T,n + ε_T Ā Δξ̃ with Δξ̃ = ξ̃ − ξ_n, t_N of the blended gap g, and
///   r_T = t_Tα ∂ξ̃^α/∂u,   K_T = ∂ξ̃^α ⊗ ∂t_Tα/∂u + t_Tα ∂²ξ̃^α/∂u²,
/// with ∂w = w_z ∂z in ∂ξ̃ and ∂Ā. Under a valley the facets' projections of a node pressed straight down
/// move apart, by |Δg_N| sin(θ/2) each; their blend does not (at the bottom), so pressing is not slip. The
/// history (ξ_n, t_T,n) is the node's on facet a, the chart's facet (the selected one), re-expressed there
/// by HistoryTransfer as everywhere; the node stores (ξ̃, t_T) on a. law = null: frictionless.
template <class Facet>
struct ValleyFriction {
  static constexpr int kSurfaceDim = Facet::kSurfaceDim;
  const ContactLawParameters* law = nullptr;
  ContactHistory<kSurfaceDim> committed{};     ///< on facet a
  CommittedApproach<kSurfaceDim> approach{};   ///< a first contact: where it was at the commit, ξ in a's chart
  double facetLength = 0.0;                    ///< L_k
};

/// ξ̃ of `slave` over the facets a and b of `edge` (ValleyFriction), e.g. a node's committed position on
/// the committed facets (its approach); nullopt when a projection fails.
template <class Facet>
std::optional<typename Facet::SurfaceCoords> valleyChartPoint(const typename Facet::Point& slave,
                                                             const MasterFacetNodes<Facet>& a,
                                                             const MasterFacetNodes<Facet>& b, const ValleyEdge& edge);

/// The blended element on the union of the two facets' nodes: block 0 the slave node, then facet a's
/// nodes, then facet b's nodes not in a (`source`: which facet, which local node). Residual and tangent
/// (row-major) over numBlocks × kSpaceDim dofs. numBlocks = 0: not evaluated (a projection failed).
template <class Facet>
struct ValleyBlendResult {
  static constexpr int kMaxBlocks = 1 + 2 * Facet::kNodes;
  static constexpr int kSurfaceDim = Facet::kSurfaceDim;
  int numBlocks = 0;
  std::array<std::pair<int, int>, kMaxBlocks> source{};  ///< block ≥ 1: (0 facet a | 1 facet b, local node)
  double gap = 0.0;             ///< g of the blend
  double normalTraction = 0.0;  ///< t_N(g), eq. (16)
  double weight = 0.0;          ///< w
  std::vector<double> residual, tangent;
  /// Open, or in contact: Slip without friction, else the return mapping's Stick or Slip.
  ContactStatus status = ContactStatus::Open;
  /// With friction (ValleyFriction), in contact: ξ̃, Ā, t_Tα (in a's chart), the return mapping's state and
  /// the trial history on facet a.
  bool frictional = false;
  Vector<kSurfaceDim> chartXi{};
  Matrix<kSurfaceDim, kSurfaceDim> chartMetric{};
  Vector<kSurfaceDim> traction{};
  ReturnMappingResult<kSurfaceDim> friction{};
  ContactHistory<kSurfaceDim> trial{};

  int numDofs() const { return numBlocks * Facet::kSpaceDim; }
  bool isActive() const { return numBlocks > 0 && gap < 0.0; }
};

template <class Facet>
ValleyBlendResult<Facet> evaluateValleyBlend(const PenaltyNormalLaw& law, const typename Facet::Point& slave,
                                             const MasterFacetNodes<Facet>& a, const MasterFacetNodes<Facet>& b,
                                             const ValleyEdge& edge, const ValleyFriction<Facet>& friction = {});

}  // namespace contessa::contact
