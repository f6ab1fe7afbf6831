#pragma once
// The mesh as read or generated: replicated on every rank (surfaces and 2D meshes are small); the
// partition (Partition.hpp) decides which rank assembles which element. Dimension-general: 2D
// quadrilaterals now, 3D hexahedra later use the same containers.
#include <string>
#include <vector>

namespace contessa::mesh {

using GlobalIndex = long long;  // matches Tpetra's global ordinal in this Trilinos build

enum class CellType { Quad4, Hex8 };

/// Number of nodes of a cell type, its spatial dimension, and its name in Exodus ("QUAD4", "HEX8").
int nodesPerCell(CellType type);
int cellDimension(CellType type);
const char* exodusCellName(CellType type);

/// Local node numbers (0-based, Exodus order) of side `side` (0-based; Exodus side number − 1).
std::vector<int> sideNodes(CellType type, int side);

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

  /// Checks internal consistency (ids in range, sizes match); throws InputError with `source` named.
  void validate(const std::string& source) const;
};

}  // namespace contessa::mesh
