#pragma once
// The deck's "Problem" part turned into plain data: the mesh, which element and material each block
// uses, boundary conditions, output and regression expectations. Everything is validated here, before
// anything runs: names, types and ranges against the published valid parameters, then the references
// between them (blocks, node sets and materials that must exist).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "contact/InterfaceSpec.hpp"
#include "deck/LoadDefinitions.hpp"
#include "deck/LoadStepDefinitions.hpp"
#include "deck/OutputRequests.hpp"
#include "mechanics/Element.hpp"
#include "mechanics/Material.hpp"
#include "mesh/DistributedMesh.hpp"
#include "mesh/Mesh.hpp"

namespace contessa::deck {

struct BlockPhysics {
  std::string block;
  std::shared_ptr<const mechanics::ElementKernel> element;
  std::shared_ptr<const mechanics::Material> material;
  std::string elementName, materialName;
};

/// Prescribed displacement on a node set: u_c = λ · value (value is the displacement at λ = 1).
struct DirichletCondition {
  std::string name, nodeSet;
  int component = 0;
  double value = 0;
};

/// Nodal force on a node set: total force λ · totalForce in direction `component`, shared equally.
struct NodalForce {
  std::string name, nodeSet;
  int component = 0;
  double totalForce = 0;
};

/// One expected answer carried by the deck ("Regression" sublist), checked against the history.
struct RegressionCheck {
  std::string name, quantity;
  int step = -1;  ///< history step to compare; -1 = the last converged increment
  int loadStep = 0;  ///< > 0: the last history row of this load step (1 for the first) instead of `step`
  double expected = 0, relativeTolerance = 0, absoluteTolerance = 0;
};

struct ProblemDefinition {
  std::string title;
  /// This rank's part of the mesh (no rank holds the whole mesh): generated meshes are built part by
  /// part, files read on rank 0 and sent out (mesh::MeshFactory::createPart). Block and set names are
  /// the whole mesh's on every rank; sizes of the whole mesh in numGlobalNodes and the global*Sizes.
  mesh::DistributedMesh mesh;
  /// Reference coordinates of every contact-surface node (slave and deformable master nodes of all
  /// interfaces, ascending), the same on every rank: the contact surfaces are replicated (the owner of a
  /// slave node sees its master facet wherever it slides), the volume is not.
  std::vector<mesh::GlobalIndex> contactNodes;
  std::vector<double> contactNodeCoordinates;  ///< dimension values per contactNodes entry
  int dimension() const { return mesh.local().dimension; }
  std::vector<BlockPhysics> blocks;  ///< in mesh block order
  /// Every block's element is revolved about the y axis (r = x, Axisymmetry.hpp): forces, areas and
  /// volumes are those of the full circumference.
  bool axisymmetric = false;
  std::vector<DirichletCondition> dirichlet;
  std::vector<NodalForce> nodalForces;
  std::vector<LoadDefinition> loads;  ///< Problem/Loads: pressure, traction, body force, springs
  std::vector<std::string> reactionNodeSets;
  bool exodusPerRank = false;  ///< Problem/Output/Exodus Layout = Per Rank
  int checkpointEvery = 0;      ///< Problem/Output/Checkpoint/Every N Increments (0: none)
  double maxWallSeconds = 0;    ///< Problem/Output/Checkpoint/Max Wall Time (0: no limit)
  std::vector<RegressionCheck> regression;
  std::vector<HistoryRequest> history;  ///< Problem/Output/History: point histories (OutputRequests.hpp)
  /// Contact interfaces; a two-pass interface appears twice (the second with the roles swapped).
  std::vector<contact::ContactInterfaceSpec> contacts;
  /// Problem/Load Steps in the order written (LoadStepDefinitions.hpp); empty: one step ending at the
  /// deck's values (a single proportional load factor).
  std::vector<LoadStepDefinition> loadSteps;
};

/// Valid parameters of each part, with docs and defaults (published for the deck reference).
Teuchos::RCP<const Teuchos::ParameterList> problemValidParameters();
std::vector<std::string> meshTypes();
Teuchos::RCP<const Teuchos::ParameterList> meshValidParameters(const std::string& type);
Teuchos::RCP<const Teuchos::ParameterList> blockValidParameters();
Teuchos::RCP<const Teuchos::ParameterList> dirichletValidParameters();
Teuchos::RCP<const Teuchos::ParameterList> nodalForceValidParameters();
Teuchos::RCP<const Teuchos::ParameterList> regressionValidParameters();
/// A contact interface's parameters common to every law (with Law, the law's name); with `law`, and that
/// law's own parameters (ContactLawFactory).
Teuchos::RCP<const Teuchos::ParameterList> contactValidParameters();
Teuchos::RCP<const Teuchos::ParameterList> contactValidParameters(const std::string& law);

/// Validates the "Problem" list in place (defaults filled in) and builds the problem; mesh file
/// names are relative to `deckDirectory`. Throws InputError with the deck path on any problem, the
/// same on every rank. Collective over `comm`, the ranks the problem is spread over (the mesh parts,
/// the contact surfaces): the problem's mesh keeps it (mesh.comm), and the model is built on the same.
ProblemDefinition buildProblem(Teuchos::ParameterList& problem, const std::string& deckDirectory, MPI_Comm comm);

/// Component index of "x", "y", "z" (InputError naming `where` otherwise, or when ≥ dimension).
int componentIndex(const std::string& name, int dimension, const std::string& where);

}  // namespace contessa::deck
