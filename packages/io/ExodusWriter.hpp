#pragma once
// Exodus II results file (netCDF-4/HDF5 flavour), written on one rank with the whole mesh. Each
// step reopens, appends and closes the file, so the file stays valid up to the last step written
// even if the run dies later.
#include <string>
#include <vector>

#include "mesh/Mesh.hpp"

namespace contessa::io {

struct ExodusFields {
  std::vector<std::string> nodal;    ///< e.g. displ_x, displ_y, contact_pressure
  std::vector<std::string> element;  ///< e.g. stress_xx, von_mises (defined on every block)
  std::vector<std::string> global;   ///< e.g. load_factor, step_size
};

class ExodusWriter {
 public:
  /// Creates (clobbers) `path` and writes the mesh: coordinates, blocks, node sets, side sets, names.
  ExodusWriter(const std::string& path, const mesh::Mesh& mesh, const ExodusFields& fields,
               const std::string& title = "Contessa results");

  /// Appends one output step. nodal[v][node], element[v][global element], global[v].
  void writeStep(double time, const std::vector<std::vector<double>>& nodal,
                 const std::vector<std::vector<double>>& element, const std::vector<double>& global);

  int stepsWritten() const { return steps_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  const mesh::Mesh& mesh_;
  ExodusFields fields_;
  int steps_ = 0;
};

}  // namespace contessa::io
