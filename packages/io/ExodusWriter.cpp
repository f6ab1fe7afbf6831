#include "io/ExodusWriter.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>

#include "common/Error.hpp"
#include "io/DiskSpace.hpp"
#include "io/ExodusResults.hpp"
#include "io/OutputWriteError.hpp"
#include "mesh/ExodusFile.hpp"

namespace contessa::io {

namespace {

using mesh::GlobalIndex;
using mesh::detail::ExodusFile;

constexpr long long kMargin = 64 * 1024;  // HDF5 metadata that may grow in a step (B-tree nodes, heaps)

// Exodus takes names as a mutable char* array; the strings outlive the call.
std::vector<char*> namePointers(std::vector<std::string>& names) {
  std::vector<char*> pointers;
  for (auto& n : names) pointers.push_back(n.data());
  return pointers;
}

std::vector<std::string> coordinateNames(int dimension) {
  std::vector<std::string> names = {"x", "y", "z"};
  names.resize(static_cast<size_t>(dimension));
  return names;
}

// The library truncates names beyond its default 32 characters unless told the longest one first.
int longestName(const mesh::Mesh& mesh, const ExodusFields& fields, const std::vector<ExodusSurfaceBlock>& surfaceBlocks) {
  size_t longest = 32;
  auto consider = [&longest](const std::string& name) { longest = std::max(longest, name.size()); };
  for (const auto& b : mesh.blocks) consider(b.name);
  for (const auto& b : surfaceBlocks) consider(b.name);
  for (const auto& s : mesh.nodeSets) consider(s.name);
  for (const auto& s : mesh.sideSets) consider(s.name);
  for (const auto* list : {&fields.nodal, &fields.element, &fields.global})
    for (const auto& name : *list) consider(name);
  return static_cast<int>(longest);
}

void checkSizes(const std::string& path, const char* kind, const std::vector<std::vector<double>>& values,
                const std::vector<std::string>& names, GlobalIndex expected) {
  if (values.size() != names.size())
    throw std::runtime_error(path + ": " + std::to_string(values.size()) + " " + kind + " variables given, " +
                                std::to_string(names.size()) + " declared");
  for (size_t v = 0; v < values.size(); ++v)
    if (static_cast<GlobalIndex>(values[v].size()) != expected)
      throw std::runtime_error(path + ": " + kind + " variable '" + names[v] + "' has " +
                                  std::to_string(values[v].size()) + " values, expected " + std::to_string(expected));
}

long long fileSize(int fd) {
  struct stat info {};
  return fstat(fd, &info) == 0 ? static_cast<long long>(info.st_size) : 0;
}

// Writes through the Exodus API, turning a failed call into an OutputWriteError that says what was
// being written and, when the system knows, why.
class Calls {
 public:
  Calls(std::string path, std::string action) : path_(std::move(path)), action_(std::move(action)) {}
  void operator()(int status, const std::string& what) const {
    if (status >= 0) return;  // positive statuses are warnings
    const int error = errno;  // HDF5 leaves the failed system call's errno
    std::string reason = what + " failed";
    const std::string detail = ExodusFile::lastError();
    if (!detail.empty()) reason += " (" + detail + ")";
    if (error != 0) reason = systemMessage(error) + " (" + reason + ")";
    throw OutputWriteError(path_, action_, reason);
  }

 private:
  std::string path_, action_;
};

// Nemesis' global node set and side set records (ids, counts, no distribution factors): ex_put_init_global
// defines them and leaves them unwritten, so a file would otherwise hold whatever the memory held.
void writeGlobalSetSizes(int id, const ExodusDecomposition& d, const mesh::Mesh& mesh, const Calls& check) {
  const auto put = [&](std::size_t count, const std::vector<GlobalIndex>& global, auto localSize, auto write,
                       const char* what) {
    if (count == 0) return;
    if (!global.empty() && global.size() != count)
      throw std::logic_error("ExodusWriter: the decomposition's set sizes do not match the piece");
    std::vector<int64_t> ids, sizes, factors(count, 0);
    for (std::size_t s = 0; s < count; ++s) {
      ids.push_back(static_cast<int64_t>(s) + 1);
      sizes.push_back(global.empty() ? localSize(s) : static_cast<int64_t>(global[s]));
    }
    check(write(id, ids.data(), sizes.data(), factors.data()), what);
  };
  put(mesh.nodeSets.size(), d.globalNodeSetSizes,
      [&](std::size_t s) { return static_cast<int64_t>(mesh.nodeSets[s].nodes.size()); }, ex_put_ns_param_global,
      "the decomposition (global node sets)");
  put(mesh.sideSets.size(), d.globalSideSetSizes,
      [&](std::size_t s) { return static_cast<int64_t>(mesh.sideSets[s].elements.size()); }, ex_put_ss_param_global,
      "the decomposition (global side sets)");
}

// The global ids (1-based, as Exodus numbers) and the Nemesis records of one file of a decomposed set.
// Nemesis numbers nodes and elements locally (1-based) in its maps; a border node is one that another
// piece holds too, a border element one with a border node; one node communication map per neighbour,
// with the neighbour's rank as its id.
void writeDecomposition(int id, const ExodusDecomposition& d, const mesh::Mesh& mesh, GlobalIndex numNodes,
                        GlobalIndex numElements, const Calls& check) {
  if (static_cast<GlobalIndex>(d.globalNodes.size()) != numNodes ||
      static_cast<GlobalIndex>(d.globalElements.size()) != numElements ||
      static_cast<GlobalIndex>(d.sharedWith.size()) != mesh.numNodes())
    throw std::logic_error("ExodusWriter: the decomposition does not match the piece");
  std::vector<int64_t> ids(d.globalNodes.begin(), d.globalNodes.end());
  for (int64_t& i : ids) ++i;
  check(ex_put_id_map(id, EX_NODE_MAP, ids.data()), "the global node ids");
  ids.assign(d.globalElements.begin(), d.globalElements.end());
  for (int64_t& i : ids) ++i;
  check(ex_put_id_map(id, EX_ELEM_MAP, ids.data()), "the global element ids");

  char type[] = "p";  // parallel: one processor per file
  check(ex_put_init_info(id, d.processors, 1, type), "the decomposition (init info)");
  check(ex_put_init_global(id, d.globalNumNodes, d.globalNumElements, static_cast<int64_t>(d.globalBlockSizes.size()),
                           static_cast<int64_t>(mesh.nodeSets.size()), static_cast<int64_t>(mesh.sideSets.size())),
        "the decomposition (global sizes)");
  std::vector<int64_t> blockIds, blockSizes(d.globalBlockSizes.begin(), d.globalBlockSizes.end());
  for (std::size_t b = 0; b < blockSizes.size(); ++b) blockIds.push_back(static_cast<int64_t>(b) + 1);
  if (!blockIds.empty())
    check(ex_put_eb_info_global(id, blockIds.data(), blockSizes.data()), "the decomposition (global blocks)");
  writeGlobalSetSizes(id, d, mesh, check);

  std::vector<int64_t> interiorNodes, borderNodes, interiorElements, borderElements;
  std::vector<char> border(d.sharedWith.size(), 0);
  std::vector<int> neighbours;
  for (std::size_t n = 0; n < d.sharedWith.size(); ++n) {
    border[n] = !d.sharedWith[n].empty();
    (border[n] ? borderNodes : interiorNodes).push_back(static_cast<int64_t>(n) + 1);
    for (int r : d.sharedWith[n])
      if (std::find(neighbours.begin(), neighbours.end(), r) == neighbours.end()) neighbours.push_back(r);
  }
  // Surface points (rigid surfaces) are drawn by one file only: interior there.
  for (GlobalIndex n = static_cast<GlobalIndex>(d.sharedWith.size()); n < numNodes; ++n) interiorNodes.push_back(n + 1);
  std::sort(neighbours.begin(), neighbours.end());
  int64_t next = 1;
  for (const auto& block : mesh.blocks) {
    const int n = mesh::nodesPerCell(block.cellType);
    for (GlobalIndex e = 0; e < block.numElements(); ++e, ++next) {
      bool onBorder = false;
      for (int a = 0; a < n && !onBorder; ++a) onBorder = border[block.connectivity[e * n + a]];
      (onBorder ? borderElements : interiorElements).push_back(next);
    }
  }
  for (; next <= numElements; ++next) interiorElements.push_back(next);
  check(ex_put_loadbal_param(id, static_cast<int64_t>(interiorNodes.size()), static_cast<int64_t>(borderNodes.size()), 0,
                             static_cast<int64_t>(interiorElements.size()), static_cast<int64_t>(borderElements.size()),
                             static_cast<int64_t>(neighbours.size()), 0, d.processor),
        "the decomposition (load balance)");
  check(ex_put_processor_node_maps(id, interiorNodes.data(), borderNodes.data(), nullptr, d.processor),
        "the decomposition (node maps)");
  check(ex_put_processor_elem_maps(id, interiorElements.data(), borderElements.data(), d.processor),
        "the decomposition (element maps)");
  if (neighbours.empty()) return;
  std::vector<int64_t> mapIds, mapSizes;
  std::vector<std::vector<int64_t>> mapNodes(neighbours.size());
  for (std::size_t n = 0; n < d.sharedWith.size(); ++n)
    for (int r : d.sharedWith[n])
      mapNodes[std::lower_bound(neighbours.begin(), neighbours.end(), r) - neighbours.begin()].push_back(
          static_cast<int64_t>(n) + 1);
  for (std::size_t k = 0; k < neighbours.size(); ++k) {
    mapIds.push_back(neighbours[k]);
    mapSizes.push_back(static_cast<int64_t>(mapNodes[k].size()));
  }
  check(ex_put_cmap_params(id, mapIds.data(), mapSizes.data(), nullptr, nullptr, d.processor),
        "the decomposition (communication maps)");
  for (std::size_t k = 0; k < neighbours.size(); ++k) {
    std::vector<int64_t> processors(mapNodes[k].size(), neighbours[k]);
    check(ex_put_node_cmap(id, mapIds[k], mapNodes[k].data(), processors.data(), d.processor),
          "the decomposition (communication map)");
  }
}

// Coordinates: the mesh nodes, then the surface blocks' points.
void writeCoordinates(int id, const mesh::Mesh& mesh, const std::vector<ExodusSurfaceBlock>& surfaceBlocks,
                      GlobalIndex numNodes, const Calls& check) {
  const int dim = mesh.dimension;
  std::vector<std::vector<double>> xyz(static_cast<size_t>(dim), std::vector<double>(numNodes));
  const GlobalIndex meshNodes = mesh.numNodes();
  for (GlobalIndex n = 0; n < meshNodes; ++n)
    for (int d = 0; d < dim; ++d) xyz[d][n] = mesh.coordinates[n * dim + d];
  GlobalIndex nextNode = meshNodes;
  for (const auto& surface : surfaceBlocks)
    for (size_t p = 0; p + dim <= surface.points.size(); p += dim, ++nextNode)
      for (int d = 0; d < dim; ++d) xyz[d][nextNode] = surface.points[p + d];
  check(ex_put_coord(id, xyz[0].data(), xyz[1].data(), dim == 3 ? xyz[2].data() : nullptr), "coordinates");
  auto coordNames = coordinateNames(dim);
  auto coordPointers = namePointers(coordNames);
  check(ex_put_coord_names(id, coordPointers.data()), "coordinate names");
}

// The mesh blocks (ids 1..), their names appended to `blockNames`. Returns each element's Exodus number:
// Exodus numbers elements 1.. over the blocks in order, and side sets refer to that numbering.
std::vector<int64_t> writeMeshBlocks(int id, const mesh::Mesh& mesh, std::vector<std::string>& blockNames,
                                     const Calls& check) {
  std::vector<int64_t> exodusElement(static_cast<size_t>(mesh.numElements()));
  int64_t next = 1;
  for (size_t b = 0; b < mesh.blocks.size(); ++b) {
    const auto& block = mesh.blocks[b];
    const int64_t blockId = static_cast<int64_t>(b) + 1;
    const std::string what = "element block '" + block.name + "'";
    check(ex_put_block(id, EX_ELEM_BLOCK, blockId, mesh::exodusCellName(block.cellType), block.numElements(),
                       mesh::nodesPerCell(block.cellType), 0, 0, 0),
          what);
    if (block.numElements() > 0) {
      std::vector<int64_t> connectivity(block.connectivity.begin(), block.connectivity.end());
      for (int64_t& node : connectivity) ++node;
      check(ex_put_conn(id, EX_ELEM_BLOCK, blockId, connectivity.data(), nullptr, nullptr), what);
    }
    for (GlobalIndex e : block.elements) exodusElement[e] = next++;
    blockNames.push_back(block.name);
  }
  return exodusElement;
}

// The surface blocks after the mesh blocks (BAR2 or SHELL4 on their points, which follow the mesh nodes),
// their names appended to `blockNames`.
void writeSurfaceBlocks(int id, const mesh::Mesh& mesh, const std::vector<ExodusSurfaceBlock>& surfaceBlocks,
                        std::vector<std::string>& blockNames, const Calls& check) {
  int64_t firstPoint = mesh.numNodes() + 1;  // Exodus node number of the block's first point
  for (size_t l = 0; l < surfaceBlocks.size(); ++l) {
    const auto& surface = surfaceBlocks[l];
    const int64_t blockId = static_cast<int64_t>(mesh.blocks.size() + l) + 1;
    const int64_t points = static_cast<int64_t>(surface.points.size()) / mesh.dimension;
    const std::string what = "surface block '" + surface.name + "'";
    if (surface.nodesPerElement != 2 && surface.nodesPerElement != 4)
      throw std::runtime_error(what + ": " + std::to_string(surface.nodesPerElement) +
                               " nodes per element (2: BAR2 or 4: SHELL4 expected)");
    const char* type = surface.nodesPerElement == 2 ? "BAR2" : "SHELL4";
    check(ex_put_block(id, EX_ELEM_BLOCK, blockId, type, surface.numElements(), surface.nodesPerElement, 0, 0, 0),
          what);
    if (surface.numElements() > 0) {
      std::vector<int64_t> connectivity;
      for (GlobalIndex point : surface.connectivity) {
        if (point < 0 || point >= points)
          throw std::runtime_error(what + ": point " + std::to_string(point) + " out of range (" +
                                   std::to_string(points) + " points)");
        connectivity.push_back(firstPoint + point);
      }
      check(ex_put_conn(id, EX_ELEM_BLOCK, blockId, connectivity.data(), nullptr, nullptr), what);
    }
    firstPoint += points;
    blockNames.push_back(surface.name);
  }
}

void writeNodeSets(int id, const mesh::Mesh& mesh, const Calls& check) {
  std::vector<std::string> nodeSetNames;
  for (size_t s = 0; s < mesh.nodeSets.size(); ++s) {
    const auto& set = mesh.nodeSets[s];
    const int64_t setId = static_cast<int64_t>(s) + 1;
    const std::string what = "node set '" + set.name + "'";
    check(ex_put_set_param(id, EX_NODE_SET, setId, static_cast<int64_t>(set.nodes.size()), 0), what);
    if (!set.nodes.empty()) {
      std::vector<int64_t> nodes(set.nodes.begin(), set.nodes.end());
      for (int64_t& node : nodes) ++node;
      check(ex_put_set(id, EX_NODE_SET, setId, nodes.data(), nullptr), what);
    }
    nodeSetNames.push_back(set.name);
  }
  if (!nodeSetNames.empty()) {
    auto pointers = namePointers(nodeSetNames);
    check(ex_put_names(id, EX_NODE_SET, pointers.data()), "node set names");
  }
}

// Side sets by the elements' Exodus numbers (writeMeshBlocks) and 1-based sides.
void writeSideSets(int id, const mesh::Mesh& mesh, const std::vector<int64_t>& exodusElement, const Calls& check) {
  std::vector<std::string> sideSetNames;
  for (size_t s = 0; s < mesh.sideSets.size(); ++s) {
    const auto& set = mesh.sideSets[s];
    const int64_t setId = static_cast<int64_t>(s) + 1;
    const std::string what = "side set '" + set.name + "'";
    check(ex_put_set_param(id, EX_SIDE_SET, setId, static_cast<int64_t>(set.elements.size()), 0), what);
    if (!set.elements.empty()) {
      std::vector<int64_t> elements, sides;
      for (GlobalIndex e : set.elements) elements.push_back(exodusElement[e]);
      for (int side : set.sides) sides.push_back(side + 1);
      check(ex_put_set(id, EX_SIDE_SET, setId, elements.data(), sides.data()), what);
    }
    sideSetNames.push_back(set.name);
  }
  if (!sideSetNames.empty()) {
    auto pointers = namePointers(sideSetNames);
    check(ex_put_names(id, EX_SIDE_SET, pointers.data()), "side set names");
  }
}

// QA and information records.
void writeRecords(int id, const ExodusRecords& records, const Calls& check) {
  if (!records.qa.empty()) {
    std::vector<std::array<std::string, 4>> qa = records.qa;
    std::vector<std::array<char*, 4>> pointers(qa.size());
    for (size_t r = 0; r < qa.size(); ++r)
      for (int k = 0; k < 4; ++k) {
        qa[r][k] = qa[r][k].substr(0, MAX_STR_LENGTH);
        pointers[r][k] = qa[r][k].data();
      }
    check(ex_put_qa(id, static_cast<int>(qa.size()), reinterpret_cast<char* (*)[4]>(pointers.data())), "QA records");
  }
  if (!records.info.empty()) {
    auto info = infoRecords(records.info);
    auto pointers = namePointers(info);
    check(ex_put_info(id, static_cast<int>(info.size()), pointers.data()), "information records");
  }
}

// The nodal, element and global variable names, and where the element variables live: on the mesh
// blocks, not on the surface blocks (declared up front, which avoids per-step redefinition).
void writeVariableNames(int id, const ExodusFields& fields, size_t meshBlocks, size_t numBlocks, const Calls& check) {
  auto putNames = [&](ex_entity_type type, std::vector<std::string> names, const char* what) {
    if (names.empty()) return;
    check(ex_put_variable_param(id, type, static_cast<int>(names.size())), what);
    auto pointers = namePointers(names);
    check(ex_put_variable_names(id, type, static_cast<int>(names.size()), pointers.data()), what);
  };
  putNames(EX_NODAL, fields.nodal, "nodal variable names");
  putNames(EX_ELEM_BLOCK, fields.element, "element variable names");
  putNames(EX_GLOBAL, fields.global, "global variable names");
  if (fields.element.empty() || numBlocks == 0) return;
  std::vector<int> truth(numBlocks * fields.element.size(), 0);
  for (size_t b = 0; b < meshBlocks; ++b)
    std::fill_n(truth.begin() + static_cast<std::ptrdiff_t>(b * fields.element.size()), fields.element.size(), 1);
  check(ex_put_truth_table(id, EX_ELEM_BLOCK, static_cast<int>(numBlocks), static_cast<int>(fields.element.size()),
                           truth.data()),
        "the element variable truth table");
}

}  // namespace

std::vector<std::string> infoRecords(const std::vector<std::string>& lines) {
  const size_t width = MAX_LINE_LENGTH;
  std::vector<std::string> records;
  for (const auto& line : lines) {
    size_t start = 0;
    while (line.size() - start > width) {
      records.push_back(line.substr(start, width - 1) + "\\");
      start += width - 1;
    }
    records.push_back(line.substr(start));
  }
  return records;
}

void disableHdf5FileLocking() { setenv("HDF5_USE_FILE_LOCKING", "FALSE", 1); }

ExodusWriter::ExodusWriter(const std::string& path, const mesh::Mesh& mesh, const ExodusFields& fields,
                           const ExodusRecords& records, const std::vector<ExodusSurfaceBlock>& surfaceBlocks,
                           const ExodusDecomposition* decomposition, ExodusNaming naming)
    : path_(path), numElements_(mesh.numElements()), fields_(fields) {
  for (const auto& block : mesh.blocks) blocks_.push_back({block.name, block.elements});
  const int dim = mesh.dimension;
  numNodes_ = mesh.numNodes();
  for (const auto& surface : surfaceBlocks) numNodes_ += static_cast<GlobalIndex>(surface.points.size()) / dim;
  createFile(naming, 8 * (static_cast<long long>(numNodes_) * dim + static_cast<long long>(mesh.numElements()) * 8) +
                         kMargin);
  try {
    const Calls check(path, "cannot create");
    const int id = id_;
    GlobalIndex surfaceElements = 0;
    for (const auto& surface : surfaceBlocks) surfaceElements += surface.numElements();
    check(ex_set_max_name_length(id, longestName(mesh, fields, surfaceBlocks)), "the name length");
    const std::string title = records.title.substr(0, MAX_LINE_LENGTH);
    check(ex_put_init(id, title.c_str(), dim, numNodes_, mesh.numElements() + surfaceElements,
                      static_cast<int64_t>(mesh.blocks.size() + surfaceBlocks.size()),
                      static_cast<int64_t>(mesh.nodeSets.size()), static_cast<int64_t>(mesh.sideSets.size())),
          "the header");
    writeCoordinates(id, mesh, surfaceBlocks, numNodes_, check);
    std::vector<std::string> blockNames;
    const std::vector<int64_t> exodusElement = writeMeshBlocks(id, mesh, blockNames, check);
    writeSurfaceBlocks(id, mesh, surfaceBlocks, blockNames, check);
    if (!blockNames.empty()) {
      auto pointers = namePointers(blockNames);
      check(ex_put_names(id, EX_ELEM_BLOCK, pointers.data()), "element block names");
    }
    writeNodeSets(id, mesh, check);
    writeSideSets(id, mesh, exodusElement, check);
    writeRecords(id, records, check);
    writeVariableNames(id, fields, mesh.blocks.size(), mesh.blocks.size() + surfaceBlocks.size(), check);
    if (decomposition != nullptr)
      writeDecomposition(id, *decomposition, mesh, numNodes_, mesh.numElements() + surfaceElements, check);
    // On disk before the first step: a run that dies at once still leaves a valid file with the mesh.
    check(ex_update(id), "the file (flush)");
  } catch (...) {
    ex_close(id_);
    ::close(spaceFd_);
    ::unlink(startingPath_.c_str());
    throw;
  }
}

void ExodusWriter::createFile(ExodusNaming naming, long long meshBytes) {
  // A results file is made under startingPath_ and takes its name at its first step (a file of another
  // run there is left alone until then); a path that is a directory would only fail at that rename.
  struct stat existing {};
  if (::stat(path_.c_str(), &existing) == 0 && S_ISDIR(existing.st_mode))
    throw OutputWriteError(path_, "cannot create", systemMessage(EISDIR));
  startingPath_ = naming == ExodusNaming::AtFirstStep ? path_ + ".starting" : path_;
  // The system's reason for a path that cannot be written (no permission, a read-only file system, a
  // full disk): the library's own message would blame netCDF-4 support for any failure.
  spaceFd_ = ::open(startingPath_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (spaceFd_ < 0) throw OutputWriteError(path_, "cannot create", systemMessage(errno));
  const auto giveUp = [this](const std::string& reason) {
    ::close(spaceFd_);
    ::unlink(startingPath_.c_str());
    throw OutputWriteError(path_, "cannot create", reason);
  };
  if (const int error = reserveAfterEnd(spaceFd_, 2 * meshBytes)) giveUp(systemMessage(error));

  int cpuWordSize = 8, ioWordSize = 8;
  // netCDF-4/HDF5: no 2 GiB variable limits, and what current ParaView/SEACAS tools expect.
  // 64-bit integers through the API take GlobalIndex data without narrowing copies.
  errno = 0;
  id_ = ex_create(startingPath_.c_str(), EX_CLOBBER | EX_NETCDF4 | EX_ALL_INT64_API, &cpuWordSize, &ioWordSize);
  if (id_ < 0) {
    const int error = errno;
    giveUp(error != 0 ? systemMessage(error) : std::string("the Exodus library cannot create it"));
  }
  // HDF5 truncates the file again when it creates it, which frees what was reserved past its end on
  // ext4 and tmpfs: reserve again, now that the file is HDF5's, for the mesh and records written next.
  if (const int error = reserveAfterEnd(spaceFd_, 2 * meshBytes)) {
    ex_close(id_);
    giveUp(systemMessage(error));
  }
}

ExodusWriter::~ExodusWriter() {
  ex_close(id_);  // every step is already on disk; nothing is left to report
  releaseAfterEnd(spaceFd_);
  ::close(spaceFd_);
  if (steps_ == 0 && startingPath_ != path_) ::unlink(startingPath_.c_str());  // a results file without a step
}

void ExodusWriter::writeStep(double time, const std::vector<std::vector<double>>& nodal,
                             const std::vector<std::vector<double>>& element, const std::vector<double>& global) {
  checkSizes(path_, "nodal", nodal, fields_.nodal, numNodes_);
  checkSizes(path_, "element", element, fields_.element, numElements_);
  if (global.size() != fields_.global.size())
    throw std::runtime_error(path_ + ": " + std::to_string(global.size()) + " global variables given, " +
                                std::to_string(fields_.global.size()) + " declared");

  const int step = steps_ + 1;  // Exodus steps count from 1
  const std::string action = "cannot write step " + std::to_string(step) + " to";
  if (failed_) throw OutputWriteError(path_, action, "an earlier step could not be written");
  // Reserve twice what a step has taken so far (or its raw data, for the first): the disk filling
  // up then stops the run between steps, with the file intact.
  const long long raw =
      8 * (static_cast<long long>(nodal.size()) * numNodes_ +
           static_cast<long long>(element.size()) * numElements_ + static_cast<long long>(global.size()) + 1);
  const long long before = fileSize(spaceFd_);
  if (const int error = reserveAfterEnd(spaceFd_, 2 * std::max(raw, stepBytes_) + kMargin))
    throw OutputWriteError(path_, action, systemMessage(error));

  try {
    const Calls check(path_, action);
    errno = 0;
    check(ex_put_time(id_, step, &time), "the time");
    for (size_t v = 0; v < nodal.size(); ++v)
      check(ex_put_nodal_var(id_, step, static_cast<int>(v) + 1, numNodes_, nodal[v].data()),
            "nodal variable '" + fields_.nodal[v] + "'");
    std::vector<double> blockValues;
    for (size_t v = 0; v < element.size(); ++v)
      for (size_t b = 0; b < blocks_.size(); ++b) {
        const auto& block = blocks_[b];
        if (block.elements.empty()) continue;
        blockValues.clear();
        for (GlobalIndex e : block.elements) blockValues.push_back(element[v][e]);
        check(ex_put_elem_var(id_, step, static_cast<int>(v) + 1, static_cast<int64_t>(b) + 1,
                              static_cast<int64_t>(block.elements.size()), blockValues.data()),
              "element variable '" + fields_.element[v] + "' on block '" + block.name + "'");
      }
    if (!global.empty())
      check(ex_put_glob_vars(id_, step, static_cast<int>(global.size()), global.data()), "global variables");
    check(ex_update(id_), "the flush to disk");
    // The first step is on disk: the file takes its name, replacing the one of an earlier run.
    if (step == 1 && startingPath_ != path_ && ::rename(startingPath_.c_str(), path_.c_str()) != 0)
      throw OutputWriteError(path_, action, systemMessage(errno));
  } catch (...) {
    failed_ = true;
    throw;
  }
  stepBytes_ = std::max(stepBytes_, fileSize(spaceFd_) - before);
  steps_ = step;
}

void ExodusWriter::copySteps(const ExodusResults& source, int steps) {
  requireInput(source.numSteps() >= steps, source.path() + ": holds " + std::to_string(source.numSteps()) +
                                               " steps, the restart file's increment needs " + std::to_string(steps));
  const auto times = source.times();
  for (int step = 0; step < steps; ++step) {
    std::vector<std::vector<double>> nodal, element;
    std::vector<double> global;
    for (const auto& name : fields_.nodal) nodal.push_back(source.nodal(name, step));
    for (const auto& name : fields_.element) element.push_back(source.element(name, step));
    for (const auto& name : fields_.global) global.push_back(source.global(name, step));
    writeStep(times[static_cast<std::size_t>(step)], nodal, element, global);
  }
}

}  // namespace contessa::io
