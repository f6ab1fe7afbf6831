#include "mechanics/DisplacementElement.hpp"

#include <algorithm>
#include <vector>

#include "mechanics/SolidOperators.hpp"

namespace contessa::mechanics {

ElementStatus DisplacementElement::evaluate(const double* X, const double* u, double* /*internal*/,
                                            const Material& material, double* internalForce,
                                            double* stiffness) const {
  const int dim = dimension(), nn = numNodes(), nd = numDofs();
  std::vector<PointGeometry> points;
  if (!referenceGeometry(reference_, X, points)) return ElementStatus::InadmissibleDeformation;
  if (internalForce) std::fill(internalForce, internalForce + nd, 0.0);
  if (stiffness) std::fill(stiffness, stiffness + nd * nd, 0.0);
  Tensor2 P{};
  Tensor4 A{};
  for (const PointGeometry& g : points) {
    // F = I + GRAD u; for small-strain laws the same F gives ε = sym GRAD u, i.e. linear elasticity.
    const Tensor2 F = add(identity2(), displacementGradient(dim, nn, g, u));
    if (!material.firstPiolaKirchhoff(F, P, stiffness ? &A : nullptr)) return ElementStatus::InadmissibleDeformation;
    if (internalForce) addInternalForce(dim, nn, g, P, internalForce);
    if (stiffness) addMaterialStiffness(dim, nn, g, A, stiffness);
  }
  return ElementStatus::Ok;
}

ElementStatus DisplacementElement::averageCauchyStress(const double* X, const double* u, const double* /*internal*/,
                                                       const Material& material, Tensor2& sigma) const {
  const int dim = dimension(), nn = numNodes();
  std::vector<PointGeometry> points;
  if (!referenceGeometry(reference_, X, points)) return ElementStatus::InadmissibleDeformation;
  sigma = Tensor2{};
  Tensor2 s{};
  for (const PointGeometry& g : points) {
    const Tensor2 F = add(identity2(), displacementGradient(dim, nn, g, u));
    if (!material.cauchyStress(F, s)) return ElementStatus::InadmissibleDeformation;
    sigma = add(sigma, s);
  }
  sigma = scaled(1.0 / static_cast<double>(points.size()), sigma);
  return ElementStatus::Ok;
}

}  // namespace contessa::mechanics
