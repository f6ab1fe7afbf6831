// Shear locking: a cantilever under a pure end couple. Euler–Bernoulli is exact for pure bending
// (no shear force), so the tip deflection is v = M L² / (2 E' I), I = h³/12, unit thickness,
// E' = E / (1 − ν²) in plane strain. Bilinear Q4 locks (spurious shear strain in bending); the EAS
// modes (Simo & Armero 1992) contain the bending mode and are exact on rectangles.
#include "MechanicsTestUtilities.hpp"

namespace contessa::mechanics::test {
namespace {

/// Tip deflection over the beam-theory value for a L × h cantilever meshed nx × 1.
double tipDeflectionRatio(const std::string& element, double nu, int nx) {
  const double L = 10.0, h = 1.0, E = 1e4, couple = 1.0;
  const auto kernel = ElementFactory::create(element, "Test/Element");
  const auto material = makeMaterial("Linear Elastic", E, nu);
  const QuadMesh m = rectangleMesh(nx, 1, L, h);
  const int bottomLeft = 0, topLeft = nx + 1, bottomTip = nx, topTip = 2 * nx + 1;
  std::vector<int> free;
  for (int n = 0; n < m.numNodes(); ++n)
    if (n != bottomLeft && n != topLeft) free.insert(free.end(), {2 * n, 2 * n + 1});
  // Couple M = F h: +F at the bottom, −F at the top (positive moment, tip bends upward).
  std::vector<double> fExt(m.numDofs(), 0.0), u(m.numDofs(), 0.0), internal;
  fExt[2 * bottomTip] = couple / h;
  fExt[2 * topTip] = -couple / h;
  EXPECT_GE(solveEquilibrium(*kernel, *material, m, free, fExt, u, internal), 0);
  const double tip = 0.5 * (u[2 * bottomTip + 1] + u[2 * topTip + 1]);
  const double EI = E / (1.0 - nu * nu) * h * h * h / 12.0;
  return tip / (couple * L * L / (2.0 * EI));
}

TEST(Bending, EnhancedIsExactAndQ4LocksWithZeroPoissonRatio) {
  const double q4 = tipDeflectionRatio("Q4", 0.0, 5);
  const double eas = tipDeflectionRatio("Q4 Enhanced", 0.0, 5);
  std::printf("[measure] bending nu=0 (5 x 1 elements, 2:1): Q4 ratio %.4f, Q4 Enhanced ratio %.8f\n", q4, eas);
  EXPECT_NEAR(eas, 1.0, 0.01);
  EXPECT_LT(q4, 0.5);
  EXPECT_GT(q4, 0.0);
}

TEST(Bending, EnhancedWithinTwoPercentInPlaneStrainWithPoissonRatio) {
  const double eas = tipDeflectionRatio("Q4 Enhanced", 0.3, 5);
  const double q4 = tipDeflectionRatio("Q4", 0.3, 5);
  std::printf("[measure] bending nu=0.3 plane strain (5 x 1): Q4 ratio %.4f, Q4 Enhanced ratio %.8f\n", q4, eas);
  EXPECT_NEAR(eas, 1.0, 0.02);
}

TEST(Bending, SquareElementsTenByOne) {
  // The 10 × 1 mesh of square elements: Q4 locks less, ratio 1 / (1 + (a/b)²/2) = 2/3 for ν = 0 and
  // a/b = 1 (the single-element pure-bending result, exact here because every element sees the same
  // constant moment); the 5 × 1 mesh above (a/b = 2) gives 1/3.
  const double q4 = tipDeflectionRatio("Q4", 0.0, 10);
  const double eas = tipDeflectionRatio("Q4 Enhanced", 0.0, 10);
  const double eas3 = tipDeflectionRatio("Q4 Enhanced", 0.3, 10);
  std::printf("[measure] bending 10 x 1: Q4 ratio %.4f, Q4 Enhanced ratio %.8f (nu=0), %.8f (nu=0.3)\n", q4, eas, eas3);
  EXPECT_NEAR(eas, 1.0, 0.01);
  EXPECT_NEAR(eas3, 1.0, 0.02);
  EXPECT_NEAR(q4, 2.0 / 3.0, 1e-3);
}

}  // namespace
}  // namespace contessa::mechanics::test
