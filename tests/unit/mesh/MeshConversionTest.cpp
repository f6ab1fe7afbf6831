// The generators' cell variants (MeshConversion.hpp, and the Box's and Rectangle's `Cell Type` and
// `Element Order`): simplices that fill the cells and match across faces, quadratic cells with their
// nodes at the middle of their edges and in the node sets of the faces, side sets on the same faces.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "MeshTestSupport.hpp"
#include "mesh/CellGeometry.hpp"
#include "mesh/Generators.hpp"
#include "mesh/MeshConversion.hpp"
#include "mesh/MeshFactory.hpp"

using namespace contessa::mesh;
using test_support::messageOf;

namespace {

std::vector<double> cellCoordinates(const Mesh& m, const ElementBlock& b, std::size_t e) {
  const int nn = nodesPerCell(b.cellType);
  std::vector<double> x;
  for (int a = 0; a < nn; ++a)
    for (int i = 0; i < m.dimension; ++i) x.push_back(m.coordinates[m.dimension * b.connectivity[nn * e + a] + i]);
  return x;
}

double totalMeasure(const Mesh& m) {
  double sum = 0;
  for (const auto& b : m.blocks)
    for (std::size_t e = 0; e < b.elements.size(); ++e) {
      const double v = cellMeasure(b.cellType, cellCoordinates(m, b, e).data());
      EXPECT_GT(v, 0);
      sum += v;
    }
  return sum;
}

// How many cells hold each side (by its sorted corners): 1 on the boundary, 2 inside; a
// non-conforming split leaves a face held once inside the mesh.
std::map<std::vector<GlobalIndex>, int> sideUse(const Mesh& m) {
  std::map<std::vector<GlobalIndex>, int> use;
  for (const auto& b : m.blocks) {
    const int nn = nodesPerCell(b.cellType);
    for (std::size_t e = 0; e < b.elements.size(); ++e)
      for (int s = 0; s < numSides(b.cellType); ++s) {
        const auto local = sideNodes(b.cellType, s);
        std::vector<GlobalIndex> key;
        for (int i = 0; i < numSideCorners(b.cellType, s); ++i) key.push_back(b.connectivity[nn * e + local[i]]);
        std::sort(key.begin(), key.end());
        ++use[key];
      }
  }
  return use;
}

Mesh box(int n) {
  BoxSpec spec;
  spec.lx = 2;
  spec.nx = spec.ny = spec.nz = n;
  spec.biasX = 1.5;  // graded: cells of different sizes
  return generateBox(spec);
}

}  // namespace

// 2 × 2 × 2 hexahedra into 48 tetrahedra: the volume kept, every face inside held by two tetrahedra and
// the boundary by 6 faces × 4 squares × 2 triangles, the side set 'left' the 8 triangles on x = 0.
TEST(MeshConversion, HexahedraIntoMatchingTetrahedra) {
  const Mesh hex = box(2);
  const Mesh tet = splitIntoSimplices(hex);
  EXPECT_NO_THROW(tet.validate("tets"));
  ASSERT_EQ(tet.blocks[0].cellType, CellType::Tet4);
  EXPECT_EQ(tet.numElements(), 48);
  EXPECT_NEAR(totalMeasure(tet), 2, 1e-12);
  int boundary = 0;
  for (const auto& [key, count] : sideUse(tet)) {
    EXPECT_LE(count, 2);
    boundary += count == 1;
  }
  EXPECT_EQ(boundary, 6 * 4 * 2);
  const SideSet& left = tet.sideSet("left");
  EXPECT_EQ(left.elements.size(), 8u);
  for (std::size_t k = 0; k < left.elements.size(); ++k) {
    const auto where = tet.locate(left.elements[k]);
    for (int a : sideNodes(CellType::Tet4, left.sides[k]))
      EXPECT_EQ(tet.coordinates[3 * tet.blocks[0].connectivity[4 * where.local + a]], 0.0);
  }
  EXPECT_EQ(tet.nodeSet("left").nodes, hex.nodeSet("left").nodes);
}

TEST(MeshConversion, QuadrilateralsIntoTriangles) {
  RectangleSpec spec = test_support::rectangleSpec(3, 2, 3);
  const Mesh tri = splitIntoSimplices(generateRectangle(spec));
  EXPECT_NO_THROW(tri.validate("tris"));
  EXPECT_EQ(tri.numElements(), 12);
  EXPECT_NEAR(totalMeasure(tri), 3, 1e-12);
  EXPECT_EQ(tri.sideSet("top").elements.size(), 3u);
  EXPECT_EQ(tri.sideSet("right").elements.size(), 2u);
}

// Hex20 and Hex27 from 2 × 2 × 2 hexahedra: 27 + 54 edge nodes (+ 36 face and 8 centre nodes), every
// mid-edge node at its edge's middle, the face node sets growing by the nodes made on them.
TEST(MeshConversion, MidEdgeNodesOfHexahedraAndTetrahedra) {
  const Mesh hex20 = withMidEdgeNodes(box(2));
  EXPECT_NO_THROW(hex20.validate("hex20"));
  EXPECT_EQ(hex20.blocks[0].cellType, CellType::Hex20);
  EXPECT_EQ(hex20.numNodes(), 27 + 54);
  EXPECT_NEAR(totalMeasure(hex20), 2, 1e-12);
  EXPECT_EQ(hex20.nodeSet("left").nodes.size(), 9u + 12u);
  EXPECT_EQ(hex20.nodeSet("all").nodes.size(), 81u);
  const auto& b = hex20.blocks[0];
  for (std::size_t e = 0; e < b.elements.size(); ++e) {
    const auto x = cellCoordinates(hex20, b, e);
    for (const MidEdgeNode& m : midEdgeNodes(CellType::Hex20))
      for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(x[3 * m.middle + i], (x[3 * m.first + i] + x[3 * m.second + i]) / 2);
  }
  for (const GlobalIndex n : hex20.nodeSet("left").nodes) EXPECT_EQ(hex20.coordinates[3 * n], 0.0);
  const Mesh hex27 = withMidEdgeNodes(box(2), true);
  EXPECT_NO_THROW(hex27.validate("hex27"));
  EXPECT_EQ(hex27.numNodes(), 125);
  EXPECT_EQ(hex27.nodeSet("left").nodes.size(), 25u);
  const Mesh tet10 = withMidEdgeNodes(splitIntoSimplices(box(2)));
  EXPECT_NO_THROW(tet10.validate("tet10"));
  EXPECT_EQ(tet10.blocks[0].cellType, CellType::Tet10);
  EXPECT_NEAR(totalMeasure(tet10), 2, 1e-12);
  // Every node of every side of 'left' on x = 0, the mid-edge nodes included.
  const SideSet& left = tet10.sideSet("left");
  for (std::size_t k = 0; k < left.elements.size(); ++k) {
    const auto where = tet10.locate(left.elements[k]);
    for (int a : sideNodes(CellType::Tet10, left.sides[k]))
      EXPECT_EQ(tet10.coordinates[3 * tet10.blocks[0].connectivity[10 * where.local + a]], 0.0);
  }
}

// The deck parameters: Cell Type and Element Order of the Box and the Rectangle, their defaults the
// grid's own linear cells, a wrong order refused naming the parameter.
TEST(MeshConversion, GeneratorParameters) {
  auto made = [](const std::string& type, const std::string& cells, int order, int n) {
    Teuchos::ParameterList list;
    list.set("Elements X", n);
    list.set("Elements Y", n);
    if (!cells.empty()) list.set("Cell Type", cells);
    if (order > 0) list.set("Element Order", order);
    list.validateParametersAndSetDefaults(*MeshFactory::validParameters(type));
    return MeshFactory::create(type, list, "Problem/Mesh", "", MPI_COMM_SELF);
  };
  EXPECT_EQ(made("Box", "", 0, 2).blocks[0].cellType, CellType::Hex8);
  EXPECT_EQ(made("Box", "Tetrahedra", 0, 2).blocks[0].cellType, CellType::Tet4);
  const Mesh tet10 = made("Box", "Tetrahedra", 2, 2);
  EXPECT_EQ(tet10.blocks[0].cellType, CellType::Tet10);
  EXPECT_EQ(tet10.numElements(), 2 * 2 * 1 * 6);
  EXPECT_EQ(made("Box", "", 2, 1).blocks[0].cellType, CellType::Hex20);
  EXPECT_EQ(made("Rectangle", "", 0, 2).blocks[0].cellType, CellType::Quad4);
  EXPECT_EQ(made("Rectangle", "Triangles", 2, 2).blocks[0].cellType, CellType::Tri6);
  EXPECT_EQ(made("Rectangle", "", 2, 2).blocks[0].cellType, CellType::Quad8);
  EXPECT_EQ(messageOf([&] { made("Box", "", 3, 1); }),
            "Problem/Mesh/Element Order: 3 is not an element order (expected 1 or 2)");
}
