#pragma once
#include <string>

#include "mesh/Mesh.hpp"

namespace contessa::mesh {

/// Reads element blocks (QUAD4/QUAD/HEX8/HEX), node sets and side sets, with their names (unnamed
/// entities become "block_<id>", "nodeset_<id>", "sideset_<id>"). Ids become 0-based. Throws
/// InputError naming the file on a missing file, an unsupported element type or a read failure.
Mesh readExodusMesh(const std::string& path);

}  // namespace contessa::mesh
