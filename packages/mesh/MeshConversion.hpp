#pragma once
// Other cell families from a mesh of linear cells, for the inline generators' variants (the Box's and
// the Rectangle's `Cell Type` and `Element Order`) and for tests: quadrilaterals and hexahedra split
// into triangles and tetrahedra, and linear cells made quadratic. Whole meshes only (MeshFactory sends
// the parts of a converted mesh out from rank 0).
#include "mesh/Mesh.hpp"

namespace contessa::mesh {

/// Every Quad4 split into 2 Tri3 along its diagonal from node 1 to node 3, every Hex8 into the 6 Tet4
/// around its diagonal from node 1 to node 7 (the Kuhn subdivision; Exodus numbers): each face of a
/// cell is split along the diagonal through its corner nearest node 1 of the cell, so two cells of a
/// structured grid (same orientation) split their shared face the same way and the result is
/// conforming. Element k becomes elements 2k, 2k+1 (6k .. 6k+5); side sets list the simplices' sides
/// on the cells' sides; node sets and coordinates are unchanged. Other cell types are refused
/// (std::logic_error).
Mesh splitIntoSimplices(const Mesh& mesh);

/// Every linear cell made quadratic: a node at the middle of each edge (shared by the cells of the
/// edge), Tri3 → Tri6, Quad4 → Quad8, Tet4 → Tet10, Hex8 → Hex20, Wedge6 → Wedge15; with
/// `complete` Quad4 → Quad9 and Hex8 → Hex27 (face and centre nodes too). New nodes are numbered after
/// the old ones and sit at the mean of the corners they are made from (so on curved generators the
/// edges stay straight: the chords); a new node joins every node set holding all those corners. Element
/// ids and side sets are unchanged (sides keep their numbers).
Mesh withMidEdgeNodes(const Mesh& mesh, bool complete = false);

}  // namespace contessa::mesh
