#pragma once
// Loads distributed over the mesh (issue 19 §1): a pressure on a facet that follows its deformation, a
// dead traction per reference area on a facet, a body force per reference volume over a cell. Local
// nodal forces and, for the follower pressure, its load stiffness only; the model assembles
// (model/ExternalLoads). Equations: docs/theory-solids.md §8.
//
// One code path for 2D and 3D and every facet shape. A facet of a D-dimensional solid is a cell of
// dimension M = D − 1: an edge of 2 or 3 nodes, a face of 3, 4, 6, 8 or 9 (the sides of every cell family,
// their shapes those of the solid kernels), integrated by a rule exact on an undistorted facet; a cell one
// of dimension D of every family of the element kernels (Quad4, Tri3, Tri6, Q8, Q9; Hex8, Tet4, Tet10, Hex20,
// Hex27, Wedge6, Wedge15), with the element's shape functions and a rule exact on a straight-sided cell
// (bodyForce); nodes in Exodus order. The only dimension-specific piece is the facet's area vector from its tangents
// (areaVector: the rotated tangent in 2D, the cross product in 3D), which points out of the body for a
// side in Exodus order.
//
// Every integral carries the weight w(x) of a LoadMeasure: 1 for plane strain and 3D. An axisymmetric
// analysis (issue 19 §3) passes w = 2πr (RevolvedMeasure, evaluated at the current point for the
// follower pressure, at the reference point for dead loads); the follower pressure's stiffness already
// has the term of ∂w/∂x, so no kernel is copied for it.

namespace contessa::mechanics {

/// The weight of the measure at a point x (D coordinates) and its gradient ∂w/∂x.
class LoadMeasure {
 public:
  virtual ~LoadMeasure() = default;
  virtual double weight(const double* x) const = 0;
  virtual void gradient(const double* x, double* dwdx) const = 0;  ///< D components
};

/// w = 1: plane strain (per unit thickness) and 3D.
class UnitMeasure final : public LoadMeasure {
 public:
  explicit UnitMeasure(int dimension) : dimension_(dimension) {}
  double weight(const double*) const override { return 1.0; }
  void gradient(const double*, double* dwdx) const override {
    for (int i = 0; i < dimension_; ++i) dwdx[i] = 0.0;
  }

 private:
  int dimension_;
};

/// w = 2π x₀: a 2D section revolved about the y axis (r = x), for the axisymmetric analysis of issue 19
/// §3 (the loads for the full circumference).
class RevolvedMeasure final : public LoadMeasure {
 public:
  double weight(const double* x) const override;
  void gradient(const double* x, double* dwdx) const override;
};

/// Nodes of a facet of a D-dimensional solid: 2 (an edge) in 2D, 4 (a quadrilateral face) in 3D.
constexpr int facetNodeCount(int D) { return D == 2 ? 2 : 4; }
/// Nodes of the cell the overloads without a node count take: 4 (Quad4) in 2D, 8 (Hex8) in 3D.
constexpr int cellNodeCount(int D) { return D == 2 ? 4 : 8; }

/// Whether the cell kernels (bodyForce, cellMeasure) take a cell of `nodes` nodes of a D-dimensional solid:
/// every family of the element kernels, which its node count tells apart within a dimension: in 2D 3 (Tri3),
/// 4 (Quad4), 6 (Tri6), 8 (Q8), 9 (Q9); in 3D 4 (Tet4), 6 (Wedge6), 8 (Hex8), 10 (Tet10), 15 (Wedge15),
/// 20 (Hex20), 27 (Hex27). The axisymmetric elements are the 2D cells with w = 2πr.
bool isLoadCell(int D, int nodes);

/// Whether the facet kernels take a side of `nodes` nodes of a D-dimensional solid: the sides of every cell
/// family, in Exodus side order (mesh::sideNodes): 2D edges of 2 (Quad4, Tri3) or 3 nodes (Tri6, Q8, Q9);
/// 3D faces of 3 (Tet4, Wedge6), 4 (Hex8, Wedge6), 6 (Tet10, Wedge15), 8 (Hex20, Wedge15) or 9 nodes (Hex27).
bool isLoadFacet(int D, int nodes);

/// Follower pressure p (> 0 pushes into the body) on a facet at current nodal coordinates x
/// (facetNodeCount(D) × D, node-major, Exodus side order): the force it exerts on the nodes,
/// f_a = −p ∫ N_a n w da (n the outward unit normal; theory-solids eq. 8.2), into `force`
/// (overwritten), and when `stiffness` is not null its load stiffness ∂f_a/∂x_b (row-major, (D·K)²
/// with K = facetNodeCount(D); eq. 8.4), which is not symmetric.
template <int D>
void followerPressure(const double* x, double p, const LoadMeasure& measure, double* force, double* stiffness);
/// The same on a facet of `nodes` nodes (isLoadFacet): x is nodes × D, the stiffness (D·nodes)².
template <int D>
void followerPressure(int nodes, const double* x, double p, const LoadMeasure& measure, double* force,
                      double* stiffness);

/// Dead traction t (D components, force per reference area) on a facet with reference coordinates X:
/// f_a = ∫ N_a t w dA (eq. 8.5), into `force` (overwritten).
template <int D>
void facetTraction(const double* X, const double* t, const LoadMeasure& measure, double* force);
template <int D>
void facetTraction(int nodes, const double* X, const double* t, const LoadMeasure& measure, double* force);

/// Body force b (D components, force per reference volume) over a cell with reference coordinates X
/// (cellNodeCount(D) × D): f_a = ∫ N_a b w dV (eq. 8.6), into `force` (overwritten).
template <int D>
void bodyForce(const double* X, const double* b, const LoadMeasure& measure, double* force);
/// The same on a cell of `nodes` nodes (isLoadCell): X is nodes × D. The element's shape functions N_a and a
/// rule that integrates N_a w det(∂X/∂ξ) exactly on a straight-sided cell (mid-edge nodes at the midpoints;
/// DistributedLoads.cpp lists the rules): so Σ_a f_a = b ∫ w dV and Σ_a f_a X_a = b ∫ X w dV exactly there.
template <int D>
void bodyForce(int nodes, const double* X, const double* b, const LoadMeasure& measure, double* force);

/// The reference measure of a facet (length in 2D, area in 3D) and of a cell (area, volume), each
/// weighted by w: for resultants and checks.
template <int D>
double facetMeasure(const double* X, const LoadMeasure& measure);
template <int D>
double facetMeasure(int nodes, const double* X, const LoadMeasure& measure);
template <int D>
double cellMeasure(const double* X, const LoadMeasure& measure);
template <int D>
double cellMeasure(int nodes, const double* X, const LoadMeasure& measure);

}  // namespace contessa::mechanics
