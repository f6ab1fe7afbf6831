#pragma once
// Standard (displacement-only) total-Lagrangian solid kernel over a reference element Shape
// (ReferenceElement.hpp) and a Kinematics (Kinematics.hpp): f_int = Σ_gp Bᵀ P w j, K = Σ_gp Bᵀ A B w j.
// "Q4" is this with the bilinear quadrilateral in plane strain, "Q4 Axisymmetric" the same revolved,
// "Hex8" with the trilinear hexahedron (Hex8.hpp). Fixed-size arithmetic throughout, the
// reference gradients precomputed per element, one material call per evaluation for all points.
// evaluate() returns InadmissibleDeformation when the material rejects F at a Gauss point or when the
// reference element itself has j ≤ 0 (clockwise node order or a degenerate element).
#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "mechanics/Kinematics.hpp"
#include "mechanics/ShapeKernel.hpp"
#include "mechanics/SolidOperators.hpp"

namespace contessa::mechanics {

template <class Shape, class Kinematics = PlanarKinematics<Shape::kDimension>>
class DisplacementElement final : public ShapeKernel<Shape, Kinematics::kHoop> {
 public:
  static constexpr int D = Shape::kDimension, N = Shape::kNodes, Q = Shape::kPoints, ND = D * N;
  static constexpr int MD = Kinematics::kMaterialDimension;  ///< the law's F is MD × MD
  using Geometry = ReferenceGeometry<Shape, Kinematics::kHoop>;
  using GeometrySet = ElementGeometrySet<Geometry>;

  explicit DisplacementElement(std::string name) : ShapeKernel<Shape, Kinematics::kHoop>(std::move(name)) {}

  std::unique_ptr<ElementGeometry> referenceGeometry(int count, const double* X) const override {
    auto set = std::make_unique<GeometrySet>(count);
    for (int e = 0; e < count; ++e) set->setValid(e, computeReferenceGeometry<Shape, Kinematics>(X + ND * e, set->record(e)));
    return set;
  }

  using ElementKernel::averageCauchyStress;
  using ElementKernel::evaluate;

  ElementStatus evaluate(const ElementGeometry& geometry, int element, const double* u, double* /*state*/,
                         const Material& material, double* internalForce, double* stiffness) const override {
    const auto& set = static_cast<const GeometrySet&>(geometry);
    if (!set.valid(element)) return ElementStatus::InadmissibleDeformation;
    const Geometry& g = set[element];
    std::array<Matrix<MD>, Q> F, P;
    std::array<Tangent<MD>, Q> A;
    // F = I + GRAD u; for small-strain laws the same F gives ε = sym GRAD u, i.e. linear elasticity.
    for (int q = 0; q < Q; ++q) F[q] = deformationGradient(g, q, u);
    if (!material.firstPiolaKirchhoffAtPoints(Q, F.data(), P.data(), stiffness ? A.data() : nullptr))
      return ElementStatus::InadmissibleDeformation;
    if (internalForce) {
      std::fill(internalForce, internalForce + ND, 0.0);
      for (int q = 0; q < Q; ++q)
        Kinematics::template addDivergence<N>(g.dNdX[q].data(), g.hoop.at(q), P[q], g.weightedVolume[q], internalForce);
    }
    if (stiffness) {
      std::fill(stiffness, stiffness + ND * ND, 0.0);
      for (int q = 0; q < Q; ++q)
        Kinematics::template addTangent<N, N>(g.dNdX[q].data(), g.hoop.at(q), g.dNdX[q].data(), g.hoop.at(q), A[q],
                                              g.weightedVolume[q], stiffness, ND);
    }
    return ElementStatus::Ok;
  }

  ElementStatus averageCauchyStress(const ElementGeometry& geometry, int element, const double* u,
                                    const double* /*internal*/, const Material& material,
                                    Tensor2& sigma) const override {
    const auto& set = static_cast<const GeometrySet&>(geometry);
    if (!set.valid(element)) return ElementStatus::InadmissibleDeformation;
    const Geometry& g = set[element];
    sigma = Tensor2{};
    Tensor2 s{};
    for (int q = 0; q < Q; ++q) {
      // Output only: the 3 × 3 path of the law (plane strain: F_33 = 1), which gives σ_zz (σ_θθ) too.
      if (!material.cauchyStress(Kinematics::threeByThree(deformationGradient(g, q, u)), s))
        return ElementStatus::InadmissibleDeformation;
      sigma = add(sigma, s);
    }
    sigma = scaled(1.0 / Q, sigma);
    return ElementStatus::Ok;
  }

 private:
  static Matrix<MD> deformationGradient(const Geometry& g, int q, const double* u) {
    Matrix<MD> H{};
    Kinematics::template addGradient<N>(g.dNdX[q].data(), g.hoop.at(q), u, H);
    for (int i = 0; i < MD; ++i) H[MD * i + i] += 1.0;
    return H;
  }
};

}  // namespace contessa::mechanics
