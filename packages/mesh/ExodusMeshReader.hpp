#pragma once
#include <string>

#include "mesh/Mesh.hpp"

namespace contessa::mesh {

/// Reads element blocks (QUAD4/QUAD/HEX8/HEX), node sets and side sets, with their names (unnamed
/// entities become "block_<id>", "nodeset_<id>", "sideset_<id>"). Ids become 0-based. Throws
/// InputError naming the file: "<path>: not a readable Exodus file (<why>)" for a missing, empty,
/// truncated, non-Exodus file or a directory (exodusFileProblem), an unsupported element type, a
/// mesh too large for the machine (requireRunFits), and
/// every check of Mesh::validate. Prints nothing to stderr.
Mesh readExodusMesh(const std::string& path);

}  // namespace contessa::mesh
