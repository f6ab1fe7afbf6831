// Loads on sets: one registry row per Type (name, doc, parameters, read), on the common Registry.
#include "deck/LoadDefinitions.hpp"

#include <sstream>

#include <Teuchos_Array.hpp>

#include "common/Error.hpp"
#include "common/Registry.hpp"
#include "deck/MeshReferences.hpp"
#include "deck/ParameterValidation.hpp"
#include "mechanics/DistributedLoads.hpp"

namespace contessa::deck {
namespace {

using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;

// One value per space dimension: a Teuchos array of doubles read and checked for its size.
std::vector<double> readVector(const ParameterList& list, const std::string& name, int dimension,
                               const std::string& where) {
  const auto& values = list.get<Teuchos::Array<double>>(name);
  requireInput(static_cast<int>(values.size()) == dimension,
               where + "/" + name + ": expected " + std::to_string(dimension) + " values (one per direction, " +
                   (dimension == 2 ? "x, y" : "x, y, z") + "), got " + std::to_string(values.size()));
  return {values.begin(), values.end()};
}

RCP<ParameterList> withType(const std::string& type) {
  auto p = rcp(new ParameterList(type));
  setChoice(*p, "Type", type, loadTypes(), "Kind of load; its parameters follow");
  return p;
}

RCP<ParameterList> pressureParameters() {
  auto p = withType("Pressure");
  p->set("Side Set", std::string(""), "Side set the pressure acts on; required");
  p->set("Pressure", 0.0,
         "Pressure at load factor 1 (force per current area; > 0 pushes into the body); it acts normal to the "
         "deformed face (a follower load, with its load stiffness in the Jacobian)");
  return p;
}

RCP<ParameterList> tractionParameters() {
  auto p = withType("Traction");
  p->set("Side Set", std::string(""), "Side set the traction acts on; required");
  p->set("Traction", Teuchos::Array<double>(),
         "Force per reference area at load factor 1 (x, y[, z]); a dead load: its direction and size do not change "
         "with the deformation (per unit thickness in 2D)");
  return p;
}

RCP<ParameterList> bodyForceParameters() {
  auto p = withType("Body Force");
  p->set("Blocks", Teuchos::Array<std::string>(), "Element blocks the force acts on; empty = every block");
  p->set("Force Per Volume", Teuchos::Array<double>(),
         "Force per reference volume at load factor 1 (x, y[, z]), e.g. gravity: density times g; a dead load, "
         "integrated with each cell's shape functions on every cell family (per unit thickness in plane strain, "
         "over the full circumference, 2 pi r, in an axisymmetric analysis)");
  return p;
}

RCP<ParameterList> springParameters() {
  auto p = withType("Spring");
  p->set("Node Set", std::string(""), "Node set whose nodes are each tied to the ground by a linear spring; required");
  p->set("Stiffness", Teuchos::Array<double>(),
         "Stiffness of each node's spring per direction (x, y[, z]), force per displacement, >= 0 (0: free in that "
         "direction); the spring force -k u does not scale with the load factor");
  return p;
}

void readPressure(const ParameterList& list, const std::string& where, const mesh::Mesh& mesh, LoadDefinition& load) {
  load.set = list.get<std::string>("Side Set");
  requireInput(!load.set.empty(), where + "/Side Set: required");
  requireSideSet(mesh, load.set, where + "/Side Set");
  load.pressure = list.get<double>("Pressure");
}

void readTraction(const ParameterList& list, const std::string& where, const mesh::Mesh& mesh, LoadDefinition& load) {
  load.set = list.get<std::string>("Side Set");
  requireInput(!load.set.empty(), where + "/Side Set: required");
  requireSideSet(mesh, load.set, where + "/Side Set");
  load.vector = readVector(list, "Traction", mesh.dimension, where);
}

void readBodyForce(const ParameterList& list, const std::string& where, const mesh::Mesh& mesh, LoadDefinition& load) {
  const auto& blocks = list.get<Teuchos::Array<std::string>>("Blocks");
  for (const auto& block : blocks) requireBlock(mesh, block, where + "/Blocks");
  load.blocks.assign(blocks.begin(), blocks.end());
  if (load.blocks.empty())
    for (const auto& block : mesh.blocks) load.blocks.push_back(block.name);
  // The body-force kernel takes every cell family of the element kernels (mechanics::isLoadCell); a cell it
  // does not take is bad input, refused here in one line on every rank, not by the model's assembly (exit 1,
  // an MPI abort).
  for (const auto& name : load.blocks) {
    const mesh::CellType type = mesh.block(name).cellType;
    requireInput(mechanics::isLoadCell(mesh.dimension, mesh::nodesPerCell(type)),
                 where + "/Blocks: block '" + name + "' has " + mesh::exodusCellName(type) +
                     " cells, which no Body Force kernel takes" +
                     (blocks.empty() ? " (an empty Blocks list means every block)" : ""));
  }
  load.vector = readVector(list, "Force Per Volume", mesh.dimension, where);
}

void readSpring(const ParameterList& list, const std::string& where, const mesh::Mesh& mesh, LoadDefinition& load) {
  load.set = list.get<std::string>("Node Set");
  requireInput(!load.set.empty(), where + "/Node Set: required");
  requireNodeSet(mesh, load.set, where + "/Node Set");
  load.vector = readVector(list, "Stiffness", mesh.dimension, where);
  for (double k : load.vector)
    if (!(k >= 0.0)) {
      std::ostringstream os;
      os << k;
      throw InputError(where + "/Stiffness: expected stiffnesses >= 0, got " + os.str());
    }
}

// A Type's row: its deck parameters and what reads it (common/Registry.hpp).
struct LoadReader {
  RCP<ParameterList> (*parameters)();
  void (*read)(const ParameterList&, const std::string&, const mesh::Mesh&, LoadDefinition&);
  LoadType type;
};
using LoadRow = RegistryRow<LoadReader>;

const Registry<LoadRow>& registry() {
  static const Registry<LoadRow> rows(
      "load type",
      {{"Pressure",
        "A pressure on a side set that follows the deformed face: f_a = -p ∫ N_a n da, n the current outward normal "
        "(docs/theory-solids.md §8); the load stiffness is in the Jacobian",
        {pressureParameters, readPressure, LoadType::Pressure}},
       {"Traction", "A dead traction on a side set: f_a = ∫ N_a t dA over the reference face",
        {tractionParameters, readTraction, LoadType::Traction}},
       {"Body Force", "A dead body force on element blocks of any cell family: f_a = ∫ N_a b dV over the reference volume "
        "(dV = 2 pi r dA in an axisymmetric analysis)",
        {bodyForceParameters, readBodyForce, LoadType::BodyForce}},
       {"Spring", "Linear springs to ground on a node set: a force -k_i u_i at every node of the set, in every direction i",
        {springParameters, readSpring, LoadType::Spring}}});
  return rows;
}

}  // namespace

std::vector<std::string> loadTypes() { return registry().names(); }

std::string loadTypeDescription(const std::string& type) { return registry().lookup(type, "Type").doc; }

RCP<const ParameterList> loadValidParameters(const std::string& type) {
  return registry().lookup(type, "Type").factory.parameters();
}

std::vector<LoadDefinition> buildLoads(ParameterList& loads, const mesh::Mesh& mesh) {
  std::vector<std::string> names;
  for (auto it = loads.begin(); it != loads.end(); ++it) {
    const std::string& name = loads.name(it);
    requireInput(loads.isSublist(name), "Problem/Loads/" + name + ": expected a sublist (one per load: Type and its parameters)");
    names.push_back(name);
  }
  std::vector<LoadDefinition> out;
  for (const auto& name : names) {
    const std::string where = "Problem/Loads/" + name;
    auto& list = loads.sublist(name);
    requireInput(list.isParameter("Type") && list.isType<std::string>("Type"),
                 where + "/Type: required; expected one of " + joinNames(loadTypes()));
    const auto& row = registry().lookup(list.get<std::string>("Type"), where + "/Type");
    validateAndSetDefaults(list, *row.factory.parameters(), where);
    LoadDefinition load;
    load.name = name;
    load.type = row.factory.type;
    row.factory.read(list, where, mesh, load);
    out.push_back(std::move(load));
  }
  return out;
}

}  // namespace contessa::deck
