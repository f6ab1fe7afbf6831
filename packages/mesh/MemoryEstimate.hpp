#pragma once
// How much memory a run will need, estimated from the mesh size before anything is allocated, and
// the refusal of a mesh that will not fit (instead of an out-of-memory kill or std::bad_alloc
// minutes later). The model and its calibration against measured peaks: docs/user-guide.md,
// "Mesh checks and memory".
#include <optional>
#include <string>

#include <mpi.h>

namespace contessa::mesh {

/// The sizes that decide a run's memory. Counts are doubles: products of deck integers can exceed
/// every integer type, and an estimate needs no exactness.
struct MeshSize {
  /// A mesh of linear cells, QUAD4 (2D) or HEX8 (3D); a reader raises nodesPerElement to its largest cell's.
  MeshSize(double nodes, double elements, int dimension)
      : nodes(nodes), elements(elements), dimension(dimension), nodesPerElement(dimension == 2 ? 4 : 8) {}

  double nodes;
  double elements;
  int dimension;
  int nodesPerElement;  ///< of the largest cell
};

/// A rough estimate of a run's memory in bytes, by part. Calibrated on 2D runs (Q4 Enhanced, MUMPS)
/// to within +4 % to +22 % above the measured peak resident memory; the 3D factor term follows
/// nested-dissection theory and is not yet measured.
struct RunMemoryEstimate {
  double mesh = 0;         ///< the mesh containers (coordinates, connectivity, sets) on one rank
  double perRank = 0;      ///< libraries + the mesh and what is derived from it (partition, maps): every rank
  double distributed = 0;  ///< matrix, vectors, element data: shared out over the ranks
  double factor = 0;       ///< direct solver (MUMPS) factor and workspace: shared out over the ranks

  /// What `ranksOnMachine` of the run's `ranks` ranks need together on one machine.
  double onMachine(int ranksOnMachine, int ranks) const;
};

/// Unknowns n = dimension × nodes; matrix entries n · d·3^d (each node couples to the 3^d nodes of
/// its element patch); 100 bytes per matrix entry (Tpetra matrix and graph, MUMPS' copies of the
/// entries, vectors); factor entries 11 · n · log2 n in 2D, 11 · n^(4/3) in 3D, 12 bytes each;
/// 96 MiB of libraries and twice the mesh containers per rank.
RunMemoryEstimate estimateRunMemory(const MeshSize& size);

/// Largest count Contessa's libraries can index: Tpetra's local ordinals, METIS' idx_t and MUMPS'
/// integers are 32-bit here, so unknowns and element-node entries must stay below 2^31.
constexpr double kMaxIndex = 2147483647.0;

/// The reason a run of `size` cannot be done with `availableBytes` for `ranksOnMachine` of `ranks`
/// ranks ("" when it fits): "<N> elements need about <X> of memory for the run, <Y> are available",
/// or the unknowns / element-node entries exceed kMaxIndex. `availableBytes` < 0: unknown, no
/// memory check.
std::string runSizeProblem(const MeshSize& size, double availableBytes, int ranksOnMachine, int ranks);

/// Bytes this process may still allocate: MemAvailable from <procRoot>/meminfo, lowered to the room
/// left under a cgroup memory limit if one is set (v2: memory.max − (memory.current − inactive_file);
/// v1: memory.limit_in_bytes − (memory.usage_in_bytes − total_inactive_file); the cgroup comes from
/// <procRoot>/self/cgroup, found under <cgroupRoot>). Reclaimable file cache counts as available.
/// std::nullopt when neither source can be read.
std::optional<double> availableMemory(const std::string& procRoot = "/proc",
                                      const std::string& cgroupRoot = "/sys/fs/cgroup");

/// The ranks agree, once, on the memory the size checks assume: the smallest available memory of
/// any rank and the most ranks sharing one machine. Collective over `comm` (the run's); the program calls
/// it at start-up, before anything that one rank alone may refuse, so that requireRunFits needs no
/// collective call and a rank that fails early (a missing file) cannot leave another waiting in it.
void agreeOnMachineMemory(MPI_Comm comm);

/// For programs that build meshes without solving on them (benchmarks of the mesh containers, e.g.
/// bench/distributed_mesh_bench): the size checks keep the index limits but no longer estimate the
/// memory of a run that will not happen. Not collective; call it before any mesh is built.
void skipRunMemoryCheck();

/// Throws InputError "<what>: <runSizeProblem>; <advice>" when a run of `size` will not fit, with the
/// figures agreed by agreeOnMachineMemory (this process's own view, one rank, when it was not called).
/// No collective call: ranks that check the same size reach the same answer.
void requireRunFits(const MeshSize& size, const std::string& what, const std::string& advice);

/// "1.5 GiB": binary units, three significant digits.
std::string formatBytes(double bytes);

/// "13000", or "2e9", "4.61e18" from a million up: counts as a user reads them.
std::string formatCount(double count);

}  // namespace contessa::mesh
