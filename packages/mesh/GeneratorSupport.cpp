#include "mesh/GeneratorSupport.hpp"

#include <cmath>
#include <sstream>

namespace contessa::mesh::generator {

std::string format(double value) {
  std::ostringstream out;
  out.precision(12);
  out << value;
  return out.str();
}

void requirePositive(double value, const char* parameter) {
  requireInput(std::isfinite(value) && value > 0,
               std::string(parameter) + ": expected a positive number, got " + format(value));
}

void requireFinite(double value, const char* parameter) {
  requireInput(std::isfinite(value), std::string(parameter) + ": expected a finite number, got " + format(value));
}

void requirePositiveCount(int value, const char* parameter) {
  requireInput(value > 0, std::string(parameter) + ": expected a positive integer, got " + std::to_string(value));
}

void requireBias(double value, const char* parameter) {
  requireInput(std::isfinite(value) && value > 0,
               std::string(parameter) + ": expected a value > 0, got " + format(value));
}

// Before anything is allocated: a grid of `counts` elements per direction (nodes counts+1 each, or
// `size` when given) must be indexable and its run must fit in memory (requireRunFits). Returns what
// the generator must say if an allocation fails all the same.
std::string requireFits(const MeshSize& size, const std::vector<std::pair<std::string, int>>& counts) {
  std::string what, advice;
  for (size_t k = 0; k < counts.size(); ++k) {
    what += (k ? ", " : "") + counts[k].first + " = " + std::to_string(counts[k].second);
    advice += (k == 0 ? "reduce " : k + 1 == counts.size() ? " or " : ", ") + counts[k].first;
  }
  requireRunFits(size, what, advice);
  return what + ": not enough memory for " + formatCount(size.elements) + " elements; " + advice;
}

std::string requireGridFits(const std::vector<std::pair<std::string, int>>& counts) {
  MeshSize size(1, 1, static_cast<int>(counts.size()));
  for (const auto& c : counts) {
    size.nodes *= c.second + 1.0;
    size.elements *= c.second;
  }
  return requireFits(size, counts);
}

// n+1 node positions from start to start + length (exactly, at both ends) with element sizes in a
// geometric progression whose last/first ratio is `bias`. bias = 1 reproduces start + length*i/n bit
// for bit. With L = ln(q), q = bias^(1/(n-1)), node i sits at the fraction (q^i − 1)/(q^n − 1),
// evaluated with expm1 so that q near 1 loses nothing to cancellation, and for q > 1 rewritten as
// q^(i−n)·(1 − q^−i)/(1 − q^−n) so that large biases cannot overflow.
std::vector<double> gradedPositions(double start, double length, int n, double bias, const char* parameter) {
  std::vector<double> x(static_cast<size_t>(n) + 1);
  const double L = n > 1 ? std::log(bias) / (n - 1) : 0.0;
  for (int i = 0; i < n; ++i) {
    if (L == 0) {
      x[i] = start + length * i / n;  // uniform: exactly as the ungraded generators computed it
      continue;
    }
    const double t = L < 0 ? std::expm1(i * L) / std::expm1(n * L)
                           : std::exp((i - n) * L) * (std::expm1(-i * L) / std::expm1(-n * L));
    x[i] = start + length * t;
  }
  x[n] = start + length;
  for (int i = 0; i < n; ++i)
    requireInput(x[i + 1] > x[i], std::string(parameter) + ": value " + format(bias) + " with " +
                                      std::to_string(n) + " elements makes elements too small to represent");
  return x;
}

// Local side (0-based Exodus) of a cell's face where reference coordinate ξ_axis is −1 (min) or +1
// (max): the same numbers for Quad4 edges (axes 0, 1) and Hex8 faces (axes 0, 1, 2).
int sideOfFace(int axis, bool max) {
  static const int kSides[3][2] = {{3, 1}, {0, 2}, {4, 5}};
  return kSides[axis][max ? 1 : 0];
}

}  // namespace contessa::mesh::generator
