#include "mechanics/Element.hpp"

#include <algorithm>
#include <cmath>

namespace contessa::mechanics {

ElementStatus ElementKernel::evaluate(const double* X, const double* u, double* internal, const Material& material,
                                      double* internalForce, double* stiffness) const {
  const auto geometry = referenceGeometry(1, X);
  // A fresh state: the given internal variables, no warm-start data (all zero).
  std::vector<double> state(numStateValues(), 0.0);
  const int ni = numInternalVariables();
  if (internal) std::copy(internal, internal + ni, state.begin());
  const ElementStatus status = evaluate(*geometry, 0, u, state.data(), material, internalForce, stiffness);
  if (status == ElementStatus::Ok && internal) std::copy(state.begin(), state.begin() + ni, internal);
  return status;
}

ElementStatus ElementKernel::averageCauchyStress(const double* X, const double* u, const double* internal,
                                                 const Material& material, Tensor2& sigma) const {
  const auto geometry = referenceGeometry(1, X);
  return averageCauchyStress(*geometry, 0, u, internal, material, sigma);
}

double vonMises(const Tensor2& sigma) {
  // sqrt(3/2 s : s) with s the deviator; for plane strain σ_zz ≠ 0 and must be included.
  const double mean = trace(sigma) / 3.0;
  Tensor2 s = sigma;
  for (int i = 0; i < 3; ++i) s[idx2(i, i)] -= mean;
  return std::sqrt(1.5 * doubleContraction(s, s));
}

}  // namespace contessa::mechanics
