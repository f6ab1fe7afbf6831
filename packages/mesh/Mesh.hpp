#pragma once
// The mesh as read or generated: replicated on every rank (surfaces and 2D meshes are small); the
// partition (Partition.hpp) decides which rank assembles which element. One rank's part of a mesh
// no rank holds whole: DistributedMesh.hpp (a Mesh in local numbering with global ids beside). Dimension-general: 2D
// quadrilaterals now, 3D hexahedra later use the same containers.
#include <string>
#include <vector>

namespace contessa::mesh {

using GlobalIndex = long long;  // matches Tpetra's global ordinal in this Trilinos build

/// The cell topologies, each with its Exodus II node order (the SEACAS "Exodus element types" page):
/// corners first, then the mid-edge nodes, then (Quad9, Hex27) the face and centre nodes. New types are
/// appended: the value travels between ranks (MeshDistribution).
enum class CellType { Quad4, Hex8, Tri3, Tri6, Quad8, Quad9, Tet4, Tet10, Hex20, Hex27, Wedge6, Wedge15 };

/// Number of nodes of a cell type, its spatial dimension, and its name in Exodus ("QUAD4", "HEX8",
/// "TETRA10", "WEDGE15", ...).
int nodesPerCell(CellType type);
int cellDimension(CellType type);
const char* exodusCellName(CellType type);
/// Number of corner (vertex) nodes: the first nodes of the cell; the others are mid-edge, face or
/// centre nodes of a quadratic cell.
int numCorners(CellType type);
/// Polynomial order of the cell's geometry: 1 (linear) or 2 (quadratic).
int cellOrder(CellType type);
/// The cell type of a dimension and node count (Tet10: 3, 10), as the element kernels are matched to a
/// block; false when there is none.
bool cellTypeOf(int dimension, int numNodes, CellType& type);

/// Number of sides of a cell type (Quad4: 4 edges, Hex8: 6 faces, Wedge6: 3 quadrilaterals then 2 triangles).
int numSides(CellType type);

/// Local node numbers (0-based, Exodus order) of side `side` (0-based; Exodus side number − 1): its
/// corners first (numSideCorners of them, counter-clockwise seen from outside in 3D, the element on the
/// left in 2D), then its mid-edge nodes in the order of its edges, then its centre node (Hex27).
std::vector<int> sideNodes(CellType type, int side);
/// Number of corners of a side (2 for an edge, 3 or 4 for a face): its nodes that identify it.
int numSideCorners(CellType type, int side);

/// An edge of a quadratic cell: its two corners and the node between them (local, 0-based).
struct MidEdgeNode {
  int first, second, middle;
};
/// The mid-edge nodes of a quadratic cell (empty for a linear one).
const std::vector<MidEdgeNode>& midEdgeNodes(CellType type);

struct ElementBlock {
  std::string name;
  CellType cellType = CellType::Quad4;
  std::vector<GlobalIndex> elements;      ///< global element ids (0-based), one per element
  std::vector<GlobalIndex> connectivity;  ///< global node ids (0-based), nodesPerCell per element
  GlobalIndex numElements() const { return static_cast<GlobalIndex>(elements.size()); }
};

struct NodeSet {
  std::string name;
  std::vector<GlobalIndex> nodes;  ///< global node ids (0-based), sorted, unique
};

struct SideSet {
  std::string name;
  std::vector<GlobalIndex> elements;  ///< global element ids (0-based)
  std::vector<int> sides;             ///< local side per element (0-based, Exodus side − 1)
};

class Mesh {
 public:
  int dimension = 2;
  std::vector<double> coordinates;  ///< node-major: x0 y0 [z0] x1 y1 [z1] ...
  std::vector<ElementBlock> blocks;
  std::vector<NodeSet> nodeSets;
  std::vector<SideSet> sideSets;

  GlobalIndex numNodes() const;
  GlobalIndex numElements() const;

  /// Lookups by name; throw contessa::InputError naming the missing set/block and listing the known ones.
  const ElementBlock& block(const std::string& name) const;
  const NodeSet& nodeSet(const std::string& name) const;
  const SideSet& sideSet(const std::string& name) const;
  bool hasBlock(const std::string& name) const;
  bool hasNodeSet(const std::string& name) const;
  bool hasSideSet(const std::string& name) const;

  /// Block index and position within that block of a global element id.
  struct ElementLocation { int block; GlobalIndex local; };
  ElementLocation locate(GlobalIndex element) const;

  /// Checks that the mesh can be computed on (MeshValidation.cpp); throws InputError whose one-line
  /// message starts with `source` (a file name, or the deck path of a generator) and names the
  /// offending entity. Numbers in messages count from 1, as in Exodus files. In order:
  /// - structure: dimension 2 or 3, array sizes, every element id in exactly one block, cell types
  ///   of the mesh dimension;
  /// - coordinates: every node's coordinates finite;
  /// - elements: connectivity in range, no node twice in an element, every mid-edge node of a
  ///   quadratic cell within 25 % of its edge's length of the edge's middle, and a positive Jacobian at
  ///   every corner (Quad4, Hex8: cornerJacobians) or at every node and integration point (the other
  ///   types: shapeCheckJacobians): inverted (clockwise), tangled (self-intersecting or
  ///   non-convex) and degenerate (zero area or volume, collinear edges) elements are refused;
  /// - node sets: node ids in range, sorted and unique;
  /// - side sets: element ids and side numbers in range, and every side on the boundary (a side
  ///   whose corners another element's side has is inside the mesh);
  /// - names of blocks, node sets and side sets unique.
  /// Cost O(n log n) in the mesh size: 0.06 s for 10^6 Quad4, 0.15 s for 10^6 Hex8 (bench/mesh_check_bench).
  void validate(const std::string& source) const;
  /// The same for one rank's part of a distributed mesh (local numbering): messages name the whole
  /// mesh's numbers, `globalNodes[n]` and `globalElements[e]` (DistributedMesh.hpp), and the number of
  /// badly shaped elements goes to `badShapes` instead of the message (the caller sums it over the
  /// parts: validatePart, MeshDistribution.hpp). A side set's side shared with an element of another
  /// rank's part is not seen here.
  void validate(const std::string& source, const std::vector<GlobalIndex>& globalNodes,
                const std::vector<GlobalIndex>& globalElements, GlobalIndex& badShapes) const;
};

}  // namespace contessa::mesh
