#pragma once
// Geometry of one cell from its node coordinates: the Jacobian of the isoparametric map at each corner
// (and, for the other families, at every node and integration point), which decides whether an element
// is usable. Dimension-general: Quad4 and Hex8 take their corner edges from the reference cell
// [-1, 1]^d; every other type goes through its shape functions (ShapeFunctions.hpp); only the
// determinant (2×2 or 3×3) depends on d.
#include <vector>

#include "mesh/Mesh.hpp"

namespace contessa::mesh {

/// Reference coordinates (each −1 or +1) of corner `corner` of a Quad4 or Hex8, in Exodus node order
/// (the other types: referenceNode, ShapeFunctions.hpp).
std::vector<int> referenceCorner(CellType type, int corner);

/// det(∂x/∂ξ) at every corner, times 2^d (the edge vectors are not halved), in Exodus node order.
/// `x` holds the cell's node coordinates, node-major (x0 y0 [z0] x1 y1 ...). At a corner of a linear
/// cell ∂x/∂ξ_k is half the edge from that corner to its neighbour along ξ_k, signed by the direction
/// of ξ_k, so the value is the cross product of the two edges (Quad4) or the triple product of the
/// three edges (Hex8) leaving the corner. Positive at every corner ⇔ the map is one-to-one and
/// orientation preserving at the corners (counter-clockwise Quad4; a right-handed Hex8, bottom face
/// counter-clockwise seen from the top).
/// `jacobians` receives nodesPerCell(type) values. Quad4 and Hex8 only (the others: shapeCheckJacobians).
void cornerJacobians(CellType type, const double* x, double* jacobians);

/// The corner Jacobians divided by the product of the lengths of the d edges meeting there: in
/// [−1, 1], 1 for a right angle (in 2D the sine of the corner angle), independent of the element's
/// size and aspect ratio. 0 where an edge has zero length.
void scaledCornerJacobians(CellType type, const double* x, double* jacobians);

/// Area or volume of the isoparametric cell, ∫ det(∂x/∂ξ) dξ by the cell's rule (integrationPoints):
/// exact for Quad4 and Hex8 and for every cell whose mid-side nodes are at the middle of straight
/// edges (an affine map); negative for an inverted cell.
double cellMeasure(CellType type, const double* x);

/// A quadrature rule on the reference cell of `type` (ShapeFunctions.hpp): 2 Gauss points per
/// direction on linear quadrilaterals and hexahedra, 3 on quadratic ones; 1 point (Tri3, Tet4), 3 (Tri6)
/// or 4 (Tet10) on simplices; the triangle's 3 points times 2 or 3 Gauss points on wedges. Points
/// d-major (point p at points[p * d]); weights sum to the reference measure.
void integrationPoints(CellType type, std::vector<double>& points, std::vector<double>& weights);

/// Scaled Jacobians (det(∂x/∂ξ) over the product of the lengths of its d columns ∂x/∂ξ_k, in [−1, 1])
/// at every node of the cell (Exodus order) and then at each of its integration points: where a
/// quadratic cell folds, det J changes sign at a node or inside. Returns the number of values
/// (nodesPerCell + the rule's points, at most kMaxShapeCheckPoints).
int shapeCheckJacobians(CellType type, const double* x, double* scaled);
constexpr int kMaxShapeCheckPoints = 27 + 27;

}  // namespace contessa::mesh
