#pragma once
// Exodus II results file (netCDF-4/HDF5 flavour), written on one rank with the whole mesh. The file
// stays open for the run and every step is flushed out of the process (ex_update: HDF5 hands its
// buffers to the operating system; no fsync) before writeStep returns, after the disk space it needs
// has been reserved: whatever happens to the process later (a kill -9, a crash, a full disk), the file
// is valid and holds every step written so far.
#include <array>
#include <string>
#include <vector>

#include "mesh/Mesh.hpp"

namespace contessa::io {

class ExodusResults;

struct ExodusFields {
  std::vector<std::string> nodal;    ///< e.g. displ_x, displ_y, contact_pressure
  std::vector<std::string> element;  ///< e.g. stress_xx, von_mises (defined on every mesh block)
  std::vector<std::string> global;   ///< e.g. load_factor, step_size
};

/// A surface drawn as its own element block next to the mesh, e.g. a rigid contact surface: 2-node line
/// elements (BAR2) in 2D, 4-node shells (SHELL4, which ParaView draws as surfaces) in 3D. Its points are
/// appended after the mesh nodes (blocks in order), so nodal values cover them too; no element variable
/// is defined on it.
struct ExodusSurfaceBlock {
  std::string name;
  std::vector<double> points;  ///< point-major: x0 y0 [z0] x1 y1 [z1] ...
  int nodesPerElement = 2;     ///< 2: BAR2, 4: SHELL4
  std::vector<mesh::GlobalIndex> connectivity;  ///< 0-based point indices, nodesPerElement per element

  mesh::GlobalIndex numElements() const {
    return static_cast<mesh::GlobalIndex>(connectivity.size()) / nodesPerElement;
  }
};

/// One file of a spatially decomposed set (`name.exo.N.r`, N files, this one rank r's): the global ids
/// that let ParaView and SEACAS `epu` put the pieces together, and the Nemesis decomposition records
/// (which nodes lie on the border with which other pieces).
struct ExodusDecomposition {
  int processor = 0, processors = 1;
  std::vector<mesh::GlobalIndex> globalNodes;     ///< 0-based global id of each node of the file (surface points too)
  std::vector<mesh::GlobalIndex> globalElements;  ///< 0-based global id of each element of the file (surface elements too)
  mesh::GlobalIndex globalNumNodes = 0, globalNumElements = 0;  ///< of the whole set
  std::vector<mesh::GlobalIndex> globalBlockSizes;  ///< elements of each block over the whole set
  /// Nodes of each node set and sides of each side set over the whole set, in the piece's set order
  /// (empty: the piece's own sizes are written).
  std::vector<mesh::GlobalIndex> globalNodeSetSizes, globalSideSetSizes;
  /// For each mesh node of the file, the other processors whose files hold it (empty: interior).
  std::vector<std::vector<int>> sharedWith;
};

/// What the file says about the run besides the results.
struct ExodusRecords {
  std::string title = "Contessa results";  ///< cut to 80 characters
  /// QA records: code name, code version, date, time (each cut to 32 characters).
  std::vector<std::array<std::string, 4>> qa;
  /// Information records: lines of free text, each split into records of at most 80 characters
  /// (infoRecords).
  std::vector<std::string> info;
};

/// Splits lines into Exodus information records of at most 80 characters: a longer line continues
/// on the next record, and every record but the last piece of a line ends with a backslash.
std::vector<std::string> infoRecords(const std::vector<std::string>& lines);

/// HDF5 takes an exclusive lock on a file it writes, for as long as the file is open, unless told not
/// to; the results file is open for the whole run, so ParaView or a netCDF script could not open it
/// before the run ends (and the run could not reopen a file a reader holds). Sets
/// HDF5_USE_FILE_LOCKING=FALSE for this process. HDF5 reads the variable once, when the library
/// initialises (its first call, e.g. reading an Exodus mesh): call this before any Exodus or netCDF
/// call. Runs are kept apart by OutputLock instead.
void disableHdf5FileLocking();

/// When the file takes its name: a mesh file as soon as it is created; a run's results file at its
/// first step, so that a run that writes no step leaves no file, and a file of an earlier run under
/// that name is kept until the new run has a step to show.
enum class ExodusNaming { AtCreation, AtFirstStep };

class ExodusWriter {
 public:
  /// Creates (clobbers) `path` and writes the mesh (coordinates, blocks, node sets, side sets, names),
  /// the surface blocks, the records and the variable names, and flushes it. Throws OutputWriteError
  /// naming `path` when it cannot be created or written, and removes what it had made of the file.
  /// ExodusNaming::AtFirstStep: the file is made as `path`.starting; the first step renames it to
  /// `path` (replacing a file of an earlier run only then), and a writer destroyed before any step
  /// removes it.
  /// With `decomposition`, the file is one piece of a decomposed set: `mesh` is the piece (numbered
  /// from 0), and the global ids and Nemesis records are written too.
  ExodusWriter(const std::string& path, const mesh::Mesh& mesh, const ExodusFields& fields,
               const ExodusRecords& records = {}, const std::vector<ExodusSurfaceBlock>& surfaceBlocks = {},
               const ExodusDecomposition* decomposition = nullptr, ExodusNaming naming = ExodusNaming::AtCreation);
  ExodusWriter(const std::string& path, const mesh::Mesh& mesh, const ExodusFields& fields, const std::string& title)
      : ExodusWriter(path, mesh, fields, ExodusRecords{title, {}, {}}) {}
  /// Closes the file.
  ~ExodusWriter();
  ExodusWriter(const ExodusWriter&) = delete;
  ExodusWriter& operator=(const ExodusWriter&) = delete;

  /// Appends one output step and flushes it (the first one then gives the file its name). nodal[v][node] over the mesh nodes then the surface
  /// blocks' points, element[v][global element] over the mesh elements, global[v]. Values of the wrong size
  /// throw std::runtime_error; a failed write throws OutputWriteError (a runtime_error too), and the
  /// file keeps the steps written before (no step is written after a failure).
  void writeStep(double time, const std::vector<std::vector<double>>& nodal,
                 const std::vector<std::vector<double>>& element, const std::vector<double>& global);

  /// Appends the first `steps` steps of `source` (a results file of the same mesh and variables, e.g. the
  /// one a restarted run replaces): their times and every variable this file defines. Throws InputError
  /// naming `source` when it has fewer steps or lacks a variable.
  void copySteps(const ExodusResults& source, int steps);

  int stepsWritten() const { return steps_; }
  const std::string& path() const { return path_; }
  /// Mesh nodes plus surface-block points: the length of every nodal variable.
  mesh::GlobalIndex numNodes() const { return numNodes_; }

 private:
  /// Creates the file under its starting name with its disk space reserved (twice `meshBytes`, before
  /// and after HDF5 truncates it): sets startingPath_, spaceFd_ and id_; OutputWriteError, and nothing
  /// left on disk, when that fails.
  void createFile(ExodusNaming naming, long long meshBytes);

  std::string path_;
  std::string startingPath_;  ///< where the file is until its first step
  /// Per mesh block: its name and the elements' indices into an element variable (the mesh itself is not
  /// kept: the caller may free it once the file is created).
  struct BlockElements {
    std::string name;
    std::vector<mesh::GlobalIndex> elements;
  };
  std::vector<BlockElements> blocks_;
  mesh::GlobalIndex numElements_ = 0;
  ExodusFields fields_;
  mesh::GlobalIndex numNodes_ = 0;
  int id_ = -1;          ///< Exodus file id
  int spaceFd_ = -1;     ///< the same file, opened to reserve disk space (DiskSpace.hpp)
  long long stepBytes_ = 0;  ///< the largest growth of the file by one step so far
  int steps_ = 0;
  bool failed_ = false;
};

}  // namespace contessa::io
