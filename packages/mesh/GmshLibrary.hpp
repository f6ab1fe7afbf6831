#pragma once
// The calls the Gmsh mesh reader makes into the Gmsh library, behind an interface. The library is a
// module loaded when the first .msh file is read, not linked into the program: Debian's libgmsh pulls
// in OpenCASCADE, FLTK, X11 and image libraries (80 of the program's 208 shared libraries), whose
// loading and symbol relocation took more than half of every run's start-up (bench/README.md).
#include <string>
#include <utility>
#include <vector>

namespace contessa::mesh {

/// Gmsh 4.8's C++ API (gmsh.h), as far as the reader needs it; errors are thrown as Gmsh throws them
/// (a std::string).
class GmshLibrary {
 public:
  virtual ~GmshLibrary() = default;
  /// Initialises Gmsh without configuration files and with nothing printed.
  virtual void initialize() = 0;
  virtual void finalize() = 0;
  virtual void open(const std::string& path) = 0;
  virtual void getPhysicalGroups(std::vector<std::pair<int, int>>& dimTags) = 0;
  virtual void getPhysicalName(int dim, int tag, std::string& name) = 0;
  virtual void getEntitiesForPhysicalGroup(int dim, int tag, std::vector<int>& entities) = 0;
  virtual void getElements(std::vector<int>& types, std::vector<std::vector<std::size_t>>& tags,
                           std::vector<std::vector<std::size_t>>& nodes, int dim, int entity) = 0;
  /// The element type's name as Gmsh gives it ("Hexahedron 8").
  virtual std::string elementTypeName(int type) = 0;
  virtual void getNodes(std::vector<std::size_t>& tags, std::vector<double>& xyz) = 0;
};

/// The module's library, loaded at the first call. Throws InputError naming the module (and the
/// loader's reason) when it cannot be loaded.
GmshLibrary& gmshLibrary();

}  // namespace contessa::mesh
