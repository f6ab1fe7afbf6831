#include "solvers/RigidBodyModes.hpp"

#include <stdexcept>

namespace contessa::solvers {

int rigidBodyModeCount(int dim) {
  if (dim != 2 && dim != 3) throw std::invalid_argument("rigidBodyModeCount: dimension must be 2 or 3");
  return dim == 2 ? 3 : 6;
}

std::array<double, 3> centroid(int dim, const std::vector<double>& coordinates) {
  std::array<double, 3> c{0.0, 0.0, 0.0};
  const std::size_t nodes = coordinates.size() / static_cast<std::size_t>(dim);
  if (nodes == 0) return c;
  for (std::size_t n = 0; n < nodes; ++n)
    for (int k = 0; k < dim; ++k) c[k] += coordinates[n * dim + k];
  for (int k = 0; k < dim; ++k) c[k] /= static_cast<double>(nodes);
  return c;
}

std::vector<double> rigidBodyModes(int dim, const std::vector<double>& coordinates, const std::array<double, 3>& center) {
  const int modes = rigidBodyModeCount(dim);
  const std::size_t size = coordinates.size();
  const std::size_t nodes = size / static_cast<std::size_t>(dim);
  std::vector<double> out(static_cast<std::size_t>(modes) * size, 0.0);
  // 2D rotates about z only (axis index 2); 3D about x, y and z.
  const int firstAxis = dim == 2 ? 2 : 0;
  for (std::size_t n = 0; n < nodes; ++n) {
    std::array<double, 3> r{0.0, 0.0, 0.0};
    for (int k = 0; k < dim; ++k) r[k] = coordinates[n * dim + k] - center[k];
    for (int c = 0; c < dim; ++c) out[static_cast<std::size_t>(c) * size + n * dim + c] = 1.0;
    for (int axis = firstAxis; axis < 3; ++axis) {
      // e_axis × r
      const std::array<double, 3> u = {axis == 1 ? r[2] : axis == 2 ? -r[1] : 0.0,
                                       axis == 0 ? -r[2] : axis == 2 ? r[0] : 0.0,
                                       axis == 0 ? r[1] : axis == 1 ? -r[0] : 0.0};
      const std::size_t m = static_cast<std::size_t>(dim + axis - firstAxis);
      for (int c = 0; c < dim; ++c) out[m * size + n * dim + c] = u[c];
    }
  }
  return out;
}

}  // namespace contessa::solvers
