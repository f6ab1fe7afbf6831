// Element kernels: consistent tangent by central differences (the EAS one of the condensed force),
// objectivity of f_int, admissibility, and the local solve.
#include "MechanicsTestUtilities.hpp"

namespace contessa::mechanics::test {
namespace {

// A distorted quadrilateral (no parallel sides), counter-clockwise.
const std::array<double, 8> kX = {0.0, 0.0, 2.0, 0.3, 2.4, 1.8, -0.2, 1.5};
const double kSize = 2.0;  // characteristic length

/// A homogeneous stretch + shear plus an hourglass/bending pattern (which the EAS modes resist, so
/// α ≠ 0), scaled by `amplitude`.
std::array<double, 8> deformation(double amplitude) {
  const double H[2][2] = {{0.15, 0.1}, {-0.05, -0.1}};
  const double hourglass[4] = {1, -1, 1, -1};
  std::array<double, 8> u{};
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 2; ++i)
      u[2 * a + i] = amplitude * (H[i][0] * kX[2 * a] + H[i][1] * kX[2 * a + 1] + 0.12 * hourglass[a] * (i ? 0.5 : 1.0));
  return u;
}

TEST_P(ElementMaterial, StiffnessMatchesCentralDifferencesOfInternalForce) {
  const auto u = deformation(1.0);
  std::array<double, 4> alpha{};
  std::array<double, 8> f{};
  std::array<double, 64> K{};
  ASSERT_EQ(kernel->evaluate(kX.data(), u.data(), alpha.data(), *material, f.data(), K.data()), ElementStatus::Ok);
  const double alphaNorm = maxAbs(alpha);
  if (kernel->numInternalVariables() > 0) {
    EXPECT_GT(alphaNorm, 1e-2 * kSize) << "EAS modes not exercised";
  }

  // Central differences of the (condensed) internal force; every evaluate re-solves α from the
  // converged α of the base state.
  const double h = 1e-6 * kSize;
  std::array<double, 64> Kfd{};
  for (int c = 0; c < 8; ++c) {
    auto up = u, um = u;
    up[c] += h;
    um[c] -= h;
    auto ap = alpha, am = alpha;
    std::array<double, 8> fp{}, fm{};
    ASSERT_EQ(kernel->evaluate(kX.data(), up.data(), ap.data(), *material, fp.data(), nullptr), ElementStatus::Ok);
    ASSERT_EQ(kernel->evaluate(kX.data(), um.data(), am.data(), *material, fm.data(), nullptr), ElementStatus::Ok);
    for (int r = 0; r < 8; ++r) Kfd[r * 8 + c] = (fp[r] - fm[r]) / (2.0 * h);
  }
  const double err = maxAbsDifference(K, Kfd) / maxAbs(K);
  std::printf("[measure] element FD %s / %s: rel err %.2e (max|alpha| %.3f)\n", GetParam().element.c_str(),
              GetParam().material.c_str(), err, alphaNorm);
  EXPECT_LT(err, 1e-6);

  // Hyperelastic (and linear) laws give a symmetric tangent, condensed or not.
  std::array<double, 64> Kt{};
  for (int r = 0; r < 8; ++r)
    for (int c = 0; c < 8; ++c) Kt[c * 8 + r] = K[r * 8 + c];
  EXPECT_LT(maxAbsDifference(K, Kt), 1e-10 * maxAbs(K));
  // Element equilibrium: the nodal forces sum to zero.
  for (int i = 0; i < 2; ++i) EXPECT_NEAR(f[i] + f[2 + i] + f[4 + i] + f[6 + i], 0.0, 1e-12 * maxAbs(f));
}

TEST_P(ElementMaterial, NullInternalStartsFromZeroAndMatches) {
  const auto u = deformation(0.5);
  std::array<double, 4> alpha{};
  std::array<double, 8> f1{}, f2{};
  ASSERT_EQ(kernel->evaluate(kX.data(), u.data(), alpha.data(), *material, f1.data(), nullptr), ElementStatus::Ok);
  ASSERT_EQ(kernel->evaluate(kX.data(), u.data(), nullptr, *material, f2.data(), nullptr), ElementStatus::Ok);
  EXPECT_LT(maxAbsDifference(f1, f2), 1e-12 * maxAbs(f1));
  Tensor2 s1{}, s2{};
  ASSERT_EQ(kernel->averageCauchyStress(kX.data(), u.data(), alpha.data(), *material, s1), ElementStatus::Ok);
  ASSERT_EQ(kernel->averageCauchyStress(kX.data(), u.data(), nullptr, *material, s2), ElementStatus::Ok);
  EXPECT_LT(maxAbsDifference(s1, s2), 1e-12 * maxAbs(s1));
}

INSTANTIATE_TEST_SUITE_P(AllElementsAllLaws, ElementMaterial, ::testing::ValuesIn(allCases()), caseName);

class FiniteStrainElement : public ElementMaterial {};

TEST_P(FiniteStrainElement, InternalForceRotatesWithRigidRotation) {
  // x' = Q x: u'_a = Q (X_a + u_a) − X_a must give f'_a = Q f_a (P(QF) = Q P(F); for EAS the local
  // solution is Q α̂, so it holds after condensation as well).
  const auto u = deformation(1.0);
  const Tensor2 Q = rotation(0.9, 0, 0, 1);
  std::array<double, 8> uRot{};
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 2; ++i)
      uRot[2 * a + i] = Q[idx2(i, 0)] * (kX[2 * a] + u[2 * a]) + Q[idx2(i, 1)] * (kX[2 * a + 1] + u[2 * a + 1]) -
                        kX[2 * a + i];
  std::array<double, 4> alpha{}, alphaRot{};
  std::array<double, 8> f{}, fRot{};
  ASSERT_EQ(kernel->evaluate(kX.data(), u.data(), alpha.data(), *material, f.data(), nullptr), ElementStatus::Ok);
  ASSERT_EQ(kernel->evaluate(kX.data(), uRot.data(), alphaRot.data(), *material, fRot.data(), nullptr),
            ElementStatus::Ok);
  std::array<double, 8> Qf{};
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 2; ++i) Qf[2 * a + i] = Q[idx2(i, 0)] * f[2 * a] + Q[idx2(i, 1)] * f[2 * a + 1];
  EXPECT_LT(maxAbsDifference(fRot, Qf), 1e-11 * maxAbs(f));
  // Cauchy stress rotates as Q σ Qᵀ.
  Tensor2 s{}, sRot{};
  ASSERT_EQ(kernel->averageCauchyStress(kX.data(), u.data(), alpha.data(), *material, s), ElementStatus::Ok);
  ASSERT_EQ(kernel->averageCauchyStress(kX.data(), uRot.data(), alphaRot.data(), *material, sRot), ElementStatus::Ok);
  EXPECT_LT(maxAbsDifference(sRot, multiply(multiply(Q, s), transpose(Q))), 1e-11 * maxAbs(s));
  EXPECT_NEAR(vonMises(sRot), vonMises(s), 1e-11 * vonMises(s));
}

TEST_P(FiniteStrainElement, InvertedElementIsInadmissible) {
  // Mirror the element through the x axis: det F = −1 everywhere.
  std::array<double, 8> u{};
  for (int a = 0; a < 4; ++a) u[2 * a + 1] = -2.0 * kX[2 * a + 1];
  std::array<double, 4> alpha{};
  std::array<double, 8> f{};
  EXPECT_EQ(kernel->evaluate(kX.data(), u.data(), alpha.data(), *material, f.data(), nullptr),
            ElementStatus::InadmissibleDeformation);
  Tensor2 s{};
  EXPECT_EQ(kernel->averageCauchyStress(kX.data(), u.data(), alpha.data(), *material, s),
            ElementStatus::InadmissibleDeformation);
}

INSTANTIATE_TEST_SUITE_P(AllElements, FiniteStrainElement,
                         ::testing::Values(Case{"Q4", "Neo-Hookean"}, Case{"Q4 Enhanced", "Neo-Hookean"},
                                           Case{"Q4", "Saint Venant-Kirchhoff"},
                                           Case{"Q4 Enhanced", "Saint Venant-Kirchhoff"}),
                         caseName);

TEST(ElementKernel, ClockwiseReferenceElementIsRejected) {
  const std::array<double, 8> clockwise = {0, 0, 0, 1, 1, 1, 1, 0};
  const std::array<double, 8> u{};
  const auto m = makeMaterial("Linear Elastic", 1, 0);
  for (const auto& name : ElementFactory::names()) {
    const auto k = ElementFactory::create(name, "E");
    std::array<double, 8> f{};
    EXPECT_EQ(k->evaluate(clockwise.data(), u.data(), nullptr, *m, f.data(), nullptr),
              ElementStatus::InadmissibleDeformation)
        << name;
  }
}

TEST(EnhancedElement, UndeformedAndHomogeneousStatesHaveZeroAlpha) {
  // A homogeneous F is reproduced by the compatible field alone: R_α = P : ∫ G dV = 0 at α = 0.
  const auto k = ElementFactory::create("Q4 Enhanced", "E");
  const auto m = makeMaterial("Neo-Hookean", 100, 0.3);
  std::array<double, 8> u{};
  for (int a = 0; a < 4; ++a) {
    u[2 * a] = 0.3 * kX[2 * a] + 0.2 * kX[2 * a + 1];
    u[2 * a + 1] = -0.1 * kX[2 * a] - 0.15 * kX[2 * a + 1];
  }
  std::array<double, 4> alpha = {0.01, -0.02, 0.03, 0.01};  // a wrong guess
  std::array<double, 8> f{};
  ASSERT_EQ(k->evaluate(kX.data(), u.data(), alpha.data(), *m, f.data(), nullptr), ElementStatus::Ok);
  EXPECT_LT(maxAbs(alpha), 1e-13 * kSize);
}

/// P = F − I with a zero tangent: K_αα is singular, so the local solve cannot proceed.
class ZeroTangentMaterial final : public Material {
 public:
  bool firstPiolaKirchhoff(const Tensor2& F, Tensor2& P, Tensor4* A) const override {
    P = add(F, scaled(-1.0, identity2()));
    if (A) A->fill(0.0);
    return true;
  }
};

TEST(EnhancedElement, SingularLocalProblemReportsInternalSolveFailed) {
  const auto k = ElementFactory::create("Q4 Enhanced", "E");
  const auto u = deformation(1.0);
  std::array<double, 4> alpha = {0.1, 0.2, 0.3, 0.4};
  const auto before = alpha;
  std::array<double, 8> f{};
  EXPECT_EQ(k->evaluate(kX.data(), u.data(), alpha.data(), ZeroTangentMaterial(), f.data(), nullptr),
            ElementStatus::InternalSolveFailed);
  EXPECT_EQ(alpha, before);  // untouched on failure
}

}  // namespace
}  // namespace contessa::mechanics::test
