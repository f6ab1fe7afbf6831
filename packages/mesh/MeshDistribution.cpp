#include "mesh/MeshDistribution.hpp"

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <memory>
#include <stdexcept>
#include <type_traits>

#include "common/Error.hpp"
#include "common/RankAgreement.hpp"
#include "mesh/MeshJoin.hpp"
#include "mesh/Partition.hpp"

namespace contessa::mesh {

namespace {

// A part as bytes. One list of its fields (describe) serves both directions: the Packer reads them,
// the Unpacker writes them. Plain values are copied, vectors go length first, structures field by field.
template <class Io>
void describe(Io& io, ElementBlock& b) {
  io(b.name);
  io(b.cellType);
  io(b.elements);
  io(b.connectivity);
}

template <class Io>
void describe(Io& io, NodeSet& s) {
  io(s.name);
  io(s.nodes);
}

template <class Io>
void describe(Io& io, SideSet& s) {
  io(s.name);
  io(s.elements);
  io(s.sides);
}

template <class Io>
void describe(Io& io, DistributedMesh& part) {
  io(part.rank);
  io(part.numRanks);
  io(part.numGlobalNodes);
  io(part.numGlobalElements);
  io(part.globalBlockSizes);
  io(part.globalNodeSetSizes);
  io(part.globalSideSetSizes);
  io(part.nodeOwner);
  io(part.sideSetPositions);
  io(part.part.globalNodes);
  io(part.part.globalElements);
  io(part.part.sharedWith);
  Mesh& mesh = part.part.mesh;
  io(mesh.dimension);
  io(mesh.coordinates);
  io(mesh.blocks);
  io(mesh.nodeSets);
  io(mesh.sideSets);
}

class Packer {
 public:
  template <class T>
  void operator()(const T& value) {
    if constexpr (std::is_trivially_copyable<T>::value) {
      const auto* p = reinterpret_cast<const char*>(&value);
      bytes_.insert(bytes_.end(), p, p + sizeof(T));
    } else {
      describe(*this, const_cast<T&>(value));  // describe only reads through a Packer
    }
  }
  template <class T>
  void operator()(const std::vector<T>& values) {
    (*this)(static_cast<std::uint64_t>(values.size()));
    if constexpr (std::is_trivially_copyable<T>::value) {
      const auto* p = reinterpret_cast<const char*>(values.data());
      bytes_.insert(bytes_.end(), p, p + values.size() * sizeof(T));
    } else {
      for (const T& v : values) (*this)(v);
    }
  }
  void operator()(const std::string& s) { (*this)(std::vector<char>(s.begin(), s.end())); }
  std::vector<char>& bytes() { return bytes_; }

 private:
  std::vector<char> bytes_;
};

class Unpacker {
 public:
  explicit Unpacker(const std::vector<char>& bytes) : bytes_(bytes) {}
  template <class T>
  void operator()(T& value) {
    if constexpr (std::is_trivially_copyable<T>::value)
      take(&value, sizeof(T));
    else
      describe(*this, value);
  }
  template <class T>
  void operator()(std::vector<T>& values) {
    std::uint64_t size = 0;
    (*this)(size);
    values.resize(static_cast<std::size_t>(size));
    if constexpr (std::is_trivially_copyable<T>::value) {
      take(values.data(), values.size() * sizeof(T));
    } else {
      for (T& v : values) (*this)(v);
    }
  }
  void operator()(std::string& s) {
    std::vector<char> chars;
    (*this)(chars);
    s.assign(chars.begin(), chars.end());
  }

 private:
  void take(void* out, std::size_t size) {
    if (size > bytes_.size() - at_) throw std::logic_error("mesh part message shorter than its contents");
    if (size > 0) std::memcpy(out, bytes_.data() + at_, size);
    at_ += size;
  }
  const std::vector<char>& bytes_;
  std::size_t at_ = 0;
};

std::vector<char> pack(const DistributedMesh& part) {
  Packer out;
  out(part);
  return std::move(out.bytes());
}

DistributedMesh unpack(const std::vector<char>& bytes) {
  Unpacker in(bytes);
  DistributedMesh part;
  in(part);
  return part;
}

// MPI counts are ints: large messages go in pieces of at most 1 GiB.
constexpr std::size_t kChunk = std::size_t(1) << 30;
constexpr int kTagSize = 7101, kTagBytes = 7102;

void sendBytes(const std::vector<char>& bytes, int to, MPI_Comm comm) {
  const std::uint64_t size = bytes.size();
  MPI_Send(&size, 1, MPI_UINT64_T, to, kTagSize, comm);
  for (std::size_t at = 0; at < bytes.size(); at += kChunk)
    MPI_Send(bytes.data() + at, static_cast<int>(std::min(kChunk, bytes.size() - at)), MPI_CHAR, to, kTagBytes, comm);
}

std::vector<char> receiveBytes(int from, MPI_Comm comm) {
  std::uint64_t size = 0;
  MPI_Recv(&size, 1, MPI_UINT64_T, from, kTagSize, comm, MPI_STATUS_IGNORE);
  std::vector<char> bytes(static_cast<std::size_t>(size));
  for (std::size_t at = 0; at < bytes.size(); at += kChunk)
    MPI_Recv(bytes.data() + at, static_cast<int>(std::min(kChunk, bytes.size() - at)), MPI_CHAR, from, kTagBytes,
             comm, MPI_STATUS_IGNORE);
  return bytes;
}

// The parts travel on a communicator of their own, a copy of the run's, so that no other
// point-to-point traffic on the run's communicator (Tpetra's) can match their tags.
class PrivateComm {
 public:
  explicit PrivateComm(MPI_Comm of) { MPI_Comm_dup(of, &comm_); }
  ~PrivateComm() { MPI_Comm_free(&comm_); }
  PrivateComm(const PrivateComm&) = delete;
  PrivateComm& operator=(const PrivateComm&) = delete;
  MPI_Comm get() const { return comm_; }

 private:
  MPI_Comm comm_;
};

}  // namespace

void throwIfAnyRankFailed(MPI_Comm comm, std::exception_ptr failure) {
  // The lowest failing rank speaks for all (common/RankAgreement): 1 = an InputError, 2 = another error.
  int status = 0;
  std::string message;
  if (failure) {
    try {
      std::rethrow_exception(failure);
    } catch (const InputError& e) {
      status = 1;
      message = e.what();
    } catch (const std::exception& e) {
      status = 2;
      message = e.what();
    } catch (...) {
      status = 2;
      message = "unknown error";
    }
  }
  const RankMessage lowest = lowestSpeakingRank(comm, status, std::move(message));
  if (!lowest.spoken()) return;
  if (lowest.rank == ranksOf(comm).rank) std::rethrow_exception(failure);
  if (lowest.status == 1) throw InputError(lowest.message);
  throw std::runtime_error(lowest.message);
}

DistributedMesh distributeMesh(MPI_Comm comm, const std::function<Mesh()>& readOnRoot) {
  const auto [rank, size] = ranksOf(comm);
  if (rank != 0) {
    throwIfAnyRankFailed(comm, nullptr);
    const PrivateComm parts(comm);
    DistributedMesh mine = unpack(receiveBytes(0, parts.get()));
    mine.comm = comm;
    return mine;
  }

  // Rank 0: read and partition; whatever fails is told to the others before it is thrown here.
  Mesh mesh;
  Partition partition;
  std::exception_ptr failure;
  try {
    mesh = readOnRoot();
    partition = partitionMesh(mesh, size);
  } catch (...) {
    failure = std::current_exception();
  }
  throwIfAnyRankFailed(comm, failure);

  const PartExtractor extractor(mesh, std::move(partition.elementOwner), size);
  partition = Partition{};
  if (size > 1) {
    const PrivateComm parts(comm);
    for (int to = 1; to < size; ++to) sendBytes(pack(extractor.part(to)), to, parts.get());
  }
  DistributedMesh mine = extractor.part(0);
  mine.comm = comm;
  return mine;
}

void validatePart(const DistributedMesh& part, const std::string& source) {
  GlobalIndex badShapes = 0;
  std::exception_ptr failure;
  std::string message;
  try {
    part.local().validate(source, part.part.globalNodes, part.part.globalElements, badShapes);
  } catch (const InputError& e) {
    failure = std::current_exception();
    message = e.what();
  } catch (...) {
    failure = std::current_exception();
  }
  long long total = badShapes;
  if (ranksOf(part.comm).size > 1) MPI_Allreduce(MPI_IN_PLACE, &total, 1, MPI_LONG_LONG, MPI_SUM, part.comm);
  if (badShapes > 0 && total > 1)
    failure = std::make_exception_ptr(InputError(message + " (" + std::to_string(total) + " elements fail this check)"));
  throwIfAnyRankFailed(part.comm, failure);
}

Mesh gatherMeshOnRoot(const DistributedMesh& part) {
  const auto [rank, size] = ranksOf(part.comm);
  std::unique_ptr<PrivateComm> comm = size > 1 ? std::make_unique<PrivateComm>(part.comm) : nullptr;
  if (rank != 0) {
    sendBytes(pack(part), 0, comm->get());
    return Mesh{};
  }
  // Rank 0 joins the parts as they arrive (one received part at a time in memory besides the join).
  MeshJoiner joiner;
  joiner.add(part, "rank 0's part of the mesh");
  for (int from = 1; from < size; ++from)
    joiner.add(unpack(receiveBytes(from, comm->get())), "rank " + std::to_string(from) + "'s part of the mesh");
  return joiner.finish("the mesh gathered on rank 0");
}

Ranks ranksOf(MPI_Comm comm) {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  Ranks ranks;
  if (initialised && !finalised) {
    MPI_Comm_rank(comm, &ranks.rank);
    MPI_Comm_size(comm, &ranks.size);
  }
  return ranks;
}

std::size_t ReplicatedSurface::bytes() const {
  return elements.size() * sizeof(GlobalIndex) + sides.size() * sizeof(int) +
         facetNodes.size() * sizeof(GlobalIndex) + nodes.size() * sizeof(GlobalIndex) +
         coordinates.size() * sizeof(double);
}

namespace {

// The facets of a side set whose entries are (element, side) of `mesh` in local numbering, written
// as global ids through globalNode/globalElement, each with its position and its nodes' coordinates:
// one record of integers (position, element, side, nodes...) and one of coordinates per facet.
struct FacetRecords {
  int nodesPerFacet = 2;
  std::vector<GlobalIndex> integers;
  std::vector<double> coordinates;
};

// nodesPerFacet: the surface's facet node count (facetNodeCount); a triangle of a surface of triangles and
// quadrilaterals is written as a quadrilateral with its last node twice.
template <class GlobalNode, class GlobalElement, class Position>
FacetRecords facetRecords(const Mesh& mesh, const SideSet& set, int nodesPerFacet, GlobalNode&& globalNode,
                          GlobalElement&& globalElement, Position&& position) {
  FacetRecords records;
  records.nodesPerFacet = nodesPerFacet;
  const int dim = mesh.dimension;
  for (std::size_t k = 0; k < set.elements.size(); ++k) {
    const auto where = mesh.locate(set.elements[k]);
    const ElementBlock& block = mesh.blocks[where.block];
    const int npe = nodesPerCell(block.cellType);
    records.integers.push_back(position(k));
    records.integers.push_back(globalElement(set.elements[k]));
    records.integers.push_back(set.sides[k]);
    std::vector<int> side = sideNodes(block.cellType, set.sides[k]);
    while (static_cast<int>(side.size()) < nodesPerFacet) side.push_back(side.back());  // a collapsed quadrilateral
    for (int a : side) {
      const GlobalIndex node = block.connectivity[where.local * npe + a];
      records.integers.push_back(globalNode(node));
      for (int d = 0; d < dim; ++d) records.coordinates.push_back(mesh.coordinates[node * dim + d]);
    }
  }
  return records;
}

// The surface from every facet record (any order), placed by position.
ReplicatedSurface assemble(const std::string& name, int dim, const FacetRecords& all, std::size_t numFacets) {
  ReplicatedSurface surface;
  surface.name = name;
  surface.dimension = dim;
  const int npf = all.nodesPerFacet;
  surface.nodesPerFacet = npf;
  surface.elements.assign(numFacets, -1);
  surface.sides.assign(numFacets, -1);
  surface.facetNodes.assign(numFacets * npf, -1);
  std::vector<double> facetCoordinates(numFacets * npf * dim);
  const std::size_t stride = 3 + static_cast<std::size_t>(npf);
  for (std::size_t f = 0; f * stride < all.integers.size(); ++f) {
    const GlobalIndex* record = &all.integers[f * stride];
    const auto at = static_cast<std::size_t>(record[0]);
    if (at >= numFacets || surface.elements[at] != -1)
      throw std::logic_error("side set '" + name + "': facet positions do not cover the set once");
    surface.elements[at] = record[1];
    surface.sides[at] = static_cast<int>(record[2]);
    std::copy(record + 3, record + stride, surface.facetNodes.begin() + at * npf);
    std::copy(all.coordinates.begin() + f * npf * dim, all.coordinates.begin() + (f + 1) * npf * dim,
              facetCoordinates.begin() + at * npf * dim);
  }
  std::vector<std::size_t> order(surface.facetNodes.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return surface.facetNodes[a] < surface.facetNodes[b]; });
  for (std::size_t k : order) {
    if (!surface.nodes.empty() && surface.nodes.back() == surface.facetNodes[k]) continue;
    surface.nodes.push_back(surface.facetNodes[k]);
    surface.coordinates.insert(surface.coordinates.end(), facetCoordinates.begin() + k * dim,
                               facetCoordinates.begin() + (k + 1) * dim);
  }
  return surface;
}

std::size_t setIndex(const Mesh& mesh, const std::string& name) {
  const SideSet& set = mesh.sideSet(name);  // InputError naming the known side sets
  return static_cast<std::size_t>(&set - mesh.sideSets.data());
}

template <class T>
std::vector<T> allGatherOf(MPI_Comm comm, const std::vector<T>& mine, MPI_Datatype type) {
  const int size = ranksOf(comm).size;
  if (size == 1) return mine;  // one process (MPI perhaps not even initialised)
  const std::size_t count = mine.size();
  if (count > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw std::runtime_error("all-gather: more than 2^31 values on one rank");
  const int myCount = static_cast<int>(count);
  std::vector<int> counts(static_cast<std::size_t>(size)), offsets(static_cast<std::size_t>(size) + 1, 0);
  MPI_Allgather(&myCount, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  std::vector<long long> total(1, 0);
  for (int r = 0; r < size; ++r) {
    total[0] += counts[r];
    if (total[0] > std::numeric_limits<int>::max())
      throw std::runtime_error("all-gather: more than 2^31 values in all");
    offsets[r + 1] = static_cast<int>(total[0]);
  }
  std::vector<T> all(static_cast<std::size_t>(total[0]));
  MPI_Allgatherv(mine.data(), myCount, type, all.data(), counts.data(), offsets.data(), type, comm);
  return all;
}

// The fewest and the most nodes of a side of `set` (mesh::sideNodes): a facet type of contact each
// (MasterFacet.hpp); {INT_MAX, 0} for a set without sides (on this rank).
std::array<int, 2> sideNodeCounts(const Mesh& mesh, const SideSet& set) {
  std::array<int, 2> counts{std::numeric_limits<int>::max(), 0};
  for (std::size_t k = 0; k < set.elements.size(); ++k) {
    const CellType type = mesh.blocks[mesh.locate(set.elements[k]).block].cellType;
    const int n = static_cast<int>(sideNodes(type, set.sides[k]).size());
    counts = {std::min(counts[0], n), std::max(counts[1], n)};
  }
  return counts;
}

// The contact facet's node count of a side set whose sides have counts[0] to counts[1] nodes: theirs when all
// agree; 4 for the triangles and quadrilaterals of hexahedra with prisms (Quad4Facet, a triangle collapsed);
// an InputError naming the side set for other mixtures (a Wedge15's TRI6 and QUAD8 faces).
int facetNodeCount(const std::string& name, const std::array<int, 2>& counts) {
  if (counts[0] == counts[1] || counts[1] == 0) return counts[1];
  if (counts[0] == 3 && counts[1] == 4) return 4;
  throw InputError("side set '" + name + "' mixes sides of " + std::to_string(counts[0]) + " and " +
                   std::to_string(counts[1]) + " nodes: a contact surface takes one facet type (or linear "
                   "triangles with quadrilaterals)");
}

}  // namespace

ReplicatedSurface surfaceOfSideSet(const Mesh& mesh, const std::string& name) {
  const SideSet& set = mesh.sideSets[setIndex(mesh, name)];
  const int nodesPerFacet = facetNodeCount(name, sideNodeCounts(mesh, set));
  const auto same = [](GlobalIndex id) { return id; };
  const FacetRecords records =
      facetRecords(mesh, set, nodesPerFacet, same, same, [](std::size_t k) { return static_cast<GlobalIndex>(k); });
  return assemble(name, mesh.dimension, records, set.elements.size());
}

ReplicatedSurface gatherSurface(const DistributedMesh& part, const std::string& name) {
  const Mesh& local = part.local();
  const std::size_t s = setIndex(local, name);
  const auto& positions = part.sideSetPositions[s];
  // Decided together: every rank takes the same facet type, and a rank without a mixed side must throw
  // too, not wait in the gather below.
  std::array<int, 2> counts = sideNodeCounts(local, local.sideSets[s]);
  if (ranksOf(part.comm).size > 1) {
    MPI_Allreduce(MPI_IN_PLACE, &counts[0], 1, MPI_INT, MPI_MIN, part.comm);
    MPI_Allreduce(MPI_IN_PLACE, &counts[1], 1, MPI_INT, MPI_MAX, part.comm);
  }
  FacetRecords records = facetRecords(
      local, local.sideSets[s], facetNodeCount(name, counts), [&](GlobalIndex n) { return part.part.globalNodes[n]; },
      [&](GlobalIndex e) { return part.part.globalElements[e]; }, [&](std::size_t k) { return positions[k]; });
  records.integers = allGather(part.comm, records.integers);
  records.coordinates = allGatherOf(part.comm, records.coordinates, MPI_DOUBLE);
  return assemble(name, local.dimension, records, static_cast<std::size_t>(part.globalSideSetSizes[s]));
}

std::vector<GlobalIndex> allGather(MPI_Comm comm, const std::vector<GlobalIndex>& values) {
  static_assert(sizeof(GlobalIndex) == sizeof(long long), "GlobalIndex travels as MPI_LONG_LONG");
  return allGatherOf(comm, values, MPI_LONG_LONG);
}

RankFigures overRanks(MPI_Comm comm, double value) {
  RankFigures figures;
  MPI_Allreduce(&value, &figures.max, 1, MPI_DOUBLE, MPI_MAX, comm);
  MPI_Allreduce(&value, &figures.sum, 1, MPI_DOUBLE, MPI_SUM, comm);
  return figures;
}

}  // namespace contessa::mesh
