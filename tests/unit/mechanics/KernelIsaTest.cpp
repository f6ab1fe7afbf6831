// The dispatched Hex8 Enhanced kernel (KernelIsa.hpp): its generic x86-64 code and its AVX2 + FMA code
// give the same force, tangent and internal variables to round-off, and each passes the tangent check
// by central differences of its own force, so that both are tested on a processor that runs the AVX2
// one by default.
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

TEST_P(DispatchedKernel, GenericAndAvx2FmaAgreeAndBothMatchCentralDifferences) {
  if (!avx2FmaAvailable()) GTEST_SKIP() << "this processor (or build) has no AVX2 + FMA";
  for (const auto& X : sampleElementsOf(*kernel)) {
    const auto u = brickDeformation(X, 1.0);
    const Evaluation generic = evaluateUnder(KernelIsa::Generic, *kernel, *material, X, u);
    const Evaluation avx2 = evaluateUnder(KernelIsa::Avx2Fma, *kernel, *material, X, u);
    ASSERT_GT(maxAbs(generic.alpha), 1e-3) << "the enhanced modes are not exercised";
    for (const Evaluation* e : {&generic, &avx2}) {
      EXPECT_LT(maxAbsDifference(e->K, e->Kfd) / maxAbs(e->K), 1e-6);
    }
    // A fused a·b + c is rounded once instead of twice: the last bits differ, nothing more.
    const double df = maxAbsDifference(generic.f, avx2.f) / maxAbs(generic.f);
    const double dK = maxAbsDifference(generic.K, avx2.K) / maxAbs(generic.K);
    const double da = maxAbsDifference(generic.alpha, avx2.alpha) / maxAbs(generic.alpha);
    std::printf("[measure] %s / %s generic against AVX2 + FMA: force %.1e, tangent %.1e, alpha %.1e\n",
                GetParam().element.c_str(), GetParam().material.c_str(), df, dK, da);
    EXPECT_LT(df, 1e-13);
    EXPECT_LT(dK, 1e-13);
    EXPECT_LT(da, 1e-13);
    // Different code really ran: with fused multiply-adds the tangent cannot come out bit for bit.
    EXPECT_NE(generic.K, avx2.K);
  }
}

std::vector<Case> dispatchedCases() {
  std::vector<Case> cases;
  for (const auto& m : MaterialFactory::names()) cases.push_back({"Hex8 Enhanced", m});
  return cases;
}

INSTANTIATE_TEST_SUITE_P(Hex8EnhancedAllLaws, DispatchedKernel, ::testing::ValuesIn(dispatchedCases()), caseName);

TEST(KernelIsa, Avx2FmaIsRefusedWhereUnavailableAndGenericAlwaysAccepted) {
  const KernelIsa before = kernelIsa();
  EXPECT_TRUE(setKernelIsa(KernelIsa::Generic));
  EXPECT_EQ(kernelIsa(), KernelIsa::Generic);
  EXPECT_EQ(setKernelIsa(KernelIsa::Avx2Fma), avx2FmaAvailable());
  EXPECT_EQ(kernelIsa(), avx2FmaAvailable() ? KernelIsa::Avx2Fma : KernelIsa::Generic);
  setKernelIsa(before);
}

}  // namespace
}  // namespace contessa::mechanics::test
