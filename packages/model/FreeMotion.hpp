#pragma once
// Words for the null space of a singular stiffness matrix: which blocks can move without resistance,
// and how (translation along an axis, rotation about an axis through the block's centroid, or a
// mechanism that is no rigid-body motion). A model with too few supports has such a null space; the
// linear solver finds it (MUMPS' null pivots, MumpsSolver.cpp) and the run stops with this text.
// Pure C++ over the replicated mesh, so every rank composes the same sentence.
#include <string>
#include <vector>

#include "mesh/Mesh.hpp"

namespace contessa::model {

/// `nullSpace`: vectors over all DOFs in global numbering (node · dimension + component), each a
/// displacement field W v = 0. Returns e.g. "block 'block_1' is free to translate in y" or
/// "block 'ring' is free to translate in x and rotate about z"; several sentences are joined by "; ".
std::string describeFreeMotion(const mesh::Mesh& mesh, const std::vector<std::vector<double>>& nullSpace);

}  // namespace contessa::model
