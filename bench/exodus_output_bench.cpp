// Cost of the Exodus output per increment, as the tube's run writes it: the tube's mesh (annulus
// sector, 13 x 101 elements, 1428 nodes), 6 nodal variables (displacements and the 4 contact fields),
// 5 element variables (stresses), 11 globals, 48 steps (the fixed-step run: lambda = 0 and 47
// increments). Prints the time to create the file and the median and mean time per step over
// `repeats` files (each a fresh file in DIR).
//   build/bin/exodus_output_bench [DIR] [repeats]
// Uses only ExodusWriter(path, mesh, fields, title) and writeStep, so that the same program can be
// built against an older io package to compare.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

#include "io/ExodusWriter.hpp"
#include "mesh/Generators.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  using namespace contessa;
  const std::string dir = argc > 1 ? argv[1] : "/tmp";
  const int repeats = argc > 2 ? std::stoi(argv[2]) : 5;
  mesh::AnnulusSectorSpec spec;
  spec.blockName = "tube";
  const mesh::Mesh mesh = mesh::generateAnnulusSector(spec);
  io::ExodusFields fields;
  fields.nodal = {"displ_x", "displ_y", "contact_pressure", "contact_gap", "contact_status", "contact_slip"};
  fields.element = {"stress_xx", "stress_yy", "stress_zz", "stress_xy", "von_mises"};
  fields.global = {"load_factor",      "step_size",        "beta",           "active_contacts",
                   "newton_iterations", "reaction_end_x",  "reaction_end_y", "reaction_start_x",
                   "reaction_start_y", "contact_force_plate_x", "contact_force_plate_y"};
  const int steps = 48;
  const auto nodes = static_cast<std::size_t>(mesh.numNodes());
  const auto elements = static_cast<std::size_t>(mesh.numElements());

  std::vector<double> create, perStep;
  for (int r = 0; r < repeats; ++r) {
    const std::string path = dir + "/exodus_output_bench_" + std::to_string(r) + ".exo";
    auto start = Clock::now();
    {
      io::ExodusWriter writer(path, mesh, fields, "exodus_output_bench");
      create.push_back(msSince(start));
      for (int s = 0; s < steps; ++s) {
        const double lambda = s / double(steps - 1);
        std::vector<std::vector<double>> nodal(fields.nodal.size(), std::vector<double>(nodes));
        for (std::size_t v = 0; v < nodal.size(); ++v)
          for (std::size_t n = 0; n < nodes; ++n) nodal[v][n] = lambda * (1.0 + v + 1e-3 * n);
        std::vector<std::vector<double>> element(fields.element.size(), std::vector<double>(elements));
        for (std::size_t v = 0; v < element.size(); ++v)
          for (std::size_t e = 0; e < elements; ++e) element[v][e] = lambda * (2.0 + v + 1e-3 * e);
        std::vector<double> global(fields.global.size(), lambda);
        start = Clock::now();
        writer.writeStep(lambda, nodal, element, global);
        perStep.push_back(msSince(start));
      }
    }
    std::remove(path.c_str());
  }
  const double mean = std::accumulate(perStep.begin(), perStep.end(), 0.0) / perStep.size();
  std::printf("Exodus output of the tube (%zu nodes, %zu elements, %zu nodal, %zu element, %zu global variables), "
              "%d steps x %d files in %s\n",
              nodes, elements, fields.nodal.size(), fields.element.size(), fields.global.size(), steps, repeats,
              dir.c_str());
  std::printf("create: median %.2f ms\n", median(create));
  std::printf("per step: median %.2f ms, mean %.2f ms; %d steps: %.0f ms\n", median(perStep), mean, steps,
              mean * steps);
  return 0;
}
