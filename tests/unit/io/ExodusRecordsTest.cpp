// What a results file holds besides the mesh and the fields: surface blocks (rigid surfaces: BAR2 in 2D,
// SHELL4 in 3D) with their own nodes and no element variables, QA and information records, and the flush after every step.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <stdexcept>
#include <string>

#include <exodusII.h>

#include "io/ExodusResults.hpp"
#include "io/ExodusWriter.hpp"
#include "io/OutputWriteError.hpp"
#include "mesh/Generators.hpp"

using namespace contessa;
using contessa::io::ExodusFields;
using contessa::io::ExodusRecords;
using contessa::io::ExodusResults;
using contessa::io::ExodusSurfaceBlock;
using contessa::io::ExodusWriter;

namespace {

std::string tempPath(const std::string& stem) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return ::testing::TempDir() + "contessa_" + info->name() + "_" + stem + "_" + std::to_string(getpid()) + ".exo";
}

}  // namespace

TEST(ExodusRecords, LongLinesAreSplitIntoEightyCharacterRecords) {
  const std::string line(200, 'a');
  const auto records = io::infoRecords({"short", "", line, std::string(80, 'b')});
  ASSERT_EQ(records.size(), 6u);
  EXPECT_EQ(records[0], "short");
  EXPECT_EQ(records[1], "");
  // 200 characters: 79 + "\", 79 + "\", the last 42.
  EXPECT_EQ(records[2], std::string(79, 'a') + "\\");
  EXPECT_EQ(records[3], std::string(79, 'a') + "\\");
  EXPECT_EQ(records[4], std::string(42, 'a'));
  EXPECT_EQ(records[5], std::string(80, 'b'));  // exactly 80 fits
  for (const auto& r : records) EXPECT_LE(r.size(), 80u);
  // Joined back, each line is whole again.
  std::string joined;
  for (int k = 2; k <= 4; ++k) joined += records[k].back() == '\\' ? records[k].substr(0, 79) : records[k];
  EXPECT_EQ(joined, line);
}

TEST(ExodusRecords, SurfaceBlocksRecordsAndGlobalsRoundTrip) {
  mesh::RectangleSpec spec;
  spec.nx = 2;
  spec.ny = 1;
  spec.blockName = "body";
  const mesh::Mesh mesh = mesh::generateRectangle(spec);  // 6 nodes, 2 elements
  const std::string path = tempPath("records");
  ExodusFields fields;
  fields.nodal = {"displ_x", "displ_y"};
  fields.element = {"von_mises"};
  fields.global = {"load_factor", "reaction_left_x", "contact_force_plate_y"};
  ExodusRecords records;
  records.title = "records test";
  records.qa.push_back({"contessa", "1.2.3 a-very-long-git-description-that-is-cut", "2024/01/02", "03:04:05"});
  records.info = {"first line", std::string(100, 'x')};
  const std::vector<ExodusSurfaceBlock> lines = {{"plate", {-1.0, 2.0, 0.0, 2.0, 3.0, 2.0}, 2, {0, 1, 1, 2}}};  // 3 points, 2 segments
  {
    ExodusWriter writer(path, mesh, fields, records, lines);
    EXPECT_EQ(writer.numNodes(), 9);
    for (int step = 0; step < 2; ++step) {
      std::vector<std::vector<double>> nodal(2, std::vector<double>(9, 0.0));
      for (int n = 0; n < 9; ++n) nodal[1][n] = -0.5 * step * (n >= 6 ? 1.0 : 0.1 * n);
      writer.writeStep(0.5 * step, nodal, {{10.0 + step, 20.0 + step}}, {0.5 * step, -3.0 * step, 7.0 * step});
    }
    // Every step is on disk when writeStep returns: the number of steps a reader finds is known
    // before the writer closes the file (checked across processes by tests/regression/output).
    EXPECT_EQ(writer.stepsWritten(), 2);
  }
  const ExodusResults results(path);
  EXPECT_EQ(results.numSteps(), 2);
  EXPECT_EQ(results.numNodes(), 9);
  EXPECT_EQ(results.blockNames(), (std::vector<std::string>{"body", "plate"}));
  EXPECT_EQ(results.blockTypes(), (std::vector<std::string>{"QUAD4", "BAR2"}));
  // The element variable lives on the mesh block only.
  EXPECT_EQ(results.element("von_mises", 1), (std::vector<double>{11.0, 21.0}));
  const auto uy = results.nodal("displ_y", 1);
  ASSERT_EQ(uy.size(), 9u);
  for (int n = 6; n < 9; ++n) EXPECT_EQ(uy[n], -0.5);
  EXPECT_EQ(results.global("reaction_left_x", 1), -3.0);
  EXPECT_EQ(results.global("contact_force_plate_y", 1), 7.0);
  const auto qa = results.qaRecords();
  ASSERT_EQ(qa.size(), 1u);
  EXPECT_EQ(qa[0][0], "contessa");
  EXPECT_EQ(qa[0][1], std::string("1.2.3 a-very-long-git-description-that-is-cut").substr(0, 32));
  EXPECT_EQ(qa[0][2], "2024/01/02");
  EXPECT_EQ(qa[0][3], "03:04:05");
  const auto info = results.infoRecords();
  ASSERT_EQ(info.size(), 3u);
  EXPECT_EQ(info[0], "first line");
  EXPECT_EQ(info[1], std::string(79, 'x') + "\\");
  EXPECT_EQ(info[2], std::string(21, 'x'));
  std::remove(path.c_str());
}

// 3D: a rigid surface of two quadrilaterals on six points is a SHELL4 block (ParaView draws surfaces, not
// outlines) whose connectivity is the facets' point indices after the mesh nodes, moving with its nodal
// displacements; the side sets and element variables of the mesh are untouched.
TEST(ExodusRecords, ShellBlockOfA3DRigidSurface) {
  mesh::BoxSpec spec;
  spec.nx = 2;
  spec.blockName = "body";
  const mesh::Mesh mesh = mesh::generateBox(spec);  // 12 nodes, 2 elements
  ASSERT_EQ(mesh.numNodes(), 12);
  const std::string path = tempPath("shell");
  ExodusFields fields;
  fields.nodal = {"displ_x", "displ_y", "displ_z"};
  fields.element = {"von_mises"};
  const std::vector<double> points = {0, 2, 0, 1, 2, 0, 2, 2, 0, 0, 2, 1, 1, 2, 1, 2, 2, 1};
  const std::vector<ExodusSurfaceBlock> surfaces = {{"plate", points, 4, {0, 3, 4, 1, 1, 4, 5, 2}}};
  {
    ExodusWriter writer(path, mesh, fields, {}, surfaces);
    EXPECT_EQ(writer.numNodes(), 18);
    std::vector<std::vector<double>> nodal(3, std::vector<double>(18, 0.0));
    for (int n = 12; n < 18; ++n) nodal[1][n] = -0.25;
    writer.writeStep(1.0, nodal, {{1.0, 2.0}}, {});
  }
  const ExodusResults results(path);
  EXPECT_EQ(results.blockNames(), (std::vector<std::string>{"body", "plate"}));
  EXPECT_EQ(results.blockTypes(), (std::vector<std::string>{"HEX8", "SHELL4"}));
  EXPECT_EQ(results.element("von_mises", 0), (std::vector<double>{1.0, 2.0}));
  const auto uy = results.nodal("displ_y", 0);
  ASSERT_EQ(uy.size(), 18u);
  for (int n = 12; n < 18; ++n) EXPECT_EQ(uy[n], -0.25);
  // The connectivity, 1-based Exodus node numbers: the facets' points after the 12 mesh nodes.
  int cpu = 8, io = 8;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ | EX_ALL_INT64_API, &cpu, &io, &version);
  ASSERT_GE(id, 0);
  std::vector<int64_t> connectivity(8);
  EXPECT_EQ(ex_get_conn(id, EX_ELEM_BLOCK, 2, connectivity.data(), nullptr, nullptr), 0);
  EXPECT_EQ(connectivity, (std::vector<int64_t>{13, 16, 17, 14, 14, 17, 18, 15}));
  std::vector<double> x(18), y(18), z(18);
  EXPECT_EQ(ex_get_coord(id, x.data(), y.data(), z.data()), 0);
  EXPECT_EQ(x[17], 2.0);
  EXPECT_EQ(y[17], 2.0);
  EXPECT_EQ(z[17], 1.0);
  ex_close(id);
  std::remove(path.c_str());
}

// A surface block whose connectivity names a point it does not have is refused, naming the block.
TEST(ExodusWriter, SurfaceBlockPointOutOfRangeIsRefused) {
  const mesh::Mesh mesh = mesh::generateRectangle({});
  const std::string path = tempPath("range");
  const std::vector<ExodusSurfaceBlock> lines = {{"plate", {0.0, 2.0, 1.0, 2.0}, 2, {0, 2}}};
  try {
    ExodusWriter writer(path, mesh, {}, {}, lines);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "surface block 'plate': point 2 out of range (2 points)");
  }
  std::remove(path.c_str());
}

TEST(ExodusWriter, PathThatIsADirectoryNamesTheSystemReason) {
  const mesh::Mesh mesh = mesh::generateRectangle({});
  const std::string path = ::testing::TempDir();  // a directory
  try {
    ExodusWriter writer(path, mesh, {});
    FAIL() << "no exception";
  } catch (const io::OutputWriteError& e) {
    EXPECT_EQ(std::string(e.what()), "cannot create " + path + ": Is a directory");
    EXPECT_EQ(e.reason(), "Is a directory");
  }
}

// A piece of a decomposed set records the whole set's node set and side set sizes (Nemesis' global set
// records, which ex_put_init_global defines but leaves unwritten).
TEST(ExodusWriter, DecomposedPieceRecordsTheGlobalSetSizes) {
  mesh::RectangleSpec spec;
  spec.nx = 2;
  spec.ny = 1;
  const mesh::Mesh mesh = mesh::generateRectangle(spec);  // node sets and side sets left, right, bottom, top, ...
  io::ExodusDecomposition d;
  for (mesh::GlobalIndex n = 0; n < mesh.numNodes(); ++n) d.globalNodes.push_back(n);
  for (mesh::GlobalIndex e = 0; e < mesh.numElements(); ++e) d.globalElements.push_back(e);
  d.sharedWith.resize(static_cast<std::size_t>(mesh.numNodes()));
  d.globalNumNodes = 100;
  d.globalNumElements = 50;
  d.globalBlockSizes = {50};
  for (const auto& set : mesh.nodeSets) d.globalNodeSetSizes.push_back(static_cast<mesh::GlobalIndex>(set.nodes.size()) + 10);
  for (const auto& set : mesh.sideSets) d.globalSideSetSizes.push_back(static_cast<mesh::GlobalIndex>(set.elements.size()) + 5);
  const std::string path = tempPath("piece");
  { ExodusWriter writer(path, mesh, {}, {}, {}, &d); }
  int cpu = 8, io = 8;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ | EX_ALL_INT64_API, &cpu, &io, &version);
  ASSERT_GE(id, 0);
  const std::size_t nodeSets = mesh.nodeSets.size(), sideSets = mesh.sideSets.size();
  ASSERT_GT(nodeSets, 0u);
  ASSERT_GT(sideSets, 0u);
  std::vector<int64_t> ids(nodeSets), counts(nodeSets), factors(nodeSets);
  ASSERT_GE(ex_get_ns_param_global(id, ids.data(), counts.data(), factors.data()), 0);
  for (std::size_t s = 0; s < nodeSets; ++s) {
    EXPECT_EQ(ids[s], static_cast<int64_t>(s) + 1);
    EXPECT_EQ(counts[s], d.globalNodeSetSizes[s]);
    EXPECT_EQ(factors[s], 0);
  }
  ids.assign(sideSets, -1);
  counts.assign(sideSets, -1);
  factors.assign(sideSets, -1);
  ASSERT_GE(ex_get_ss_param_global(id, ids.data(), counts.data(), factors.data()), 0);
  for (std::size_t s = 0; s < sideSets; ++s) {
    EXPECT_EQ(ids[s], static_cast<int64_t>(s) + 1);
    EXPECT_EQ(counts[s], d.globalSideSetSizes[s]);
    EXPECT_EQ(factors[s], 0);
  }
  ex_close(id);
  std::remove(path.c_str());
}
