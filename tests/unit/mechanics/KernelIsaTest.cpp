// The dispatched Hex8 Enhanced kernel (KernelIsa.hpp): its generic x86-64 code and its AVX2 code give
// the same force, tangent and internal variables bit for bit (no fused multiply-adds, the same order of
// every sum), and each passes the tangent check by central differences of its own force, so that both
// are tested on a processor that runs the AVX2 one by default; likewise every law's dispatched 3D point
// loop (MaterialLaw::atPointsAvx2).
#include "MechanicsTestUtilities.hpp"
#include "mechanics/KernelIsa.hpp"

namespace contessa::mechanics::test {
namespace {

/// Sets the kernels' instruction set for one test and restores the one before.
class IsaScope {
 public:
  explicit IsaScope(KernelIsa isa) : before_(kernelIsa()) { ok_ = setKernelIsa(isa); }
  ~IsaScope() { setKernelIsa(before_); }
  bool ok() const { return ok_; }

 private:
  KernelIsa before_;
  bool ok_ = false;
};

struct Evaluation {
  std::vector<double> f, K, alpha, Kfd;
};

/// One Jacobian evaluation of `kernel` at u from α = 0 under `isa`, and the central differences of its force.
Evaluation evaluateUnder(KernelIsa isa, const ElementKernel& kernel, const Material& material,
                         const std::vector<double>& X, const std::vector<double>& u) {
  const IsaScope scope(isa);
  EXPECT_TRUE(scope.ok());
  const int nd = kernel.numDofs();
  Evaluation e{std::vector<double>(nd), std::vector<double>(nd * nd),
               std::vector<double>(kernel.numInternalVariables(), 0.0), {}};
  EXPECT_EQ(kernel.evaluate(X.data(), u.data(), e.alpha.data(), material, e.f.data(), e.K.data()), ElementStatus::Ok);
  e.Kfd = centralDifferenceTangent(kernel, material, X, u, e.alpha, 1e-6);
  return e;
}

class DispatchedKernel : public ElementMaterial {};

TEST_P(DispatchedKernel, GenericAndAvx2GiveTheSameBitsAndBothMatchCentralDifferences) {
  if (!avx2Available()) GTEST_SKIP() << "this processor (or build) has no AVX2";
  for (const auto& X : sampleElementsOf(*kernel)) {
    const auto u = brickDeformation(X, 1.0);
    const Evaluation generic = evaluateUnder(KernelIsa::Generic, *kernel, *material, X, u);
    const Evaluation avx2 = evaluateUnder(KernelIsa::Avx2, *kernel, *material, X, u);
    ASSERT_GT(maxAbs(generic.alpha), 1e-3) << "the enhanced modes are not exercised";
    for (const Evaluation* e : {&generic, &avx2}) {
      EXPECT_LT(maxAbsDifference(e->K, e->Kfd) / maxAbs(e->K), 1e-6);
    }
    // The same bits: a fused a·b + c (rounded once) would move the last bits, and with them contact
    // statuses that sit on a knife edge (issue 23, sixth round: edges_ring_jacobian_3d_friction).
    std::printf("[measure] %s / %s generic against AVX2: force %.1e, tangent %.1e, alpha %.1e\n",
                GetParam().element.c_str(), GetParam().material.c_str(),
                maxAbsDifference(generic.f, avx2.f), maxAbsDifference(generic.K, avx2.K),
                maxAbsDifference(generic.alpha, avx2.alpha));
    EXPECT_EQ(generic.f, avx2.f);
    EXPECT_EQ(generic.K, avx2.K);
    EXPECT_EQ(generic.alpha, avx2.alpha);
  }
}

std::vector<Case> dispatchedCases() {
  std::vector<Case> cases;
  for (const auto& m : MaterialFactory::names()) cases.push_back({"Hex8 Enhanced", m});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Hex8EnhancedAllLaws, DispatchedKernel, ::testing::ValuesIn(dispatchedCases()), caseName);

/// P and A of `material` at Q deformation gradients in one call under `isa`.
std::pair<std::vector<Matrix<3>>, std::vector<Tangent<3>>> lawUnder(KernelIsa isa, const Material& material,
                                                                     const std::vector<Matrix<3>>& F) {
  const IsaScope scope(isa);
  EXPECT_TRUE(scope.ok());
  std::vector<Matrix<3>> P(F.size());
  std::vector<Tangent<3>> A(F.size());
  EXPECT_TRUE(material.firstPiolaKirchhoffAtPoints(static_cast<int>(F.size()), F.data(), P.data(), A.data()));
  return {P, A};
}

// Every law's 3D point loop is dispatched too (Material.hpp, MaterialLaw): every 3D element calls it,
// and Hex8 Enhanced's AVX2 code calls it virtually. The same bits from both, at finite stretches and
// rotations (F far from I, so that every term of every law contributes).
TEST(KernelIsa, EveryLawGivesTheSameBitsGenericAndAvx2) {
  if (!avx2Available()) GTEST_SKIP() << "this processor (or build) has no AVX2";
  std::vector<Matrix<3>> F(8);
  for (std::size_t q = 0; q < F.size(); ++q)
    for (int k = 0; k < 9; ++k)
      F[q][static_cast<std::size_t>(k)] = (k % 4 == 0 ? 1.0 : 0.0) + 0.13 * std::sin(1.7 * k + 0.9 * static_cast<double>(q));
  for (const auto& name : MaterialFactory::names()) {
    const auto material = makeMaterial(name, 200.0, 0.3);
    const auto generic = lawUnder(KernelIsa::Generic, *material, F);
    const auto avx2 = lawUnder(KernelIsa::Avx2, *material, F);
    double largest = 0.0;
    for (const auto& P : generic.first)
      for (double p : P) largest = std::max(largest, std::abs(p));
    EXPECT_GT(largest, 1.0) << name << ": the stress is not exercised";
    EXPECT_EQ(generic.first, avx2.first) << name;
    EXPECT_EQ(generic.second, avx2.second) << name;
  }
}

TEST(KernelIsa, Avx2IsRefusedWhereUnavailableAndGenericAlwaysAccepted) {
  const KernelIsa before = kernelIsa();
  EXPECT_TRUE(setKernelIsa(KernelIsa::Generic));
  EXPECT_EQ(kernelIsa(), KernelIsa::Generic);
  EXPECT_EQ(setKernelIsa(KernelIsa::Avx2), avx2Available());
  EXPECT_EQ(kernelIsa(), avx2Available() ? KernelIsa::Avx2 : KernelIsa::Generic);
  setKernelIsa(before);
}

}  // namespace
}  // namespace contessa::mechanics::test
