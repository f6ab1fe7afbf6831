#pragma once
// Whether a problem is a solid of revolution: decided by its blocks' elements ("Q4 Axisymmetric", "Q4
// Enhanced Axisymmetric": revolved about the y axis, r = x), checked against the mesh. Loads, contact
// areas and reported forces then refer to the full circumference.
#include <vector>

#include "deck/ProblemDefinition.hpp"

namespace contessa::deck {

/// True when every block's element is axisymmetric, false when none is. InputError naming the block's
/// Element when they are mixed, and naming the mesh when a node of the revolved mesh lies at x < 0 (the
/// far side of the axis, beyond round-off). Collective over the part's communicator: each rank checks its part of the mesh and
/// every rank throws the lowest failing rank's message.
bool axisymmetricProblem(const std::vector<BlockPhysics>& blocks, const mesh::DistributedMesh& part);

}  // namespace contessa::deck
