// The element kernels as the model drives them: reference geometry precomputed for a set of elements,
// element states carried from evaluation to evaluation, and the enhanced element's warm start (its
// local solve starts from α + dα/du (u − u_α)). The warm start must save local iterations without
// changing the converged α beyond round-off, and the tangent must stay the derivative of the force.
#include "MechanicsTestUtilities.hpp"

namespace contessa::mechanics::test {
namespace {

// Three distorted quadrilaterals (counter-clockwise) and one clockwise one.
const std::vector<std::array<double, 8>> kElements = {
    {0.0, 0.0, 2.0, 0.3, 2.4, 1.8, -0.2, 1.5},
    {1.0, -0.5, 2.6, 0.1, 2.2, 1.4, 0.8, 1.1},
    {-1.0, 0.2, 0.1, -0.1, 0.3, 0.9, -0.8, 1.2}};
const std::array<double, 8> kClockwise = {0, 0, 0, 1, 1, 1, 1, 0};

/// Stretch, shear, rotation and a bending pattern (so α ≠ 0), scaled by `amplitude`.
std::array<double, 8> deformation(const std::array<double, 8>& X, double amplitude) {
  const double H[2][2] = {{0.12, 0.08}, {-0.06, -0.1}};
  const double hourglass[4] = {1, -1, 1, -1};
  std::array<double, 8> u{};
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 2; ++i)
      u[2 * a + i] = amplitude * (H[i][0] * X[2 * a] + H[i][1] * X[2 * a + 1] + 0.1 * hourglass[a] * (i ? 0.5 : 1.0));
  return u;
}

std::vector<double> allCoordinates() {
  std::vector<double> X;
  for (const auto& e : kElements) X.insert(X.end(), e.begin(), e.end());
  return X;
}

/// Counts material calls: the kernels make one per local iteration (all Gauss points at once).
class CountingMaterial final : public Material {
 public:
  explicit CountingMaterial(const Material& law) : law_(law) {}
  bool firstPiolaKirchhoff(const Tensor2& F, Tensor2& P, Tensor4* A) const override {
    ++calls;
    return law_.firstPiolaKirchhoff(F, P, A);
  }
  bool firstPiolaKirchhoffAtPoints(int n, const Matrix<2>* F, Matrix<2>* P, Tangent<2>* A) const override {
    ++calls;
    return law_.firstPiolaKirchhoffAtPoints(n, F, P, A);
  }
  bool firstPiolaKirchhoffAtPoints(int n, const Matrix<3>* F, Matrix<3>* P, Tangent<3>* A) const override {
    ++calls;
    return law_.firstPiolaKirchhoffAtPoints(n, F, P, A);
  }
  mutable int calls = 0;

 private:
  const Material& law_;
};

class ElementState : public ElementMaterial {};

TEST_P(ElementState, PrecomputedGeometryOfASetGivesTheSingleElementAnswer) {
  const auto X = allCoordinates();
  const auto geometry = kernel->referenceGeometry(static_cast<int>(kElements.size()), X.data());
  ASSERT_EQ(geometry->size(), static_cast<int>(kElements.size()));
  const int ns = kernel->numStateValues(), ni = kernel->numInternalVariables();
  ASSERT_GE(ns, ni);
  for (std::size_t e = 0; e < kElements.size(); ++e) {
    const auto u = deformation(kElements[e], 1.0);
    std::vector<double> state(ns, 0.0), internal(ni, 0.0);
    std::array<double, 8> f{}, fSingle{};
    std::array<double, 64> K{}, KSingle{};
    ASSERT_EQ(kernel->evaluate(*geometry, static_cast<int>(e), u.data(), state.data(), *material, f.data(), K.data()),
              ElementStatus::Ok);
    ASSERT_EQ(kernel->evaluate(kElements[e].data(), u.data(), internal.data(), *material, fSingle.data(),
                               KSingle.data()),
              ElementStatus::Ok);
    // Same arithmetic from the same (zero) start: identical.
    EXPECT_EQ(f, fSingle);
    EXPECT_EQ(K, KSingle);
    for (int k = 0; k < ni; ++k) EXPECT_EQ(state[k], internal[k]);
    Tensor2 s{}, sSingle{};
    ASSERT_EQ(kernel->averageCauchyStress(*geometry, static_cast<int>(e), u.data(), state.data(), *material, s),
              ElementStatus::Ok);
    ASSERT_EQ(kernel->averageCauchyStress(kElements[e].data(), u.data(), internal.data(), *material, sSingle),
              ElementStatus::Ok);
    EXPECT_EQ(s, sSingle);
  }
}

TEST_P(ElementState, ClockwiseElementInASetIsInadmissibleAndLeavesTheOthersAlone) {
  std::vector<double> X(kElements[0].begin(), kElements[0].end());
  X.insert(X.end(), kClockwise.begin(), kClockwise.end());
  X.insert(X.end(), kElements[1].begin(), kElements[1].end());
  const auto geometry = kernel->referenceGeometry(3, X.data());
  std::vector<double> state(kernel->numStateValues(), 0.0);
  std::array<double, 8> f{};
  const std::array<double, 8> zero{};
  EXPECT_EQ(kernel->evaluate(*geometry, 1, zero.data(), state.data(), *material, f.data(), nullptr),
            ElementStatus::InadmissibleDeformation);
  Tensor2 s{};
  EXPECT_EQ(kernel->averageCauchyStress(*geometry, 1, zero.data(), state.data(), *material, s),
            ElementStatus::InadmissibleDeformation);
  for (int e : {0, 2}) {
    const auto u = deformation(kElements[e == 0 ? 0 : 1], 0.5);
    std::vector<double> fresh(kernel->numStateValues(), 0.0);
    EXPECT_EQ(kernel->evaluate(*geometry, e, u.data(), fresh.data(), *material, f.data(), nullptr), ElementStatus::Ok);
  }
}

TEST_P(ElementState, TangentWithCarriedStateMatchesCentralDifferences) {
  // A state that has been through a Jacobian at a nearby u (so the warm start is active in every
  // evaluation below), then K at u against central differences of f, each perturbed evaluation
  // starting from a copy of that state.
  const auto& Xe = kElements[1];
  const auto geometry = kernel->referenceGeometry(1, Xe.data());
  const int ns = kernel->numStateValues();
  std::vector<double> state(ns, 0.0);
  std::array<double, 8> f{};
  std::array<double, 64> K{};
  const auto u0 = deformation(Xe, 0.9), u = deformation(Xe, 1.0);
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u0.data(), state.data(), *material, f.data(), K.data()), ElementStatus::Ok);
  const std::vector<double> base = state;
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u.data(), state.data(), *material, f.data(), K.data()), ElementStatus::Ok);
  const double h = 1e-6 * 2.0;
  std::array<double, 64> Kfd{};
  for (int c = 0; c < 8; ++c) {
    auto up = u, um = u;
    up[c] += h;
    um[c] -= h;
    auto sp = base, sm = base;
    std::array<double, 8> fp{}, fm{};
    ASSERT_EQ(kernel->evaluate(*geometry, 0, up.data(), sp.data(), *material, fp.data(), nullptr), ElementStatus::Ok);
    ASSERT_EQ(kernel->evaluate(*geometry, 0, um.data(), sm.data(), *material, fm.data(), nullptr), ElementStatus::Ok);
    for (int r = 0; r < 8; ++r) Kfd[r * 8 + c] = (fp[r] - fm[r]) / (2.0 * h);
  }
  const double err = maxAbsDifference(K, Kfd) / maxAbs(K);
  std::printf("[measure] element FD with carried state %s / %s: rel err %.2e\n", GetParam().element.c_str(),
              GetParam().material.c_str(), err);
  EXPECT_LT(err, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(AllElementsAllLaws, ElementState, ::testing::ValuesIn(allCases()), caseName);

// ---- The enhanced element's warm start ----

class WarmStart : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<ElementKernel> kernel = ElementFactory::create("Q4 Enhanced", "Test/Element");
  std::unique_ptr<Material> law = makeMaterial(GetParam(), 100.0, 0.3);
  std::array<double, 8> X = kElements[0];
  std::unique_ptr<ElementGeometry> geometry = kernel->referenceGeometry(1, X.data());

  /// α at u solved from zero with no warm start, the reference answer.
  std::array<double, 4> coldAlpha(const std::array<double, 8>& u) {
    std::array<double, 4> alpha{};
    std::array<double, 8> f{};
    EXPECT_EQ(kernel->evaluate(X.data(), u.data(), alpha.data(), *law, f.data(), nullptr), ElementStatus::Ok);
    return alpha;
  }
};

TEST_P(WarmStart, SmallChangeAfterAJacobianConvergesInOneLocalIteration) {
  const auto u0 = deformation(X, 1.0);
  std::vector<double> state(kernel->numStateValues(), 0.0);
  std::array<double, 8> f{};
  std::array<double, 64> K{};
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u0.data(), state.data(), *law, f.data(), K.data()), ElementStatus::Ok);
  // A late Newton correction: δu ~ 1e-7 of the element size. The predicted α is off by O(δu²),
  // below the local tolerance, so the first residual check passes.
  auto u1 = u0;
  for (int k = 0; k < 8; ++k) u1[k] += 1e-7 * (k % 3 - 1) * (1.0 + 0.1 * k);
  const CountingMaterial counting(*law);
  auto warm = state;
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u1.data(), warm.data(), counting, f.data(), nullptr), ElementStatus::Ok);
  const int warmIterations = counting.calls;
  // Without the warm-start data (α of u0 only), as before: one Newton step and a check.
  std::vector<double> alphaOnly(kernel->numStateValues(), 0.0);
  std::copy(state.begin(), state.begin() + 4, alphaOnly.begin());
  counting.calls = 0;
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u1.data(), alphaOnly.data(), counting, f.data(), nullptr),
            ElementStatus::Ok);
  const int coldIterations = counting.calls;
  std::printf("[measure] warm start %s: local iterations %d with the prediction, %d from the last alpha\n",
              GetParam().c_str(), warmIterations, coldIterations);
  EXPECT_EQ(warmIterations, 1);
  EXPECT_EQ(coldIterations, 2);
  // The converged α does not depend on the start beyond round-off.
  const auto reference = coldAlpha(u1);
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(warm[k], reference[k], 1e-12 * maxAbs(reference));
    EXPECT_NEAR(alphaOnly[k], reference[k], 1e-12 * maxAbs(reference));
  }
}

TEST_P(WarmStart, LargeChangeGivesTheColdAnswerWithFewerIterations) {
  // A whole load increment (u0 → u1 = 1.1 u0 plus a rotation): the prediction is only first order,
  // but it is still closer than the last α, and the answer is the same.
  const auto u0 = deformation(X, 0.8);
  std::array<double, 8> u1{};
  const double c = std::cos(0.05), s = std::sin(0.05);
  for (int a = 0; a < 4; ++a) {
    const double x = X[2 * a] + 1.1 * u0[2 * a], y = X[2 * a + 1] + 1.1 * u0[2 * a + 1];
    u1[2 * a] = c * x - s * y - X[2 * a];
    u1[2 * a + 1] = s * x + c * y - X[2 * a + 1];
  }
  std::vector<double> state(kernel->numStateValues(), 0.0);
  std::array<double, 8> f{}, fCold{};
  std::array<double, 64> K{};
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u0.data(), state.data(), *law, f.data(), K.data()), ElementStatus::Ok);
  std::vector<double> alphaOnly(kernel->numStateValues(), 0.0);
  std::copy(state.begin(), state.begin() + 4, alphaOnly.begin());
  const CountingMaterial counting(*law);
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u1.data(), state.data(), counting, f.data(), nullptr), ElementStatus::Ok);
  const int warmIterations = counting.calls;
  counting.calls = 0;
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u1.data(), alphaOnly.data(), counting, fCold.data(), nullptr),
            ElementStatus::Ok);
  std::printf("[measure] warm start %s, one increment: local iterations %d with the prediction, %d without\n",
              GetParam().c_str(), warmIterations, counting.calls);
  EXPECT_LE(warmIterations, counting.calls);
  EXPECT_LT(maxAbsDifference(f, fCold), 1e-12 * maxAbs(fCold));
  const auto reference = coldAlpha(u1);
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(state[k], reference[k], 1e-12 * maxAbs(reference));
}

TEST_P(WarmStart, AWildPredictionFallsBackToTheLastAlpha) {
  // Corrupt dα/du so that the predicted α inverts the element: the solve restarts from α itself and
  // reaches the same answer.
  const auto u0 = deformation(X, 1.0), u1 = deformation(X, 1.05);
  std::vector<double> state(kernel->numStateValues(), 0.0);
  std::array<double, 8> f{}, fReference{};
  std::array<double, 64> K{};
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u0.data(), state.data(), *law, f.data(), K.data()), ElementStatus::Ok);
  for (int k = 4 + 8; k < kernel->numStateValues(); ++k) state[k] = 1e4 * (k % 2 ? 1.0 : -1.0);
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u1.data(), state.data(), *law, f.data(), nullptr), ElementStatus::Ok);
  std::array<double, 4> alpha{};
  ASSERT_EQ(kernel->evaluate(X.data(), u1.data(), alpha.data(), *law, fReference.data(), nullptr), ElementStatus::Ok);
  EXPECT_LT(maxAbsDifference(f, fReference), 1e-12 * maxAbs(fReference));
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(state[k], alpha[k], 1e-12 * maxAbs(alpha));
}

TEST_P(WarmStart, StateIsUnchangedWhenTheEvaluationFails) {
  const auto u0 = deformation(X, 1.0);
  std::vector<double> state(kernel->numStateValues(), 0.0);
  std::array<double, 8> f{};
  std::array<double, 64> K{};
  ASSERT_EQ(kernel->evaluate(*geometry, 0, u0.data(), state.data(), *law, f.data(), K.data()), ElementStatus::Ok);
  const auto before = state;
  std::array<double, 8> inverted{};
  for (int a = 0; a < 4; ++a) inverted[2 * a + 1] = -2.0 * X[2 * a + 1];
  EXPECT_EQ(kernel->evaluate(*geometry, 0, inverted.data(), state.data(), *law, f.data(), K.data()),
            ElementStatus::InadmissibleDeformation);
  EXPECT_EQ(state, before);
}

INSTANTIATE_TEST_SUITE_P(FiniteStrainLaws, WarmStart, ::testing::Values("Saint Venant-Kirchhoff", "Neo-Hookean"),
                         [](const auto& param) { return param.index == 0 ? std::string("SVK") : std::string("NeoHookean"); });

}  // namespace
}  // namespace contessa::mechanics::test
