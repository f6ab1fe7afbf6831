#include "deck/MeshReferences.hpp"

#include "common/Error.hpp"

namespace contessa::deck {
namespace {

template <class Entity>
std::string namesOf(const std::vector<Entity>& entities) {
  std::vector<std::string> names;
  for (const auto& e : entities) names.push_back(e.name);
  return joinNames(names);
}

}  // namespace

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

void requireNodeSet(const mesh::Mesh& mesh, const std::string& name, const std::string& where) {
  if (mesh.hasNodeSet(name)) return;
  throw InputError(where + ": node set '" + name + "' does not exist in the mesh (known: " + namesOf(mesh.nodeSets) + ")");
}

void requireSideSet(const mesh::Mesh& mesh, const std::string& name, const std::string& where) {
  if (mesh.hasSideSet(name)) return;
  throw InputError(where + ": side set '" + name + "' does not exist in the mesh (known: " + namesOf(mesh.sideSets) + ")");
}

void requireBlock(const mesh::Mesh& mesh, const std::string& name, const std::string& where) {
  if (mesh.hasBlock(name)) return;
  throw InputError(where + ": element block '" + name + "' does not exist in the mesh (known: " + namesOf(mesh.blocks) + ")");
}

}  // namespace contessa::deck
