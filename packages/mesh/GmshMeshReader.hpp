#pragma once
#include <string>

#include "mesh/Mesh.hpp"

namespace contessa::mesh {

/// Reads a Gmsh mesh file (.msh, any version Gmsh reads) through the Gmsh library. The mesh
/// dimension d is the highest dimension (2 or 3) of its physical groups; then
/// - each physical group of dimension d (Physical Volume, in 2D Physical Surface) is an element
///   block of 8-node hexahedra (4-node quadrilaterals in 2D);
/// - each physical group of dimension d − 1 is a side set (every face matched to the side of the
///   block element it bounds, in Exodus side numbering) and a node set of the same name;
/// - each physical group of lower dimension (points, curves in 3D) is a node set.
/// Unnamed groups are called "volume_<tag>", "surface_<tag>", "curve_<tag>", "point_<tag>". Only
/// nodes of block elements are kept, numbered in the order of their Gmsh tags; elements are
/// numbered block by block. A 2D mesh must lie in the plane z = 0.
///
/// Throws InputError with one line naming the file for a file Gmsh cannot read (Gmsh's own message,
/// nothing printed), other element types ("element type 'tetrahedron 4' in physical group 'x' is not
/// supported ..."), missing physical groups, faces that bound no block element, a mesh too large for
/// the machine (requireRunFits) and every check of Mesh::validate.
Mesh readGmshMesh(const std::string& path);

}  // namespace contessa::mesh
