#pragma once
// Read access to an Exodus II results file (as written by ExodusWriter), for tests and tools.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace contessa::io {

/// Opens the file for the object's lifetime. Steps are indexed from 0 (Exodus step k+1). Element
/// values are concatenated over the blocks that define the variable, in file order, which is the
/// global element order of meshes from readExodusMesh and the generators (a results file's line
/// blocks define no element variable). Nodal values cover every node of the file: the mesh nodes,
/// then the points of line blocks. Unknown names, out-of-range steps and read
/// failures throw contessa::InputError naming the file.
class ExodusResults {
 public:
  explicit ExodusResults(const std::string& path);
  ~ExodusResults();
  ExodusResults(ExodusResults&&) noexcept;
  ExodusResults& operator=(ExodusResults&&) noexcept;

  const std::string& path() const;
  int numSteps() const;
  std::vector<double> times() const;

  const std::vector<std::string>& nodalNames() const;
  const std::vector<std::string>& elementNames() const;
  const std::vector<std::string>& globalNames() const;
  const std::vector<std::string>& blockNames() const;
  const std::vector<std::string>& blockTypes() const;  ///< "QUAD4", "BAR2", ...
  std::int64_t numNodes() const;
  /// QA records (code, version, date, time) and information records, as stored.
  std::vector<std::array<std::string, 4>> qaRecords() const;
  std::vector<std::string> infoRecords() const;

  std::vector<double> nodal(const std::string& name, int step) const;
  std::vector<double> element(const std::string& name, int step) const;
  double global(const std::string& name, int step) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace contessa::io
