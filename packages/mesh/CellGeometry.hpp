#pragma once
// Geometry of one linear cell (Quad4, Hex8) from its corner coordinates: the Jacobian of the
// isoparametric map at each corner, which decides whether an element is usable. Dimension-general:
// the corners and their edges come from the reference cell [-1, 1]^d, so quadrilaterals and
// hexahedra share the code; only the determinant (2×2 or 3×3) depends on d.
#include <vector>

#include "mesh/Mesh.hpp"

namespace contessa::mesh {

/// Reference coordinates (each −1 or +1) of corner `corner` of `type`, in Exodus node order.
std::vector<int> referenceCorner(CellType type, int corner);

/// det(∂x/∂ξ) at every corner, times 2^d (the edge vectors are not halved), in Exodus node order.
/// `x` holds the cell's node coordinates, node-major (x0 y0 [z0] x1 y1 ...). At a corner of a linear
/// cell ∂x/∂ξ_k is half the edge from that corner to its neighbour along ξ_k, signed by the direction
/// of ξ_k, so the value is the cross product of the two edges (Quad4) or the triple product of the
/// three edges (Hex8) leaving the corner. Positive at every corner ⇔ the map is one-to-one and
/// orientation preserving at the corners (counter-clockwise Quad4; a right-handed Hex8, bottom face
/// counter-clockwise seen from the top).
/// `jacobians` receives nodesPerCell(type) values.
void cornerJacobians(CellType type, const double* x, double* jacobians);

/// The corner Jacobians divided by the product of the lengths of the d edges meeting there: in
/// [−1, 1], 1 for a right angle (in 2D the sine of the corner angle), independent of the element's
/// size and aspect ratio. 0 where an edge has zero length.
void scaledCornerJacobians(CellType type, const double* x, double* jacobians);

}  // namespace contessa::mesh
