#include "io/ExodusWriter.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

#include "mesh/ExodusFile.hpp"

namespace contessa::io {

namespace {

using mesh::GlobalIndex;
using mesh::detail::ExodusFile;

[[noreturn]] void fail(const std::string& path, const std::string& message) {
  const std::string detail = ExodusFile::lastError();
  throw std::runtime_error(path + ": " + message + (detail.empty() ? "" : " (" + detail + ")"));
}

void check(int status, const std::string& path, const std::string& what) {
  if (status < 0) fail(path, "cannot write " + what);  // positive statuses are warnings
}

// Exodus takes names as a mutable char* array; the strings outlive the call.
std::vector<char*> namePointers(std::vector<std::string>& names) {
  std::vector<char*> pointers;
  for (auto& n : names) pointers.push_back(n.data());
  return pointers;
}

void writeVariableNames(int id, const std::string& path, ex_entity_type type, std::vector<std::string> names,
                        const char* what) {
  if (names.empty()) return;
  check(ex_put_variable_param(id, type, static_cast<int>(names.size())), path, what);
  auto pointers = namePointers(names);
  check(ex_put_variable_names(id, type, static_cast<int>(names.size()), pointers.data()), path, what);
}

std::vector<std::string> coordinateNames(int dimension) {
  std::vector<std::string> names = {"x", "y", "z"};
  names.resize(static_cast<size_t>(dimension));
  return names;
}

// The library truncates names beyond its default 32 characters unless told the longest one first.
int longestName(const mesh::Mesh& mesh, const ExodusFields& fields) {
  size_t longest = 32;
  auto consider = [&longest](const std::string& name) { longest = std::max(longest, name.size()); };
  for (const auto& b : mesh.blocks) consider(b.name);
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

}  // namespace

ExodusWriter::ExodusWriter(const std::string& path, const mesh::Mesh& mesh, const ExodusFields& fields,
                           const std::string& title)
    : path_(path), mesh_(mesh), fields_(fields) {
  int cpuWordSize = 8, ioWordSize = 8;
  // netCDF-4/HDF5: no 2 GiB variable limits, and what current ParaView/SEACAS tools expect.
  // 64-bit integers through the API take GlobalIndex data without narrowing copies.
  const int id = ex_create(path.c_str(), EX_CLOBBER | EX_NETCDF4 | EX_ALL_INT64_API, &cpuWordSize, &ioWordSize);
  // The library's own message blames netCDF-4 support for any failure, so leave it out.
  if (id < 0) throw std::runtime_error(path + ": cannot create the Exodus file (is the directory writable?)");
  ExodusFile file(path, id);
  check(ex_set_max_name_length(id, longestName(mesh, fields)), path, "the name length");

  const int dim = mesh.dimension;
  const GlobalIndex numNodes = mesh.numNodes();
  const std::string shortTitle = title.substr(0, MAX_LINE_LENGTH);
  check(ex_put_init(id, shortTitle.c_str(), dim, numNodes, mesh.numElements(),
                    static_cast<int64_t>(mesh.blocks.size()), static_cast<int64_t>(mesh.nodeSets.size()),
                    static_cast<int64_t>(mesh.sideSets.size())),
        path, "the header");

  std::vector<std::vector<double>> xyz(static_cast<size_t>(dim), std::vector<double>(numNodes));
  for (GlobalIndex n = 0; n < numNodes; ++n)
    for (int d = 0; d < dim; ++d) xyz[d][n] = mesh.coordinates[n * dim + d];
  check(ex_put_coord(id, xyz[0].data(), xyz[1].data(), dim == 3 ? xyz[2].data() : nullptr), path, "coordinates");
  auto coordNames = coordinateNames(dim);
  auto coordPointers = namePointers(coordNames);
  check(ex_put_coord_names(id, coordPointers.data()), path, "coordinate names");

  // Exodus numbers elements 1.. over the blocks in order; side sets refer to that numbering.
  std::vector<int64_t> exodusElement(static_cast<size_t>(mesh.numElements()));
  int64_t next = 1;
  std::vector<std::string> blockNames;
  for (size_t b = 0; b < mesh.blocks.size(); ++b) {
    const auto& block = mesh.blocks[b];
    const int64_t blockId = static_cast<int64_t>(b) + 1;
    const std::string what = "element block '" + block.name + "'";
    check(ex_put_block(id, EX_ELEM_BLOCK, blockId, mesh::exodusCellName(block.cellType), block.numElements(),
                       mesh::nodesPerCell(block.cellType), 0, 0, 0),
          path, what);
    if (block.numElements() > 0) {
      std::vector<int64_t> connectivity(block.connectivity.begin(), block.connectivity.end());
      for (int64_t& node : connectivity) ++node;
      check(ex_put_conn(id, EX_ELEM_BLOCK, blockId, connectivity.data(), nullptr, nullptr), path, what);
    }
    for (GlobalIndex e : block.elements) exodusElement[e] = next++;
    blockNames.push_back(block.name);
  }
  if (!blockNames.empty()) {
    auto pointers = namePointers(blockNames);
    check(ex_put_names(id, EX_ELEM_BLOCK, pointers.data()), path, "element block names");
  }

  std::vector<std::string> nodeSetNames;
  for (size_t s = 0; s < mesh.nodeSets.size(); ++s) {
    const auto& set = mesh.nodeSets[s];
    const int64_t setId = static_cast<int64_t>(s) + 1;
    const std::string what = "node set '" + set.name + "'";
    check(ex_put_set_param(id, EX_NODE_SET, setId, static_cast<int64_t>(set.nodes.size()), 0), path, what);
    if (!set.nodes.empty()) {
      std::vector<int64_t> nodes(set.nodes.begin(), set.nodes.end());
      for (int64_t& node : nodes) ++node;
      check(ex_put_set(id, EX_NODE_SET, setId, nodes.data(), nullptr), path, what);
    }
    nodeSetNames.push_back(set.name);
  }
  if (!nodeSetNames.empty()) {
    auto pointers = namePointers(nodeSetNames);
    check(ex_put_names(id, EX_NODE_SET, pointers.data()), path, "node set names");
  }

  std::vector<std::string> sideSetNames;
  for (size_t s = 0; s < mesh.sideSets.size(); ++s) {
    const auto& set = mesh.sideSets[s];
    const int64_t setId = static_cast<int64_t>(s) + 1;
    const std::string what = "side set '" + set.name + "'";
    check(ex_put_set_param(id, EX_SIDE_SET, setId, static_cast<int64_t>(set.elements.size()), 0), path, what);
    if (!set.elements.empty()) {
      std::vector<int64_t> elements, sides;
      for (GlobalIndex e : set.elements) elements.push_back(exodusElement[e]);
      for (int side : set.sides) sides.push_back(side + 1);
      check(ex_put_set(id, EX_SIDE_SET, setId, elements.data(), sides.data()), path, what);
    }
    sideSetNames.push_back(set.name);
  }
  if (!sideSetNames.empty()) {
    auto pointers = namePointers(sideSetNames);
    check(ex_put_names(id, EX_SIDE_SET, pointers.data()), path, "side set names");
  }

  writeVariableNames(id, path, EX_NODAL, fields.nodal, "nodal variable names");
  writeVariableNames(id, path, EX_ELEM_BLOCK, fields.element, "element variable names");
  writeVariableNames(id, path, EX_GLOBAL, fields.global, "global variable names");
  if (!fields.element.empty() && !mesh.blocks.empty()) {
    // Declaring every variable on every block up front avoids per-step redefinition.
    std::vector<int> truth(mesh.blocks.size() * fields.element.size(), 1);
    check(ex_put_truth_table(id, EX_ELEM_BLOCK, static_cast<int>(mesh.blocks.size()),
                             static_cast<int>(fields.element.size()), truth.data()),
          path, "the element variable truth table");
  }
  check(file.close(), path, "the file (close)");
}

void ExodusWriter::writeStep(double time, const std::vector<std::vector<double>>& nodal,
                             const std::vector<std::vector<double>>& element, const std::vector<double>& global) {
  checkSizes(path_, "nodal", nodal, fields_.nodal, mesh_.numNodes());
  checkSizes(path_, "element", element, fields_.element, mesh_.numElements());
  if (global.size() != fields_.global.size())
    throw std::runtime_error(path_ + ": " + std::to_string(global.size()) + " global variables given, " +
                             std::to_string(fields_.global.size()) + " declared");

  int cpuWordSize = 8, ioWordSize = 0;
  float version = 0;
  const int id = ex_open(path_.c_str(), EX_WRITE, &cpuWordSize, &ioWordSize, &version);
  if (id < 0) fail(path_, "cannot reopen the Exodus file to write step " + std::to_string(steps_ + 1));
  ExodusFile file(path_, id);
  const int step = steps_ + 1;  // Exodus steps count from 1
  const std::string what = "step " + std::to_string(step);
  check(ex_put_time(id, step, &time), path_, what + " time");
  for (size_t v = 0; v < nodal.size(); ++v)
    check(ex_put_nodal_var(id, step, static_cast<int>(v) + 1, mesh_.numNodes(), nodal[v].data()), path_,
          what + " nodal variable '" + fields_.nodal[v] + "'");
  std::vector<double> blockValues;
  for (size_t v = 0; v < element.size(); ++v)
    for (size_t b = 0; b < mesh_.blocks.size(); ++b) {
      const auto& block = mesh_.blocks[b];
      if (block.numElements() == 0) continue;
      blockValues.clear();
      for (GlobalIndex e : block.elements) blockValues.push_back(element[v][e]);
      check(ex_put_elem_var(id, step, static_cast<int>(v) + 1, static_cast<int64_t>(b) + 1, block.numElements(),
                            blockValues.data()),
            path_, what + " element variable '" + fields_.element[v] + "' on block '" + block.name + "'");
    }
  if (!global.empty())
    check(ex_put_glob_vars(id, step, static_cast<int>(global.size()), global.data()), path_,
          what + " global variables");
  check(file.close(), path_, what + " (close)");
  steps_ = step;
}

}  // namespace contessa::io
