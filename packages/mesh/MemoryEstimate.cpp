#include "mesh/MemoryEstimate.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "common/Error.hpp"

namespace contessa::mesh {

namespace {

// Calibration (docs/user-guide.md): peak resident memory of the tube deck on 1 and 2 ranks, 40 to
// 200 000 elements, measured with /usr/bin/time -v.
constexpr double kMiB = 1024.0 * 1024.0;
constexpr double kLibraryBytesPerRank = 96 * kMiB;  // Trilinos, MPI, MUMPS loaded: an 8-element run peaks at 94 MiB
constexpr double kBytesPerMatrixEntry = 100;        // measured 95-100 beside the factor
constexpr double kFactorEntriesCoefficient = 11;    // MUMPS' INFOG(9): 7-11 n log2 n in 2D
constexpr double kBytesPerFactorEntry = 12;         // a double, plus MUMPS' integer and work arrays

// The root of an absent or unlimited cgroup limit: v1 reports "unlimited" as about 2^63.
constexpr double kUnlimited = 1e18;

std::optional<double> readNumber(const std::string& path) {
  std::ifstream in(path);
  std::string text;
  if (!(in >> text) || text == "max") return std::nullopt;
  try {
    return std::stod(text);
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// The value of `key` in a "key value" file (memory.stat, /proc/meminfo with its "kB" unit).
std::optional<double> readKey(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string name;
    double value = 0;
    if (!(fields >> name >> value)) continue;
    if (name == key || name == key + ":") {
      std::string unit;
      fields >> unit;
      return unit == "kB" ? value * 1024 : value;
    }
  }
  return std::nullopt;
}

// Room left under a cgroup limit, from its directory: the v2 or v1 file names.
std::optional<double> cgroupRoom(const std::string& dir, bool v2) {
  const auto limit = readNumber(dir + (v2 ? "/memory.max" : "/memory.limit_in_bytes"));
  if (!limit || *limit >= kUnlimited) return std::nullopt;
  const double usage = readNumber(dir + (v2 ? "/memory.current" : "/memory.usage_in_bytes")).value_or(0);
  const double inactive = readKey(dir + "/memory.stat", v2 ? "inactive_file" : "total_inactive_file").value_or(0);
  return std::max(0.0, *limit - std::max(0.0, usage - inactive));
}

// The cgroup of this process: "0::/path" (v2) or "N:...memory...:/path" (v1). Inside a container
// the path may not exist under cgroupRoot (its own cgroup is mounted as the root): try the root too.
std::optional<double> cgroupAvailable(const std::string& procRoot, const std::string& cgroupRoot) {
  std::ifstream in(procRoot + "/self/cgroup");
  std::string line;
  std::optional<double> room;
  while (std::getline(in, line)) {
    const auto first = line.find(':'), second = line.find(':', first + 1);
    if (first == std::string::npos || second == std::string::npos) continue;
    const std::string controllers = line.substr(first + 1, second - first - 1);
    const std::string path = line.substr(second + 1);
    bool v1Memory = false;
    std::istringstream list(controllers);
    for (std::string c; std::getline(list, c, ',');) v1Memory = v1Memory || c == "memory";
    const bool v2 = line.compare(0, first, "0") == 0 && controllers.empty();
    if (!v2 && !v1Memory) continue;
    const std::string base = v2 ? cgroupRoot : cgroupRoot + "/memory";
    auto here = cgroupRoom(base + path, v2);
    if (!here) here = cgroupRoom(base, v2);
    if (here) room = room ? std::min(*room, *here) : *here;
  }
  return room;
}

std::string withRanks(int ranksOnMachine) {
  return ranksOnMachine > 1 ? " on " + std::to_string(ranksOnMachine) + " ranks of this machine" : "";
}

}  // namespace

double RunMemoryEstimate::onMachine(int ranksOnMachine, int ranks) const {
  const double share = static_cast<double>(ranksOnMachine) / std::max(1, ranks);
  return ranksOnMachine * perRank + share * (distributed + factor);
}

RunMemoryEstimate estimateRunMemory(const MeshSize& size) {
  const double d = size.dimension;
  RunMemoryEstimate e;
  // Coordinates, element ids and connectivity (8-byte ids), and node sets (the generators' "all"
  // holds every node).
  e.mesh = 8 * d * size.nodes + 8 * (1.0 + size.nodesPerElement) * size.elements + 8 * size.nodes;
  e.perRank = kLibraryBytesPerRank + 2 * e.mesh;
  const double unknowns = d * size.nodes;
  const double entriesPerRow = d * std::pow(3.0, d);
  e.distributed = kBytesPerMatrixEntry * entriesPerRow * unknowns;
  // Nested dissection: separators of n^(1/2) unknowns in 2D give n log n factor entries, separators
  // of n^(2/3) in 3D give n^(4/3).
  const double n = std::max(unknowns, 2.0);
  const double factorEntries =
      kFactorEntriesCoefficient * (size.dimension == 2 ? n * std::log2(n) : std::pow(n, 4.0 / 3.0));
  e.factor = kBytesPerFactorEntry * factorEntries;
  return e;
}

std::string runSizeProblem(const MeshSize& size, double availableBytes, int ranksOnMachine, int ranks) {
  if (availableBytes >= 0) {
    const double need = estimateRunMemory(size).onMachine(ranksOnMachine, ranks);
    if (need > availableBytes)
      return formatCount(size.elements) + " elements need about " + formatBytes(need) + " of memory for the run" +
             withRanks(ranksOnMachine) + ", " + formatBytes(availableBytes) + " are available";
  }
  const double unknowns = size.dimension * size.nodes;
  if (unknowns > kMaxIndex)
    return formatCount(size.nodes) + " nodes make " + formatCount(unknowns) +
           " unknowns, more than the 2147483647 Contessa's solvers can index (32-bit indices)";
  const double entries = size.nodesPerElement * size.elements;
  if (entries > kMaxIndex)
    return formatCount(size.elements) + " elements make " + formatCount(entries) +
           " element-node entries, more than the 2147483647 Contessa can index (32-bit indices)";
  return "";
}

std::optional<double> availableMemory(const std::string& procRoot, const std::string& cgroupRoot) {
  const auto meminfo = readKey(procRoot + "/meminfo", "MemAvailable");
  const auto cgroup = cgroupAvailable(procRoot, cgroupRoot);
  if (meminfo && cgroup) return std::min(*meminfo, *cgroup);
  return meminfo ? meminfo : cgroup;
}

namespace {
// The machine facts every rank's size check uses, agreed once by agreeOnMachineMemory. Until then
// (unit tests, tools without MPI) each process uses its own view: one rank, its own memory.
struct MachineMemory {
  bool agreed = false;
  double available = -1;
  int ranksOnMachine = 1;
  int ranks = 1;
};
MachineMemory& machineMemory() {
  static MachineMemory memory;
  return memory;
}
}  // namespace

void agreeOnMachineMemory(MPI_Comm comm) {
  MachineMemory& memory = machineMemory();
  memory.available = availableMemory().value_or(-1);
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  if (initialised && !finalised) {
    MPI_Comm_size(comm, &memory.ranks);
    MPI_Comm machine;
    MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &machine);
    MPI_Comm_size(machine, &memory.ranksOnMachine);
    MPI_Comm_free(&machine);
    // One answer for all ranks: the most crowded machine and the least memory decide. An unknown
    // amount (−1) anywhere switches the memory check off everywhere.
    const double unknown = memory.available < 0 ? 1 : 0;
    double flags[2] = {memory.available < 0 ? std::numeric_limits<double>::infinity() : memory.available, unknown};
    double agreed[2];
    MPI_Allreduce(&flags[0], &agreed[0], 1, MPI_DOUBLE, MPI_MIN, comm);
    MPI_Allreduce(&flags[1], &agreed[1], 1, MPI_DOUBLE, MPI_MAX, comm);
    memory.available = agreed[1] > 0 ? -1 : agreed[0];
    MPI_Allreduce(MPI_IN_PLACE, &memory.ranksOnMachine, 1, MPI_INT, MPI_MAX, comm);
  }
  memory.agreed = true;
}

void skipRunMemoryCheck() {
  MachineMemory& memory = machineMemory();
  memory.available = -1;  // unknown: runSizeProblem checks the index limits only
  memory.agreed = true;
}

void requireRunFits(const MeshSize& size, const std::string& what, const std::string& advice) {
  const MachineMemory& agreed = machineMemory();
  const double available = agreed.agreed ? agreed.available : availableMemory().value_or(-1);
  const std::string problem = runSizeProblem(size, available, agreed.ranksOnMachine, agreed.ranks);
  requireInput(problem.empty(), what + ": " + problem + "; " + advice);
}

std::string formatBytes(double bytes) {
  const char* units[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int unit = 0;
  while (bytes >= 1024 && unit < 6) {
    bytes /= 1024;
    ++unit;
  }
  char text[48];
  if (unit == 6 && bytes >= 1000) return formatCount(std::round(bytes)) + " " + units[unit];  // no larger unit
  if (unit == 0)
    std::snprintf(text, sizeof text, "%.0f bytes", bytes);
  else
    std::snprintf(text, sizeof text, "%.3g %s", bytes, units[unit]);
  return text;
}

std::string formatCount(double count) {
  char text[48];
  if (count < 1e6) {
    std::snprintf(text, sizeof text, "%.0f", count);
    return text;
  }
  int exponent = static_cast<int>(std::floor(std::log10(count)));
  double mantissa = count / std::pow(10.0, exponent);
  if (mantissa >= 9.995) {  // rounds to 10: 9.999e9 is 1e10 (and log10 may land just below an integer)
    mantissa /= 10;
    ++exponent;
  }
  std::snprintf(text, sizeof text, "%.3g", mantissa);
  return std::string(text) + "e" + std::to_string(exponent);
}

}  // namespace contessa::mesh
