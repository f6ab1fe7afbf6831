#include "mechanics/Element.hpp"

#include <cmath>

namespace contessa::mechanics {

double vonMises(const Tensor2& sigma) {
  // sqrt(3/2 s : s) with s the deviator; for plane strain σ_zz ≠ 0 and must be included.
  const double mean = trace(sigma) / 3.0;
  Tensor2 s = sigma;
  for (int i = 0; i < 3; ++i) s[idx2(i, i)] -= mean;
  return std::sqrt(1.5 * doubleContraction(s, s));
}

}  // namespace contessa::mechanics
