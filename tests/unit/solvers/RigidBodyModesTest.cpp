// The rigid-body modes given to MueLu (solvers/RigidBodyModes.hpp): dim translations and the small
// rotations, in the node-major DOF layout node * dim + component. A small rigid motion keeps every
// distance to first order: (u_j - u_k) . (x_j - x_k) = 0 for every pair of nodes, which is what makes
// them the null space of an unsupported elastic stiffness.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solvers/RigidBodyModes.hpp"

namespace contessa::solvers {
namespace {

// Irregular nodes (no symmetry that could hide a sign or index error).
std::vector<double> nodes(int dim) {
  const std::vector<double> xyz = {0.3, -1.2, 2.0, 1.7, 0.4, -0.5, -0.8, 2.2, 1.1, 2.5, 1.9, 0.7, 0.1, 0.2, -1.4};
  std::vector<double> out;
  for (int n = 0; n < 5; ++n)
    for (int c = 0; c < dim; ++c) out.push_back(xyz[3 * n + c]);
  return out;
}

class RigidBodyModes : public ::testing::TestWithParam<int> {};

TEST_P(RigidBodyModes, CountAndLayout) {
  const int dim = GetParam();
  const auto x = nodes(dim);
  const auto modes = rigidBodyModes(dim, x, centroid(dim, x));
  ASSERT_EQ(rigidBodyModeCount(dim), dim == 2 ? 3 : 6);
  ASSERT_EQ(modes.size(), static_cast<std::size_t>(rigidBodyModeCount(dim)) * x.size());
  // The first dim modes are unit translations: component c of every node is 1, the others 0.
  for (int m = 0; m < dim; ++m)
    for (std::size_t i = 0; i < x.size(); ++i)
      EXPECT_EQ(modes[m * x.size() + i], static_cast<int>(i % dim) == m ? 1.0 : 0.0) << "mode " << m << " dof " << i;
}

TEST_P(RigidBodyModes, RotationsKeepDistancesToFirstOrder) {
  const int dim = GetParam();
  const auto x = nodes(dim);
  const auto modes = rigidBodyModes(dim, x, centroid(dim, x));
  const std::size_t n = x.size() / dim;
  for (int m = dim; m < rigidBodyModeCount(dim); ++m) {
    const double* u = &modes[m * x.size()];
    double size = 0;
    for (std::size_t i = 0; i < x.size(); ++i) size = std::max(size, std::abs(u[i]));
    EXPECT_GT(size, 0.5) << "mode " << m << " is (nearly) zero";
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < n; ++k) {
        double dot = 0;
        for (int c = 0; c < dim; ++c) dot += (u[j * dim + c] - u[k * dim + c]) * (x[j * dim + c] - x[k * dim + c]);
        EXPECT_NEAR(dot, 0.0, 1e-12) << "mode " << m << " nodes " << j << ", " << k;
      }
  }
}

TEST_P(RigidBodyModes, LinearlyIndependent) {
  // The Gram matrix of the modes is positive definite: a Cholesky factorisation succeeds with pivots
  // well away from zero.
  const int dim = GetParam();
  const auto x = nodes(dim);
  const auto modes = rigidBodyModes(dim, x, centroid(dim, x));
  const int count = rigidBodyModeCount(dim);
  std::vector<double> gram(count * count, 0.0);
  for (int a = 0; a < count; ++a)
    for (int b = 0; b < count; ++b)
      for (std::size_t i = 0; i < x.size(); ++i) gram[a * count + b] += modes[a * x.size() + i] * modes[b * x.size() + i];
  for (int k = 0; k < count; ++k) {
    for (int p = 0; p < k; ++p) gram[k * count + k] -= gram[k * count + p] * gram[k * count + p];
    ASSERT_GT(gram[k * count + k], 1e-3) << "pivot " << k;
    gram[k * count + k] = std::sqrt(gram[k * count + k]);
    for (int r = k + 1; r < count; ++r) {
      for (int p = 0; p < k; ++p) gram[r * count + k] -= gram[r * count + p] * gram[k * count + p];
      gram[r * count + k] /= gram[k * count + k];
    }
  }
}

TEST(RigidBodyModes2D, RotationAboutCentroid) {
  // Two nodes at (0, 0) and (2, 0): centroid (1, 0); the rotation about z moves them by ∓1 in y.
  const std::vector<double> x = {0.0, 0.0, 2.0, 0.0};
  const auto modes = rigidBodyModes(2, x, centroid(2, x));
  const std::vector<double> rotation(modes.begin() + 8, modes.end());
  EXPECT_EQ(rotation, (std::vector<double>{0.0, -1.0, 0.0, 1.0}));
}

INSTANTIATE_TEST_SUITE_P(Dimensions, RigidBodyModes, ::testing::Values(2, 3));

}  // namespace
}  // namespace contessa::solvers
