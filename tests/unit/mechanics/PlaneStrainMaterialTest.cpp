// The D-dimensional material path the element kernels use (Material::firstPiolaKirchhoffAtPoints):
// in plane strain (D = 2) the in-plane P and A must be those of the 3D law with F_33 = 1, to
// round-off; the 2D tangent must be the derivative of the 2D stress; the batched 3D path must be the
// point path.
#include "MechanicsTestUtilities.hpp"

namespace contessa::mechanics::test {
namespace {

constexpr double kE = 210.0, kNu = 0.3;

/// The in-plane block of a 3 × 3 plane-strain F.
Matrix<2> inPlane(const Tensor2& F) { return {F[idx2(0, 0)], F[idx2(0, 1)], F[idx2(1, 0)], F[idx2(1, 1)]}; }

/// A law seen only through its 3D point function: Material's default batched entries then embed the
/// 2D F in 3 × 3, i.e. this is the padded reference path.
class PointOnly final : public Material {
 public:
  explicit PointOnly(const Material& law) : law_(law) {}
  bool firstPiolaKirchhoff(const Tensor2& F, Tensor2& P, Tensor4* A) const override {
    return law_.firstPiolaKirchhoff(F, P, A);
  }

 private:
  const Material& law_;
};

class PlaneStrainLaw : public ::testing::TestWithParam<std::string> {};

TEST_P(PlaneStrainLaw, InPlaneStressAndTangentEqualThe3DLawWithUnitStretchOutOfPlane) {
  const auto law = makeMaterial(GetParam(), kE, kNu);
  const PointOnly padded(*law);
  constexpr int n = 3;
  std::array<Matrix<2>, n> F, P, Ppadded;
  std::array<Tangent<2>, n> A, Apadded;
  for (int q = 0; q < n; ++q) F[q] = inPlane(randomDeformationGradient(20 + q, 0.4, true));
  ASSERT_TRUE(law->firstPiolaKirchhoffAtPoints(n, F.data(), P.data(), A.data()));
  ASSERT_TRUE(padded.firstPiolaKirchhoffAtPoints(n, F.data(), Ppadded.data(), Apadded.data()));
  double pErr = 0.0, aErr = 0.0;
  for (int q = 0; q < n; ++q) {
    // Against the 3 × 3 computation by hand as well: the padded path extracts exactly these entries.
    Tensor2 P3{};
    Tensor4 A3{};
    ASSERT_TRUE(law->firstPiolaKirchhoff(embedIn3D<2>(F[q], 1.0), P3, &A3));
    for (int i = 0; i < 2; ++i)
      for (int J = 0; J < 2; ++J) {
        EXPECT_EQ(Ppadded[q][2 * i + J], P3[idx2(i, J)]);
        for (int k = 0; k < 2; ++k)
          for (int L = 0; L < 2; ++L) EXPECT_EQ(Apadded[q][8 * i + 4 * J + 2 * k + L], A3[idx4(i, J, k, L)]);
      }
    pErr = std::max(pErr, maxAbsDifference(P[q], Ppadded[q]) / maxAbs(Ppadded[q]));
    aErr = std::max(aErr, maxAbsDifference(A[q], Apadded[q]) / maxAbs(Apadded[q]));
  }
  std::printf("[measure] plane strain %s: 2D vs 3D law, rel diff P %.2e, A %.2e\n", GetParam().c_str(), pErr, aErr);
  EXPECT_LT(pErr, 1e-14);
  EXPECT_LT(aErr, 1e-14);
}

TEST_P(PlaneStrainLaw, TwoDimensionalTangentMatchesCentralDifferences) {
  const auto law = makeMaterial(GetParam(), kE, kNu);
  for (unsigned seed : {5u, 6u}) {
    const Matrix<2> F = inPlane(randomDeformationGradient(seed, 0.4, true));
    Matrix<2> P{};
    Tangent<2> A{};
    ASSERT_TRUE(law->firstPiolaKirchhoffAtPoints(1, &F, &P, &A));
    const double h = 1e-6;
    Tangent<2> Afd{};
    for (int kl = 0; kl < 4; ++kl) {
      Matrix<2> Fp = F, Fm = F, Pp{}, Pm{};
      Fp[kl] += h;
      Fm[kl] -= h;
      ASSERT_TRUE(law->firstPiolaKirchhoffAtPoints(1, &Fp, &Pp, nullptr));
      ASSERT_TRUE(law->firstPiolaKirchhoffAtPoints(1, &Fm, &Pm, nullptr));
      for (int ij = 0; ij < 4; ++ij) Afd[4 * ij + kl] = (Pp[ij] - Pm[ij]) / (2.0 * h);
    }
    const double err = maxAbsDifference(A, Afd) / maxAbs(A);
    std::printf("[measure] material FD 2D %s seed %u: rel err %.2e\n", GetParam().c_str(), seed, err);
    EXPECT_LT(err, 1e-7);
  }
}

TEST_P(PlaneStrainLaw, Batched3DPathIsThePointPath) {
  const auto law = makeMaterial(GetParam(), kE, kNu);
  constexpr int n = 2;
  std::array<Tensor2, n> F = {randomDeformationGradient(31, 0.3, false), randomDeformationGradient(32, 0.3, false)};
  std::array<Tensor2, n> P;
  std::array<Tensor4, n> A;
  ASSERT_TRUE(law->firstPiolaKirchhoffAtPoints(n, F.data(), P.data(), A.data()));
  for (int q = 0; q < n; ++q) {
    Tensor2 Pq{};
    Tensor4 Aq{};
    ASSERT_TRUE(law->firstPiolaKirchhoff(F[q], Pq, &Aq));
    EXPECT_EQ(P[q], Pq);
    EXPECT_EQ(A[q], Aq);
  }
}

INSTANTIATE_TEST_SUITE_P(AllLaws, PlaneStrainLaw,
                         ::testing::Values("Saint Venant-Kirchhoff", "Neo-Hookean", "Linear Elastic"),
                         [](const auto& param) {
                           std::string s = param.param;
                           s.erase(std::remove_if(s.begin(), s.end(), [](char c) { return !std::isalnum(c); }), s.end());
                           return s;
                         });

TEST(PlaneStrainLaw, OneInadmissiblePointFailsTheBatch) {
  for (const char* model : {"Saint Venant-Kirchhoff", "Neo-Hookean"}) {
    const auto law = makeMaterial(model, kE, kNu);
    const std::array<Matrix<2>, 3> F = {Matrix<2>{1.1, 0.0, 0.1, 0.9}, Matrix<2>{1.0, 0.0, 0.0, -1.0},
                                        Matrix<2>{1.0, 0.0, 0.0, 1.0}};
    std::array<Matrix<2>, 3> P;
    std::array<Tangent<2>, 3> A;
    EXPECT_FALSE(law->firstPiolaKirchhoffAtPoints(3, F.data(), P.data(), A.data())) << model;
    EXPECT_FALSE(law->firstPiolaKirchhoffAtPoints(3, F.data(), P.data(), nullptr)) << model;
    EXPECT_TRUE(law->firstPiolaKirchhoffAtPoints(1, F.data(), P.data(), nullptr)) << model;
  }
}

}  // namespace
}  // namespace contessa::mechanics::test
