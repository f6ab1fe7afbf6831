#pragma once
// Closest-point projection of a slave node onto a master facet, eq. (1)–(5) of the reference paper,
// written for any facet type of MasterFacet.hpp (2D: Line2Facet, one ξ; 3D: Quad4Facet, two ξ^α).
#include "contact/MasterFacet.hpp"

#include <vector>

namespace contessa::contact {

/// Geometry of the master facet at a surface point ξ̄, seen from one slave node x^k.
template <class Facet>
struct ProjectionResult {
  static constexpr int kSurfaceDim = Facet::kSurfaceDim;
  using Point = typename Facet::Point;
  using SurfaceCoords = typename Facet::SurfaceCoords;

  SurfaceCoords xi{};                                  ///< ξ̄^α, not clamped to the parent domain
  Point position{};                                    ///< x̄(ξ̄) = Σ H_i x_i
  Vector<Facet::kNodes> shape{};                       ///< H_i(ξ̄)
  std::array<Point, kSurfaceDim> covariantBasis{};     ///< ā_α, eq. (2)–(3)
  Matrix<kSurfaceDim, kSurfaceDim> metric{};           ///< ā_αβ = ā_α · ā_β (metric of eq. 9)
  Matrix<kSurfaceDim, kSurfaceDim> inverseMetric{};    ///< ā^αβ
  std::array<Point, kSurfaceDim> contravariantBasis{}; ///< ā^α = ā^αβ ā_β (eq. 8, 14)
  Point normal{};                                      ///< n̄, eq. (5)
  double gap = 0.0;                                    ///< g_N = (x^k − x̄)·n̄, eq. (4); < 0 penetration (6)

  bool converged = false;  ///< Newton met the tolerance on |Δξ|
  int iterations = 0;      ///< Newton corrections computed (the last one is below the tolerance)
  int starts = 1;          ///< starts tried (> 1: the best start failed and the fallback was used)

  /// ξ̄ lies in the parent domain enlarged by `tolerance` (in units of ξ).
  bool isInside(double tolerance) const { return Facet::contains(xi, tolerance); }
  /// eq. (6): g_N < 0 is penetration.
  bool isPenetrating() const { return gap < 0.0; }
};

struct ProjectionOptions {
  double tolerance = 1e-12;  ///< on max_α |Δξ^α| (ξ is dimensionless)
  int maxIterations = 25;
};

/// Closest-point projection x̄(ξ̄) of a slave node x^k onto a master facet.
///
/// eq. (1) asks for (x^k − x̄)/‖x^k − x̄‖ · ā_α = 0. Newton solves the equivalent, non-normalised
///   r_α(ξ) = (x^k − x̄(ξ)) · ā_α(ξ) = 0,
/// which stays defined when the slave node lies exactly on the facet, with the Jacobian
///   ∂r_α/∂ξ^β = −ā_αβ + (x^k − x̄) · x̄,αβ ,
/// (x̄,αβ = Σ H_i,αβ x_i; zero for the straight 2-node segment, so there Newton is exact in one step).
/// r_α = −∂φ/∂ξ^α with φ(ξ) = ½‖x^k − x̄(ξ)‖²: the closest point is a stationary point of φ.
///
/// Straight facets (Facet::kAffine): plain Newton from the centre, exact after one step.
/// Curved facets (the bilinear 4-node face), made robust in three ways:
///   - start: the best (closest) of the centre and the closest points of the facet's flat pieces (its two
///     triangles), mapped to ξ; a slave node near an edge or a corner starts there, not at the centre;
///   - step: Newton where −∂r/∂ξ = ā_αβ − (x^k − x̄)·x̄,αβ is positive definite, else the Gauss–Newton step
///     with ā_αβ (always a descent direction of φ); each step is limited to 2 in ξ (the width of the
///     parent domain) and halved until φ does not grow (backtracking), so the iteration cannot run off
///     along the unbounded bilinear extension of a warped face;
///   - fallback: when Newton from the best start does not converge (a degenerate metric, the iteration
///     limit), the other starts are tried in order of their distance, and the first that converges is taken.
/// The result is NOT clamped to the parent domain: choosing among facets is the selector's job.
template <class Facet>
class Projection {
 public:
  using Point = typename Facet::Point;
  using SurfaceCoords = typename Facet::SurfaceCoords;
  using NodeCoords = std::array<Point, Facet::kNodes>;

  explicit Projection(ProjectionOptions options = {}) : options_(options) {}

  /// The closest point, from the robust start described above (the centre for a straight facet).
  ProjectionResult<Facet> project(const Point& slave, const NodeCoords& master) const;

  /// Newton iteration on r_α(ξ) = 0 from a given `start` (e.g. the previous iterate's ξ̄).
  ProjectionResult<Facet> project(const Point& slave, const NodeCoords& master, const SurfaceCoords& start) const;

  /// Facet geometry (x̄, ā_α, ā_αβ, ā^αβ, ā^α, n̄, g_N) at a given ξ, without iterating.
  static ProjectionResult<Facet> evaluateAt(const Point& slave, const NodeCoords& master, const SurfaceCoords& xi);

  /// The starts tried by project(slave, master): the centre, then the closest point of each flat piece
  /// (clamped to the piece), best (closest to x^k on the facet) first.
  static std::vector<SurfaceCoords> startCandidates(const Point& slave, const NodeCoords& master);

  const ProjectionOptions& options() const { return options_; }

 private:
  ProjectionOptions options_;
};

#define CONTESSA_EXTERN_PROJECTION(F) extern template class Projection<F>;
CONTESSA_FOR_EACH_FACET(CONTESSA_EXTERN_PROJECTION)
#undef CONTESSA_EXTERN_PROJECTION

using SegmentProjection2D = Projection<Line2Facet>;
using FaceProjection3D = Projection<Quad4Facet>;

}  // namespace contessa::contact
