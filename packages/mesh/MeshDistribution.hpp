#pragma once
// Moving distributed-mesh parts between ranks (MPI, over the communicator the caller gives, which the
// parts then carry: DistributedMesh::comm): a mesh read once on rank 0
// and sent out part by part, so that only rank 0 holds the whole mesh, and only while it distributes
// it; and the replicated contact surfaces gathered from the parts (an all-gather of the side-set
// facets contact needs: the surface is O(n^(2/3)) of a 3D mesh, the volume stays distributed).
#include <cstddef>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "mesh/DistributedMesh.hpp"
#include "mesh/Mesh.hpp"

namespace contessa::mesh {

/// This process's rank in `comm` and its size (0 and 1 without MPI initialised).
struct Ranks {
  int rank = 0, size = 1;
};
Ranks ranksOf(MPI_Comm comm);

/// Collective over `comm` (every collective below is over the communicator given, or the part's).
/// Rank 0 calls `readOnRoot` (e.g. readExodusMesh on a file), partitions the mesh as
/// partitionMesh does (METIS, same seed, same node owners), and sends every other rank its part
/// (PartExtractor), keeping its own; the whole mesh is freed before returning. Every rank returns its
/// part (on `comm`). An error on rank 0 (an unreadable file: InputError; anything else: runtime_error) is
/// thrown on every rank with the same message, so none is left waiting.
DistributedMesh distributeMesh(MPI_Comm comm, const std::function<Mesh()>& readOnRoot);

/// Collective: the whole mesh assembled on rank 0 from every rank's part (an empty Mesh elsewhere), as
/// the replicated mesh was: blocks list their elements in increasing global id, node sets sorted, side
/// sets in their original order (sideSetPositions). For output gathered into one file, which rank 0
/// writes whole.
Mesh gatherMeshOnRoot(const DistributedMesh& part);
/// Collective: every rank checks its part (Mesh::validate in the part's numbering, messages in the whole
/// mesh's numbers) and all throw the lowest failing rank's InputError, with the number of badly shaped
/// elements summed over the parts, as the check of the whole mesh words it.
void validatePart(const DistributedMesh& part, const std::string& source);
/// Collective: every rank throws the error of the lowest rank whose `failure` is set (null on a rank
/// that did not fail), with its message: an InputError as an InputError, anything else as a
/// runtime_error. Returns on every rank when none failed. What a step that one rank alone may fail
/// (reading its file) calls before the next collective, so that no rank is left waiting.
void throwIfAnyRankFailed(MPI_Comm comm, std::exception_ptr failure);

/// A side set of the whole mesh as contact needs it on every rank: its entries (element, side) in the
/// side set's order, each facet's global nodes (Exodus side order), and the coordinates of the nodes
/// it touches.
struct ReplicatedSurface {
  std::string name;
  int dimension = 2;
  /// 2, 3 (2D edges); 3, 4, 6, 8, 9 (3D faces); 4 also for triangles among quadrilaterals, each written with
  /// its last node twice (a collapsed quadrilateral)
  int nodesPerFacet = 2;
  std::vector<GlobalIndex> elements;      ///< global element of each facet
  std::vector<int> sides;                 ///< its local side (0-based)
  std::vector<GlobalIndex> facetNodes;    ///< global node ids, nodesPerFacet per facet
  std::vector<GlobalIndex> nodes;         ///< the surface's nodes, ascending
  std::vector<double> coordinates;        ///< of `nodes`, node-major
  std::size_t bytes() const;
};

/// The surface of side set `name` from a replicated mesh (the reference: what contact reads today).
ReplicatedSurface surfaceOfSideSet(const Mesh& mesh, const std::string& name);

/// Collective. The same surface from the ranks' parts: each contributes the facets of its elements
/// (with their positions in the whole side set) and their coordinates, all-gathered. Throws InputError
/// naming the side set and the known ones when the mesh has no side set `name` (every rank alike).
ReplicatedSurface gatherSurface(const DistributedMesh& part, const std::string& name);

/// Collective: every rank's `values` concatenated in rank order, on every rank (surface-sized data:
/// at most 2^31 values in all).
std::vector<GlobalIndex> allGather(MPI_Comm comm, const std::vector<GlobalIndex>& values);

/// Collective: the largest and the sum over the ranks of `value` (the memory figures).
struct RankFigures {
  double max = 0, sum = 0;
};
RankFigures overRanks(MPI_Comm comm, double value);

}  // namespace contessa::mesh
