#include "io/ExodusResults.hpp"

#include <algorithm>
#include <cstdint>

#include "common/Error.hpp"
#include "mesh/ExodusFile.hpp"

namespace contessa::io {

using mesh::detail::ExodusFile;

struct ExodusResults::Impl {
  ExodusFile file;
  size_t nameLength = 32;
  int64_t numNodes = 0;
  std::vector<int64_t> blockIds;
  std::vector<int64_t> blockSizes;
  std::vector<std::string> blockNames, blockTypes;
  std::vector<int> truth;  ///< element variable v is defined on block b when truth[b * count + v]
  std::vector<std::string> nodalNames, elementNames, globalNames;

  Impl(const std::string& path, int id) : file(path, id) {}

  const std::string& path() const { return file.path(); }

  void check(int status, const std::string& what) const {
    if (status < 0) {
      const std::string detail = ExodusFile::lastError();
      throw InputError(path() + ": cannot read " + what + (detail.empty() ? "" : " (" + detail + ")"));
    }
  }

  std::vector<std::string> variableNames(ex_entity_type type, const char* what) const {
    int count = 0;
    check(ex_get_variable_param(file.id(), type, &count), what);
    if (count <= 0) return {};
    std::vector<std::vector<char>> buffers(static_cast<size_t>(count), std::vector<char>(nameLength + 1, '\0'));
    std::vector<char*> pointers;
    for (auto& b : buffers) pointers.push_back(b.data());
    check(ex_get_variable_names(file.id(), type, count, pointers.data()), what);
    std::vector<std::string> names;
    for (auto& b : buffers) names.emplace_back(b.data());
    return names;
  }

  // Exodus variable index (1-based) of `name`, or an error listing the known names.
  int index(const std::vector<std::string>& names, const std::string& name, const char* kind) const {
    auto it = std::find(names.begin(), names.end(), name);
    if (it != names.end()) return static_cast<int>(it - names.begin()) + 1;
    std::string known;
    for (const auto& n : names) known += (known.empty() ? "" : ", ") + n;
    throw InputError(path() + ": " + kind + " variable '" + name + "' does not exist (known: " +
                     (known.empty() ? "none" : known) + ")");
  }

  int numSteps() const {
    const int64_t steps = ex_inquire_int(file.id(), EX_INQ_TIME);
    check(steps < 0 ? -1 : 0, "the number of steps");
    return static_cast<int>(steps);
  }

  // Exodus step number (1-based) of a 0-based step index.
  int exodusStep(int step) const {
    const int n = numSteps();
    requireInput(step >= 0 && step < n, path() + ": step " + std::to_string(step) + " does not exist (the file has " +
                                            std::to_string(n) + " steps, indexed from 0)");
    return step + 1;
  }
};

ExodusResults::ExodusResults(const std::string& path) {
  int cpuWordSize = 8, ioWordSize = 0;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ | EX_ALL_INT64_API, &cpuWordSize, &ioWordSize, &version);
  requireInput(id >= 0, path + ": cannot open Exodus file");
  impl_ = std::make_unique<Impl>(path, id);
  // Names longer than the library's default of 32 characters would be truncated otherwise.
  const int64_t nameLength = std::max<int64_t>(32, ex_inquire_int(id, EX_INQ_DB_MAX_USED_NAME_LENGTH));
  impl_->check(ex_set_max_name_length(id, static_cast<int>(nameLength)), "the name length");
  impl_->nameLength = static_cast<size_t>(nameLength);

  ex_init_params init{};
  impl_->check(ex_get_init_ext(id, &init), "the header");
  impl_->numNodes = init.num_nodes;
  impl_->blockIds.resize(static_cast<size_t>(init.num_elem_blk));
  if (init.num_elem_blk > 0) impl_->check(ex_get_ids(id, EX_ELEM_BLOCK, impl_->blockIds.data()), "element block ids");
  for (int64_t blockId : impl_->blockIds) {
    ex_block block{};
    block.id = blockId;
    block.type = EX_ELEM_BLOCK;
    impl_->check(ex_get_block_param(id, &block), "element block " + std::to_string(blockId));
    impl_->blockSizes.push_back(block.num_entry);
    impl_->blockTypes.emplace_back(block.topology);
  }
  if (init.num_elem_blk > 0) {
    std::vector<std::vector<char>> buffers(impl_->blockIds.size(), std::vector<char>(impl_->nameLength + 1, '\0'));
    std::vector<char*> pointers;
    for (auto& b : buffers) pointers.push_back(b.data());
    impl_->check(ex_get_names(id, EX_ELEM_BLOCK, pointers.data()), "element block names");
    for (auto& b : buffers) impl_->blockNames.emplace_back(b.data());
  }
  impl_->nodalNames = impl_->variableNames(EX_NODAL, "nodal variable names");
  impl_->elementNames = impl_->variableNames(EX_ELEM_BLOCK, "element variable names");
  impl_->truth.assign(impl_->blockIds.size() * impl_->elementNames.size(), 1);
  if (!impl_->truth.empty())
    impl_->check(ex_get_truth_table(id, EX_ELEM_BLOCK, static_cast<int>(impl_->blockIds.size()),
                                    static_cast<int>(impl_->elementNames.size()), impl_->truth.data()),
                 "the element variable truth table");
  impl_->globalNames = impl_->variableNames(EX_GLOBAL, "global variable names");
}

ExodusResults::~ExodusResults() = default;
ExodusResults::ExodusResults(ExodusResults&&) noexcept = default;
ExodusResults& ExodusResults::operator=(ExodusResults&&) noexcept = default;

const std::string& ExodusResults::path() const { return impl_->path(); }
int ExodusResults::numSteps() const { return impl_->numSteps(); }
const std::vector<std::string>& ExodusResults::nodalNames() const { return impl_->nodalNames; }
const std::vector<std::string>& ExodusResults::elementNames() const { return impl_->elementNames; }
const std::vector<std::string>& ExodusResults::globalNames() const { return impl_->globalNames; }

const std::vector<std::string>& ExodusResults::blockNames() const { return impl_->blockNames; }
const std::vector<std::string>& ExodusResults::blockTypes() const { return impl_->blockTypes; }
int64_t ExodusResults::numNodes() const { return impl_->numNodes; }

std::vector<std::array<std::string, 4>> ExodusResults::qaRecords() const {
  const int64_t count = ex_inquire_int(impl_->file.id(), EX_INQ_QA);
  impl_->check(count < 0 ? -1 : 0, "the number of QA records");
  std::vector<std::array<std::string, 4>> records(static_cast<size_t>(count));
  if (count == 0) return records;
  std::vector<std::array<std::vector<char>, 4>> buffers(records.size());
  std::vector<std::array<char*, 4>> pointers(records.size());
  for (size_t r = 0; r < records.size(); ++r)
    for (int k = 0; k < 4; ++k) {
      buffers[r][k].assign(MAX_STR_LENGTH + 1, '\0');
      pointers[r][k] = buffers[r][k].data();
    }
  impl_->check(ex_get_qa(impl_->file.id(), reinterpret_cast<char* (*)[4]>(pointers.data())), "the QA records");
  for (size_t r = 0; r < records.size(); ++r)
    for (int k = 0; k < 4; ++k) records[r][k] = buffers[r][k].data();
  return records;
}

std::vector<std::string> ExodusResults::infoRecords() const {
  const int64_t count = ex_inquire_int(impl_->file.id(), EX_INQ_INFO);
  impl_->check(count < 0 ? -1 : 0, "the number of information records");
  std::vector<std::vector<char>> buffers(static_cast<size_t>(count), std::vector<char>(MAX_LINE_LENGTH + 1, '\0'));
  std::vector<char*> pointers;
  for (auto& b : buffers) pointers.push_back(b.data());
  if (count > 0) impl_->check(ex_get_info(impl_->file.id(), pointers.data()), "the information records");
  std::vector<std::string> records;
  for (auto& b : buffers) records.emplace_back(b.data());
  return records;
}

std::vector<double> ExodusResults::times() const {
  std::vector<double> result(static_cast<size_t>(numSteps()));
  if (!result.empty()) impl_->check(ex_get_all_times(impl_->file.id(), result.data()), "the step times");
  return result;
}

std::vector<double> ExodusResults::nodal(const std::string& name, int step) const {
  const int variable = impl_->index(impl_->nodalNames, name, "nodal");
  std::vector<double> values(static_cast<size_t>(impl_->numNodes));
  if (!values.empty())
    impl_->check(ex_get_nodal_var(impl_->file.id(), impl_->exodusStep(step), variable, impl_->numNodes, values.data()),
                 "nodal variable '" + name + "'");
  return values;
}

std::vector<double> ExodusResults::element(const std::string& name, int step) const {
  const int variable = impl_->index(impl_->elementNames, name, "element");
  const int exodusStep = impl_->exodusStep(step);
  std::vector<double> values;
  std::vector<double> blockValues;
  for (size_t b = 0; b < impl_->blockIds.size(); ++b) {
    if (!impl_->truth[b * impl_->elementNames.size() + static_cast<size_t>(variable) - 1]) continue;
    blockValues.assign(static_cast<size_t>(impl_->blockSizes[b]), 0.0);
    if (!blockValues.empty())
      impl_->check(ex_get_elem_var(impl_->file.id(), exodusStep, variable, impl_->blockIds[b], impl_->blockSizes[b],
                                   blockValues.data()),
                   "element variable '" + name + "' on block " + std::to_string(impl_->blockIds[b]));
    values.insert(values.end(), blockValues.begin(), blockValues.end());
  }
  return values;
}

double ExodusResults::global(const std::string& name, int step) const {
  const int variable = impl_->index(impl_->globalNames, name, "global");
  std::vector<double> values(impl_->globalNames.size());
  impl_->check(ex_get_glob_vars(impl_->file.id(), impl_->exodusStep(step), static_cast<int>(values.size()),
                                values.data()),
               "global variables");
  return values[static_cast<size_t>(variable) - 1];
}

}  // namespace contessa::io
