#pragma once
// Element partition (METIS) and node ownership. Deterministic: every rank computes the same answer
// from the same replicated mesh, so no communication is needed.
#include <vector>

#include "mesh/Mesh.hpp"

namespace contessa::mesh {

struct Partition {
  int numParts = 1;
  std::vector<int> elementOwner;  ///< rank that assembles each global element
  std::vector<int> nodeOwner;     ///< rank that owns each global node (lowest rank among its elements)

  /// Elements assembled by `rank`, nodes owned by `rank`, and every node of its elements (all ascending).
  std::vector<GlobalIndex> ownedElements(int rank) const;
  std::vector<GlobalIndex> ownedNodes(int rank) const;
  std::vector<GlobalIndex> overlapNodes(const Mesh& mesh, int rank) const;
};

/// METIS_PartMeshDual with a fixed seed; one part gives everything to rank 0.
Partition partitionMesh(const Mesh& mesh, int numParts);

/// Throws InputError unless a mesh of `numElements` elements can be split over `numParts` ranks (at
/// least one part, at most one rank per element): every partition's precondition.
void requirePartsFit(GlobalIndex numElements, int numParts);

}  // namespace contessa::mesh
