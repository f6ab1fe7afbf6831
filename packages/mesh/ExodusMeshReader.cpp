#include "mesh/ExodusMeshReader.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <new>
#include <vector>

#include "common/Error.hpp"
#include "mesh/ExodusFile.hpp"
#include "mesh/ExodusProbe.hpp"
#include "mesh/MemoryEstimate.hpp"

namespace contessa::mesh {

namespace {

using detail::ExodusFile;

class Reader {
 public:
  explicit Reader(const std::string& path) : file_(path, open(path)) {}

  Mesh read() {
    ex_init_params init{};
    check(ex_get_init_ext(id(), &init), "the header");
    requireInput(init.num_dim == 2 || init.num_dim == 3,
                 path() + ": unsupported mesh dimension " + std::to_string(init.num_dim) + " (supported: 2, 3)");
    requireInput(init.num_nodes >= 0 && init.num_elem >= 0,
                 path() + ": not a readable Exodus file (its header gives " + std::to_string(init.num_nodes) +
                     " nodes and " + std::to_string(init.num_elem) + " elements)");
    // Before anything is allocated: a file's header can promise more than the machine holds.
    MeshSize size(static_cast<double>(init.num_nodes), static_cast<double>(init.num_elem),
                  static_cast<int>(init.num_dim));
    size.nodesPerElement = largestNodesPerElement(init.num_elem_blk, size.nodesPerElement);
    requireRunFits(size, path(), "use a coarser mesh or a machine with more memory");
    // Names longer than the library's default of 32 characters would be truncated otherwise.
    const int64_t nameLength = std::max<int64_t>(32, ex_inquire_int(id(), EX_INQ_DB_MAX_USED_NAME_LENGTH));
    check(ex_set_max_name_length(id(), static_cast<int>(nameLength)), "the name length");
    nameLength_ = static_cast<size_t>(nameLength);

    Mesh mesh;
    mesh.dimension = static_cast<int>(init.num_dim);
    readCoordinates(mesh, init.num_nodes);
    readBlocks(mesh, init.num_elem_blk);
    readNodeSets(mesh, init.num_node_sets);
    readSideSets(mesh, init.num_side_sets);
    check(file_.close(), "the file (close)");
    mesh.validate(path());
    return mesh;
  }

 private:
  static int open(const std::string& path) {
    // Diagnosed first: ex_open prints "does not support netcdf-4" to stderr for any HDF5 file
    // netCDF cannot open (a truncated one) and reports only "failed to open".
    const std::string problem = exodusFileProblem(path);
    requireInput(problem.empty(), path + ": not a readable Exodus file (" + problem + ")");
    ex_opts(EX_DEFAULT);  // errors come back through ex_get_err, not printed by the library
    int cpuWordSize = 8, ioWordSize = 0;
    float version = 0;
    // 64-bit integers through the API accept any file, whatever integer size it stores.
    const int id = ex_open(path.c_str(), EX_READ | EX_ALL_INT64_API, &cpuWordSize, &ioWordSize, &version);
    requireInput(id >= 0, path + ": not a readable Exodus file (" + ExodusFile::lastError() + ")");
    return id;
  }

  int id() const { return file_.id(); }
  const std::string& path() const { return file_.path(); }

  void check(int status, const std::string& what) const {
    // Negative is an error; positive is a warning (e.g. an optional entity is absent).
    if (status < 0) {
      const std::string detail = ExodusFile::lastError();
      throw InputError(path() + ": not a readable Exodus file (cannot read " + what +
                       (detail.empty() ? "" : ": " + detail) + ")");
    }
  }

  std::vector<int64_t> ids(ex_entity_type type, int64_t count, const char* what) {
    std::vector<int64_t> result(static_cast<size_t>(count));
    if (count > 0) check(ex_get_ids(id(), type, result.data()), what);
    return result;
  }

  std::vector<std::string> names(ex_entity_type type, const std::vector<int64_t>& entityIds, const char* prefix,
                                 const char* what) {
    const size_t count = entityIds.size();
    std::vector<std::vector<char>> buffers(count, std::vector<char>(nameLength_ + 1, '\0'));
    std::vector<char*> pointers(count);
    for (size_t k = 0; k < count; ++k) pointers[k] = buffers[k].data();
    if (count > 0) check(ex_get_names(id(), type, pointers.data()), what);
    std::vector<std::string> result(count);
    for (size_t k = 0; k < count; ++k) {
      result[k] = buffers[k].data();
      // Unnamed entities need a name for the deck to refer to them.
      if (result[k].empty()) result[k] = prefix + std::to_string(entityIds[k]);
    }
    return result;
  }

  void readCoordinates(Mesh& mesh, int64_t numNodes) {
    const size_t n = static_cast<size_t>(numNodes);
    std::vector<double> x(n), y(n), z(mesh.dimension == 3 ? n : 0);
    if (n > 0) check(ex_get_coord(id(), x.data(), y.data(), mesh.dimension == 3 ? z.data() : nullptr), "coordinates");
    mesh.coordinates.resize(n * mesh.dimension);
    for (size_t k = 0; k < n; ++k) {
      mesh.coordinates[k * mesh.dimension] = x[k];
      mesh.coordinates[k * mesh.dimension + 1] = y[k];
      if (mesh.dimension == 3) mesh.coordinates[k * 3 + 2] = z[k];
    }
  }

  // The Exodus topology names common tools write ("HEX8", "hex", "HEX20", "TETRA10", "tetra", "TET4",
  // "WEDGE6", "TRI6", "TRIANGLE", "QUAD8", ...): the family is the name without its digits, the cell
  // the family's of the block's node count and dimension ("QUAD" of 4 nodes is QUAD4, of 8 QUAD8).
  static std::string family(const std::string& topology) {
    std::string upper;
    for (char c : topology)
      if (!std::isdigit(static_cast<unsigned char>(c))) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (upper == "HEXAHEDRON") return "HEX";
    if (upper == "TET" || upper == "TETRAHEDRON") return "TETRA";
    if (upper == "TRIANGLE") return "TRI";
    if (upper == "QUADRILATERAL") return "QUAD";
    return upper;
  }

  CellType cellType(const std::string& blockName, const std::string& topology, int64_t nodesPerElement,
                    int dimension) const {
    CellType type = CellType::Quad4;
    std::string cellFamily = "?";
    if (cellTypeOf(dimension, static_cast<int>(nodesPerElement), type)) cellFamily = family(exodusCellName(type));
    if (cellFamily == family(topology)) return type;
    throw InputError(path() + ": element block '" + blockName + "' has unsupported type '" + topology + "' with " +
                     std::to_string(nodesPerElement) + " nodes per element in a " + std::to_string(dimension) +
                     "D mesh (supported: " +
                     (dimension == 2 ? "TRI3, TRI6, QUAD4, QUAD8, QUAD9" : "TETRA4, TETRA10, HEX8, HEX20, HEX27, WEDGE6, WEDGE15") +
                     ")");
  }

  // The most nodes per element of any block (quadratic cells hold 2 to 3 times those of linear ones),
  // at least `atLeast`; read from the block headers only.
  int largestNodesPerElement(int64_t numBlocks, int atLeast) {
    int largest = atLeast;
    for (int64_t blockId : ids(EX_ELEM_BLOCK, numBlocks, "element block ids")) {
      ex_block param{};
      param.id = blockId;
      param.type = EX_ELEM_BLOCK;
      check(ex_get_block_param(id(), &param), "element block " + std::to_string(blockId));
      largest = std::max(largest, static_cast<int>(param.num_nodes_per_entry));
    }
    return largest;
  }

  void readBlocks(Mesh& mesh, int64_t numBlocks) {
    const auto blockIds = ids(EX_ELEM_BLOCK, numBlocks, "element block ids");
    const auto blockNames = names(EX_ELEM_BLOCK, blockIds, "block_", "element block names");
    GlobalIndex nextElement = 0;  // global ids run over the blocks in file order, as in Exodus
    for (size_t b = 0; b < blockIds.size(); ++b) {
      ex_block param{};
      param.id = blockIds[b];
      param.type = EX_ELEM_BLOCK;
      check(ex_get_block_param(id(), &param), "element block '" + blockNames[b] + "'");
      ElementBlock block;
      block.name = blockNames[b];
      // An empty block (a piece of a decomposed set where the rank has none of its elements) is
      // written with topology "NULL": its cells are the mesh dimension's.
      block.cellType = param.num_entry == 0 ? (mesh.dimension == 2 ? CellType::Quad4 : CellType::Hex8)
                                            : cellType(block.name, param.topology, param.num_nodes_per_entry,
                                                       mesh.dimension);
      requireInput(cellDimension(block.cellType) == mesh.dimension,
                   path() + ": element block '" + block.name + "' has " + exodusCellName(block.cellType) +
                       " cells in a " + std::to_string(mesh.dimension) + "D mesh");
      const size_t count = static_cast<size_t>(param.num_entry);
      std::vector<int64_t> connectivity(count * static_cast<size_t>(param.num_nodes_per_entry));
      if (count > 0)
        check(ex_get_conn(id(), EX_ELEM_BLOCK, param.id, connectivity.data(), nullptr, nullptr),
              "connectivity of element block '" + block.name + "'");
      block.elements.resize(count);
      for (size_t k = 0; k < count; ++k) block.elements[k] = nextElement++;
      block.connectivity.assign(connectivity.begin(), connectivity.end());
      for (GlobalIndex& node : block.connectivity) --node;
      mesh.blocks.push_back(std::move(block));
    }
  }

  // A set's entries as the file lists them (1-based): its nodes or elements, and a side set's sides.
  struct SetEntries {
    std::vector<int64_t> entries, sides;
  };
  SetEntries readSet(ex_entity_type type, int64_t setId, const std::string& what) {
    int64_t count = 0, numFactors = 0;
    check(ex_get_set_param(id(), type, setId, &count, &numFactors), what);
    SetEntries set{std::vector<int64_t>(static_cast<size_t>(count)),
                   std::vector<int64_t>(type == EX_SIDE_SET ? static_cast<size_t>(count) : 0)};
    if (count > 0)
      check(ex_get_set(id(), type, setId, set.entries.data(), type == EX_SIDE_SET ? set.sides.data() : nullptr), what);
    return set;
  }

  void readNodeSets(Mesh& mesh, int64_t numSets) {
    const auto setIds = ids(EX_NODE_SET, numSets, "node set ids");
    const auto setNames = names(EX_NODE_SET, setIds, "nodeset_", "node set names");
    for (size_t s = 0; s < setIds.size(); ++s) {
      const std::vector<int64_t> nodes = readSet(EX_NODE_SET, setIds[s], "node set '" + setNames[s] + "'").entries;
      NodeSet set;
      set.name = setNames[s];
      set.nodes.assign(nodes.begin(), nodes.end());
      for (GlobalIndex& node : set.nodes) --node;
      // Files may list nodes in any order and repeat them; the mesh promises sorted and unique.
      std::sort(set.nodes.begin(), set.nodes.end());
      set.nodes.erase(std::unique(set.nodes.begin(), set.nodes.end()), set.nodes.end());
      mesh.nodeSets.push_back(std::move(set));
    }
  }

  void readSideSets(Mesh& mesh, int64_t numSets) {
    const auto setIds = ids(EX_SIDE_SET, numSets, "side set ids");
    const auto setNames = names(EX_SIDE_SET, setIds, "sideset_", "side set names");
    for (size_t s = 0; s < setIds.size(); ++s) {
      const auto [elements, sides] = readSet(EX_SIDE_SET, setIds[s], "side set '" + setNames[s] + "'");
      SideSet set;
      set.name = setNames[s];
      // Exodus numbers elements 1.. over the blocks in file order: our global id plus one.
      for (int64_t e : elements) set.elements.push_back(e - 1);
      for (int64_t side : sides) set.sides.push_back(static_cast<int>(side - 1));
      mesh.sideSets.push_back(std::move(set));
    }
  }

  ExodusFile file_;
  size_t nameLength_ = 32;
};

}  // namespace

Mesh readExodusMesh(const std::string& path) {
  try {
    return Reader(path).read();
  } catch (const std::bad_alloc&) {
    // The estimate passed, yet an allocation failed: a set larger than the header's counts, or
    // other processes took the memory meanwhile.
    throw InputError(path + ": not enough memory to read this mesh");
  }
}

}  // namespace contessa::mesh
