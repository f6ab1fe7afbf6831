// The element kernels as the model drives them: reference geometry precomputed for a set of elements,
// element states carried from evaluation to evaluation, and the enhanced element's warm start (its
// local solve starts from α + dα/du (u − u_α)). The warm start must save local iterations without
// changing the converged α beyond round-off, and the tangent must stay the derivative of the force.
#include <algorithm>

#include "MechanicsTestUtilities.hpp"

namespace contessa::mechanics::test {
namespace {

/// 2D: stretch, shear, rotation and a bending pattern (so α ≠ 0), scaled by `amplitude`; 3D:
/// brickDeformation; other families familyDeformation.
std::vector<double> deformation(const std::vector<double>& X, const ElementKernel& kernel, double amplitude) {
  const double H[2][2] = {{0.12, 0.08}, {-0.06, -0.1}};
  return familyDeformation(X, kernel, amplitude, H, 0.1);
}

std::vector<double> allCoordinates(const std::vector<std::vector<double>>& elements) {
  std::vector<double> X;
  for (const auto& e : elements) X.insert(X.end(), e.begin(), e.end());
  return X;
}

/// Counts material calls: the kernels make one per local iteration (all Gauss points at once).
class CountingMaterial final : public Material {
 public:
  explicit CountingMaterial(const Material& law) : law_(law) {}
  bool firstPiolaKirchhoff(const Tensor2& F, Tensor2& P, Tensor4* A) const override {
    count(F.data(), A != nullptr);
    return law_.firstPiolaKirchhoff(F, P, A);
  }
  bool firstPiolaKirchhoffAtPoints(int n, const Matrix<2>* F, Matrix<2>* P, Tangent<2>* A) const override {
    count(F[0].data(), A != nullptr);
    return law_.firstPiolaKirchhoffAtPoints(n, F, P, A);
  }
  bool firstPiolaKirchhoffAtPoints(int n, const Matrix<3>* F, Matrix<3>* P, Tangent<3>* A) const override {
    count(F[0].data(), A != nullptr);
    return law_.firstPiolaKirchhoffAtPoints(n, F, P, A);
  }
  /// Local iterations: evaluations at a new F. A residual evaluation asks for P alone and adds A at the
  /// same F only where a Newton step needs it: that second call is not an iteration.
  mutable int calls = 0;
  mutable int tangents = 0;  ///< calls that asked for A

 private:
  void count(const double* F0, bool withTangent) const {
    tangents += withTangent ? 1 : 0;
    const bool sameF = withTangent && lastWithoutTangent_ && std::equal(F0, F0 + 4, lastF_);
    if (!sameF) ++calls;
    lastWithoutTangent_ = !withTangent;
    std::copy(F0, F0 + 4, lastF_);
  }
  const Material& law_;
  mutable bool lastWithoutTangent_ = false;
  mutable double lastF_[4] = {};
};

class ElementState : public ElementMaterial {
 protected:
  const int D = kernel->dimension(), nd = kernel->numDofs();
  const std::vector<std::vector<double>> elements = sampleElementsOf(*kernel);
};

TEST_P(ElementState, PrecomputedGeometryOfASetGivesTheSingleElementAnswer) {
  const auto X = allCoordinates(elements);
  const auto geometry = kernel->referenceGeometry(static_cast<int>(elements.size()), X.data());
  ASSERT_EQ(geometry->size(), static_cast<int>(elements.size()));
  const int ns = kernel->numStateValues(), ni = kernel->numInternalVariables();
  ASSERT_GE(ns, ni);
  for (std::size_t e = 0; e < elements.size(); ++e) {
    const auto u = deformation(elements[e], *kernel, 1.0);
    std::vector<double> state(ns, 0.0), internal(ni, 0.0);
    std::vector<double> f(nd), fSingle(nd), K(nd * nd), KSingle(nd * nd);
    ASSERT_EQ(kernel->evaluate(*geometry, static_cast<int>(e), u.data(), state.data(), *material, f.data(), K.data()),
              ElementStatus::Ok);
    ASSERT_EQ(kernel->evaluate(elements[e].data(), u.data(), internal.data(), *material, fSingle.data(),
                               KSingle.data()),
              ElementStatus::Ok);
    // Same arithmetic from the same (zero) start: identical.
    EXPECT_EQ(f, fSingle);
    EXPECT_EQ(K, KSingle);
    for (int k = 0; k < ni; ++k) EXPECT_EQ(state[k], internal[k]);
    Tensor2 s{}, sSingle{};
    ASSERT_EQ(kernel->averageCauchyStress(*geometry, static_cast<int>(e), u.data(), state.data(), *material, s),
              ElementStatus::Ok);
    ASSERT_EQ(kernel->averageCauchyStress(elements[e].data(), u.data(), internal.data(), *material, sSingle),
              ElementStatus::Ok);
    EXPECT_EQ(s, sSingle);
  }
}

TEST_P(ElementState, MirroredElementInASetIsInadmissibleAndLeavesTheOthersAlone) {
  const auto mirrored = mirroredElement(elements[2], D);
  std::vector<double> X(elements[0].begin(), elements[0].end());
  X.insert(X.end(), mirrored.begin(), mirrored.end());
  X.insert(X.end(), elements[1].begin(), elements[1].end());
  const auto geometry = kernel->referenceGeometry(3, X.data());
  std::vector<double> state(kernel->numStateValues(), 0.0);
  std::vector<double> f(nd);
  const std::vector<double> zero(nd, 0.0);
  EXPECT_EQ(kernel->evaluate(*geometry, 1, zero.data(), state.data(), *material, f.data(), nullptr),
            ElementStatus::InadmissibleDeformation);
  Tensor2 s{};
  EXPECT_EQ(kernel->averageCauchyStress(*geometry, 1, zero.data(), state.data(), *material, s),
            ElementStatus::InadmissibleDeformation);
  for (int e : {0, 2}) {
    const auto u = deformation(elements[e == 0 ? 0 : 1], *kernel, 0.5);
    std::vector<double> fresh(kernel->numStateValues(), 0.0);
    EXPECT_EQ(kernel->evaluate(*geometry, e, u.data(), fresh.data(), *material, f.data(), nullptr), ElementStatus::Ok);
  }
}

TEST_P(ElementState, TangentWithCarriedStateMatchesCentralDifferences) {
  // A state that has been through a Jacobian at a nearby u (so the warm start is active in every
  // evaluation below), then K at u against central differences of f, each perturbed evaluation
  // starting from a copy of that state.
  const auto& Xe = elements[1];
  const auto geometry = kernel->referenceGeometry(1, Xe.data());
  const int ns = kernel->numStateValues();
  std::vector<double> state(ns, 0.0);
  std::vector<double> f(nd), K(nd * nd);
  const auto u0 = deformation(Xe, *kernel, 0.9), u = deformation(Xe, *kernel, 1.0);
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u0.data(), state.data(), *material, f.data(), K.data()), ElementStatus::Ok);
  const std::vector<double> base = state;
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u.data(), state.data(), *material, f.data(), K.data()), ElementStatus::Ok);
  const double h = 1e-6 * 2.0;
  std::vector<double> Kfd(nd * nd);
  for (int c = 0; c < nd; ++c) {
    auto up = u, um = u;
    up[c] += h;
    um[c] -= h;
    auto sp = base, sm = base;
    std::vector<double> fp(nd), fm(nd);
    ASSERT_EQ(kernel->evaluate(*geometry, 0, up.data(), sp.data(), *material, fp.data(), nullptr), ElementStatus::Ok);
    ASSERT_EQ(kernel->evaluate(*geometry, 0, um.data(), sm.data(), *material, fm.data(), nullptr), ElementStatus::Ok);
    for (int r = 0; r < nd; ++r) Kfd[r * nd + c] = (fp[r] - fm[r]) / (2.0 * h);
  }
  const double err = maxAbsDifference(K, Kfd) / maxAbs(K);
  std::printf("[measure] element FD with carried state %s / %s: rel err %.2e\n", GetParam().element.c_str(),
              GetParam().material.c_str(), err);
  EXPECT_LT(err, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(AllElementsAllLaws, ElementState, ::testing::ValuesIn(allCases()), caseName);

// ---- The enhanced elements' warm start ----

std::vector<Case> warmStartCases() {
  std::vector<Case> cases;
  for (const char* e : {"Q4 Enhanced", "Hex8 Enhanced"})
    for (const char* m : {"Saint Venant-Kirchhoff", "Neo-Hookean"}) cases.push_back({e, m});
  return cases;
}

class WarmStart : public ElementMaterial {
 protected:
  const int D = kernel->dimension(), nd = kernel->numDofs(), na = kernel->numInternalVariables();
  const std::vector<double> X = sampleElementsOf(*kernel)[0];
  std::unique_ptr<ElementGeometry> geometry = kernel->referenceGeometry(1, X.data());
  /// How closely two local solves from different starts agree (relative to max |α|): each stops at
  /// ‖R_α‖ ≤ 1e-13 s (EnhancedStrainElement.hpp), i.e. within K_αα⁻¹ of that residual of α*. With the
  /// 9 modes of a distorted brick that is ~1e-12 of α (measured up to 2.2e-12), with 4 modes below it.
  const double alphaAgreement = D == 2 ? 1e-12 : 1e-11;

  /// α at u solved from zero with no warm start, the reference answer.
  std::vector<double> coldAlpha(const std::vector<double>& u) {
    std::vector<double> alpha(na, 0.0), f(nd);
    EXPECT_EQ(kernel->evaluate(X.data(), u.data(), alpha.data(), *material, f.data(), nullptr), ElementStatus::Ok);
    return alpha;
  }
};

TEST_P(WarmStart, SmallChangeAfterAJacobianConvergesInOneLocalIteration) {
  const auto u0 = deformation(X, *kernel, 1.0);
  std::vector<double> state(kernel->numStateValues(), 0.0);
  std::vector<double> f(nd), K(nd * nd);
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u0.data(), state.data(), *material, f.data(), K.data()), ElementStatus::Ok);
  // A late Newton correction: δu ~ 1e-7 of the element size. The predicted α is off by O(δu²),
  // below the local tolerance, so the first residual check passes.
  auto u1 = u0;
  for (int k = 0; k < nd; ++k) u1[k] += 1e-7 * (k % 3 - 1) * (1.0 + 0.1 * k);
  const CountingMaterial counting(*material);
  auto warm = state;
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u1.data(), warm.data(), counting, f.data(), nullptr), ElementStatus::Ok);
  const int warmIterations = counting.calls;
  // Converged at its first check: a residual evaluation that needs no Newton step evaluates no tangent.
  EXPECT_EQ(counting.tangents, 0);
  // Without the warm-start data (α of u0 only), as before: one Newton step and a check.
  std::vector<double> alphaOnly(kernel->numStateValues(), 0.0);
  std::copy(state.begin(), state.begin() + na, alphaOnly.begin());
  counting.calls = 0;
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u1.data(), alphaOnly.data(), counting, f.data(), nullptr),
            ElementStatus::Ok);
  const int coldIterations = counting.calls;
  std::printf("[measure] warm start %s / %s: local iterations %d with the prediction, %d from the last alpha\n",
              GetParam().element.c_str(), GetParam().material.c_str(), warmIterations, coldIterations);
  EXPECT_EQ(warmIterations, 1);
  EXPECT_EQ(coldIterations, 2);
  // The converged α does not depend on the start beyond round-off.
  const auto reference = coldAlpha(u1);
  for (int k = 0; k < na; ++k) {
    EXPECT_NEAR(warm[k], reference[k], alphaAgreement * maxAbs(reference));
    EXPECT_NEAR(alphaOnly[k], reference[k], alphaAgreement * maxAbs(reference));
  }
}

TEST_P(WarmStart, LargeChangeGivesTheColdAnswerWithFewerIterations) {
  // A whole load increment (u0 → u1 = 1.1 u0 plus a rotation of 0.05 rad): the prediction is only
  // first order, but it is still closer than the last α, and the answer is the same.
  const auto u0 = deformation(X, *kernel, 0.8);
  const Tensor2 Q = rotation(0.05, D == 2 ? 0.0 : 1.0, D == 2 ? 0.0 : 1.0, 1.0);
  std::vector<double> u1(nd);
  for (int a = 0; a < kernel->numNodes(); ++a)
    for (int i = 0; i < D; ++i) {
      double s = -X[D * a + i];
      for (int J = 0; J < D; ++J) s += Q[idx2(i, J)] * (X[D * a + J] + 1.1 * u0[D * a + J]);
      u1[D * a + i] = s;
    }
  std::vector<double> state(kernel->numStateValues(), 0.0);
  std::vector<double> f(nd), fCold(nd), K(nd * nd);
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u0.data(), state.data(), *material, f.data(), K.data()), ElementStatus::Ok);
  std::vector<double> alphaOnly(kernel->numStateValues(), 0.0);
  std::copy(state.begin(), state.begin() + na, alphaOnly.begin());
  const CountingMaterial counting(*material);
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u1.data(), state.data(), counting, f.data(), nullptr), ElementStatus::Ok);
  const int warmIterations = counting.calls;
  counting.calls = 0;
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u1.data(), alphaOnly.data(), counting, fCold.data(), nullptr),
            ElementStatus::Ok);
  std::printf("[measure] warm start %s / %s, one increment: local iterations %d with the prediction, %d without\n",
              GetParam().element.c_str(), GetParam().material.c_str(), warmIterations, counting.calls);
  EXPECT_LE(warmIterations, counting.calls);
  EXPECT_LT(maxAbsDifference(f, fCold), 1e-12 * maxAbs(fCold));
  const auto reference = coldAlpha(u1);
  for (int k = 0; k < na; ++k) EXPECT_NEAR(state[k], reference[k], alphaAgreement * maxAbs(reference));
}

TEST_P(WarmStart, AWildPredictionFallsBackToTheLastAlpha) {
  // Corrupt dα/du so that the predicted α inverts the element: the solve restarts from α itself and
  // reaches the same answer.
  const auto u0 = deformation(X, *kernel, 1.0), u1 = deformation(X, *kernel, 1.05);
  std::vector<double> state(kernel->numStateValues(), 0.0);
  std::vector<double> f(nd), fReference(nd), K(nd * nd);
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u0.data(), state.data(), *material, f.data(), K.data()), ElementStatus::Ok);
  for (int k = na + nd; k < kernel->numStateValues(); ++k) state[k] = 1e4 * (k % 2 ? 1.0 : -1.0);
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u1.data(), state.data(), *material, f.data(), nullptr), ElementStatus::Ok);
  std::vector<double> alpha(na, 0.0);
  ASSERT_EQ(kernel->evaluate(X.data(), u1.data(), alpha.data(), *material, fReference.data(), nullptr),
            ElementStatus::Ok);
  EXPECT_LT(maxAbsDifference(f, fReference), 1e-12 * maxAbs(fReference));
  for (int k = 0; k < na; ++k) EXPECT_NEAR(state[k], alpha[k], alphaAgreement * maxAbs(alpha));
}

TEST_P(WarmStart, StateIsUnchangedWhenTheEvaluationFails) {
  const auto u0 = deformation(X, *kernel, 1.0);
  std::vector<double> state(kernel->numStateValues(), 0.0);
  std::vector<double> f(nd), K(nd * nd);
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u0.data(), state.data(), *material, f.data(), K.data()), ElementStatus::Ok);
  const auto before = state;
  std::vector<double> inverted(nd, 0.0);
  for (int a = 0; a < kernel->numNodes(); ++a) inverted[D * a + 1] = -2.0 * X[D * a + 1];
  EXPECT_EQ(kernel->evaluate(*geometry, 0, inverted.data(), state.data(), *material, f.data(), K.data()),
            ElementStatus::InadmissibleDeformation);
  EXPECT_EQ(state, before);
}

INSTANTIATE_TEST_SUITE_P(EnhancedFiniteStrain, WarmStart, ::testing::ValuesIn(warmStartCases()), caseName);

}  // namespace
}  // namespace contessa::mechanics::test
