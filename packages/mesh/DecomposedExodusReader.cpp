#include "mesh/DecomposedExodusReader.hpp"

#include <mpi.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <numeric>
#include <sstream>
#include <utility>
#include <vector>

#include "common/Error.hpp"
#include "mesh/ExodusFile.hpp"
#include "mesh/ExodusMeshReader.hpp"
#include "mesh/MeshDistribution.hpp"
#include "mesh/MeshJoin.hpp"

namespace contessa::mesh {

std::string decomposedFileName(const std::string& base, int numFiles, int rank) {
  const std::string r = std::to_string(rank), n = std::to_string(numFiles);
  return base + "." + n + "." + std::string(n.size() - std::min(n.size(), r.size()), '0') + r;
}

namespace {

using detail::ExodusFile;

// What the Nemesis records and id maps of one file say: global ids and, per local node, the other
// files holding it.
struct Decomposition {
  std::vector<GlobalIndex> globalNodes, globalElements;
  std::vector<std::vector<int>> sharedWith;
  GlobalIndex recordedNodes = 0, recordedElements = 0;  ///< of the whole mesh, as the file's records say
};

Decomposition readDecomposition(const std::string& path, GlobalIndex numNodes, GlobalIndex numElements, int rank,
                                int numRanks) {
  ex_opts(EX_DEFAULT);
  int cpuWordSize = 8, ioWordSize = 0;
  float version = 0;
  ExodusFile file(path, ex_open(path.c_str(), EX_READ | EX_ALL_INT64_API, &cpuWordSize, &ioWordSize, &version));
  requireInput(file.id() >= 0, path + ": not a readable Exodus file (" + ExodusFile::lastError() + ")");
  auto check = [&](int status, const std::string& what) {
    requireInput(status >= 0, path + ": not a file of a decomposed mesh (cannot read " + what + ": " +
                                  ExodusFile::lastError() + ")");
  };
  int processors = 0, processorsInFile = 0;
  char type[2] = {};
  check(ex_get_init_info(file.id(), &processors, &processorsInFile, type), "its decomposition records");
  requireInput(processors == numRanks, path + ": a file of a mesh split for " + std::to_string(processors) +
                                           " ranks; the run has " + std::to_string(numRanks));

  Decomposition d;
  int64_t globalNodes = 0, globalElements = 0, globalBlocks = 0, globalNodeSets = 0, globalSideSets = 0;
  check(ex_get_init_global(file.id(), &globalNodes, &globalElements, &globalBlocks, &globalNodeSets, &globalSideSets),
        "its global sizes");
  d.recordedNodes = globalNodes;
  d.recordedElements = globalElements;
  std::vector<int64_t> ids(static_cast<std::size_t>(numNodes));
  if (numNodes > 0) check(ex_get_id_map(file.id(), EX_NODE_MAP, ids.data()), "the global node ids");
  for (int64_t id : ids) d.globalNodes.push_back(id - 1);
  ids.assign(static_cast<std::size_t>(numElements), 0);
  if (numElements > 0) check(ex_get_id_map(file.id(), EX_ELEM_MAP, ids.data()), "the global element ids");
  for (int64_t id : ids) d.globalElements.push_back(id - 1);

  int64_t interiorNodes = 0, borderNodes = 0, externalNodes = 0, interiorElements = 0, borderElements = 0,
          nodeMaps = 0, elementMaps = 0;
  check(ex_get_loadbal_param(file.id(), &interiorNodes, &borderNodes, &externalNodes, &interiorElements,
                             &borderElements, &nodeMaps, &elementMaps, rank),
        "its load balance records");
  d.sharedWith.assign(static_cast<std::size_t>(numNodes), {});
  if (nodeMaps > 0) {
    std::vector<int64_t> mapIds(static_cast<std::size_t>(nodeMaps)), mapSizes(mapIds.size());
    std::vector<int64_t> elementMapIds(static_cast<std::size_t>(std::max<int64_t>(elementMaps, 1))),
        elementMapSizes(elementMapIds.size());
    check(ex_get_cmap_params(file.id(), mapIds.data(), mapSizes.data(), elementMapIds.data(), elementMapSizes.data(),
                             rank),
          "its communication maps");
    for (std::size_t m = 0; m < mapIds.size(); ++m) {
      std::vector<int64_t> nodes(static_cast<std::size_t>(mapSizes[m])), procs(nodes.size());
      if (nodes.empty()) continue;
      check(ex_get_node_cmap(file.id(), mapIds[m], nodes.data(), procs.data(), rank), "a communication map");
      for (std::size_t k = 0; k < nodes.size(); ++k) {
        requireInput(nodes[k] >= 1 && nodes[k] <= numNodes && procs[k] >= 0 && procs[k] < numRanks,
                     path + ": communication map " + std::to_string(mapIds[m]) + " names node " +
                         std::to_string(nodes[k]) + " of rank " + std::to_string(procs[k]) + ", out of range");
        if (procs[k] != rank) d.sharedWith[nodes[k] - 1].push_back(static_cast<int>(procs[k]));
      }
    }
  }
  for (auto& s : d.sharedWith) {
    std::sort(s.begin(), s.end());
    s.erase(std::unique(s.begin(), s.end()), s.end());
  }
  check(file.close(), "the file (close)");
  return d;
}

// What a file's decomposition records say of the whole mesh.
struct RecordedSizes {
  GlobalIndex nodes = 0, elements = 0;
};

// The file's mesh and decomposition as this rank's part, nodes renumbered in increasing global id.
DistributedMesh readPart(const std::string& path, int rank, int numRanks, RecordedSizes* recorded = nullptr) {
  Mesh mesh = readExodusMesh(path);
  Decomposition d = readDecomposition(path, mesh.numNodes(), mesh.numElements(), rank, numRanks);
  if (recorded != nullptr) *recorded = {d.recordedNodes, d.recordedElements};
  const int dim = mesh.dimension;
  const auto numNodes = static_cast<std::size_t>(mesh.numNodes());

  std::vector<std::size_t> order(numNodes);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return d.globalNodes[a] < d.globalNodes[b]; });
  std::vector<GlobalIndex> renumbered(numNodes);
  DistributedMesh part;
  part.rank = rank;
  part.numRanks = numRanks;
  MeshPiece& piece = part.part;
  piece.mesh.dimension = dim;
  for (std::size_t k = 0; k < numNodes; ++k) {
    const std::size_t old = order[k];
    requireInput(k == 0 || d.globalNodes[old] != piece.globalNodes.back(),
                 path + ": global node id " + std::to_string(d.globalNodes[old] + 1) + " given to two nodes");
    renumbered[old] = static_cast<GlobalIndex>(k);
    piece.globalNodes.push_back(d.globalNodes[old]);
    piece.mesh.coordinates.insert(piece.mesh.coordinates.end(), mesh.coordinates.begin() + old * dim,
                                  mesh.coordinates.begin() + (old + 1) * dim);
    piece.sharedWith.push_back(std::move(d.sharedWith[old]));
    // Partition's rule: the lowest rank among the files (so the elements) that hold the node.
    const auto& others = piece.sharedWith.back();
    part.nodeOwner.push_back(others.empty() ? rank : std::min(rank, others.front()));
  }
  mesh.coordinates.clear();
  for (auto& block : mesh.blocks)
    for (GlobalIndex& node : block.connectivity) node = renumbered[node];
  for (auto& set : mesh.nodeSets) {
    for (GlobalIndex& node : set.nodes) node = renumbered[node];
    std::sort(set.nodes.begin(), set.nodes.end());
  }
  piece.mesh.blocks = std::move(mesh.blocks);
  piece.mesh.nodeSets = std::move(mesh.nodeSets);
  piece.mesh.sideSets = std::move(mesh.sideSets);
  piece.globalElements = std::move(d.globalElements);
  return part;
}

unsigned long long reduced(MPI_Comm comm, unsigned long long value, MPI_Op op) {
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_UNSIGNED_LONG_LONG, op, comm);
  return value;
}

std::vector<GlobalIndex> summed(MPI_Comm comm, std::vector<GlobalIndex> values) {
  MPI_Allreduce(MPI_IN_PLACE, values.data(), static_cast<int>(values.size()), MPI_LONG_LONG, MPI_SUM, comm);
  return values;
}

// Collective: what each rank has for every other (outgoing[r], r = 0..size-1) exchanged; returns what the
// others sent this rank, concatenated in rank order.
template <class T>
std::vector<T> exchanged(MPI_Comm comm, const std::vector<std::vector<T>>& outgoing, MPI_Datatype type) {
  const int size = static_cast<int>(outgoing.size());
  std::vector<int> sendCounts(size), receiveCounts(size), sendOffsets(size + 1, 0), receiveOffsets(size + 1, 0);
  std::vector<T> sent;
  for (int r = 0; r < size; ++r) {
    sendCounts[r] = static_cast<int>(outgoing[r].size());
    sendOffsets[r + 1] = sendOffsets[r] + sendCounts[r];
    sent.insert(sent.end(), outgoing[r].begin(), outgoing[r].end());
  }
  MPI_Alltoall(sendCounts.data(), 1, MPI_INT, receiveCounts.data(), 1, MPI_INT, comm);
  for (int r = 0; r < size; ++r) receiveOffsets[r + 1] = receiveOffsets[r] + receiveCounts[r];
  std::vector<T> received(static_cast<std::size_t>(receiveOffsets[size]));
  MPI_Alltoallv(sent.data(), sendCounts.data(), sendOffsets.data(), type, received.data(), receiveCounts.data(),
                receiveOffsets.data(), type, comm);
  return received;
}

std::string rankList(std::vector<GlobalIndex> ranks) {
  std::sort(ranks.begin(), ranks.end());
  std::string text;
  for (std::size_t k = 0; k < ranks.size(); ++k)
    text += (k == 0 ? "" : k + 1 == ranks.size() ? " and " : ", ") + std::to_string(ranks[k]);
  return text;
}

// The names a set's messages use: the set, and the file of rank r.
struct SetNames {
  std::string set;
  std::function<std::string(GlobalIndex)> file;
};

// What one rank sends another about the ids that rank checks: (id, holder) per element; (id, holder,
// number of files holding it by the holder's maps) and x, y, z per node.
struct IdsToCheck {
  std::vector<std::vector<GlobalIndex>> elements, nodes;
  std::vector<std::vector<double>> coordinates;
  double extent = 0;  ///< the largest coordinate magnitude of the part
};

// Global ids in range (InputError naming the file otherwise), sorted by their checking rank (id % N).
IdsToCheck idsToCheck(const DistributedMesh& part, const RecordedSizes& recorded, const SetNames& names) {
  const int rank = part.rank, numRanks = part.numRanks;
  const Mesh& local = part.local();
  const int dim = local.dimension;
  IdsToCheck out{std::vector<std::vector<GlobalIndex>>(numRanks), std::vector<std::vector<GlobalIndex>>(numRanks),
                 std::vector<std::vector<double>>(numRanks), 0.0};
  for (GlobalIndex g : part.part.globalElements) {
    requireInput(g >= 0 && g < recorded.elements,
                 names.set + ": " + names.file(rank) + " holds global element id " + std::to_string(g + 1) +
                     ", beyond the " + std::to_string(recorded.elements) + " elements its records give the mesh");
    out.elements[g % numRanks].insert(out.elements[g % numRanks].end(), {g, rank});
  }
  for (std::size_t n = 0; n < part.part.globalNodes.size(); ++n) {
    const GlobalIndex g = part.part.globalNodes[n];
    requireInput(g >= 0 && g < recorded.nodes, names.set + ": " + names.file(rank) + " holds global node id " +
                                                   std::to_string(g + 1) + ", beyond the " +
                                                   std::to_string(recorded.nodes) + " nodes its records give the mesh");
    const auto holders = static_cast<GlobalIndex>(part.part.sharedWith[n].size()) + 1;
    out.nodes[g % numRanks].insert(out.nodes[g % numRanks].end(), {g, rank, holders});
    for (int i = 0; i < 3; ++i) {
      const double x = i < dim ? local.coordinates[n * dim + i] : 0.0;
      out.coordinates[g % numRanks].push_back(x);
      out.extent = std::max(out.extent, std::abs(x));
    }
  }
  return out;
}

// Each element id of this rank's share (id % N == rank) in exactly one file; `elements` holds the
// (id, holder) pairs the ranks sent.
void requireEachElementOnce(const std::vector<GlobalIndex>& elements, GlobalIndex numElements, int rank,
                            int numRanks, const SetNames& names) {
  std::vector<std::vector<GlobalIndex>> elementHolders(static_cast<std::size_t>(numElements / numRanks + 1));
  for (std::size_t k = 0; k < elements.size(); k += 2) elementHolders[elements[k] / numRanks].push_back(elements[k + 1]);
  for (GlobalIndex g = rank; g < numElements; g += numRanks) {
    const auto& holders = elementHolders[g / numRanks];
    requireInput(!holders.empty(), names.set + ": global element id " + std::to_string(g + 1) +
                                       " is in none of the files (the files cover the elements of another "
                                       "decomposition or mesh)");
    requireInput(holders.size() == 1, names.set + ": global element id " + std::to_string(g + 1) +
                                          " is in the files of ranks " + rankList(holders) +
                                          " (pieces of two decompositions or meshes)");
  }
}

// Each node id of this rank's share in a file at least, held by as many files as each holder's maps
// say, at one place (within `tolerance`); `nodes` holds the (id, holder, holders) triples the ranks
// sent and `coordinates` their x, y, z.
void requireNodesAgree(const std::vector<GlobalIndex>& nodes, const std::vector<double>& coordinates,
                       GlobalIndex numNodes, int rank, int numRanks, int dim, double tolerance, const SetNames& names) {
  struct Copy {
    GlobalIndex holder, holders;
    const double* x;
  };
  std::vector<std::vector<Copy>> nodeCopies(static_cast<std::size_t>(numNodes / numRanks + 1));
  for (std::size_t k = 0, c = 0; k < nodes.size(); k += 3, c += 3)
    nodeCopies[nodes[k] / numRanks].push_back({nodes[k + 1], nodes[k + 2], coordinates.data() + c});
  for (GlobalIndex g = rank; g < numNodes; g += numRanks) {
    const auto& copies = nodeCopies[g / numRanks];
    const std::string node = names.set + ": global node id " + std::to_string(g + 1);
    requireInput(!copies.empty(), node + " is in none of the files (the files cover the nodes of another "
                                         "decomposition or mesh)");
    std::vector<GlobalIndex> holders;
    for (const Copy& c : copies) holders.push_back(c.holder);
    for (const Copy& c : copies) {
      requireInput(c.holders == static_cast<GlobalIndex>(copies.size()),
                   node + " is in the files of ranks " + rankList(holders) + ", but the communication maps of " +
                       names.file(c.holder) + " share it with " + std::to_string(c.holders - 1) +
                       " other file(s) (pieces of two decompositions or meshes)");
      for (int i = 0; i < 3; ++i)
        if (std::abs(c.x[i] - copies.front().x[i]) > tolerance) {
          std::ostringstream where;
          where.precision(9);
          for (const Copy* copy : {&copies.front(), &c}) {
            where << (copy == &c ? " and (" : " (");
            for (int j = 0; j < dim; ++j) where << (j > 0 ? ", " : "") << copy->x[j];
            where << ") in " << names.file(copy->holder);
          }
          throw InputError(node + " lies at different places:" + where.str() + " (pieces of two meshes)");
        }
    }
  }
}

// Collective. The files of a set must be pieces of one decomposition of one mesh: the same global sizes
// in every file's records, every global element in exactly one file, every global node in at least
// one, held by as many files as the communication maps of each say, at the same coordinates in all.
// Pieces of two decompositions (or two meshes) would otherwise be read as one mesh, holes and overlaps
// included. Each global id is checked by rank id % N, which the others send what they hold of it (an
// all-to-all of the part's ids and node coordinates: the cost of reading the part once more). Throws,
// on every rank, the InputError of the lowest rank that finds a difference, naming the set.
void requireOneDecomposition(const DistributedMesh& part, const RecordedSizes& recorded, const std::string& base) {
  const int rank = part.rank, numRanks = part.numRanks;
  const SetNames names{decomposedFileName(base, numRanks, 0) + " ...",
                       [&](GlobalIndex r) { return decomposedFileName(base, numRanks, static_cast<int>(r)); }};
  const int dim = part.local().dimension;

  // The records and the dimension, compared on every rank alike.
  const std::vector<GlobalIndex> facts = allGather(part.comm, {recorded.nodes, recorded.elements, dim});
  for (int r = 1; r < numRanks; ++r)
    requireInput(std::equal(facts.begin(), facts.begin() + 3, facts.begin() + 3 * r),
                 names.set + ": the files are not pieces of one mesh: " + names.file(0) + " records " +
                     std::to_string(facts[0]) + " nodes, " + std::to_string(facts[1]) + " elements in " +
                     std::to_string(facts[2]) + "D, " + names.file(r) + " " + std::to_string(facts[3 * r]) +
                     " nodes, " + std::to_string(facts[3 * r + 1]) + " elements in " +
                     std::to_string(facts[3 * r + 2]) + "D");

  std::exception_ptr failure;
  IdsToCheck out;
  try {
    out = idsToCheck(part, recorded, names);
  } catch (...) {
    failure = std::current_exception();
  }
  throwIfAnyRankFailed(part.comm, failure);
  MPI_Allreduce(MPI_IN_PLACE, &out.extent, 1, MPI_DOUBLE, MPI_MAX, part.comm);
  const std::vector<GlobalIndex> elements = exchanged(part.comm, out.elements, MPI_LONG_LONG);
  const std::vector<GlobalIndex> nodes = exchanged(part.comm, out.nodes, MPI_LONG_LONG);
  const std::vector<double> coordinates = exchanged(part.comm, out.coordinates, MPI_DOUBLE);
  try {
    requireEachElementOnce(elements, recorded.elements, rank, numRanks, names);
    requireNodesAgree(nodes, coordinates, recorded.nodes, rank, numRanks, dim, 1e-12 * std::max(out.extent, 1.0),
                      names);
  } catch (...) {
    failure = std::current_exception();
  }
  throwIfAnyRankFailed(part.comm, failure);
}

}  // namespace

namespace {

// A file without elements of a block stores no cell type for it (topology "NULL"): the block takes
// the type the other files give it, so that every rank matches the same element kernel to it. Files
// that give one block different types are refused.
void agreeOnCellTypes(MPI_Comm comm, Mesh& local, const std::string& files) {
  constexpr unsigned long long kNone = 1000;  // more than any CellType value
  for (ElementBlock& block : local.blocks) {
    const unsigned long long mine = block.elements.empty() ? kNone : static_cast<unsigned long long>(block.cellType);
    const unsigned long long lowest = reduced(comm, mine, MPI_MIN);
    const unsigned long long highest = reduced(comm, block.elements.empty() ? 0 : mine, MPI_MAX);
    if (lowest == kNone) continue;  // empty in every file
    requireInput(lowest == highest, files + ": block '" + block.name + "' holds " +
                                        exodusCellName(static_cast<CellType>(lowest)) + " elements in one file, " +
                                        exodusCellName(static_cast<CellType>(highest)) + " in another");
    block.cellType = static_cast<CellType>(lowest);
  }
}

}  // namespace

DistributedMesh readDecomposedExodus(const std::string& base, MPI_Comm comm) {
  const auto [rank, numRanks] = ranksOf(comm);
  const std::string path = decomposedFileName(base, numRanks, rank);
  DistributedMesh part;
  RecordedSizes recorded;
  std::exception_ptr failure;
  try {
    part = readPart(path, rank, numRanks, &recorded);
  } catch (...) {
    failure = std::current_exception();
  }
  part.comm = comm;
  throwIfAnyRankFailed(comm, failure);

  // The files must list the same blocks and sets (empty where a file has none of their elements).
  const Mesh& local = part.local();
  const int counts[3] = {static_cast<int>(local.blocks.size()), static_cast<int>(local.nodeSets.size()),
                         static_cast<int>(local.sideSets.size())};
  const unsigned long long signature = std::hash<std::string>()(meshListing(local));
  requireInput(reduced(comm, signature, MPI_MIN) == reduced(comm, signature, MPI_MAX),
               decomposedFileName(base, numRanks, 0) + " ...: the files of the set list different element blocks, "
                                                       "node sets or side sets (names and order must agree)");
  requireOneDecomposition(part, recorded, base);
  agreeOnCellTypes(comm, part.part.mesh, decomposedFileName(base, numRanks, 0) + " ...");

  // Global sizes: each element is in one file, each node owned by one.
  std::vector<GlobalIndex> sizes{static_cast<GlobalIndex>(part.ownedNodes().size()), local.numElements()};
  for (const auto& b : local.blocks) sizes.push_back(b.numElements());
  for (const auto& s : local.nodeSets)
    sizes.push_back(std::count_if(s.nodes.begin(), s.nodes.end(), [&](GlobalIndex n) { return part.nodeOwner[n] == rank; }));
  for (const auto& s : local.sideSets) sizes.push_back(static_cast<GlobalIndex>(s.elements.size()));
  sizes = summed(comm, std::move(sizes));
  part.numGlobalNodes = sizes[0];
  part.numGlobalElements = sizes[1];
  auto next = sizes.begin() + 2;
  part.globalBlockSizes.assign(next, next + counts[0]);
  next += counts[0];
  part.globalNodeSetSizes.assign(next, next + counts[1]);
  next += counts[1];
  part.globalSideSetSizes.assign(next, next + counts[2]);

  // The files do not say where an entry sits in the whole side set: (global element, side) order.
  for (const auto& set : local.sideSets) {
    std::vector<GlobalIndex> mine;
    for (std::size_t k = 0; k < set.elements.size(); ++k)
      mine.push_back(part.part.globalElements[set.elements[k]] * 8 + set.sides[k]);  // sides < 6
    std::vector<GlobalIndex> all = allGather(comm, mine);
    std::sort(all.begin(), all.end());
    std::vector<GlobalIndex> positions;
    for (GlobalIndex key : mine) positions.push_back(std::lower_bound(all.begin(), all.end(), key) - all.begin());
    part.sideSetPositions.push_back(std::move(positions));
  }
  return part;
}

std::vector<int> decomposedFileSets(const std::string& base) {
  namespace fs = std::filesystem;
  const fs::path path(base);
  const std::string stem = path.filename().string();
  const auto digits = [](const std::string& t) {
    return !t.empty() && t.size() <= 9 && std::all_of(t.begin(), t.end(), [](unsigned char c) { return std::isdigit(c); });
  };
  std::vector<int> counts;
  std::error_code error;  // an unreadable directory holds no set
  for (fs::directory_iterator it(path.has_parent_path() ? path.parent_path() : fs::path("."), error), end;
       !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= stem.size() + 1 || name.compare(0, stem.size() + 1, stem + ".") != 0) continue;
    const std::string rest = name.substr(stem.size() + 1);
    const std::size_t dot = rest.find('.');
    if (dot == std::string::npos || !digits(rest.substr(0, dot)) || !digits(rest.substr(dot + 1))) continue;
    const int count = std::stoi(rest.substr(0, dot)), rank = std::stoi(rest.substr(dot + 1));
    // Only the names decomposedFileName gives (the rank below the count, padded to its digits).
    if (count >= 1 && rank < count && decomposedFileName(stem, count, rank) == name) counts.push_back(count);
  }
  std::sort(counts.begin(), counts.end());
  counts.erase(std::unique(counts.begin(), counts.end()), counts.end());
  return counts;
}

Mesh joinDecomposedExodus(const std::string& base, int numFiles) {
  MeshJoiner joiner;
  for (int r = 0; r < numFiles; ++r) {
    const std::string path = decomposedFileName(base, numFiles, r);
    joiner.add(readPart(path, r, numFiles), path);
  }
  const std::string set = decomposedFileName(base, numFiles, 0) + " ...";
  Mesh whole = joiner.finish(set);
  whole.validate(set);  // every element id once, in range; connectivity in range; sides on the boundary
  return whole;
}

}  // namespace contessa::mesh
