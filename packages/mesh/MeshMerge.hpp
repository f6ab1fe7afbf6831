#pragma once
// Assembling multi-body meshes from parts (e.g. a generated cylinder on a generated block for a
// contact problem): place the parts with translateMesh, then concatenate them with mergeMeshes.
#include <string>
#include <utility>
#include <vector>

#include "mesh/Mesh.hpp"

namespace contessa::mesh {

/// Concatenates named parts, in order, into one mesh. Every part must be valid (Mesh::validate) and of
/// the same dimension; part names must be non-empty and unique (InputError naming the part otherwise).
///
/// - Nodes: part p's node n becomes n + (nodes of parts before p); coordinates are concatenated.
///   Coincident nodes of different parts are NOT merged: parts are separate bodies.
/// - Elements: renumbered sequentially over all blocks in order (part 0's blocks first), so blocks
///   hold contiguous id ranges; side sets follow the renumbering.
/// - Names: every block, node set and side set of part "P" named "N" becomes "P_N" (node set "top" of
///   part "lower" → "lower_top"; its "all" → "lower_all"). EXCEPTION: a part with exactly one block
///   names that block just "P", so single-block parts give blocks named after the part.
///   Renamed names that still collide (part "a" block "b_c" vs part "a_b" block "c") are reported
///   by the final validate as an InputError.
///
/// The result passes Mesh::validate("merged mesh"). An empty part list is an InputError, and so is
/// a merged mesh whose run would not fit in memory (requireRunFits).
Mesh mergeMeshes(const std::vector<std::pair<std::string, Mesh>>& parts);

/// Returns `mesh` with every node moved by `offset` (one finite component per dimension; InputError
/// otherwise). Topology and names are unchanged.
Mesh translateMesh(Mesh mesh, const std::vector<double>& offset);

}  // namespace contessa::mesh
