#include "model/ForceRoundOff.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace contessa::model {

ForceRoundOff::ForceRoundOff(std::vector<double> reference, int dimension, bool axisymmetric)
    : reference_(std::move(reference)), squaredLevels_(reference_.size(), 0.0), dimension_(dimension), axisymmetric_(axisymmetric) {}

void ForceRoundOff::addElement(const int* dofs, int n, const double* stiffness) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const int nodes = n / dimension_;
  // d: each DOF's position relative to the element's mean position in its component (a translation of the
  // element is no strain), the radius itself for r in an axisymmetric mesh; the field d_c e_c is a unit
  // stretch along c, and K^e restricted to axis c's columns times d_c the element's forces under it.
  double mean[3] = {0.0, 0.0, 0.0};
  for (int a = 0; a < nodes; ++a)
    for (int c = 0; c < dimension_; ++c) mean[c] += reference_[static_cast<std::size_t>(dofs[a * dimension_ + c])] / nodes;
  stretch_.resize(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) {
    const int c = j % dimension_;
    const double X = reference_[static_cast<std::size_t>(dofs[j])];
    stretch_[static_cast<std::size_t>(j)] = axisymmetric_ && c == 0 ? X : X - mean[c];
  }
  // The stretches' roundings are independent from element to element and from component to component:
  // their forces add in squares (the probabilistic bound of Higham and Mary, SIAM J. Sci. Comput. 41,
  // 2019: √n ε instead of n ε).
  for (int i = 0; i < n; ++i) {
    double squares = 0.0;
    for (int c = 0; c < dimension_; ++c) {
      double force = 0.0;  // row i of the element's force under a unit stretch along c
      for (int j = c; j < n; j += dimension_) force += stiffness[i * n + j] * stretch_[static_cast<std::size_t>(j)];
      squares += eps * eps * force * force;
    }
    squaredLevels_[static_cast<std::size_t>(dofs[i])] += squares;
  }
}

}  // namespace contessa::model
