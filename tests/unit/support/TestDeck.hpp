#pragma once
// The unit tests' decks, built in steps: a Problem list with a generated mesh, blocks and their
// materials, Dirichlet conditions, nodal forces and reaction sets, each one call. A test writes what its
// problem is (the sizes, the element, the conditions) and breaks or adds the one thing it tests; the
// list goes through the deck's own validation (deck::buildProblem), as a run's does.
#include <initializer_list>
#include <string>
#include <vector>

#include <mpi.h>

#include <Teuchos_Array.hpp>
#include <Teuchos_ParameterList.hpp>

#include "deck/ProblemDefinition.hpp"

namespace contessa::test {

using Teuchos::ParameterList;

/// A deck array parameter's value.
template <class T>
Teuchos::Array<T> arrayOf(std::initializer_list<T> values) {
  return Teuchos::Array<T>(values.begin(), values.end());
}

/// An empty "Problem" list.
inline Teuchos::RCP<ParameterList> newProblem() { return Teuchos::rcp(new ParameterList("Problem")); }

/// Problem/Mesh (or a Parts sublist of it): a generated `type` ("Rectangle", "Box") with the lengths and
/// element counts given along x, y, z (the generator's defaults, 1, where a list is shorter).
inline ParameterList& setGrid(ParameterList& mesh, const std::string& type, const std::vector<int>& elements,
                              const std::vector<double>& lengths = {}) {
  const char* axes[] = {"X", "Y", "Z"};
  mesh.set("Type", type);
  for (std::size_t a = 0; a < lengths.size(); ++a) mesh.set(std::string("Length ") + axes[a], lengths[a]);
  for (std::size_t a = 0; a < elements.size(); ++a) mesh.set(std::string("Elements ") + axes[a], elements[a]);
  return mesh;
}

/// Problem/Materials/<name>: `model` ("Neo-Hookean", "Linear Elastic") with Young's modulus and
/// Poisson's ratio.
inline void addMaterial(ParameterList& problem, const std::string& name, const std::string& model, double young,
                        double poisson) {
  auto& material = problem.sublist("Materials").sublist(name);
  material.set("Model", model);
  material.set("Young's Modulus", young);
  material.set("Poisson's Ratio", poisson);
}

/// Problem/Blocks/<name>: `element` of `material`.
inline void addBlock(ParameterList& problem, const std::string& name, const std::string& element,
                     const std::string& material) {
  auto& block = problem.sublist("Blocks").sublist(name);
  block.set("Element", element);
  block.set("Material", material);
}

/// Problem/Dirichlet Conditions/<name>: `component` of node set `nodeSet` held (at the deck's default
/// value 0 unless the caller sets "Value" on the returned list).
inline ParameterList& addDirichlet(ParameterList& problem, const std::string& name, const std::string& nodeSet,
                                   const std::string& component) {
  auto& condition = problem.sublist("Dirichlet Conditions").sublist(name);
  condition.set("Node Set", nodeSet);
  condition.set("Component", component);
  return condition;
}

/// Problem/Nodal Forces/<name>: `totalForce` along `component`, shared by the nodes of `nodeSet`.
inline void addNodalForce(ParameterList& problem, const std::string& name, const std::string& nodeSet,
                          const std::string& component, double totalForce) {
  auto& force = problem.sublist("Nodal Forces").sublist(name);
  force.set("Node Set", nodeSet);
  force.set("Component", component);
  force.set("Total Force", totalForce);
}

/// Problem/Output/Reaction Node Sets.
inline void setReactionSets(ParameterList& problem, const std::vector<std::string>& sets) {
  problem.sublist("Output").set("Reaction Node Sets", Teuchos::Array<std::string>(sets.begin(), sets.end()));
}

/// The problem of `deck` built by the deck's validation, on `comm` (its mesh spread over those ranks).
inline deck::ProblemDefinition buildOn(ParameterList& deck, MPI_Comm comm) { return deck::buildProblem(deck, "", comm); }

/// The deck tests' problem, small and valid: a 2 x 1 rectangle of 2 x 1 Q4 Enhanced elements (nodes at
/// x = 0, 1, 2 and y = 0, 1), Neo-Hookean steel, left held in x, its reaction written. Tests break one
/// thing at a time or add what they test.
inline Teuchos::RCP<ParameterList> goodProblem() {
  auto problem = newProblem();
  setGrid(problem->sublist("Mesh"), "Rectangle", {2}, {2.0});
  addBlock(*problem, "block_1", "Q4 Enhanced", "steel");
  addMaterial(*problem, "steel", "Neo-Hookean", 200.0, 0.3);
  addDirichlet(*problem, "fix", "left", "x");
  setReactionSets(*problem, {"left"});
  return problem;
}

}  // namespace contessa::test
