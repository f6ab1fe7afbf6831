#include <gtest/gtest.h>
#include <unistd.h>

#include <climits>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "MeshTestSupport.hpp"
#include "common/Error.hpp"
#include "mesh/Generators.hpp"
#include "mesh/MemoryEstimate.hpp"

using namespace contessa;
using namespace contessa::mesh;
using test_support::messageOf;
namespace fs = std::filesystem;

namespace {

MeshSize grid(double n0, double n1) { return MeshSize((n0 + 1) * (n1 + 1), n0 * n1, 2); }

constexpr double kKiB = 1024;
constexpr double kGiB = 1024.0 * 1024 * 1024;

}  // namespace

// The calibration runs (docs/user-guide.md): inputs/tube_bending.xml with the given elements through
// the thickness x around the arc, Method=Constant, 2 increments, peak resident memory from
// the run summary's VmHWM per rank (summed over the ranks for 2 ranks), re-measured 2026-11-23. The estimate must not be below what was
// measured, nor more than 30 % above it.
TEST(MemoryEstimate, CalibrationRunsOfTheTube) {
  struct Run {
    double nr, nt;
    int ranks;
    double measuredKiB;
  };
  for (const Run& run : {Run{13, 101, 1, 106080}, Run{13, 1000, 1, 188068}, Run{50, 1000, 1, 458316},
                         Run{300, 300, 1, 818244}, Run{100, 2000, 1, 1548800}, Run{50, 1000, 2, 307804 + 287252}}) {
    const double estimate = estimateRunMemory(grid(run.nr, run.nt)).onMachine(run.ranks, run.ranks);
    const double measured = run.measuredKiB * kKiB;
    EXPECT_GE(estimate, measured) << run.nr << " x " << run.nt << " on " << run.ranks;
    EXPECT_LE(estimate, 1.3 * measured) << run.nr << " x " << run.nt << " on " << run.ranks;
  }
}

TEST(MemoryEstimate, PartsAndScaling) {
  const RunMemoryEstimate e = estimateRunMemory(grid(100, 100));
  // 10201 nodes x (2 coordinates + 1 set entry) + 10000 elements x (1 id + 4 nodes), 8 bytes each.
  EXPECT_DOUBLE_EQ(e.mesh, 8 * (3 * 10201.0 + 5 * 10000.0));
  EXPECT_DOUBLE_EQ(e.distributed, 100 * 18 * 20402.0);
  EXPECT_NEAR(e.factor, 12 * 11 * 20402.0 * std::log2(20402.0), 1);
  // Ranks on one machine each load the libraries and hold the mesh; the matrix and factor are shared.
  EXPECT_DOUBLE_EQ(e.onMachine(2, 2) - e.onMachine(1, 1), e.perRank);
  EXPECT_DOUBLE_EQ(e.onMachine(1, 2), e.perRank + (e.distributed + e.factor) / 2);
  // 3D: 81 matrix entries per unknown, n^(4/3) factor.
  const MeshSize cube(1e6, 1e6, 3);
  const RunMemoryEstimate c = estimateRunMemory(cube);
  EXPECT_DOUBLE_EQ(c.distributed, 100 * 81 * 3e6);
  EXPECT_NEAR(c.factor / (12 * 11 * std::pow(3e6, 4.0 / 3.0)), 1, 1e-12);
}

TEST(MemoryEstimate, RefusesWhatDoesNotFit) {
  EXPECT_EQ(runSizeProblem(grid(13, 101), 22 * kGiB, 1, 1), "");
  EXPECT_EQ(runSizeProblem(grid(1e9, 2), 22 * kGiB, 1, 1),
            "2e9 elements need about " + formatBytes(estimateRunMemory(grid(1e9, 2)).onMachine(1, 1)) +
                " of memory for the run, 22 GiB are available");
  // Two ranks on the machine need the libraries and the mesh twice.
  const double one = estimateRunMemory(grid(300, 300)).onMachine(1, 1);
  EXPECT_EQ(runSizeProblem(grid(300, 300), one * 1.01, 1, 1), "");
  EXPECT_NE(runSizeProblem(grid(300, 300), one * 1.01, 2, 2).find("of memory for the run on 2 ranks of this machine"),
            std::string::npos);
  // Unknown memory (−1): only the index limit applies.
  EXPECT_EQ(runSizeProblem(grid(1e4, 1e4), -1, 1, 1), "");
  EXPECT_EQ(runSizeProblem(grid(1e5, 1e5), -1, 1, 1),
            "1e10 nodes make 2e10 unknowns, more than the 2147483647 Contessa's solvers can index (32-bit indices)");
  MeshSize entries = grid(1e3, 1e3);
  entries.elements = 6e8;  // 2.4e9 element-node entries on 1e6 nodes
  EXPECT_EQ(runSizeProblem(entries, -1, 1, 1),
            "6e8 elements make 2.4e9 element-node entries, more than the 2147483647 Contessa can index (32-bit "
            "indices)");
}

TEST(MemoryEstimate, Formats) {
  EXPECT_EQ(formatBytes(512), "512 bytes");
  EXPECT_EQ(formatBytes(1536), "1.5 KiB");
  EXPECT_EQ(formatBytes(22 * kGiB), "22 GiB");
  EXPECT_EQ(formatBytes(480.4 * kGiB), "480 GiB");
  EXPECT_EQ(formatBytes(3.5 * kGiB * 1024 * 1024), "3.5 PiB");
  EXPECT_EQ(formatBytes(75400 * kGiB * kGiB), "75400 EiB");
  EXPECT_EQ(formatCount(13000), "13000");
  EXPECT_EQ(formatCount(2e9), "2e9");
  EXPECT_EQ(formatCount(1e10), "1e10");
  EXPECT_EQ(formatCount(9.9999e9), "1e10");
  EXPECT_EQ(formatCount(4.6116860141e18), "4.61e18");
}

namespace {

// A fake /proc and /sys/fs/cgroup under a temporary directory.
class FakeSystem {
 public:
  FakeSystem() : root_(fs::temp_directory_path() / ("contessa_memory_" + std::to_string(getpid()) + "_" +
                                                    ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    fs::remove_all(root_);
    fs::create_directories(root_ / "proc" / "self");
    fs::create_directories(root_ / "cgroup");
  }
  ~FakeSystem() { fs::remove_all(root_); }
  void write(const std::string& relative, const std::string& text) const {
    fs::create_directories((root_ / relative).parent_path());
    std::ofstream(root_ / relative) << text;
  }
  std::optional<double> available() const {
    return availableMemory((root_ / "proc").string(), (root_ / "cgroup").string());
  }

 private:
  fs::path root_;
};

}  // namespace

TEST(AvailableMemory, MemAvailableAlone) {
  FakeSystem sys;
  EXPECT_FALSE(sys.available().has_value());
  sys.write("proc/meminfo", "MemTotal:       24683620 kB\nMemFree:  100 kB\nMemAvailable:   24267556 kB\n");
  EXPECT_DOUBLE_EQ(*sys.available(), 24267556.0 * 1024);
  sys.write("proc/self/cgroup", "0::/\n");  // v2 without a limit file
  EXPECT_DOUBLE_EQ(*sys.available(), 24267556.0 * 1024);
}

TEST(AvailableMemory, CgroupV2LimitWithoutReclaimableCache) {
  FakeSystem sys;
  sys.write("proc/meminfo", "MemAvailable: 24000000 kB\n");
  sys.write("proc/self/cgroup", "0::/jobs/run1\n");
  sys.write("cgroup/jobs/run1/memory.max", "4294967296\n");         // 4 GiB
  sys.write("cgroup/jobs/run1/memory.current", "2147483648\n");     // 2 GiB used
  sys.write("cgroup/jobs/run1/memory.stat", "anon 1\ninactive_file 1073741824\nactive_file 5\n");  // 1 GiB cache
  EXPECT_DOUBLE_EQ(*sys.available(), 3.0 * kGiB);
  sys.write("cgroup/jobs/run1/memory.max", "max\n");
  EXPECT_DOUBLE_EQ(*sys.available(), 24000000.0 * 1024);
}

TEST(AvailableMemory, CgroupV1LimitAndNamespacedRoot) {
  FakeSystem sys;
  sys.write("proc/meminfo", "MemAvailable: 24000000 kB\n");
  // The process' cgroup path does not exist below the mount (a container): the root's files count.
  sys.write("proc/self/cgroup", "5:cpu,cpuacct:/x\n4:memory:/docker/abc\n0::/\n");
  sys.write("cgroup/memory/memory.limit_in_bytes", "1073741824\n");
  sys.write("cgroup/memory/memory.usage_in_bytes", "536870912\n");
  sys.write("cgroup/memory/memory.stat", "cache 1\ntotal_inactive_file 268435456\n");
  EXPECT_DOUBLE_EQ(*sys.available(), 0.75 * kGiB);
  // v1's "unlimited" is about 2^63.
  sys.write("cgroup/memory/memory.limit_in_bytes", "9223372036854771712\n");
  EXPECT_DOUBLE_EQ(*sys.available(), 24000000.0 * 1024);
}

TEST(MemoryEstimate, GeneratorsRefuseBeforeAllocating) {
  // Far beyond any machine: refused with the parameters named, no std::bad_alloc, no overflow.
  AnnulusSectorSpec tube;
  tube.elementsThroughThickness = 1000000000;
  tube.elementsAroundArc = 2;
  const std::string message = messageOf([&] { generateAnnulusSector(tube); });
  EXPECT_EQ(message.rfind("Elements Through Thickness = 1000000000, Elements Around Arc = 2: 2e9 elements need about ", 0),
            0u)
      << message;
  EXPECT_NE(message.find(" are available; reduce Elements Through Thickness or Elements Around Arc"), std::string::npos)
      << message;
  RectangleSpec plate;
  plate.nx = plate.ny = INT_MAX;
  EXPECT_EQ(messageOf([&] { generateRectangle(plate); })
                .rfind("Elements X = 2147483647, Elements Y = 2147483647: 4.61e18 elements need about ", 0),
            0u);
}
