// The dispatched Hex8 Enhanced kernel (KernelIsa.hpp): its generic x86-64 code and its AVX2 code give
// the same force, tangent and internal variables bit for bit (no fused multiply-adds, the same order of
// every sum), and each passes the tangent check by central differences of its own force, so that both
// are tested on a processor that runs the AVX2 one by default.
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
