#include "mechanics/ReferenceElement.hpp"

#include <cassert>
#include <cmath>

namespace contessa::mechanics {

std::vector<QuadraturePoint> gaussLegendreRule(int dimension, int n) {
  assert(dimension >= 1 && dimension <= kMaxDimension && n >= 1 && n <= 3);
  static const double kPoints[3][3] = {{0.0, 0.0, 0.0},
                                       {-1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0), 0.0},
                                       {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}};
  static const double kWeights[3][3] = {{2.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};
  int total = 1;
  for (int d = 0; d < dimension; ++d) total *= n;
  std::vector<QuadraturePoint> rule(total);
  for (int q = 0; q < total; ++q) {
    // ξ varies fastest, then η, then ζ.
    int rest = q;
    rule[q].weight = 1.0;
    for (int d = 0; d < dimension; ++d) {
      const int k = rest % n;
      rest /= n;
      rule[q].xi[d] = kPoints[n - 1][k];
      rule[q].weight *= kWeights[n - 1][k];
    }
  }
  return rule;
}

}  // namespace contessa::mechanics
