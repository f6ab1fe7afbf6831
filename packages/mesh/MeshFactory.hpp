#pragma once
// Mesh sources by name ("Problem/Mesh/Type"): the inline generators and the mesh file readers, one
// registry row each (MeshFactory.cpp) with the deck parameters it takes, their docs and defaults,
// and the function that builds the mesh. The deck validates a Mesh list against validParameters
// before create; the deck reference is generated from the same lists. A generator's parameters are one
// table (common/ParameterTable.hpp) that both publishes them and reads them into its spec. Adding a mesh
// source = one function that builds a Mesh + its parameter table + one row.
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "mesh/DistributedMesh.hpp"
#include "mesh/Mesh.hpp"

namespace contessa::mesh {

/// How a set of Exodus II files holds a mesh or a run's results: one file, or the per-rank set
/// <name>.N.r (DecomposedExodusReader.hpp).
enum class ExodusLayout { SingleFile, PerRank };

/// The deck's names of ExodusLayout, in its order: Problem/Mesh's Layout (Type = Exodus File) and
/// Problem/Output's Exodus Layout.
const std::vector<std::string>& exodusLayoutNames();

class MeshFactory {
 public:
  /// Registered types, e.g. "Rectangle", "Box", "Exodus File".
  static std::vector<std::string> names();

  /// What the type builds or reads, and the sets it defines (one paragraph, for the deck reference).
  static std::string description(const std::string& type);

  /// The type's parameters with docs and defaults, without "Type" itself. Throws InputError listing
  /// the known names for an unknown type.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters(const std::string& type);

  /// Builds the mesh from `params` (validated against validParameters(type)). `where` is the deck
  /// path of the list: a generator's InputError becomes "<where>/<parameter>: ...", a reader's names
  /// the file. Relative file names are taken from `directory` (the deck's). The mesh is validated. A
  /// per-rank Exodus set is joined from its set for `comm`'s rank count when there is one.
  static Mesh create(const std::string& type, const Teuchos::ParameterList& params, const std::string& where,
                     const std::string& directory, MPI_Comm comm);

  /// This rank's part of the same mesh, collective over `comm` (DistributedMesh.hpp; the part is on it): the
  /// generators build only the rank's part (generate*Part: no
  /// communication: the structured grids in GridPartition's index boxes, the sphere octant in id ranges); the file readers read on rank 0, which partitions with
  /// METIS and sends the parts out (distributeMesh), except an Exodus set with Layout = Per Rank, whose
  /// files each rank reads itself. Errors as create's, on every rank.
  static DistributedMesh createPart(const std::string& type, const Teuchos::ParameterList& params,
                                    const std::string& where, const std::string& directory, MPI_Comm comm);
};

}  // namespace contessa::mesh
