// Patch tests on distorted meshes, 2D and 3D: a linear displacement field must be reproduced exactly
// (small strain), and a homogeneous finite deformation must be an exact equilibrium state.
#include "MechanicsTestUtilities.hpp"

namespace contessa::mechanics::test {
namespace {

/// The MacNeal–Harder (1985) patch: a 0.24 × 0.12 rectangle, 4 boundary nodes, 4 interior nodes
/// at irregular positions, 5 distorted elements.
TestMesh macNealHarderPatch(std::vector<int>& interiorNodes) {
  TestMesh m;
  m.X = {0.0, 0.0, 0.24, 0.0, 0.24, 0.12, 0.0, 0.12, 0.04, 0.02, 0.18, 0.03, 0.16, 0.08, 0.08, 0.08};
  m.cells = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}, {4, 5, 6, 7}};
  interiorNodes = {4, 5, 6, 7};
  return m;
}

/// A 2 × 2 patch on the unit square with the centre node moved off-centre.
TestMesh distortedTwoByTwo(std::vector<int>& interiorNodes) {
  TestMesh m = rectangleMesh(2, 2, 1.0, 1.0);
  m.X[2 * 4] = 0.62;
  m.X[2 * 4 + 1] = 0.33;
  interiorNodes = {4};
  return m;
}

/// det ∂X/∂ξ at the centre of hexahedron `cell` (Exodus order): its orientation.
double centreVolumeSign(const TestMesh& m, const std::vector<int>& c) {
  // ∂X/∂ξ at ξ = 0 is ⅛ Σ_a ξ_a X_a per direction: differences of opposite faces.
  const double sign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                             {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  double J[3][3] = {};
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i)
      for (int b = 0; b < 3; ++b) J[i][b] += 0.125 * sign[a][b] * m.X[3 * c[a] + i];
  return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

/// The MacNeal–Harder (1985) 3D patch: the unit cube, its 8 corners on the boundary, 8 interior
/// nodes at irregular positions forming an inner hexahedron, and 6 hexahedra joining each face of
/// the cube to the corresponding inner face: 7 elements, all distorted, with warped faces.
TestMesh macNealHarderCube(std::vector<int>& interiorNodes) {
  TestMesh m;
  m.dimension = 3;
  m.X = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1,  // the cube's corners
         0.249, 0.342, 0.192, 0.826, 0.288, 0.288, 0.850, 0.649, 0.263, 0.273, 0.750, 0.230,
         0.320, 0.186, 0.643, 0.677, 0.305, 0.683, 0.788, 0.693, 0.644, 0.165, 0.745, 0.702};
  m.cells.push_back({8, 9, 10, 11, 12, 13, 14, 15});
  const int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (const auto& f : faces) {
    std::vector<int> cell = {f[0], f[1], f[2], f[3], f[0] + 8, f[1] + 8, f[2] + 8, f[3] + 8};
    if (centreVolumeSign(m, cell) < 0.0) std::rotate(cell.begin(), cell.begin() + 4, cell.end());  // inner face first
    m.cells.push_back(cell);
  }
  interiorNodes = {8, 9, 10, 11, 12, 13, 14, 15};
  return m;
}

/// A 2 × 2 × 2 patch on the unit cube with the centre node moved off-centre.
TestMesh distortedTwoByTwoByTwo(std::vector<int>& interiorNodes) {
  TestMesh m = brickMesh(2, 2, 2, 1.0, 1.0, 1.0);
  const int centre = 13;
  m.X[3 * centre] = 0.62;
  m.X[3 * centre + 1] = 0.33;
  m.X[3 * centre + 2] = 0.58;
  interiorNodes = {centre};
  return m;
}

struct PatchCase {
  std::string element;
  int mesh;  // 0: MacNeal–Harder, 1: one interior node off-centre
};
void PrintTo(const PatchCase& c, std::ostream* os) { *os << c.element << " / mesh " << c.mesh; }

class Patch : public ::testing::TestWithParam<PatchCase> {
 protected:
  std::unique_ptr<ElementKernel> kernel = ElementFactory::create(GetParam().element, "Test/Element");
  const int D = kernel->dimension();
  std::vector<int> interior_;
  TestMesh mesh() {
    if (D == 2) return GetParam().mesh == 0 ? macNealHarderPatch(interior_) : distortedTwoByTwo(interior_);
    return GetParam().mesh == 0 ? macNealHarderCube(interior_) : distortedTwoByTwoByTwo(interior_);
  }
  std::vector<int> interiorDofs() const {
    std::vector<int> dofs;
    for (int n : interior_)
      for (int i = 0; i < D; ++i) dofs.push_back(D * n + i);
    return dofs;
  }
  /// u = G X + c at every node, G and c the first D × D and D entries of the given 3D ones.
  std::vector<double> affineField(const TestMesh& m, const double (&G)[3][3], const double (&c)[3]) const {
    std::vector<double> u(m.numDofs());
    for (int n = 0; n < m.numNodes(); ++n)
      for (int i = 0; i < D; ++i) {
        double s = c[i];
        for (int J = 0; J < D; ++J) s += G[i][J] * m.X[D * n + J];
        u[D * n + i] = s;
      }
    return u;
  }
};

TEST_P(Patch, LinearFieldIsReproducedExactly) {
  const double E = 1e6, nu = 0.25;
  const auto material = makeMaterial("Linear Elastic", E, nu);
  const TestMesh m = mesh();
  // The MacNeal–Harder strains (2D: ε_xx = ε_yy = 1e-3, γ_xy = 1e-3; 3D: u = 1e-3 (2x + y + z)/2,
  // v = 1e-3 (x + 2y + z)/2, w = 1e-3 (x + y + 2z)/2) plus a rigid rotation and translation.
  const double G2[3][3] = {{1e-3, 0.5e-3 - 2e-4, 0}, {0.5e-3 + 2e-4, 1e-3, 0}, {0, 0, 0}};
  const double G3[3][3] = {{1e-3, 0.5e-3 - 2e-4, 0.5e-3 + 1e-4},
                           {0.5e-3 + 2e-4, 1e-3, 0.5e-3 - 3e-4},
                           {0.5e-3 - 1e-4, 0.5e-3 + 3e-4, 1e-3}};
  const double c[3] = {1e-4, -3e-4, 2e-4};
  const auto& G = D == 2 ? G2 : G3;
  const std::vector<double> uExact = affineField(m, G, c);
  const auto free = interiorDofs();
  std::vector<double> u = uExact;
  for (int d : free) u[d] = 0.0;  // unknown: solved for
  std::vector<double> internal, fExt(m.numDofs(), 0.0);
  const int iterations = solveEquilibrium(*kernel, *material, m, free, fExt, u, internal);
  ASSERT_GE(iterations, 0);
  EXPECT_LE(iterations, 2);  // linear problem: one Newton step

  const double uErr = maxAbsDifference(u, uExact) / maxAbs(uExact);
  // Exact constant stress σ = λ tr ε I + 2 μ ε of the 3 × 3 ε (plane strain: ε_zz = 0, σ_zz = λ tr ε).
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  Tensor2 eps{}, sigmaExact{};
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J) eps[idx2(i, J)] = 0.5 * (G[i][J] + G[J][i]);
  for (int n = 0; n < 9; ++n) sigmaExact[n] = 2 * mu * eps[n] + (n % 4 == 0 ? lambda * trace(eps) : 0.0);
  double sErr = 0.0;
  const int ni = kernel->numInternalVariables();
  for (std::size_t e = 0; e < m.cells.size(); ++e) {
    const auto Xe = gather(m.X, m.cells[e], D), ue = gather(u, m.cells[e], D);
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
  const TestMesh m = mesh();
  // 2D: stretch 1.3 / 0.85 with shear; 3D: the same plus an out-of-plane stretch, shear and twist.
  const double H[3][3] = {{0.3, 0.2, -0.1}, {-0.15, -0.15, 0.12}, {0.08, -0.1, 0.2}};
  const double zero[3] = {0, 0, 0};
  const std::vector<double> uExact = affineField(m, H, zero);
  const auto free = interiorDofs();

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
  std::string element = info.param.element;
  element.erase(std::remove(element.begin(), element.end(), ' '), element.end());
  const bool threeD = element.rfind("Hex8", 0) == 0;
  return element + (info.param.mesh == 0 ? "_MacNealHarder" : (threeD ? "_Distorted2x2x2" : "_Distorted2x2"));
}

INSTANTIATE_TEST_SUITE_P(AllElements, Patch,
                         ::testing::Values(PatchCase{"Q4", 0}, PatchCase{"Q4 Enhanced", 0}, PatchCase{"Q4", 1},
                                           PatchCase{"Q4 Enhanced", 1}, PatchCase{"Hex8", 0},
                                           PatchCase{"Hex8 Enhanced", 0}, PatchCase{"Hex8", 1},
                                           PatchCase{"Hex8 Enhanced", 1}),
                         patchName);

}  // namespace
}  // namespace contessa::mechanics::test
