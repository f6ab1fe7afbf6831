#pragma once
// Local search for one slave node among candidate master facets: which facet (or which edge or corner
// vertex shared by several facets) the node is in contact with, after the global search (BoundingBoxTree)
// has produced the candidates. The rules are facet geometry (docs/theory-contact.md §3): one selector per
// facet type, Line2Facet (2D node-to-segment) and Quad4Facet (3D node-to-face).
#include "contact/Projection.hpp"

#include <vector>

namespace contessa::contact {

enum class SelectionKind {
  OnFacet,   ///< ξ̄ inside the parent domain of `facet`, enlarged by the inside tolerance
  AtEdge,    ///< 3D: the closest point lies on an edge shared by two candidate faces (a ridge or valley)
  AtVertex,  ///< the closest point is a vertex shared by candidate facets (a corner region)
  None       ///< no valid projection: the node has left the master surface, not in contact
};

template <class Facet>
struct FacetSelection {
  SelectionKind kind = SelectionKind::None;
  int facet = -1;       ///< facet on which the node-to-facet element is evaluated
  int vertexNode = -1;  ///< AtVertex: the global node id of the vertex
  std::array<int, 2> edgeNodes{-1, -1};  ///< AtEdge: the global node ids of the edge's ends
  ProjectionResult<Facet> projection{};  ///< projection on `facet`, unclamped
  double gap = 0.0;                  ///< signed distance to the closest point, eq. (4)
  typename Facet::Point normal{};    ///< unit normal at the closest point, g_N = (x^k − closest point)·normal
  typename Facet::Point closestPoint{};

  /// eq. (6): only a penetrating node carries a contact force.
  bool isPenetrating() const { return kind != SelectionKind::None && gap < 0.0; }
};

struct FacetSelectorOptions {
  /// A projection with ξ̄ within the parent domain enlarged by insideTolerance counts as inside its facet.
  /// 0: the facet's own domain. Past it, the node touches the facet's edge or vertex (ContactPoint), whose
  /// element equals the facet's on the domain's boundary, so nothing jumps as a node sitting on an edge or
  /// vertex flickers between the two by round-off. A tolerance band (it was 1e-8) evaluated a node just
  /// past the boundary on the facet extended: under a valley that turned the force by the valley's angle
  /// as the node crossed the band, and a node on a line of master nodes stalled the run (issue 22).
  double insideTolerance = 0.0;
  /// A node IN CONTACT past a free boundary of the master surface stays on the boundary facet while its
  /// distance beyond that boundary, measured on the facet's extension (‖x̄(ξ̄) − x̄(clamped ξ̄)‖), is below
  /// freeEdgeTolerance × L_k, L_k being the size of the slave facets at the node (the `slaveSize` given to
  /// select); its force fades to zero over that reach (ContactPoint::freeEdgeReach, w = 1 − 3s² + 2s³), so
  /// a node carried across the edge loses its force continuously. So a slave node on a flush edge (the 2D
  /// patch test's free ends: both bodies expand alike and the node drifts past the end by round-off, or by
  /// |g_N| tan θ when the end facet tilts by θ) keeps its contact, while a free-surface node beside a punch
  /// is not in contact however large the punch's facet is: the rule is a length of the slave mesh, not a
  /// fraction of the master facet (issue 22; the former 0.1 in ξ kept a row 1.11 mm past a 70 mm punch
  /// face). It does not depend on the penetration either: a rule that did (past by less than |g_N|) let a
  /// node 0.11 mm past the edge switch between open and closed from one Newton iterate to the next. The
  /// value: with 1e-3 (a cut-off, then a fade) a node row exactly on a punch's edge, spreading outwards
  /// under the pressure, stalled Newton; with 1e-2 it converges slowly (9–11 iterations in an increment);
  /// from 3e-2 on in 2–4, with the punch force within 1e-5 of that at 1e-1 (docs/verification-contact.md
  /// §6). Nodes 0.2 L_k or more past an edge (the punch at n = 18, 32, 48) stay out. "In contact" is the
  /// contact law's condition (the `heldGap` given to select): g_N < 0 with the penalty law (eq. 6), and
  /// λ_N + ε_N g_N < 0, i.e. g_N < −λ_N/ε_N, with the augmented Lagrangian (eq. 15.1 of
  /// docs/theory-contact.md), where the multiplier holds a node in contact at a small positive gap.
  double freeEdgeTolerance = 3e-2;
  /// 3D: a projection on a face whose area Jacobian ‖ā_1 × ā_2‖ at ξ̄ is below this fraction of its value
  /// at the face centre (near the apex of a collapsed face) does not count as inside: the node is handed to
  /// a neighbour, or to the apex vertex.
  double collapsedJacobianRatio = 1e-3;
  /// A vertex or edge point shared by facets whose unit normals there agree to within this angle (radians)
  /// is no corner or ridge: the surface is flat across it, its closest point to a node outside both facets
  /// by round-off is the facets' common projection, and the node stays on the facet it overshoots least,
  /// extended (OnFacet), instead of touching the point (AtVertex, AtEdge) along x^k − x_b. That direction
  /// is the normal only outside a genuine corner: on a flat surface, at a gap g_N that the augmented
  /// Lagrangian drives towards 0, it tilts by (round-off offset)/g_N, and a node on a line of master nodes
  /// went from one kind to the other from iterate to iterate (the 3D frictional patch test: ‖f‖ 1.5e-8 and
  /// 1.8e-6 alternately, to the iteration limit). Round-off level: a node switching between two facets
  /// treated as flat sees its force turn by up to this angle (at the edge point the force turns
  /// continuously instead); with 1e-6 the Tet10 patch test (penalty, ‖f‖ ≤ 1e-8) stalled at ‖f‖ 1.6e-8.
  double flatAngle = 1e-12;
  ProjectionOptions projection{};
};

/// Chooses the master facet of one slave node among candidates (rules common to both facet types):
///  - projections inside their facet (eq. 1–4) are preferred; when several are inside (a node above a
///    concave corner or valley of the master body, or a penetrating node near a convex one), the smaller
///    |g_N| wins: the node is pushed out the shortest way. A node sliding from one facet to the next
///    therefore switches facet exactly when its projection leaves the first one;
///  - when the node projects outside every candidate sharing an interior vertex (2D and 3D) or an interior
///    edge (3D), and that vertex or edge point is the closest point of the master surface (the node is
///    outside a convex corner or ridge, or under a concave one), that point is the contact point:
///    g_N = ±‖x^k − x_p‖, signed by the averaged outward normal of the facets sharing it, normal along
///    x^k − x_p. It is the true closest point of the piecewise surface, so the gap stays continuous as the
///    node goes round the corner or ridge (the load-step predictor of eq. (11) relies on that). Such a point
///    wins over an inside projection only when strictly closer. The element is then evaluated on one facet
///    sharing the point (2D: the one whose projection overshoots least; 3D: the one whose normal best
///    matches x^k − x_p), i.e. on that facet extended;
///  - a node in contact (g_N below `heldGap`) just past a free boundary (by less than freeEdgeTolerance × L_k)
///    stays on the boundary facet, extended, its force faded (ContactPoint::freeEdgeReach);
///  - otherwise the node has left the master surface: kind None, not in contact.
/// The 3D rules for edges and vertices (which are interior, collapsed faces) are in FacetSelector.cpp.
template <class Facet>
class FacetSelector {
 public:
  explicit FacetSelector(FacetSelectorOptions options = {}) : options_(options) {}

  /// `slaveSize`: L_k, the size of the slave facets at the node (the free-edge rule's length; 0: none).
  /// `heldGap`: the gap below which the contact law holds the node in contact, the free-edge rule's test:
  /// 0 for the penalty law (g_N < 0, eq. 6); −λ_N/ε_N ≥ 0 for the augmented Lagrangian with the node's
  /// multiplier λ_N ≤ 0 (λ_N + ε_N g_N < 0, eq. 15.1). Tested against the penetration alone, a node held
  /// at a positive gap by λ_N past a flush free end was dropped at the iterate after each multiplier
  /// update, lost its force, penetrated, was kept again: Newton cycled between the two to its iteration
  /// limit (the frictional patch test, docs/verification-contact.md §12).
  FacetSelection<Facet> select(const typename Facet::Point& slave,
                               const std::vector<MasterFacetNodes<Facet>>& candidates, double slaveSize = 0.0,
                               double heldGap = 0.0) const;

  const FacetSelectorOptions& options() const { return options_; }

 private:
  FacetSelectorOptions options_;
};

#define CONTESSA_EXTERN_FACET_SELECTOR(F) extern template class FacetSelector<F>;
CONTESSA_FOR_EACH_FACET(CONTESSA_EXTERN_FACET_SELECTOR)
#undef CONTESSA_EXTERN_FACET_SELECTOR

}  // namespace contessa::contact
