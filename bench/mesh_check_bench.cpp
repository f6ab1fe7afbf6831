// mesh_check_bench: time of Mesh::validate (every check a mesh gets on reading or generation) on
// 10^6-element meshes: a generated 1000 x 1000 Quad4 rectangle with its four boundary side sets, and
// a 100 x 100 x 100 Hex8 cube with six. Prints the median of 5 runs per mesh.
//   build/bin/mesh_check_bench
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "mesh/Generators.hpp"
#include "mesh/Mesh.hpp"

using namespace contessa::mesh;

namespace {

// n^3 unit hexahedra, Exodus node order, with side sets on the six faces of the cube.
Mesh cube(int n) {
  Mesh m;
  m.dimension = 3;
  const GlobalIndex p = n + 1;
  auto node = [p](GlobalIndex i, GlobalIndex j, GlobalIndex k) { return (k * p + j) * p + i; };
  m.coordinates.reserve(static_cast<size_t>(3 * p * p * p));
  for (int k = 0; k <= n; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) m.coordinates.insert(m.coordinates.end(), {double(i), double(j), double(k)});
  ElementBlock b{"cube", CellType::Hex8, {}, {}};
  std::vector<SideSet> faces = {{"y_min", {}, {}}, {"x_max", {}, {}}, {"y_max", {}, {}},
                                {"x_min", {}, {}}, {"z_min", {}, {}}, {"z_max", {}, {}}};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const GlobalIndex e = static_cast<GlobalIndex>(b.elements.size());
        b.elements.push_back(e);
        for (GlobalIndex v : {node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                              node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)})
          b.connectivity.push_back(v);
        // Exodus HEX8 sides (0-based): 0 y-, 1 x+, 2 y+, 3 x-, 4 z-, 5 z+.
        const bool on[6] = {j == 0, i == n - 1, j == n - 1, i == 0, k == 0, k == n - 1};
        for (int s = 0; s < 6; ++s)
          if (on[s]) {
            faces[s].elements.push_back(e);
            faces[s].sides.push_back(s);
          }
      }
  m.blocks.push_back(std::move(b));
  m.sideSets = std::move(faces);
  return m;
}

double medianSeconds(const Mesh& mesh) {
  std::vector<double> times;
  for (int run = 0; run < 5; ++run) {
    const auto start = std::chrono::steady_clock::now();
    mesh.validate("bench");
    times.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(times.begin(), times.end());
  return times[2];
}

}  // namespace

int main() {
  RectangleSpec spec;
  spec.nx = spec.ny = 1000;
  const Mesh plate = generateRectangle(spec);
  std::printf("Quad4 1000 x 1000:      %lld elements, %lld nodes: validate %.3f s\n",
              static_cast<long long>(plate.numElements()), static_cast<long long>(plate.numNodes()),
              medianSeconds(plate));
  const Mesh hexes = cube(100);
  std::printf("Hex8 100 x 100 x 100:   %lld elements, %lld nodes: validate %.3f s\n",
              static_cast<long long>(hexes.numElements()), static_cast<long long>(hexes.numNodes()),
              medianSeconds(hexes));
  return 0;
}
