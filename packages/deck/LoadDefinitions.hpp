#pragma once
// The deck's loads on sets (issue 19 §1), Problem/Loads/<name>, one sublist per load with its Type:
//   Pressure    on a side set: follows the deformed face, positive pushing into the body
//   Traction    on a side set: a dead vector per reference area
//   Body Force  on blocks: a dead vector per reference volume (gravity: ρ g)
//   Spring      on a node set: a linear spring to ground at every node, a stiffness per direction
// Each Type is a registry row (its parameters published for the deck reference, what it reads). Loads
// are given at load factor 1 and scale with λ, as nodal forces and Dirichlet values do; springs do not.
// Problem/Nodal Forces is read as before (ProblemDefinition.cpp).
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "mesh/Mesh.hpp"

namespace contessa::deck {

enum class LoadType { Pressure, Traction, BodyForce, Spring };

struct LoadDefinition {
  std::string name;
  LoadType type = LoadType::Pressure;
  std::string set;                  ///< side set (Pressure, Traction) or node set (Spring)
  std::vector<std::string> blocks;  ///< Body Force: the blocks it acts on (every block when the deck names none)
  double pressure = 0;              ///< Pressure at λ = 1
  /// Traction (per reference area) or body force (per reference volume) at λ = 1; Spring: the stiffness
  /// of each node's spring in every direction. One value per space dimension.
  std::vector<double> vector;
};

/// The Type names, in the order the deck reference lists them, and each one's description.
std::vector<std::string> loadTypes();
std::string loadTypeDescription(const std::string& type);
/// The parameters of a load of `type` (Type among them).
Teuchos::RCP<const Teuchos::ParameterList> loadValidParameters(const std::string& type);

/// Validates every sublist of Problem/Loads (defaults filled in) and reads it against `mesh` (set and
/// block names, vector sizes, ranges); InputError naming the deck parameter otherwise. No communication.
std::vector<LoadDefinition> buildLoads(Teuchos::ParameterList& loads, const mesh::Mesh& mesh);

}  // namespace contessa::deck
