// write_family_exodus DIR: the committed Gmsh-made Tet10 and Hex20 (and Hex20 + Wedge15) meshes of
// tests/unit/mesh/gmsh, read by Contessa's Gmsh reader and written by its ExodusWriter (io package,
// the solver's results writer) to DIR/tet10.exo, DIR/hex20.exo and DIR/hex20_wedge15.exo, with one nodal
// field (x · y · z, so a reader that dropped the mid-edge nodes would show other values). The files
// the pvbatch test tests/regression/mesh_input/paraview_quadratic.py opens.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "io/ExodusWriter.hpp"
#include "mesh/GmshMeshReader.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_family_exodus DIR\n");
    return 2;
  }
  try {
    for (const std::string stem : {"tet10", "hex20", "hex20_wedge15"}) {
      const auto mesh = contessa::mesh::readGmshMesh(std::string(CONTESSA_TEST_MESHES) + "/" + stem + ".msh");
      contessa::io::ExodusFields fields;
      fields.nodal = {"xyz"};
      contessa::io::ExodusWriter writer(std::string(argv[1]) + "/" + stem + ".exo", mesh, fields);
      std::vector<double> xyz(static_cast<std::size_t>(mesh.numNodes()));
      for (std::size_t n = 0; n < xyz.size(); ++n)
        xyz[n] = mesh.coordinates[3 * n] * mesh.coordinates[3 * n + 1] * mesh.coordinates[3 * n + 2];
      writer.writeStep(0.0, {xyz}, {}, {});
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "write_family_exodus: %s\n", e.what());
    return 1;
  }
  return 0;
}
