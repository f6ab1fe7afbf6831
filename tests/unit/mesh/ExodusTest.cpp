#include <gtest/gtest.h>

#include <exodusII.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "MeshTestSupport.hpp"
#include "common/Error.hpp"
#include "io/ExodusResults.hpp"
#include "io/ExodusWriter.hpp"
#include "mesh/ExodusMeshReader.hpp"
#include "mesh/Generators.hpp"
#include "mesh/ShapeFunctions.hpp"

using namespace contessa;
using namespace contessa::mesh;
using test_support::messageOf;
using test_support::expectSameMesh;
using test_support::Coordinates;
using contessa::io::ExodusFields;
using contessa::io::ExodusResults;
using contessa::io::ExodusWriter;

namespace {

// One file per test and process: ctest may run the tests of this executable in parallel.
std::string tempPath(const std::string& stem) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return ::testing::TempDir() + "contessa_" + info->name() + "_" + stem + "_" + std::to_string(getpid()) + ".exo";
}

// Distinct, step-dependent values so that a mix-up of steps, variables or entities shows.
double value(int step, int variable, GlobalIndex entity) { return 1000.0 * step + 100.0 * variable + 0.001 * entity + 0.1; }

}  // namespace

TEST(ExodusRoundTrip, AnnulusSectorMeshAndResults) {
  AnnulusSectorSpec spec = test_support::annulusSpec(3, 8, 50, 5, 10, 100);
  spec.blockName = "ring";
  const Mesh mesh = generateAnnulusSector(spec);
  const std::string path = tempPath("annulus");

  ExodusFields fields;
  fields.nodal = {"displ_x", "displ_y", "contact_pressure"};
  fields.element = {"stress_xx", "von_mises"};
  fields.global = {"load_factor", "step_size"};
  const double times[3] = {0.25, 0.5, 1.0};
  {
    ExodusWriter writer(path, mesh, fields);
    EXPECT_EQ(writer.path(), path);
    for (int step = 0; step < 3; ++step) {
      std::vector<std::vector<double>> nodal(3, std::vector<double>(mesh.numNodes()));
      std::vector<std::vector<double>> element(2, std::vector<double>(mesh.numElements()));
      for (int v = 0; v < 3; ++v)
        for (GlobalIndex n = 0; n < mesh.numNodes(); ++n) nodal[v][n] = value(step, v, n);
      for (int v = 0; v < 2; ++v)
        for (GlobalIndex e = 0; e < mesh.numElements(); ++e) element[v][e] = -value(step, v, e);
      writer.writeStep(times[step], nodal, element, {times[step], 0.25 * (step + 1)});
      EXPECT_EQ(writer.stepsWritten(), step + 1);
    }
  }

  // netCDF-4 files are HDF5 files: they start with the HDF5 signature.
  std::ifstream raw(path, std::ios::binary);
  char signature[4] = {};
  raw.read(signature, 4);
  EXPECT_EQ(std::string(signature, 4), "\x89HDF");

  expectSameMesh(readExodusMesh(path), mesh, Coordinates::WithinFourUlps);

  const ExodusResults results(path);
  EXPECT_EQ(results.numSteps(), 3);
  EXPECT_EQ(results.times(), (std::vector<double>{0.25, 0.5, 1.0}));
  EXPECT_EQ(results.nodalNames(), fields.nodal);
  EXPECT_EQ(results.elementNames(), fields.element);
  EXPECT_EQ(results.globalNames(), fields.global);
  for (int step = 0; step < 3; ++step) {
    for (int v = 0; v < 3; ++v) {
      const auto values = results.nodal(fields.nodal[v], step);
      ASSERT_EQ(values.size(), static_cast<size_t>(mesh.numNodes()));
      for (GlobalIndex n = 0; n < mesh.numNodes(); ++n) EXPECT_EQ(values[n], value(step, v, n));
    }
    for (int v = 0; v < 2; ++v) {
      const auto values = results.element(fields.element[v], step);
      ASSERT_EQ(values.size(), static_cast<size_t>(mesh.numElements()));
      for (GlobalIndex e = 0; e < mesh.numElements(); ++e) EXPECT_EQ(values[e], -value(step, v, e));
    }
    EXPECT_EQ(results.global("load_factor", step), times[step]);
    EXPECT_EQ(results.global("step_size", step), 0.25 * (step + 1));
  }
  EXPECT_NE(messageOf([&] { results.nodal("displ_z", 0); })
                .find("nodal variable 'displ_z' does not exist (known: displ_x, displ_y, contact_pressure)"),
            std::string::npos);
  EXPECT_THROW(results.element("stress_yy", 0), InputError);
  EXPECT_THROW(results.global("time", 0), InputError);
  EXPECT_THROW(results.nodal("displ_x", 3), InputError);
  std::remove(path.c_str());
}

TEST(ExodusRoundTrip, TwoBlocksScatteredIdsLongNamesAndHexes) {
  // Two unit hexes side by side; the element ids run against the block order, so the writer
  // must map side sets and element values through Exodus' block-order numbering.
  Mesh mesh;
  mesh.dimension = 3;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) mesh.coordinates.insert(mesh.coordinates.end(), {double(i), double(j), double(k)});
  auto node = [](int i, int j, int k) -> GlobalIndex { return k * 6 + j * 3 + i; };
  auto hex = [&](int i) {
    return std::vector<GlobalIndex>{node(i, 0, 0), node(i + 1, 0, 0), node(i + 1, 1, 0), node(i, 1, 0),
                                    node(i, 0, 1), node(i + 1, 0, 1), node(i + 1, 1, 1), node(i, 1, 1)};
  };
  const std::string longName = "a_block_name_that_is_longer_than_thirty_two_characters";
  mesh.blocks.push_back({longName, CellType::Hex8, {1}, hex(0)});
  mesh.blocks.push_back({"right", CellType::Hex8, {0}, hex(1)});
  mesh.nodeSets.push_back({"x_max", {node(2, 0, 0), node(2, 0, 1), node(2, 1, 0), node(2, 1, 1)}});
  std::sort(mesh.nodeSets[0].nodes.begin(), mesh.nodeSets[0].nodes.end());
  mesh.sideSets.push_back({"ends", {0, 1}, {1, 3}});
  ASSERT_NO_THROW(mesh.validate("test"));

  const std::string path = tempPath("hex");
  ExodusFields fields;
  fields.element = {"an_element_variable_with_a_very_long_name_indeed"};
  {
    ExodusWriter writer(path, mesh, fields, "two hexes");
    writer.writeStep(1.0, {}, {{10.0, 20.0}}, {});  // element 0 = 10 (block "right"), element 1 = 20
    EXPECT_THROW(writer.writeStep(2.0, {}, {{1.0}}, {}), std::runtime_error);
    EXPECT_THROW(writer.writeStep(2.0, {{1.0}}, {{1.0, 2.0}}, {}), std::runtime_error);
  }

  const Mesh back = readExodusMesh(path);
  EXPECT_EQ(back.dimension, 3);
  EXPECT_EQ(back.coordinates, mesh.coordinates);
  ASSERT_EQ(back.blocks.size(), 2u);
  EXPECT_EQ(back.blocks[0].name, longName);
  EXPECT_EQ(back.blocks[0].cellType, CellType::Hex8);
  // The reader numbers elements in file (block) order.
  EXPECT_EQ(back.blocks[0].elements, (std::vector<GlobalIndex>{0}));
  EXPECT_EQ(back.blocks[1].elements, (std::vector<GlobalIndex>{1}));
  EXPECT_EQ(back.blocks[0].connectivity, hex(0));
  EXPECT_EQ(back.blocks[1].connectivity, hex(1));
  EXPECT_EQ(back.nodeSet("x_max").nodes, mesh.nodeSets[0].nodes);
  // Element 0 (block "right", file element 1) side 1 and element 1 (first block, file element 0) side 3.
  EXPECT_EQ(back.sideSet("ends").elements, (std::vector<GlobalIndex>{1, 0}));
  EXPECT_EQ(back.sideSet("ends").sides, (std::vector<int>{1, 3}));

  const ExodusResults results(path);
  EXPECT_EQ(results.numSteps(), 1);
  EXPECT_EQ(results.element(fields.element[0], 0), (std::vector<double>{20.0, 10.0}));
  std::remove(path.c_str());
}

TEST(ExodusMeshReader, MissingFileNamesThePath) {
  const std::string path = "/nonexistent/dir/mesh.exo";
  EXPECT_EQ(messageOf([&] { readExodusMesh(path); }), path + ": not a readable Exodus file (it does not exist)");
  EXPECT_EQ(messageOf([&] { ExodusResults results(path); }), path + ": cannot open Exodus file");
}

TEST(ExodusMeshReader, NotAnExodusFile) {
  const std::string path = tempPath("text");
  std::ofstream(path) << "not a mesh\n";
  EXPECT_EQ(messageOf([&] { readExodusMesh(path); }),
            path + ": not a readable Exodus file (it is neither netCDF nor HDF5: Exodus II files start with "
                   "'CDF' or '\\x89HDF')");
  std::remove(path.c_str());
}

namespace {

// Writes a classic-format file directly, as other tools would: unnamed entities, arbitrary ids,
// unordered node sets, any element type.
void writeRawFile(const std::string& path, const char* elementType, int nodesPerElement) {
  int cpu = 8, io = 8;
  const int id = ex_create(path.c_str(), EX_CLOBBER, &cpu, &io);
  ASSERT_GE(id, 0);
  ASSERT_EQ(ex_put_init(id, "raw", 2, 4, 1, 1, 1, 1), 0);
  const double x[4] = {0, 1, 1, 0}, y[4] = {0, 0, 1, 1};
  ASSERT_EQ(ex_put_coord(id, x, y, nullptr), 0);
  ASSERT_EQ(ex_put_block(id, EX_ELEM_BLOCK, 10, elementType, 1, nodesPerElement, 0, 0, 0), 0);
  const int conn[8] = {1, 2, 3, 4, 1, 2, 3, 4};  // room for the 8-node case
  ASSERT_EQ(ex_put_conn(id, EX_ELEM_BLOCK, 10, conn, nullptr, nullptr), 0);
  ASSERT_EQ(ex_put_set_param(id, EX_NODE_SET, 7, 3, 0), 0);
  const int nodes[3] = {4, 1, 4};
  ASSERT_EQ(ex_put_set(id, EX_NODE_SET, 7, nodes, nullptr), 0);
  ASSERT_EQ(ex_put_set_param(id, EX_SIDE_SET, 3, 1, 0), 0);
  const int elements[1] = {1}, sides[1] = {4};
  ASSERT_EQ(ex_put_set(id, EX_SIDE_SET, 3, elements, sides), 0);
  ASSERT_EQ(ex_close(id), 0);
}

}  // namespace

TEST(ExodusMeshReader, UnnamedEntitiesGetDefaultNames) {
  const std::string path = tempPath("raw");
  writeRawFile(path, "quad", 4);
  const Mesh mesh = readExodusMesh(path);
  ASSERT_EQ(mesh.blocks.size(), 1u);
  EXPECT_EQ(mesh.blocks[0].name, "block_10");
  EXPECT_EQ(mesh.blocks[0].cellType, CellType::Quad4);
  EXPECT_EQ(mesh.blocks[0].connectivity, (std::vector<GlobalIndex>{0, 1, 2, 3}));
  EXPECT_EQ(mesh.nodeSet("nodeset_7").nodes, (std::vector<GlobalIndex>{0, 3}));  // sorted, unique
  EXPECT_EQ(mesh.sideSet("sideset_3").elements, (std::vector<GlobalIndex>{0}));
  EXPECT_EQ(mesh.sideSet("sideset_3").sides, (std::vector<int>{3}));
  EXPECT_EQ(messageOf([&] { mesh.nodeSet("top"); }), "node set 'top' does not exist in the mesh (known: nodeset_7)");
  EXPECT_EQ(messageOf([&] { mesh.sideSet("top"); }), "side set 'top' does not exist in the mesh (known: sideset_3)");
  std::remove(path.c_str());
}

TEST(ExodusMeshReader, RejectsUnsupportedElementTypes) {
  const std::string path = tempPath("tri");
  writeRawFile(path, "TRI4", 4);
  EXPECT_EQ(messageOf([&] { readExodusMesh(path); }),
            path + ": element block 'block_10' has unsupported type 'TRI4' with 4 nodes per element in a 2D mesh "
                   "(supported: TRI3, TRI6, QUAD4, QUAD8, QUAD9)");
  writeRawFile(path, "SHELL4", 4);
  EXPECT_EQ(messageOf([&] { readExodusMesh(path); }),
            path + ": element block 'block_10' has unsupported type 'SHELL4' with 4 nodes per element in a 2D mesh "
                   "(supported: TRI3, TRI6, QUAD4, QUAD8, QUAD9)");
  writeRawFile(path, "QUAD5", 5);
  EXPECT_EQ(messageOf([&] { readExodusMesh(path); }),
            path + ": element block 'block_10' has unsupported type 'QUAD5' with 5 nodes per element in a 2D mesh "
                   "(supported: TRI3, TRI6, QUAD4, QUAD8, QUAD9)");
  std::remove(path.c_str());
}

// The topology names other tools write: any case, with or without the node count, long forms.
TEST(ExodusMeshReader, TopologyNamesOfCommonTools) {
  struct Case {
    const char* topology;
    int nodes;
    CellType type;
  };
  const Case cases[] = {{"TETRA10", 10, CellType::Tet10}, {"tetra10", 10, CellType::Tet10}, {"TETRA", 4, CellType::Tet4},
                        {"tet4", 4, CellType::Tet4},      {"HEX20", 20, CellType::Hex20},  {"hex", 27, CellType::Hex27},
                        {"WEDGE6", 6, CellType::Wedge6},  {"wedge15", 15, CellType::Wedge15}, {"HEX8", 8, CellType::Hex8}};
  for (const Case& c : cases) {
    // One cell, the reference cell of its type, its nodes in order; its side 1 in a side set.
    const std::string path = tempPath("topology");
    int cpu = 8, io = 8;
    const int id = ex_create(path.c_str(), EX_CLOBBER, &cpu, &io);
    ASSERT_GE(id, 0);
    ASSERT_EQ(ex_put_init(id, "tools", 3, c.nodes, 1, 1, 0, 1), 0);
    std::vector<double> x, y, z;
    for (int a = 0; a < c.nodes; ++a) {
      const auto p = referenceNode(c.type, a);
      x.push_back(p[0]);
      y.push_back(p[1]);
      z.push_back(p[2]);
    }
    ASSERT_EQ(ex_put_coord(id, x.data(), y.data(), z.data()), 0);
    ASSERT_EQ(ex_put_block(id, EX_ELEM_BLOCK, 1, c.topology, 1, c.nodes, 0, 0, 0), 0);
    std::vector<int> conn;
    for (int a = 1; a <= c.nodes; ++a) conn.push_back(a);
    ASSERT_EQ(ex_put_conn(id, EX_ELEM_BLOCK, 1, conn.data(), nullptr, nullptr), 0);
    ASSERT_EQ(ex_put_set_param(id, EX_SIDE_SET, 1, 1, 0), 0);
    const int elements[1] = {1}, sides[1] = {1};
    ASSERT_EQ(ex_put_set(id, EX_SIDE_SET, 1, elements, sides), 0);
    ASSERT_EQ(ex_close(id), 0);
    const Mesh mesh = readExodusMesh(path);
    ASSERT_EQ(mesh.blocks.size(), 1u);
    EXPECT_EQ(mesh.blocks[0].cellType, c.type) << c.topology;
    EXPECT_EQ(mesh.sideSets[0].sides, (std::vector<int>{0})) << c.topology;
    std::remove(path.c_str());
  }
}

TEST(ExodusWriter, UnwritablePathThrowsNamingIt) {
  const Mesh mesh = generateRectangle({});
  const std::string path = "/nonexistent/dir/out.exo";
  try {
    ExodusWriter writer(path, mesh, {});
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

namespace {

// Copies the first `bytes` bytes of `from` to `to`: a file cut short by a full disk or a broken copy.
void truncateCopy(const std::string& from, const std::string& to, std::uintmax_t bytes) {
  std::ifstream in(from, std::ios::binary);
  std::string data(bytes, '\0');
  in.read(data.data(), static_cast<std::streamsize>(bytes));
  std::ofstream(to, std::ios::binary).write(data.data(), in.gcount());
}

// The reader's message for `path`, asserting that nothing reached stderr (the Exodus and netCDF
// libraries print their own diagnostics unless kept from it).
std::string silentMessage(const std::string& path) {
  ::testing::internal::CaptureStderr();
  const std::string message = messageOf([&] { readExodusMesh(path); });
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << path;
  return message;
}

}  // namespace

TEST(ExodusMeshReader, DamagedFilesSayWhyInOneLine) {
  namespace fs = std::filesystem;
  const std::string good = tempPath("good");
  { ExodusWriter writer(good, generateRectangle({0, 0, 2, 1, 4, 2, "block_1"}), {}); }
  const auto size = fs::file_size(good);
  const std::string prefix = ": not a readable Exodus file (";

  const std::string empty = tempPath("empty");
  std::ofstream(empty).close();
  EXPECT_EQ(silentMessage(empty), empty + prefix + "it is empty)");

  const std::string directory = tempPath("directory");
  fs::create_directories(directory);
  EXPECT_EQ(silentMessage(directory), directory + prefix + "it is a directory)");

  const std::string random = tempPath("random");
  std::ofstream(random, std::ios::binary) << std::string("\x13\x37\xbe\xef\x00\x01 random bytes", 19);
  EXPECT_EQ(silentMessage(random),
            random + prefix + "it is neither netCDF nor HDF5: Exodus II files start with 'CDF' or '\\x89HDF')");

  // netCDF-4 (HDF5) cut in half: ex_open itself would print "does not support netcdf-4" here.
  const std::string half = tempPath("half");
  truncateCopy(good, half, size / 2);
  EXPECT_EQ(silentMessage(half), half + prefix +
                                     "it is an HDF5 file that netCDF cannot open, probably truncated or damaged: "
                                     "NetCDF: HDF error)");

  // A netCDF file of another kind.
  const std::string other = tempPath("other");
  int ncid = -1, dim = -1;
  ASSERT_EQ(nc_create(other.c_str(), NC_CLOBBER | NC_NETCDF4, &ncid), NC_NOERR);
  ASSERT_EQ(nc_def_dim(ncid, "time", 3, &dim), NC_NOERR);
  ASSERT_EQ(nc_close(ncid), NC_NOERR);
  EXPECT_EQ(silentMessage(other), other + prefix + "it is a netCDF file without Exodus' 'num_dim' dimension)");

  // Classic format (what most mesh generators write) cut short: netCDF would read zeros silently.
  const std::string classic = tempPath("classic"), classicCut = tempPath("classic_cut");
  writeRawFile(classic, "quad", 4);
  std::ifstream head(classic, std::ios::binary);
  char signature[3] = {};
  head.read(signature, 3);
  ASSERT_EQ(std::string(signature, 3), "CDF");
  EXPECT_NO_THROW(readExodusMesh(classic));
  truncateCopy(classic, classicCut, fs::file_size(classic) - 40);
  const std::string cut = silentMessage(classicCut);
  EXPECT_EQ(cut.rfind(classicCut + prefix + "it is truncated: " + std::to_string(fs::file_size(classic) - 40) +
                          " bytes, but its header describes ",
                      0),
            0u)
      << cut;

  for (const auto& path : {good, empty, random, half, other, classic, classicCut}) std::remove(path.c_str());
  fs::remove_all(directory);
}
