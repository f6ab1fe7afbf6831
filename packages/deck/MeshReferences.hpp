#pragma once
// A deck's references to the mesh checked by name: a block, node set or side set that does not exist
// is an InputError naming the deck parameter and listing the mesh's names. Every rank's part holds
// every name of the whole mesh (DistributedMesh.hpp), so the check gives the same answer on every rank.
#include <string>
#include <vector>

#include "mesh/Mesh.hpp"

namespace contessa::deck {

/// "a, b, c".
std::string joinNames(const std::vector<std::string>& names);

/// InputError "<where>: node set 'name' does not exist in the mesh (known: ...)" unless it exists; the
/// same for side sets and element blocks.
void requireNodeSet(const mesh::Mesh& mesh, const std::string& name, const std::string& where);
void requireSideSet(const mesh::Mesh& mesh, const std::string& name, const std::string& where);
void requireBlock(const mesh::Mesh& mesh, const std::string& name, const std::string& where);

}  // namespace contessa::deck
