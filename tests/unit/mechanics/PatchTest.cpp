// Patch tests on distorted meshes: a linear displacement field must be reproduced exactly (small
// strain), and a homogeneous finite deformation must be an exact equilibrium state.
#include "MechanicsTestUtilities.hpp"

namespace contessa::mechanics::test {
namespace {

/// The MacNeal–Harder (1985) patch: a 0.24 × 0.12 rectangle, 4 boundary nodes, 4 interior nodes
/// at irregular positions, 5 distorted elements.
QuadMesh macNealHarderPatch(std::vector<int>& interiorNodes) {
  QuadMesh m;
  m.X = {0.0, 0.0, 0.24, 0.0, 0.24, 0.12, 0.0, 0.12, 0.04, 0.02, 0.18, 0.03, 0.16, 0.08, 0.08, 0.08};
  m.cells = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}};
  interiorNodes = {4, 5, 6, 7};
  return m;
}

/// A 2 × 2 patch on the unit square with the centre node moved off-centre.
QuadMesh distortedTwoByTwo(std::vector<int>& interiorNodes) {
  QuadMesh m = rectangleMesh(2, 2, 1.0, 1.0);
  m.X[2 * 4] = 0.62;
  m.X[2 * 4 + 1] = 0.33;
  interiorNodes = {4};
  return m;
}

std::vector<int> interiorDofs(const std::vector<int>& nodes) {
  std::vector<int> dofs;
  for (int n : nodes) dofs.insert(dofs.end(), {2 * n, 2 * n + 1});
  return dofs;
}

struct PatchCase {
  std::string element;
  int mesh;  // 0: MacNeal–Harder, 1: distorted 2 × 2
};
void PrintTo(const PatchCase& c, std::ostream* os) { *os << c.element << " / mesh " << c.mesh; }

class Patch : public ::testing::TestWithParam<PatchCase> {
 protected:
  QuadMesh mesh() {
    return GetParam().mesh == 0 ? macNealHarderPatch(interior_) : distortedTwoByTwo(interior_);
  }
  std::unique_ptr<ElementKernel> kernel = ElementFactory::create(GetParam().element, "Test/Element");
  std::vector<int> interior_;
};

TEST_P(Patch, LinearFieldIsReproducedExactly) {
  const double E = 1e6, nu = 0.25;
  const auto material = makeMaterial("Linear Elastic", E, nu);
  const QuadMesh m = mesh();
  // u = 1e-3 (x + y/2), v = 1e-3 (y + x/2) (MacNeal–Harder) plus a rigid rotation and translation.
  auto exact = [](double x, double y) {
    return std::array<double, 2>{1e-3 * (x + 0.5 * y) - 2e-4 * y + 1e-4, 1e-3 * (y + 0.5 * x) + 2e-4 * x - 3e-4};
  };
  std::vector<double> u(m.numDofs(), 0.0), uExact(m.numDofs());
  for (int n = 0; n < m.numNodes(); ++n) {
    const auto v = exact(m.X[2 * n], m.X[2 * n + 1]);
    uExact[2 * n] = v[0], uExact[2 * n + 1] = v[1];
  }
  const auto free = interiorDofs(interior_);
  u = uExact;
  for (int d : free) u[d] = 0.0;  // unknown: solved for
  std::vector<double> internal, fExt(m.numDofs(), 0.0);
  const int iterations = solveEquilibrium(*kernel, *material, m, free, fExt, u, internal);
  ASSERT_GE(iterations, 0);
  EXPECT_LE(iterations, 2);  // linear problem: one Newton step

  const double uErr = maxAbsDifference(u, uExact) / maxAbs(uExact);
  // Exact constant stress, plane strain: σ_zz = λ tr ε.
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double exx = 1e-3, eyy = 1e-3, exy = 0.5e-3;
  const Tensor2 sigmaExact = {lambda * (exx + eyy) + 2 * mu * exx, 2 * mu * exy, 0,
                              2 * mu * exy, lambda * (exx + eyy) + 2 * mu * eyy, 0,
                              0, 0, lambda * (exx + eyy)};
  double sErr = 0.0;
  const int ni = kernel->numInternalVariables();
  for (std::size_t e = 0; e < m.cells.size(); ++e) {
    const auto Xe = gather(m.X, m.cells[e]), ue = gather(u, m.cells[e]);
    Tensor2 s{};
    ASSERT_EQ(kernel->averageCauchyStress(Xe.data(), ue.data(), ni ? &internal[e * ni] : nullptr, *material, s),
              ElementStatus::Ok);
    sErr = std::max(sErr, maxAbsDifference(s, sigmaExact) / maxAbs(sigmaExact));
    // The enhanced parameters stay zero: a constant stress does no work on H̃.
    for (int k = 0; k < ni; ++k) EXPECT_LT(std::fabs(internal[e * ni + k]), 1e-12);
  }
  std::printf("[measure] linear patch %s mesh %d: rel displacement err %.2e, rel stress err %.2e\n",
              GetParam().element.c_str(), GetParam().mesh, uErr, sErr);
  EXPECT_LT(uErr, 1e-10);
  EXPECT_LT(sErr, 1e-10);
}

TEST_P(Patch, HomogeneousFiniteDeformationIsInEquilibrium) {
  const auto material = makeMaterial("Neo-Hookean", 1e3, 0.3);
  const QuadMesh m = mesh();
  const double F[2][2] = {{1.3, 0.2}, {-0.15, 0.85}};
  std::vector<double> uExact(m.numDofs());
  for (int n = 0; n < m.numNodes(); ++n)
    for (int i = 0; i < 2; ++i)
      uExact[2 * n + i] = (F[i][0] - (i == 0)) * m.X[2 * n] + (F[i][1] - (i == 1)) * m.X[2 * n + 1];
  const auto free = interiorDofs(interior_);

  // (1) At the exact state the interior nodes carry no residual force.
  std::vector<double> internal, f;
  ASSERT_TRUE(assemble(*kernel, *material, m, uExact, internal, f, nullptr));
  double interiorForce = 0.0;
  for (int d : free) interiorForce = std::max(interiorForce, std::fabs(f[d]));
  const double residual = interiorForce / maxAbs(f);
  // (2) Newton from perturbed interior nodes returns to it (quadratically: few iterations).
  std::vector<double> u = uExact, fExt(m.numDofs(), 0.0);
  for (std::size_t k = 0; k < free.size(); ++k) u[free[k]] += (k % 2 ? -0.004 : 0.006);
  std::vector<double> internal2;
  const int iterations = solveEquilibrium(*kernel, *material, m, free, fExt, u, internal2);
  std::printf("[measure] finite-strain patch %s mesh %d: rel interior residual %.2e, Newton iterations %d\n",
              GetParam().element.c_str(), GetParam().mesh, residual, iterations);
  EXPECT_LT(residual, 1e-12);
  ASSERT_GE(iterations, 0);
  EXPECT_LE(iterations, 6);
  EXPECT_LT(maxAbsDifference(u, uExact), 1e-10 * maxAbs(uExact));
}

std::string patchName(const ::testing::TestParamInfo<PatchCase>& info) {
  return std::string(info.param.element == "Q4" ? "Q4" : "Q4Enhanced") +
         (info.param.mesh == 0 ? "_MacNealHarder" : "_Distorted2x2");
}

INSTANTIATE_TEST_SUITE_P(BothElements, Patch,
                         ::testing::Values(PatchCase{"Q4", 0}, PatchCase{"Q4 Enhanced", 0}, PatchCase{"Q4", 1},
                                           PatchCase{"Q4 Enhanced", 1}),
                         patchName);

}  // namespace
}  // namespace contessa::mechanics::test
