#pragma once
// The isoparametric geometry map of every cell type, for the mesh's own checks (MeshValidation):
// reference coordinates of the nodes, shape-function values and derivatives. The element kernels
// (packages/mechanics) have their own, tuned for speed; these are written for clarity.
// Reference cells: [−1, 1]^d for quadrilaterals and hexahedra; the unit simplex (ξ_k ≥ 0, Σ ξ_k ≤ 1)
// for triangles and tetrahedra; the unit triangle × [−1, 1] for wedges.
#include <array>
#include <vector>

#include "mesh/Mesh.hpp"

namespace contessa::mesh {

constexpr int kMaxNodesPerCell = 27;

/// Reference coordinates of node `node` (Exodus order) of `type`: cellDimension(type) values.
std::array<double, 3> referenceNode(CellType type, int node);

/// Shape functions N_a(ξ), a = 0 .. nodesPerCell − 1, at reference point `xi`.
void shapeValues(CellType type, const double* xi, double* values);

/// ∂N_a/∂ξ_k at `xi`, node-major: gradients[a * d + k].
void shapeGradients(CellType type, const double* xi, double* gradients);

}  // namespace contessa::mesh
