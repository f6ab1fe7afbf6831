#pragma once
// The rigid-body modes of a solid: the near-null space an algebraic multigrid preconditioner (MueLu
// smoothed aggregation) needs to build coarse spaces that represent elasticity. Without them its
// coarse spaces hold only translations and the iteration count grows with the mesh size.
// Pure C++ (no Trilinos): the solver factory copies the modes into a Tpetra multivector.
#include <array>
#include <vector>

namespace contessa::solvers {

/// 3 in 2D (two translations, the rotation about z), 6 in 3D (three translations, three rotations).
int rigidBodyModeCount(int dim);

/// The rigid-body modes of `coordinates.size() / dim` nodes (coordinates node-major, `dim` per node),
/// in the DOF layout node · dim + component: translations along x, y [, z], then the small rotations
/// e_a × (X − center) about z (2D) or about x, y, z (3D). `center` (e.g. the centroid) keeps the
/// rotations of the size of the translations. Mode m, DOF i at [m · coordinates.size() + i].
std::vector<double> rigidBodyModes(int dim, const std::vector<double>& coordinates, const std::array<double, 3>& center);

/// The centroid of the nodes (coordinates node-major).
std::array<double, 3> centroid(int dim, const std::vector<double>& coordinates);

}  // namespace contessa::solvers
