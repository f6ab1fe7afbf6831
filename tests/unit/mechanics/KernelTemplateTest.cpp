// The kernel templates are written for any reference element: instantiated here with a trilinear
// hexahedron defined in this test only (a traits class of ~20 lines; Hex8 proper, with meshes and
// output, is issue 10), both kernels pass the checks the quadrilaterals pass: the tangent is the
// derivative of the internal force, and a homogeneous deformation needs no enhanced strain.
#include "MechanicsTestUtilities.hpp"

#include "mechanics/DisplacementElement.hpp"
#include "mechanics/EnhancedStrain.hpp"
#include "mechanics/EnhancedStrainElement.hpp"
#include "mechanics/ReferenceElement.hpp"

namespace contessa::mechanics::test {
namespace {

/// Trilinear 8-node hexahedron, nodes at (ξ, η, ζ) = (∓1, ∓1, ∓1) counter-clockwise in ζ = −1 then
/// ζ = +1; N_a = ⅛ (1 + ξ_a ξ)(1 + η_a η)(1 + ζ_a ζ), 2 × 2 × 2 Gauss.
struct TrilinearHexahedron {
  static constexpr int kDimension = 3, kNodes = 8, kPoints = 8;
  static std::array<QuadraturePoint<3>, kPoints> quadrature() { return gaussLegendreRule<3, 2>(); }
  static void shapeGradients(const double* xi, double* dNdxi) {
    static const double node[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                      {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    for (int a = 0; a < 8; ++a) {
      const double f[3] = {1 + node[a][0] * xi[0], 1 + node[a][1] * xi[1], 1 + node[a][2] * xi[2]};
      dNdxi[3 * a] = 0.125 * node[a][0] * f[1] * f[2];
      dNdxi[3 * a + 1] = 0.125 * node[a][1] * f[0] * f[2];
      dNdxi[3 * a + 2] = 0.125 * node[a][2] * f[0] * f[1];
    }
  }
};

using Hex = DisplacementElement<TrilinearHexahedron>;
using HexEnhanced = EnhancedStrainElement<TrilinearHexahedron, WilsonBubbleModes<3>>;

/// A distorted brick about 2 × 1.5 × 1.
std::array<double, 24> distortedBrick() {
  const double node[8][3] = {{0, 0, 0}, {2, 0, 0}, {2, 1.5, 0}, {0, 1.5, 0}, {0, 0, 1}, {2, 0, 1}, {2, 1.5, 1}, {0, 1.5, 1}};
  const double jitter[8][3] = {{0.05, -0.1, 0.02}, {0.2, 0.1, -0.05}, {-0.1, 0.15, 0.1}, {0.1, -0.05, -0.08},
                               {-0.05, 0.1, 0.1},  {0.1, -0.1, 0.05}, {0.15, 0.2, -0.1}, {-0.1, 0.05, 0.15}};
  std::array<double, 24> X{};
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i) X[3 * a + i] = node[a][i] + jitter[a][i];
  return X;
}

/// Homogeneous stretch and shear, plus (when `bending`) a bending pattern u_x ∝ x z that the
/// trilinear field cannot represent without parasitic shear (so α ≠ 0).
std::array<double, 24> deformation(const std::array<double, 24>& X, bool bending) {
  const double H[3][3] = {{0.12, 0.05, -0.04}, {-0.03, -0.08, 0.06}, {0.02, 0.04, 0.1}};
  std::array<double, 24> u{};
  for (int a = 0; a < 8; ++a) {
    const double* x = &X[3 * a];
    for (int i = 0; i < 3; ++i) u[3 * a + i] = H[i][0] * x[0] + H[i][1] * x[1] + H[i][2] * x[2];
    if (bending) {
      u[3 * a] += 0.1 * (x[2] - 0.5) * x[0];
      u[3 * a + 2] -= 0.05 * x[0] * x[0];
    }
  }
  return u;
}

template <class Kernel>
void checkTangent(const std::string& model) {
  const Kernel kernel("test hexahedron");
  const auto material = makeMaterial(model, 100.0, 0.3);
  const auto X = distortedBrick();
  const auto geometry = kernel.referenceGeometry(1, X.data());
  const auto u = deformation(X, true);
  std::vector<double> state(kernel.numStateValues(), 0.0);
  std::array<double, 24> f{};
  std::array<double, 576> K{};
  ASSERT_EQ(kernel.evaluate(*geometry, 0, u.data(), state.data(), *material, f.data(), K.data()), ElementStatus::Ok);
  const double h = 1e-6;
  std::array<double, 576> Kfd{};
  for (int c = 0; c < 24; ++c) {
    auto up = u, um = u;
    up[c] += h;
    um[c] -= h;
    auto sp = state, sm = state;
    std::array<double, 24> fp{}, fm{};
    ASSERT_EQ(kernel.evaluate(*geometry, 0, up.data(), sp.data(), *material, fp.data(), nullptr), ElementStatus::Ok);
    ASSERT_EQ(kernel.evaluate(*geometry, 0, um.data(), sm.data(), *material, fm.data(), nullptr), ElementStatus::Ok);
    for (int r = 0; r < 24; ++r) Kfd[r * 24 + c] = (fp[r] - fm[r]) / (2.0 * h);
  }
  const double err = maxAbsDifference(K, Kfd) / maxAbs(K);
  double alpha = 0.0;
  for (int k = 0; k < kernel.numInternalVariables(); ++k) alpha = std::max(alpha, std::fabs(state[k]));
  std::printf("[measure] hexahedron FD %s / %s: rel err %.2e (max|alpha| %.3f)\n", kernel.numInternalVariables() ? "enhanced" : "standard",
              model.c_str(), err, alpha);
  EXPECT_LT(err, 1e-6);
  if (kernel.numInternalVariables() > 0) {
    EXPECT_GT(alpha, 1e-3) << "enhanced modes not exercised";
  }
  // Hyperelastic: symmetric tangent; equilibrium of the element.
  for (int r = 0; r < 24; ++r)
    for (int c = 0; c < r; ++c) EXPECT_NEAR(K[r * 24 + c], K[c * 24 + r], 1e-10 * maxAbs(K));
  for (int i = 0; i < 3; ++i) {
    double sum = 0.0;
    for (int a = 0; a < 8; ++a) sum += f[3 * a + i];
    EXPECT_NEAR(sum, 0.0, 1e-12 * maxAbs(f));
  }
}

TEST(KernelTemplates, HexahedronTangentsMatchCentralDifferences) {
  for (const char* model : {"Neo-Hookean", "Saint Venant-Kirchhoff"}) {
    checkTangent<Hex>(model);
    checkTangent<HexEnhanced>(model);
  }
}

TEST(KernelTemplates, HexahedronHomogeneousDeformationNeedsNoEnhancedStrain) {
  // R_α = P : Σ G_m w j = 0 at α = 0 for a constant P (the modes integrate to zero on any shape).
  const auto material = makeMaterial("Neo-Hookean", 100.0, 0.3);
  const auto X = distortedBrick();
  const auto u = deformation(X, false);
  const Hex standard("Hex");
  const HexEnhanced enhanced("Hex Enhanced");
  std::array<double, 9> alpha = {0.01, -0.02, 0.03, 0.01, 0.02, -0.01, 0.005, 0.0, -0.02};  // a wrong guess
  std::array<double, 24> f{}, fStandard{};
  ASSERT_EQ(enhanced.evaluate(X.data(), u.data(), alpha.data(), *material, f.data(), nullptr), ElementStatus::Ok);
  ASSERT_EQ(standard.evaluate(X.data(), u.data(), nullptr, *material, fStandard.data(), nullptr), ElementStatus::Ok);
  EXPECT_LT(maxAbs(alpha), 1e-13);
  EXPECT_LT(maxAbsDifference(f, fStandard), 1e-12 * maxAbs(fStandard));
  // And the Cauchy stress is that of the homogeneous F.
  Tensor2 F = identity2(), sigma{}, sigmaExact{};
  const double H[3][3] = {{0.12, 0.05, -0.04}, {-0.03, -0.08, 0.06}, {0.02, 0.04, 0.1}};
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J) F[idx2(i, J)] += H[i][J];
  ASSERT_TRUE(material->cauchyStress(F, sigmaExact));
  ASSERT_EQ(enhanced.averageCauchyStress(X.data(), u.data(), alpha.data(), *material, sigma), ElementStatus::Ok);
  EXPECT_LT(maxAbsDifference(sigma, sigmaExact), 1e-12 * maxAbs(sigmaExact));
}

}  // namespace
}  // namespace contessa::mechanics::test
