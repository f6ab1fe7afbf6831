#pragma once
// What the inline generators (Generators.hpp) share: the checks of their deck parameters (each error
// starts with the parameter's name, MeshFactory adds the deck path), the memory check before anything
// is allocated, graded node positions along an axis, and the Exodus side of a cell's face. Internal to
// packages/mesh.
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "common/Error.hpp"
#include "mesh/MemoryEstimate.hpp"

namespace contessa::mesh::generator {

/// A parameter's value in messages (12 significant digits).
std::string format(double value);

/// InputError "<parameter>: expected ..., got <value>" unless the value is as named.
void requirePositive(double value, const char* parameter);
void requireFinite(double value, const char* parameter);
void requirePositiveCount(int value, const char* parameter);
void requireBias(double value, const char* parameter);

/// Before anything is allocated: a mesh of `size` (a grid of `counts` elements per direction for
/// requireGridFits) must be indexable and its run must fit in memory (requireRunFits). Returns what
/// the generator must say if an allocation fails all the same.
std::string requireFits(const MeshSize& size, const std::vector<std::pair<std::string, int>>& counts);
std::string requireGridFits(const std::vector<std::pair<std::string, int>>& counts);

/// generate(), with an allocation failure turned into InputError(outOfMemoryMessage): the message the
/// generator's parameter check returned, so the check runs before anything is allocated.
template <class Generate>
auto guardAllocation(const std::string& outOfMemoryMessage, Generate&& generate) {
  try {
    return generate();
  } catch (const std::bad_alloc&) {
    throw InputError(outOfMemoryMessage);
  }
}

/// n+1 node positions from start to start + length (exactly, at both ends) with element sizes in a
/// geometric progression whose last/first ratio is `bias` (bias = 1 reproduces start + length*i/n bit
/// for bit). `parameter` names the bias in the error when elements become too small to represent.
std::vector<double> gradedPositions(double start, double length, int n, double bias, const char* parameter);

/// Local side (0-based Exodus) of a cell's face where reference coordinate ξ_axis is −1 (min) or +1
/// (max): the same numbers for Quad4 edges (axes 0, 1) and Hex8 faces (axes 0, 1, 2).
int sideOfFace(int axis, bool max);

}  // namespace contessa::mesh::generator
