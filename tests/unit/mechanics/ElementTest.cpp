// Element kernels: consistent tangent by central differences (the EAS one of the condensed force),
// objectivity of f_int, admissibility, and the local solve. Every registered kernel (2D and 3D) with
// every law, each on a distorted element of its own type.
#include "MechanicsTestUtilities.hpp"

namespace contessa::mechanics::test {
namespace {

const double kSize = 2.0;  // characteristic length of both sample elements

/// In 2D a homogeneous stretch + shear plus an hourglass/bending pattern (which the EAS modes
/// resist, so α ≠ 0), scaled by `amplitude`; in 3D brickDeformation (with a rotation as well); other
/// families familyDeformation.
std::vector<double> deformation(const std::vector<double>& X, const ElementKernel& kernel, double amplitude) {
  const double H[2][2] = {{0.15, 0.1}, {-0.05, -0.1}};
  return familyDeformation(X, kernel, amplitude, H, 0.12);
}

/// A kernel, a law, and the sample element of the kernel's dimension.
class ElementCase : public ElementMaterial {
 protected:
  const int D = kernel->dimension(), nd = kernel->numDofs(), ni = kernel->numInternalVariables();
  const std::vector<double> X = sampleElementsOf(*kernel)[0];
};

TEST_P(ElementCase, StiffnessMatchesCentralDifferencesOfInternalForce) {
  const auto u = deformation(X, *kernel, 1.0);
  std::vector<double> alpha(ni, 0.0), f(nd), K(nd * nd);
  ASSERT_EQ(kernel->evaluate(X.data(), u.data(), alpha.data(), *material, f.data(), K.data()), ElementStatus::Ok);
  const double alphaNorm = maxAbs(alpha);
  if (ni > 0) {
    EXPECT_GT(alphaNorm, 1e-2 * kSize) << "EAS modes not exercised";
  }

  // Central differences of the (condensed) internal force; every evaluate re-solves α from the
  // converged α of the base state.
  const auto Kfd = centralDifferenceTangent(*kernel, *material, X, u, alpha, 1e-6 * kSize);
  const double err = maxAbsDifference(K, Kfd) / maxAbs(K);
  std::printf("[measure] element FD %s / %s: rel err %.2e (max|alpha| %.3f)\n", GetParam().element.c_str(),
              GetParam().material.c_str(), err, alphaNorm);
  EXPECT_LT(err, 1e-6);

  // Hyperelastic (and linear) laws give a symmetric tangent, condensed or not.
  std::vector<double> Kt(nd * nd);
  for (int r = 0; r < nd; ++r)
    for (int c = 0; c < nd; ++c) Kt[c * nd + r] = K[r * nd + c];
  EXPECT_LT(maxAbsDifference(K, Kt), 1e-10 * maxAbs(K));
  // Element equilibrium: the nodal forces sum to zero.
  for (int i = 0; i < D; ++i) {
    double sum = 0.0;
    for (int a = 0; a < kernel->numNodes(); ++a) sum += f[D * a + i];
    EXPECT_NEAR(sum, 0.0, 1e-12 * maxAbs(f));
  }
}

TEST_P(ElementCase, NullInternalStartsFromZeroAndMatches) {
  const auto u = deformation(X, *kernel, 0.5);
  std::vector<double> alpha(ni, 0.0), f1(nd), f2(nd);
  ASSERT_EQ(kernel->evaluate(X.data(), u.data(), alpha.data(), *material, f1.data(), nullptr), ElementStatus::Ok);
  ASSERT_EQ(kernel->evaluate(X.data(), u.data(), nullptr, *material, f2.data(), nullptr), ElementStatus::Ok);
  EXPECT_LT(maxAbsDifference(f1, f2), 1e-12 * maxAbs(f1));
  Tensor2 s1{}, s2{};
  ASSERT_EQ(kernel->averageCauchyStress(X.data(), u.data(), alpha.data(), *material, s1), ElementStatus::Ok);
  ASSERT_EQ(kernel->averageCauchyStress(X.data(), u.data(), nullptr, *material, s2), ElementStatus::Ok);
  EXPECT_LT(maxAbsDifference(s1, s2), 1e-12 * maxAbs(s1));
}

TEST_P(ElementCase, HomogeneousDeformationIsExactAndNeedsNoEnhancedStrain) {
  // A homogeneous F is reproduced by the compatible field alone: R_α = P : Σ G_m w j = 0 at α = 0
  // (the modes integrate to zero on any element shape), and the stress is that of F.
  const Tensor2 F3 = randomDeformationGradient(11, 0.2, D == 2);
  std::vector<double> u(nd);
  for (int a = 0; a < kernel->numNodes(); ++a)
    for (int i = 0; i < D; ++i) {
      double s = -X[D * a + i];
      for (int J = 0; J < D; ++J) s += F3[idx2(i, J)] * X[D * a + J];
      u[D * a + i] = s;
    }
  std::vector<double> alpha(ni), f(nd);
  for (int k = 0; k < ni; ++k) alpha[k] = 0.01 * ((k * 7) % 5 - 2);  // a wrong guess
  ASSERT_EQ(kernel->evaluate(X.data(), u.data(), alpha.data(), *material, f.data(), nullptr), ElementStatus::Ok);
  // α = 0 to the local solve's accuracy: it stops at ‖R_α‖ ≤ 1e-13 s (EnhancedStrainElement.hpp),
  // which K_αα⁻¹ turns into |α| ~ 1e-13 of the element size with 4 modes and ~1e-12 with the 9
  // modes of a distorted brick (measured 2.2e-12 for Saint Venant–Kirchhoff here).
  if (ni > 0) {
    EXPECT_LT(maxAbs(alpha), (D == 2 ? 1e-13 : 1e-11) * kSize);
  }
  Tensor2 sigma{}, sigmaExact{};
  ASSERT_TRUE(material->cauchyStress(F3, sigmaExact));
  ASSERT_EQ(kernel->averageCauchyStress(X.data(), u.data(), alpha.data(), *material, sigma), ElementStatus::Ok);
  EXPECT_LT(maxAbsDifference(sigma, sigmaExact), 1e-12 * maxAbs(sigmaExact));
}

TEST_P(ElementCase, MirroredReferenceElementIsRejected) {
  const auto mirrored = mirroredElement(X, D);
  const std::vector<double> u(nd, 0.0);
  std::vector<double> f(nd);
  EXPECT_EQ(kernel->evaluate(mirrored.data(), u.data(), nullptr, *material, f.data(), nullptr),
            ElementStatus::InadmissibleDeformation);
}

TEST_P(ElementCase, StiffnessHasOnlyTheRigidBodyModesAsZeroEnergyModes) {
  // At the reference state K is the small-strain stiffness: its null space must be the rigid motions,
  // D (D + 1) / 2 of them; an integration rule too weak for the element would add spurious
  // (hourglass) modes.
  const std::vector<double> u(nd, 0.0);
  std::vector<double> f(nd), K(nd * nd);
  ASSERT_EQ(kernel->evaluate(X.data(), u.data(), nullptr, *material, f.data(), K.data()), ElementStatus::Ok);
  EXPECT_EQ(nullity(K, nd), D * (D + 1) / 2);
}

/// The same law, not declaring its tangent symmetric: the kernels then take their general path (the
/// whole tangent, Gaussian elimination for the enhanced modes).
class UndeclaredSymmetry final : public Material {
 public:
  explicit UndeclaredSymmetry(const Material& law) : law_(law) {}
  bool firstPiolaKirchhoff(const Tensor2& F, Tensor2& P, Tensor4* A) const override {
    return law_.firstPiolaKirchhoff(F, P, A);
  }
  bool firstPiolaKirchhoffAtPoints(int n, const Matrix<2>* F, Matrix<2>* P, Tangent<2>* A) const override {
    return law_.firstPiolaKirchhoffAtPoints(n, F, P, A);
  }
  bool firstPiolaKirchhoffAtPoints(int n, const Matrix<3>* F, Matrix<3>* P, Tangent<3>* A) const override {
    return law_.firstPiolaKirchhoffAtPoints(n, F, P, A);
  }
  bool isSmallStrain() const override { return law_.isSmallStrain(); }

 private:
  const Material& law_;
};

TEST_P(ElementCase, SymmetricPathEqualsGeneralPath) {
  // Half the tangent mirrored and the LDLᵀ condensation (a law that declares A_iJkL = A_kLiJ; Hex8
  // Enhanced) against the whole tangent and Gaussian elimination: the same force, tangent and internal
  // variables to round-off. The other kernels take one path for both.
  ASSERT_TRUE(material->tangentIsSymmetric());
  const UndeclaredSymmetry general(*material);
  const auto u = deformation(X, *kernel, 1.0);
  std::vector<double> alphaS(ni, 0.0), alphaG(ni, 0.0), fS(nd), fG(nd), KS(nd * nd), KG(nd * nd);
  ASSERT_EQ(kernel->evaluate(X.data(), u.data(), alphaS.data(), *material, fS.data(), KS.data()), ElementStatus::Ok);
  ASSERT_EQ(kernel->evaluate(X.data(), u.data(), alphaG.data(), general, fG.data(), KG.data()), ElementStatus::Ok);
  EXPECT_LT(maxAbsDifference(fS, fG), 1e-12 * maxAbs(fG));
  EXPECT_LT(maxAbsDifference(KS, KG), 1e-12 * maxAbs(KG));
  if (ni > 0) {
    EXPECT_LT(maxAbsDifference(alphaS, alphaG), 1e-12 * maxAbs(alphaG));
  }
  if (GetParam().element == "Hex8 Enhanced") {  // the one kernel that takes the symmetric path (kSymmetricPathPays)
    for (int r = 0; r < nd; ++r)
      for (int c = 0; c < r; ++c) {
        EXPECT_EQ(KS[r * nd + c], KS[c * nd + r]) << "mirrored, so exactly symmetric";
      }
  }
}

INSTANTIATE_TEST_SUITE_P(AllElementsAllLaws, ElementCase, ::testing::ValuesIn(allCases()), caseName);

class FiniteStrainElement : public ElementCase {};

TEST_P(FiniteStrainElement, InternalForceRotatesWithRigidRotation) {
  // x' = Q x: u'_a = Q (X_a + u_a) − X_a must give f'_a = Q f_a (P(QF) = Q P(F); for EAS the local
  // solution is Q α̂, so it holds after condensation as well). In 3D about an oblique axis.
  const auto u = deformation(X, *kernel, 1.0);
  const Tensor2 Q = D == 2 ? rotation(0.9, 0, 0, 1) : rotation(0.9, 0.3, -1.0, 0.6);
  const auto rotate = [&](const double* v, int i) {
    double s = 0.0;
    for (int J = 0; J < D; ++J) s += Q[idx2(i, J)] * v[J];
    return s;
  };
  std::vector<double> uRot(nd);
  for (int a = 0; a < kernel->numNodes(); ++a) {
    double x[3] = {};
    for (int i = 0; i < D; ++i) x[i] = X[D * a + i] + u[D * a + i];
    for (int i = 0; i < D; ++i) uRot[D * a + i] = rotate(x, i) - X[D * a + i];
  }
  std::vector<double> alpha(ni), alphaRot(ni), f(nd), fRot(nd), Qf(nd);
  ASSERT_EQ(kernel->evaluate(X.data(), u.data(), alpha.data(), *material, f.data(), nullptr), ElementStatus::Ok);
  ASSERT_EQ(kernel->evaluate(X.data(), uRot.data(), alphaRot.data(), *material, fRot.data(), nullptr),
            ElementStatus::Ok);
  for (int a = 0; a < kernel->numNodes(); ++a)
    for (int i = 0; i < D; ++i) Qf[D * a + i] = rotate(&f[D * a], i);
  EXPECT_LT(maxAbsDifference(fRot, Qf), 1e-11 * maxAbs(f));
  // Cauchy stress rotates as Q σ Qᵀ.
  Tensor2 s{}, sRot{};
  ASSERT_EQ(kernel->averageCauchyStress(X.data(), u.data(), alpha.data(), *material, s), ElementStatus::Ok);
  ASSERT_EQ(kernel->averageCauchyStress(X.data(), uRot.data(), alphaRot.data(), *material, sRot), ElementStatus::Ok);
  EXPECT_LT(maxAbsDifference(sRot, multiply(multiply(Q, s), transpose(Q))), 1e-11 * maxAbs(s));
  EXPECT_NEAR(vonMises(sRot), vonMises(s), 1e-11 * vonMises(s));
}

TEST_P(FiniteStrainElement, RigidMotionOfTheUndeformedElementGivesZeroForce) {
  // Objectivity at the reference state: a finite rotation plus translation is stress free.
  const Tensor2 Q = D == 2 ? rotation(1.2, 0, 0, 1) : rotation(1.2, -0.4, 0.7, 1.0);
  std::vector<double> u(nd);
  for (int a = 0; a < kernel->numNodes(); ++a)
    for (int i = 0; i < D; ++i) {
      double s = 0.3 * (i + 1) - X[D * a + i];
      for (int J = 0; J < D; ++J) s += Q[idx2(i, J)] * X[D * a + J];
      u[D * a + i] = s;
    }
  std::vector<double> alpha(ni), f(nd), fScale(nd);
  ASSERT_EQ(kernel->evaluate(X.data(), u.data(), alpha.data(), *material, f.data(), nullptr), ElementStatus::Ok);
  // Force scale: the same element under a 1 % stretch.
  std::vector<double> stretch(nd, 0.0);
  for (int a = 0; a < kernel->numNodes(); ++a) stretch[D * a] = 0.01 * X[D * a];
  ASSERT_EQ(kernel->evaluate(X.data(), stretch.data(), nullptr, *material, fScale.data(), nullptr), ElementStatus::Ok);
  const double residual = maxAbs(f) / maxAbs(fScale);
  std::printf("[measure] rigid motion %s / %s: max|f| / max|f(1%% stretch)| = %.2e\n", GetParam().element.c_str(),
              GetParam().material.c_str(), residual);
  EXPECT_LT(residual, 1e-12);
  if (ni > 0) {
    EXPECT_LT(maxAbs(alpha), 1e-13 * kSize);
  }
}

TEST_P(FiniteStrainElement, InvertedElementIsInadmissible) {
  // Mirror the element through the plane y = 0: det F = −1 everywhere.
  std::vector<double> u(nd, 0.0);
  for (int a = 0; a < kernel->numNodes(); ++a) u[D * a + 1] = -2.0 * X[D * a + 1];
  std::vector<double> alpha(ni), f(nd);
  EXPECT_EQ(kernel->evaluate(X.data(), u.data(), alpha.data(), *material, f.data(), nullptr),
            ElementStatus::InadmissibleDeformation);
  Tensor2 s{};
  EXPECT_EQ(kernel->averageCauchyStress(X.data(), u.data(), alpha.data(), *material, s),
            ElementStatus::InadmissibleDeformation);
}

std::vector<Case> finiteStrainCases() {
  std::vector<Case> cases;
  for (const auto& e : elementNames(false))
    for (const char* m : {"Neo-Hookean", "Saint Venant-Kirchhoff"}) cases.push_back({e, m});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(AllElements, FiniteStrainElement, ::testing::ValuesIn(finiteStrainCases()), caseName);

/// P = F − I with a zero tangent: K_αα is singular, so the local solve cannot proceed.
class ZeroTangentMaterial final : public Material {
 public:
  bool firstPiolaKirchhoff(const Tensor2& F, Tensor2& P, Tensor4* A) const override {
    P = add(F, scaled(-1.0, identity2()));
    if (A) A->fill(0.0);
    return true;
  }
};

class EnhancedElement : public ::testing::TestWithParam<std::string> {};

TEST_P(EnhancedElement, SingularLocalProblemReportsInternalSolveFailed) {
  const auto k = ElementFactory::create(GetParam(), "E");
  const auto X = sampleElementsOf(*k)[0];
  const auto u = deformation(X, *k, 1.0);
  std::vector<double> alpha(k->numInternalVariables());
  for (std::size_t m = 0; m < alpha.size(); ++m) alpha[m] = 0.1 * (m + 1);
  const auto before = alpha;
  std::vector<double> f(k->numDofs());
  EXPECT_EQ(k->evaluate(X.data(), u.data(), alpha.data(), ZeroTangentMaterial(), f.data(), nullptr),
            ElementStatus::InternalSolveFailed);
  EXPECT_EQ(alpha, before);  // untouched on failure
}

INSTANTIATE_TEST_SUITE_P(BothEnhanced, EnhancedElement, ::testing::Values("Q4 Enhanced", "Hex8 Enhanced"),
                         [](const auto& info) { return info.index == 0 ? std::string("Q4") : std::string("Hex8"); });

}  // namespace
}  // namespace contessa::mechanics::test
