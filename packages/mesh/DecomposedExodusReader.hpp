#pragma once
// A pre-split mesh: a set of per-rank Exodus files `base.N.r` (N files, rank r's zero-padded to the
// digits of N, as SEACAS decomp / nem_spread write them and as Contessa's per-rank output does), read
// with each rank opening only its own file. The files' global node and element id maps and their
// Nemesis node communication maps (which other files hold each border node) give the part's global
// ids and halo; the part is the DistributedMesh the file's elements make.
#include <string>
#include <vector>

#include "mesh/DistributedMesh.hpp"
#include "mesh/Mesh.hpp"

namespace contessa::mesh {

/// "base.N.r": rank r's file of a set of N (the rank zero-padded to the digits of N).
std::string decomposedFileName(const std::string& base, int numFiles, int rank);

/// Collective over `comm` (N = its size; the part is on it). Every rank reads decomposedFileName(base, N, rank):
/// its mesh (as readExodusMesh: checked the same way), its global node and element ids (Exodus id
/// maps, 1-based in the file) and its node communication maps. Nodes are renumbered in increasing
/// global id; a node's owner is the lowest rank among the files that hold it (Partition's rule, the
/// file's rank owning its elements); global sizes are summed over the ranks; a side set's entries
/// are placed in the whole set in (global element, side) order. Any rank's failure (a missing or
/// unreadable file, a set written for another number of ranks) is an InputError naming the file on
/// every rank. The files must be the pieces of one decomposition of one mesh: the same global sizes in
/// every file's records, each global element in exactly one file, each global node in one at least, in
/// as many files as their communication maps say and at the same coordinates (to 1e-12 of the mesh's
/// extent) in all; otherwise every rank throws one InputError naming the set and what differs.
DistributedMesh readDecomposedExodus(const std::string& base, MPI_Comm comm);

/// The rank counts N of the sets `base.N.r` present beside `base` (a file of the set for any r is
/// enough), ascending: what a reader names when the set for its rank count is missing.
std::vector<int> decomposedFileSets(const std::string& base);

/// Serial: all numFiles files of the set `base.numFiles.r` read on the calling rank (as each rank reads
/// its own) and joined into the whole mesh (MeshJoiner: node g at global id g, blocks by global element
/// id, side sets in (global element, side) order), which is validated (Mesh::validate). The files must
/// list the same blocks and sets and number every node; errors are InputErrors naming the file.
Mesh joinDecomposedExodus(const std::string& base, int numFiles);

}  // namespace contessa::mesh
