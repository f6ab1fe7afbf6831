// Reading Gmsh meshes (readGmshMesh, and the "Gmsh File" / "Mesh File" types of MeshFactory): the
// committed Gmsh-made mesh gmsh/two_blocks.msh (from two_blocks.geo), small hand-written MSH 2.2
// files for 2D meshes and for what must be refused, and the Exodus round trip of 3D meshes with
// their side sets and node sets.
#include <gtest/gtest.h>

#include <exodusII.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>

#include "MeshTestSupport.hpp"
#include "common/Error.hpp"
#include "io/ExodusWriter.hpp"
#include "mesh/CellGeometry.hpp"
#include "mesh/ExodusMeshReader.hpp"
#include "mesh/Generators.hpp"
#include "mesh/GmshMeshReader.hpp"
#include "mesh/MeshFactory.hpp"

using namespace contessa;
using namespace contessa::mesh;
using test_support::messageOf;
using test_support::expectSameMesh;

namespace {

const std::string kTwoBlocks = std::string(CONTESSA_TEST_MESHES) + "/two_blocks.msh";

std::string tempPath(const std::string& stem, const std::string& extension) {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return ::testing::TempDir() + "contessa_" + info->name() + "_" + stem + "_" + std::to_string(getpid()) + extension;
}

// A file in Gmsh's MSH 2.2 ASCII format: physical names ("dim tag \"name\"" lines), nodes ("tag x y z"),
// elements ("tag type 2 physical elementary node tags...").
std::string writeMsh(const std::string& stem, const std::vector<std::string>& names, const std::vector<std::string>& nodes,
                     const std::vector<std::string>& elements) {
  const std::string path = tempPath(stem, ".msh");
  std::ofstream out(path);
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n" << names.size() << "\n";
  for (const auto& n : names) out << n << "\n";
  out << "$EndPhysicalNames\n$Nodes\n" << nodes.size() << "\n";
  for (const auto& n : nodes) out << n << "\n";
  out << "$EndNodes\n$Elements\n" << elements.size() << "\n";
  for (const auto& e : elements) out << e << "\n";
  out << "$EndElements\n";
  return path;
}

// The unit cube's 8 corners as Gmsh nodes 1..8 (Exodus / Gmsh hexahedron order), z offset by `z`.
std::vector<std::string> cubeNodes() {
  return {"1 0 0 0", "2 1 0 0", "3 1 1 0", "4 0 1 0", "5 0 0 1", "6 1 0 1", "7 1 1 1", "8 0 1 1"};
}

using Vec = std::array<double, 3>;

// Unit outward normal of side `side` of `element` (from the side's node order).
Vec sideNormal(const Mesh& m, GlobalIndex element, int side) {
  const auto loc = m.locate(element);
  const auto& b = m.blocks[loc.block];
  const auto local = sideNodes(b.cellType, side);
  auto p = [&](int a) {
    const GlobalIndex n = b.connectivity[8 * loc.local + local[a]];
    return Vec{m.coordinates[3 * n], m.coordinates[3 * n + 1], m.coordinates[3 * n + 2]};
  };
  const Vec d1{p(2)[0] - p(0)[0], p(2)[1] - p(0)[1], p(2)[2] - p(0)[2]};
  const Vec d2{p(3)[0] - p(1)[0], p(3)[1] - p(1)[1], p(3)[2] - p(1)[2]};
  Vec n{d1[1] * d2[2] - d1[2] * d2[1], d1[2] * d2[0] - d1[0] * d2[2], d1[0] * d2[1] - d1[1] * d2[0]};
  const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& c : n) c /= length;
  return n;
}

}  // namespace

TEST(GmshMeshReader, GmshMadeMeshBlocksSetsAndOrientation) {
  const Mesh m = readGmshMesh(kTwoBlocks);  // validated: positive Jacobians, sides on the boundary
  EXPECT_EQ(m.dimension, 3);
  EXPECT_EQ(m.numNodes(), 5 * 3 * 3);
  ASSERT_EQ(m.blocks.size(), 2u);
  EXPECT_EQ(m.blocks[0].name, "steel");
  EXPECT_EQ(m.blocks[1].name, "rubber");
  double volume = 0;
  for (const auto& b : m.blocks) {
    EXPECT_EQ(b.cellType, CellType::Hex8);
    EXPECT_EQ(b.numElements(), 8);
    for (size_t e = 0; e < b.elements.size(); ++e) {
      std::vector<double> x;
      double centroidX = 0;
      for (int a = 0; a < 8; ++a)
        for (int i = 0; i < 3; ++i) {
          x.push_back(m.coordinates[3 * b.connectivity[8 * e + a] + i]);
          if (i == 0) centroidX += x.back() / 8;
        }
      EXPECT_NEAR(cellMeasure(CellType::Hex8, x.data()), 0.125, 1e-12);
      volume += cellMeasure(CellType::Hex8, x.data());
      EXPECT_EQ(centroidX < 1, b.name == "steel");  // the physical volumes are where the .geo put them
    }
  }
  EXPECT_NEAR(volume, 2, 1e-12);

  // Physical surfaces: side sets with outward sides, and node sets of the same name.
  const struct {
    const char* name;
    size_t sides, nodes;
    Vec normal;
  } surfaces[] = {{"left", 4, 9, {-1, 0, 0}}, {"right", 4, 9, {1, 0, 0}}, {"top", 8, 15, {0, 1, 0}}, {"surface_7", 8, 15, {0, 0, 1}}};
  for (const auto& s : surfaces) {
    const auto& set = m.sideSet(s.name);
    ASSERT_EQ(set.elements.size(), s.sides) << s.name;
    for (size_t k = 0; k < set.elements.size(); ++k) {
      const Vec n = sideNormal(m, set.elements[k], set.sides[k]);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(n[i], s.normal[i], 1e-12) << s.name;
    }
    EXPECT_EQ(m.nodeSet(s.name).nodes.size(), s.nodes) << s.name;
  }
  for (GlobalIndex e : m.sideSet("left").elements) EXPECT_EQ(m.blocks[m.locate(e).block].name, "steel");
  // Physical curve and point: node sets.
  const auto& edge = m.nodeSet("bottom_back_edge").nodes;
  ASSERT_EQ(edge.size(), 5u);
  for (GlobalIndex n : edge) {
    EXPECT_EQ(m.coordinates[3 * n + 1], 0.0);
    EXPECT_EQ(m.coordinates[3 * n + 2], 0.0);
  }
  ASSERT_EQ(m.nodeSet("origin").nodes.size(), 1u);
  const GlobalIndex origin = m.nodeSet("origin").nodes[0];
  EXPECT_EQ(m.coordinates[3 * origin] + m.coordinates[3 * origin + 1] + m.coordinates[3 * origin + 2], 0.0);
}

TEST(GmshMeshReader, TwoDimensionalQuadMesh) {
  // Two quads [0,2]×[0,1] in the plane z = 0, a physical line on x = 2, a physical point; node 7 is
  // in no element (Gmsh keeps geometry points) and is dropped.
  const std::string path = writeMsh(
      "quads", {"2 1 \"plate\"", "1 2 \"right\"", "0 3 \"corner\""},
      {"1 0 0 0", "2 1 0 0", "3 2 0 0", "4 0 1 0", "5 1 1 0", "6 2 1 0", "7 5 5 0"},
      {"1 3 2 1 1 1 2 5 4", "2 3 2 1 1 2 3 6 5", "3 1 2 2 2 3 6", "4 15 2 3 3 1"});
  const Mesh m = readGmshMesh(path);
  EXPECT_EQ(m.dimension, 2);
  EXPECT_EQ(m.numNodes(), 6);
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].name, "plate");
  EXPECT_EQ(m.blocks[0].cellType, CellType::Quad4);
  EXPECT_EQ(m.blocks[0].connectivity, (std::vector<GlobalIndex>{0, 1, 4, 3, 1, 2, 5, 4}));
  // The line 3–6 is side 1 (nodes 1, 2) of the second quad.
  EXPECT_EQ(m.sideSet("right").elements, (std::vector<GlobalIndex>{1}));
  EXPECT_EQ(m.sideSet("right").sides, (std::vector<int>{1}));
  EXPECT_EQ(m.nodeSet("right").nodes, (std::vector<GlobalIndex>{2, 5}));
  EXPECT_EQ(m.nodeSet("corner").nodes, (std::vector<GlobalIndex>{0}));
  std::remove(path.c_str());
}

TEST(GmshMeshReader, RefusesWhatContessaCannotUse) {
  auto pyramid = writeMsh("pyramid", {"3 1 \"x\""}, {"1 0 0 0", "2 1 0 0", "3 1 1 0", "4 0 1 0", "5 0.5 0.5 1"},
                          {"1 7 2 1 1 1 2 3 4 5"});
  EXPECT_EQ(messageOf([&] { readGmshMesh(pyramid); }),
            pyramid + ": element type 'pyramid 5' in physical group 'x' is not supported (Contessa reads tetrahedra "
                      "of 4 and 10 nodes, hexahedra of 8, 20 and 27 and prisms of 6 and 15)");
  std::remove(pyramid.c_str());

  // A 27-node hexahedron whose nodes are listed in lexicographic order, not Gmsh's: its first mid-edge
  // node (Gmsh's 9th node, at (2, 2, 0)) is far from the middle of the edge between its first corners.
  std::vector<std::string> nodes27;
  std::string hex27 = "1 12 2 1 1";
  for (int k = 0, tag = 1; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i, ++tag) {
        nodes27.push_back(std::to_string(tag) + " " + std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(k));
        hex27 += " " + std::to_string(tag);
      }
  auto quadratic = writeMsh("hex27", {"3 1 \"body\""}, nodes27, {hex27});
  EXPECT_EQ(messageOf([&] { readGmshMesh(quadratic); }),
            quadratic + ": element 1 of block 'body' has its mid-edge node 9 off the middle of the edge from node 1 to "
                        "node 2 by 250 % of the edge's length (at most 25 % is accepted): check the mid-edge node order "
                        "(HEX27 in Exodus order) and the node's coordinates");
  std::remove(quadratic.c_str());

  // A triangle on the boundary of a hexahedron mesh is no side of it.
  auto triangles = writeMsh("tri", {"3 1 \"body\"", "2 2 \"bottom\""}, cubeNodes(),
                            {"1 5 2 1 1 1 2 3 4 5 6 7 8", "2 2 2 2 2 1 2 3"});
  EXPECT_EQ(messageOf([&] { readGmshMesh(triangles); }),
            triangles + ": physical group 'bottom' holds a face (nodes 1, ...) that is not a side of any element of the blocks");
  std::remove(triangles.c_str());

  // A physical surface that is not a face of the hexahedron (a diagonal plane).
  auto diagonal = writeMsh("diagonal", {"3 1 \"body\"", "2 2 \"cut\""}, cubeNodes(),
                           {"1 5 2 1 1 1 2 3 4 5 6 7 8", "2 3 2 2 2 1 2 7 8"});
  EXPECT_EQ(messageOf([&] { readGmshMesh(diagonal); }),
            diagonal + ": physical group 'cut' holds a face (nodes 1, ...) that is not a side of any element of the blocks");
  std::remove(diagonal.c_str());

  // Mesh::validate applies: a hexahedron listed upside down is inverted.
  auto inverted = writeMsh("inverted", {"3 1 \"body\""}, cubeNodes(), {"1 5 2 1 1 5 6 7 8 1 2 3 4"});
  EXPECT_NE(messageOf([&] { readGmshMesh(inverted); }).find(inverted + ": element 1 of block 'body' is inverted"),
            std::string::npos);
  std::remove(inverted.c_str());

  // No physical volume or surface: no blocks to make.
  auto unnamed = writeMsh("nophysical", {"0 1 \"p\""}, cubeNodes(), {"1 15 2 1 1 1"});
  EXPECT_EQ(messageOf([&] { readGmshMesh(unnamed); }).rfind(unnamed + ": no physical surface or volume", 0), 0u);
  std::remove(unnamed.c_str());

  // A 2D mesh off the plane z = 0.
  auto tilted = writeMsh("tilted", {"2 1 \"plate\""}, {"1 0 0 0", "2 1 0 0", "3 1 1 1", "4 0 1 1"}, {"1 3 2 1 1 1 2 3 4"});
  EXPECT_EQ(messageOf([&] { readGmshMesh(tilted); }),
            tilted + ": node 3 has z = 1.000000; a 2D mesh must lie in the plane z = 0");
  std::remove(tilted.c_str());
}

TEST(GmshMeshReader, UnreadableFilesInOneLine) {
  const std::string missing = "/nonexistent/dir/mesh.msh";
  EXPECT_EQ(messageOf([&] { readGmshMesh(missing); }), missing + ": the mesh file does not exist");
  const std::string garbage = tempPath("garbage", ".msh");
  std::ofstream(garbage) << "this is not a mesh\n";
  const std::string message = messageOf([&] { readGmshMesh(garbage); });
  EXPECT_EQ(message.rfind(garbage + ": not a readable Gmsh file (", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  std::remove(garbage.c_str());
  const std::string empty = tempPath("empty", ".msh");
  std::ofstream{empty};
  EXPECT_EQ(messageOf([&] { readGmshMesh(empty); }), empty + ": not a readable Gmsh file (it is empty)");
  std::remove(empty.c_str());
  EXPECT_EQ(messageOf([&] { readGmshMesh(::testing::TempDir()); }),
            ::testing::TempDir() + ": not a readable Gmsh file (it is not a regular file)");
  const std::string geo = std::string(CONTESSA_TEST_MESHES) + "/two_blocks.geo";  // Gmsh would run the script
  EXPECT_EQ(messageOf([&] { readGmshMesh(geo); }), geo + ": not a Gmsh mesh file (expected the extension .msh)");
}

// A damaged ASCII file is refused before Gmsh reads it (Gmsh skips to the next section it knows and
// reads a file with its $EndNodes missing without a word): one line naming the file, the section and
// the line. Variants of the Gmsh-made two_blocks.msh ($Nodes on lines 62-199, $Elements on 200-258)
// and of a hand-written MSH 2.2 file.
TEST(GmshMeshReader, DamagedSectionsAreNamedWithTheirLines) {
  std::vector<std::string> lines;
  {
    std::ifstream in(kTwoBlocks);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
  }
  ASSERT_EQ(lines.size(), 258u);
  ASSERT_EQ(lines[198], "$EndNodes");
  const auto refusal = [&](const std::string& stem, std::vector<std::string> text) {
    const std::string path = tempPath(stem, ".msh");
    {
      std::ofstream out(path);
      for (const auto& line : text) out << line << "\n";
    }
    std::string message = messageOf([&] { readGmshMesh(path); });
    std::remove(path.c_str());
    EXPECT_EQ(message.rfind(path + ": not a readable Gmsh file (", 0), 0u) << message;
    return message.substr(std::min(message.size(), path.size()));
  };
  auto without = [&](std::size_t line) {  // 1-based
    auto text = lines;
    text.erase(text.begin() + static_cast<long>(line - 1));
    return text;
  };
  EXPECT_EQ(refusal("no_end_nodes", without(199)),
            ": not a readable Gmsh file (line 199: $Elements begins before $EndNodes closes $Nodes (line 62))");
  auto miscounted = lines;
  ASSERT_EQ(miscounted[62], "45 45 1 45");
  miscounted[62] = "45 46 1 45";
  EXPECT_EQ(refusal("miscounted_nodes", miscounted),
            ": not a readable Gmsh file ($Nodes (line 62) announces 46 nodes, its blocks hold 45)");
  EXPECT_EQ(refusal("coordinates_missing", without(198)),
            ": not a readable Gmsh file ($Nodes (line 62) ends at line 198 where the coordinates of node 1 of node block "
            "45 of 45 was expected: a count does not match the lines, or lines are missing)");
  EXPECT_EQ(refusal("truncated", std::vector<std::string>(lines.begin(), lines.begin() + 230)),
            ": not a readable Gmsh file ($Elements (line 200) has no $EndElements: the file ends at line 230 (a "
            "truncated file?))");
  // MSH 2.2: $Nodes on lines 8-16 (6 nodes), $Elements on lines 17-21 (2 elements).
  const std::string quads = writeMsh("quads22", {"2 1 \"plate\""}, {"1 0 0 0", "2 1 0 0", "3 2 0 0", "4 0 1 0", "5 1 1 0", "6 2 1 0"},
                                     {"1 3 2 1 1 1 2 5 4", "2 3 2 1 1 2 3 6 5"});
  std::vector<std::string> v2;
  {
    std::ifstream in(quads);
    for (std::string line; std::getline(in, line);) v2.push_back(line);
  }
  std::remove(quads.c_str());
  ASSERT_EQ(v2[16], "$Elements");
  ASSERT_EQ(v2[17], "2");
  v2[17] = "3";
  EXPECT_EQ(refusal("more_announced", v2),
            ": not a readable Gmsh file ($Elements (line 17) ends at line 21 where element 3 of 3 (tag type tags nodes) "
            "was expected: a count does not match the lines, or lines are missing)");
  v2[17] = "1";
  EXPECT_EQ(refusal("fewer_announced", v2),
            ": not a readable Gmsh file (line 20 of $Elements (line 17): more lines than its counts announce, or "
            "$EndElements missing)");
  v2[17] = "2";
  ASSERT_EQ(v2[13], "5 1 1 0");
  v2[13] = "5 1 1";  // node 5 without its z
  EXPECT_EQ(refusal("node_line_short", v2),
            ": not a readable Gmsh file (line 14 of $Nodes (line 8): 3 values where node 5 of 6 (tag x y z) needs 4)");
}

TEST(MeshFactory, ReadersByTypeAndByExtension) {
  Teuchos::ParameterList list;
  list.set("File Name", std::string("two_blocks.msh"));
  const Mesh byType = MeshFactory::create("Gmsh File", list, "Problem/Mesh", CONTESSA_TEST_MESHES, MPI_COMM_SELF);
  const Mesh byExtension = MeshFactory::create("Mesh File", list, "Problem/Mesh", CONTESSA_TEST_MESHES, MPI_COMM_SELF);
  expectSameMesh(byType, byExtension);
  EXPECT_EQ(byType.numElements(), 16);

  const std::string exodus = tempPath("box", ".exo");
  BoxSpec box;
  box.nx = 2;
  const Mesh written = generateBox(box);
  io::ExodusWriter(exodus, written, {}, "box");
  list.set("File Name", exodus);
  expectSameMesh(MeshFactory::create("Mesh File", list, "Problem/Mesh", "", MPI_COMM_SELF), written);
  std::remove(exodus.c_str());

  list.set("File Name", std::string("two_blocks.geo"));
  EXPECT_EQ(messageOf([&] { MeshFactory::create("Mesh File", list, "Problem/Mesh", CONTESSA_TEST_MESHES, MPI_COMM_SELF); }),
            "Problem/Mesh/File Name: '" + std::string(CONTESSA_TEST_MESHES) +
                "/two_blocks.geo' has none of the extensions .msh, .exo, .e, .g, .gen, .ex2 (or choose the reader "
                "with Type = Exodus File or Gmsh File)");
  list.set("File Name", std::string(""));
  EXPECT_EQ(messageOf([&] { MeshFactory::create("Gmsh File", list, "Problem/Mesh", "", MPI_COMM_SELF); }),
            "Problem/Mesh/File Name: required (a Gmsh .msh file)");
  EXPECT_EQ(messageOf([&] { MeshFactory::validParameters("Cube"); }),
            "Type: unknown mesh type 'Cube' (known: Rectangle, Annulus Sector, Box, Hollow Cylinder Sector, Sphere "
            "Octant, Exodus File, Gmsh File, Mesh File)");
}

TEST(ExodusRoundTrip, GeneratedHexMeshesKeepTheirSideSetsAndNodeSets) {
  const HollowCylinderSectorSpec tube = test_support::tubeSpec(2, 5, 3);
  const SphereOctantSpec sphere = test_support::octantSpec(3, 2);
  BoxSpec box;
  box.nx = 3, box.ny = 2, box.nz = 2;
  box.biasZ = 2;
  for (const Mesh& mesh : {generateBox(box), generateHollowCylinderSector(tube), generateSphereOctant(sphere),
                           readGmshMesh(kTwoBlocks)}) {
    const std::string path = tempPath("hex", ".exo");
    io::ExodusWriter(path, mesh, {}, "round trip");
    expectSameMesh(readExodusMesh(path), mesh);
    std::remove(path.c_str());
  }
}

namespace {

// Node `n` of the mesh as a point (z = 0 in 2D).
Vec nodeAt(const Mesh& m, GlobalIndex n) {
  Vec p{0, 0, 0};
  for (int i = 0; i < m.dimension; ++i) p[i] = m.coordinates[m.dimension * n + i];
  return p;
}

// The Gmsh-made straight-sided meshes put every mid-edge node at the middle of its edge and every face
// or centre node at the centre of its face or cell; after the reader's reordering, the Exodus order
// must say the same: mid-edge node k between the corners the Exodus table names (midEdgeNodes), the
// Hex27 face centres at the centre of the side whose nodes list them last, the Quad9 and Hex27 centre at
// the centre of the corners. A node order read wrongly puts another edge's middle there, at least a
// quarter of an element away; Gmsh writes its extruded nodes with errors of 1e-12 (measured), hence the
// tolerance kPlaced.
constexpr double kPlaced = 1e-9;
void expectExodusOrder(const Mesh& m, const ElementBlock& b) {
  const int nn = nodesPerCell(b.cellType);
  const std::string name = exodusCellName(b.cellType);
  auto node = [&](std::size_t e, int a) { return nodeAt(m, b.connectivity[nn * e + a]); };
  auto centre = [&](std::size_t e, const std::vector<int>& local, int count) {
    Vec c{0, 0, 0};
    for (int i = 0; i < count; ++i)
      for (int j = 0; j < 3; ++j) c[j] += node(e, local[i])[j] / count;
    return c;
  };
  for (std::size_t e = 0; e < b.elements.size(); ++e) {
    for (const MidEdgeNode& edge : midEdgeNodes(b.cellType))
      for (int j = 0; j < 3; ++j)
        ASSERT_NEAR(node(e, edge.middle)[j], (node(e, edge.first)[j] + node(e, edge.second)[j]) / 2, kPlaced)
            << name << " element " << e << " node " << edge.middle;
    std::vector<int> corners(static_cast<std::size_t>(numCorners(b.cellType)));
    for (int a = 0; a < numCorners(b.cellType); ++a) corners[a] = a;
    if (b.cellType == CellType::Quad9) {
      for (int j = 0; j < 3; ++j) ASSERT_NEAR(node(e, 8)[j], centre(e, corners, 4)[j], kPlaced) << "QUAD9 centre";
    }
    if (b.cellType == CellType::Hex27) {
      for (int j = 0; j < 3; ++j) ASSERT_NEAR(node(e, 20)[j], centre(e, corners, 8)[j], kPlaced) << "HEX27 centre";
      for (int s = 0; s < 6; ++s) {
        const auto side = sideNodes(b.cellType, s);
        for (int j = 0; j < 3; ++j) ASSERT_NEAR(node(e, side[8])[j], centre(e, side, 4)[j], kPlaced) << "HEX27 side " << s;
      }
    }
  }
}

struct FamilyMesh {
  const char* file;
  std::vector<std::pair<std::string, CellType>> blocks;
  double measure;  ///< of the whole mesh
};

const std::vector<FamilyMesh> kFamilyMeshes = {
    {"tet4.msh", {{"body", CellType::Tet4}}, 2},
    {"tet10.msh", {{"body", CellType::Tet10}}, 2},
    {"hex20.msh", {{"body", CellType::Hex20}}, 1},
    {"hex27.msh", {{"body", CellType::Hex27}}, 1},
    {"hex8_wedge6.msh", {{"body_hex8", CellType::Hex8}, {"body_wedge6", CellType::Wedge6}}, 2},
    {"hex20_wedge15.msh", {{"body_hex20", CellType::Hex20}, {"body_wedge15", CellType::Wedge15}}, 2},
    {"quad4_tri3.msh", {{"plate_quad4", CellType::Quad4}, {"plate_tri3", CellType::Tri3}}, 2},
    {"quad8_tri6.msh", {{"plate_quad8", CellType::Quad8}, {"plate_tri6", CellType::Tri6}}, 2},
    {"quad9_tri6.msh", {{"plate_quad9", CellType::Quad9}, {"plate_tri6", CellType::Tri6}}, 2},
};

}  // namespace

// Every family Gmsh makes, of order 1 and 2, mixed in one physical group: the blocks by cell type, the
// Exodus node order (expectExodusOrder), the measure, and the side sets of the physical surfaces or
// lines (every node of every side, mid-side nodes included, on the plane of its group).
TEST(GmshMeshReader, NodeOrdersOfEveryFamilyBecomeExodus) {
  for (const FamilyMesh& f : kFamilyMeshes) {
    SCOPED_TRACE(f.file);
    const Mesh m = readGmshMesh(std::string(CONTESSA_TEST_MESHES) + "/" + f.file);
    ASSERT_EQ(m.blocks.size(), f.blocks.size());
    double measure = 0;
    for (std::size_t k = 0; k < f.blocks.size(); ++k) {
      const ElementBlock& b = m.blocks[k];
      EXPECT_EQ(b.name, f.blocks[k].first);
      ASSERT_EQ(b.cellType, f.blocks[k].second);
      EXPECT_GT(b.numElements(), 0);
      expectExodusOrder(m, b);
      const int nn = nodesPerCell(b.cellType);
      for (std::size_t e = 0; e < b.elements.size(); ++e) {
        std::vector<double> x;
        for (int a = 0; a < nn; ++a)
          for (int i = 0; i < m.dimension; ++i) x.push_back(m.coordinates[m.dimension * b.connectivity[nn * e + a] + i]);
        const double v = cellMeasure(b.cellType, x.data());
        EXPECT_GT(v, 0);
        measure += v;
      }
    }
    EXPECT_NEAR(measure, f.measure, kPlaced);
    // Side sets: z = 0 and z = 1 (3D), x = 0 and x = 2 (2D).
    const int axis = m.dimension == 3 ? 2 : 0;
    const std::vector<std::pair<std::string, double>> planes =
        m.dimension == 3 ? std::vector<std::pair<std::string, double>>{{"bottom", 0}, {"top", 1}}
                         : std::vector<std::pair<std::string, double>>{{"left", 0}, {"right", 2}};
    for (const auto& [name, value] : planes) {
      const SideSet& set = m.sideSet(name);
      ASSERT_FALSE(set.elements.empty()) << name;
      for (std::size_t k = 0; k < set.elements.size(); ++k) {
        const auto where = m.locate(set.elements[k]);
        const ElementBlock& b = m.blocks[where.block];
        for (int a : sideNodes(b.cellType, set.sides[k]))
          EXPECT_NEAR(nodeAt(m, b.connectivity[where.local * nodesPerCell(b.cellType) + a])[axis], value, kPlaced) << name;
      }
    }
  }
}

// Written by Contessa's ExodusWriter in the native Exodus types (TETRA10, HEX20, WEDGE15, TRI6, ...)
// and read back: the same mesh, the block topology names and node counts as other tools read them.
TEST(ExodusRoundTrip, EveryFamilyInItsNativeExodusType) {
  for (const FamilyMesh& f : kFamilyMeshes) {
    SCOPED_TRACE(f.file);
    const Mesh m = readGmshMesh(std::string(CONTESSA_TEST_MESHES) + "/" + f.file);
    const std::string path = tempPath(std::string(f.file).substr(0, std::string(f.file).size() - 4), ".exo");
    { io::ExodusWriter writer(path, m, {}); }
    const Mesh back = readExodusMesh(path);
    expectSameMesh(m, back, test_support::Coordinates::WithinFourUlps);
    int cpu = 8, io = 0;
    float version = 0;
    const int id = ex_open(path.c_str(), EX_READ, &cpu, &io, &version);
    ASSERT_GE(id, 0);
    std::vector<int> ids(m.blocks.size());
    ASSERT_EQ(ex_get_ids(id, EX_ELEM_BLOCK, ids.data()), 0);
    for (std::size_t k = 0; k < ids.size(); ++k) {
      ex_block block{};
      block.id = ids[k];
      block.type = EX_ELEM_BLOCK;
      ASSERT_EQ(ex_get_block_param(id, &block), 0);
      EXPECT_STREQ(block.topology, exodusCellName(m.blocks[k].cellType));
      EXPECT_EQ(block.num_nodes_per_entry, nodesPerCell(m.blocks[k].cellType));
    }
    ex_close(id);
    std::remove(path.c_str());
  }
}

// What the conversion prevents: the Gmsh-made Tet10 and Hex20 meshes with their cells in Gmsh's own
// node order (rebuilt here from the Gmsh manual's edge lists), taken as Exodus order, are refused by
// the mid-edge check, naming a node and its wrong edge.
TEST(GmshMeshReader, GmshOrderTakenAsExodusIsRefused) {
  struct Case {
    const char* file;
    CellType type;
    std::vector<std::pair<int, int>> gmshEdges;  ///< the corners of Gmsh's mid-edge nodes, in its order
  };
  const Case cases[] = {
      {"tet10.msh", CellType::Tet10, {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}}},
      {"hex20.msh", CellType::Hex20,
       {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3}, {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}}},
  };
  for (const Case& c : cases) {
    Mesh m = readGmshMesh(std::string(CONTESSA_TEST_MESHES) + "/" + c.file);
    ElementBlock& b = m.blocks[0];
    ASSERT_EQ(b.cellType, c.type);
    const int nn = nodesPerCell(c.type), corners = numCorners(c.type);
    for (std::size_t e = 0; e < b.elements.size(); ++e) {
      std::vector<GlobalIndex> gmsh(b.connectivity.begin() + nn * e, b.connectivity.begin() + nn * (e + 1));
      for (std::size_t k = 0; k < c.gmshEdges.size(); ++k)
        for (const MidEdgeNode& edge : midEdgeNodes(c.type))
          if ((edge.first == c.gmshEdges[k].first && edge.second == c.gmshEdges[k].second) ||
              (edge.first == c.gmshEdges[k].second && edge.second == c.gmshEdges[k].first))
            gmsh[corners + k] = b.connectivity[nn * e + edge.middle];
      std::copy(gmsh.begin(), gmsh.end(), b.connectivity.begin() + nn * e);
    }
    const std::string message = messageOf([&] { m.validate(c.file); });
    EXPECT_NE(message.find("has its mid-edge node"), std::string::npos) << c.file << ": " << message;
  }
}
