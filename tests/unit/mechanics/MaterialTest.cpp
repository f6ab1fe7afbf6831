// Material laws: tangent by central differences, frame indifference, small-strain consistency,
// admissibility.
#include "MechanicsTestUtilities.hpp"

#include "mechanics/NeoHookean.hpp"

namespace contessa::mechanics::test {
namespace {

constexpr double kE = 210.0, kNu = 0.3;

/// max |A_fd − A| / max |A| with A_fd from central differences of P, step h = 1e-6 (|F| ~ 1).
double tangentError(const Material& m, const Tensor2& F) {
  Tensor2 P{};
  Tensor4 A{};
  EXPECT_TRUE(m.firstPiolaKirchhoff(F, P, &A));
  const double h = 1e-6;
  Tensor4 Afd{};
  for (int kl = 0; kl < 9; ++kl) {
    Tensor2 Fp = F, Fm = F, Pp{}, Pm{};
    Fp[kl] += h;
    Fm[kl] -= h;
    EXPECT_TRUE(m.firstPiolaKirchhoff(Fp, Pp, nullptr));
    EXPECT_TRUE(m.firstPiolaKirchhoff(Fm, Pm, nullptr));
    for (int ij = 0; ij < 9; ++ij) Afd[9 * ij + kl] = (Pp[ij] - Pm[ij]) / (2.0 * h);  // idx4 = 9·(3i+J) + 3k+L
  }
  return maxAbsDifference(A, Afd) / maxAbs(A);
}

class MaterialLaw : public ::testing::TestWithParam<std::string> {};

TEST_P(MaterialLaw, TangentMatchesCentralDifferences3D) {
  const auto m = makeMaterial(GetParam(), kE, kNu);
  for (unsigned seed : {1u, 2u, 3u}) {
    const Tensor2 F = randomDeformationGradient(seed, 0.3, false);
    ASSERT_NE(F[8], 1.0);
    const double err = tangentError(*m, F);
    std::printf("[measure] material FD 3D %s seed %u: rel err %.2e\n", GetParam().c_str(), seed, err);
    EXPECT_LT(err, 1e-7);
  }
}

TEST_P(MaterialLaw, TangentMatchesCentralDifferencesPlaneStrain) {
  const auto m = makeMaterial(GetParam(), kE, kNu);
  const Tensor2 F = randomDeformationGradient(7, 0.4, true);
  const double err = tangentError(*m, F);
  std::printf("[measure] material FD plane strain %s: rel err %.2e\n", GetParam().c_str(), err);
  EXPECT_LT(err, 1e-7);
}

TEST_P(MaterialLaw, ReducesToLinearElasticityAtSmallStrain) {
  // All three laws share λ, μ: at F = I their tangents are the same elasticity tensor.
  const auto m = makeMaterial(GetParam(), kE, kNu);
  const auto linear = makeMaterial("Linear Elastic", kE, kNu);
  Tensor2 P{}, P0{};
  Tensor4 A{}, A0{};
  ASSERT_TRUE(m->firstPiolaKirchhoff(identity2(), P, &A));
  ASSERT_TRUE(linear->firstPiolaKirchhoff(identity2(), P0, &A0));
  EXPECT_LT(maxAbs(P), 1e-12 * kE);
  EXPECT_LT(maxAbsDifference(A, A0), 1e-12 * kE);
}

TEST_P(MaterialLaw, DeclaredTangentSymmetryHolds) {
  // The element kernels build half of K and condense it by LDLᵀ when a law declares A_iJkL = A_kLiJ
  // (Material::tangentIsSymmetric); every law here does, and its A must then be symmetric at any F,
  // in 3D and in plane strain (the D = 2 formula), to round-off.
  const auto m = makeMaterial(GetParam(), kE, kNu);
  ASSERT_TRUE(m->tangentIsSymmetric());
  for (unsigned seed : {1u, 2u, 3u}) {
    const Tensor2 F = randomDeformationGradient(seed, 0.4, false);
    Tensor2 P{};
    Tensor4 A{};
    ASSERT_TRUE(m->firstPiolaKirchhoff(F, P, &A));
    double asymmetry = 0.0;
    for (int ij = 0; ij < 9; ++ij)
      for (int kl = 0; kl < 9; ++kl) asymmetry = std::max(asymmetry, std::abs(A[9 * ij + kl] - A[9 * kl + ij]));
    EXPECT_LT(asymmetry, 1e-13 * maxAbs(A)) << "seed " << seed;
    const Matrix<2> F2 = {F[0], F[1], F[3], F[4]};
    Matrix<2> P2{};
    Tangent<2> A2{};
    ASSERT_TRUE(m->firstPiolaKirchhoffAtPoints(1, &F2, &P2, &A2));
    for (int ij = 0; ij < 4; ++ij)
      for (int kl = 0; kl < 4; ++kl) EXPECT_LT(std::abs(A2[4 * ij + kl] - A2[4 * kl + ij]), 1e-13 * kE);
  }
}

INSTANTIATE_TEST_SUITE_P(AllLaws, MaterialLaw,
                         ::testing::Values("Saint Venant-Kirchhoff", "Neo-Hookean", "Linear Elastic"),
                         [](const auto& param) {
                           std::string s = param.param;
                           s.erase(std::remove_if(s.begin(), s.end(), [](char c) { return !std::isalnum(c); }), s.end());
                           return s;
                         });

class FiniteStrainLaw : public ::testing::TestWithParam<std::string> {};

TEST_P(FiniteStrainLaw, IsFrameIndifferent) {
  const auto m = makeMaterial(GetParam(), kE, kNu);
  const Tensor2 F = randomDeformationGradient(11, 0.3, false);
  const Tensor2 Q = rotation(1.1, 0.3, -0.5, 0.8);
  Tensor2 P{}, PQ{}, s{}, sQ{};
  ASSERT_TRUE(m->firstPiolaKirchhoff(F, P, nullptr));
  ASSERT_TRUE(m->firstPiolaKirchhoff(multiply(Q, F), PQ, nullptr));
  ASSERT_TRUE(m->cauchyStress(F, s));
  ASSERT_TRUE(m->cauchyStress(multiply(Q, F), sQ));
  const double scale = maxAbs(P);
  ASSERT_GT(scale, 1.0);
  EXPECT_LT(maxAbsDifference(PQ, multiply(Q, P)), 1e-12 * scale);                  // P(QF) = Q P(F)
  EXPECT_LT(maxAbsDifference(sQ, multiply(multiply(Q, s), transpose(Q))), 1e-12 * scale);  // σ(QF) = Q σ Qᵀ
  // σ is symmetric (balance of angular momentum).
  EXPECT_LT(maxAbsDifference(s, transpose(s)), 1e-12 * scale);
}

TEST_P(FiniteStrainLaw, RejectsNonPositiveJacobian) {
  const auto m = makeMaterial(GetParam(), kE, kNu);
  Tensor2 P{}, s{};
  const Tensor2 reflected = {1, 0, 0, 0, -1, 0, 0, 0, 1};
  const Tensor2 flat = {1, 0, 0, 0, 0, 0, 0, 0, 1};
  EXPECT_FALSE(m->firstPiolaKirchhoff(reflected, P, nullptr));
  EXPECT_FALSE(m->firstPiolaKirchhoff(flat, P, nullptr));
  EXPECT_FALSE(m->cauchyStress(reflected, s));
  EXPECT_FALSE(m->isSmallStrain());
}

INSTANTIATE_TEST_SUITE_P(FiniteStrain, FiniteStrainLaw, ::testing::Values("Saint Venant-Kirchhoff", "Neo-Hookean"),
                         [](const auto& param) { return param.index == 0 ? std::string("SVK") : std::string("NeoHookean"); });

TEST(NeoHookean, StressMatchesClosedFormForUniaxialStretch) {
  const NeoHookean m({/*lambda=*/2.0, /*mu=*/3.0});
  const double s = 1.5;
  const Tensor2 F = {s, 0, 0, 0, 1, 0, 0, 0, 1};
  Tensor2 P{};
  ASSERT_TRUE(m.firstPiolaKirchhoff(F, P, nullptr));
  EXPECT_NEAR(P[0], 3.0 * (s - 1.0 / s) + 2.0 * std::log(s) / s, 1e-14);
  EXPECT_NEAR(P[4], 2.0 * std::log(s), 1e-14);
  EXPECT_NEAR(P[1], 0.0, 1e-14);
}

TEST(LinearElastic, StressIsLameLawOfSymmetricStrain) {
  const double E = 200.0, nu = 0.25;
  const auto m = makeMaterial("Linear Elastic", E, nu);
  EXPECT_TRUE(m->isSmallStrain());
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  // Non-symmetric displacement gradient: only its symmetric part produces stress.
  const Tensor2 F = {1.001, 0.004, 0, -0.002, 0.999, 0, 0, 0, 1};
  Tensor2 P{}, s{};
  ASSERT_TRUE(m->firstPiolaKirchhoff(F, P, nullptr));
  ASSERT_TRUE(m->cauchyStress(F, s));
  const double tr = 0.001 - 0.001;
  EXPECT_NEAR(P[0], lambda * tr + 2 * mu * 0.001, 1e-12);
  EXPECT_NEAR(P[4], lambda * tr - 2 * mu * 0.001, 1e-12);
  EXPECT_NEAR(P[1], 2 * mu * 0.001, 1e-12);
  EXPECT_NEAR(P[3], 2 * mu * 0.001, 1e-12);
  EXPECT_NEAR(P[8], lambda * tr, 1e-12);
  EXPECT_EQ(P, s);
}

TEST(VonMises, UniaxialAndShear) {
  EXPECT_NEAR(vonMises({5, 0, 0, 0, 0, 0, 0, 0, 0}), 5.0, 1e-14);
  EXPECT_NEAR(vonMises({0, 2, 0, 2, 0, 0, 0, 0, 0}), 2.0 * std::sqrt(3.0), 1e-14);
  EXPECT_NEAR(vonMises({-7, 0, 0, 0, -7, 0, 0, 0, -7}), 0.0, 1e-14);  // hydrostatic
  // Plane strain: σ_zz counts.
  EXPECT_NEAR(vonMises({1, 0, 0, 0, 1, 0, 0, 0, 0}), 1.0, 1e-14);
}

}  // namespace
}  // namespace contessa::mechanics::test
