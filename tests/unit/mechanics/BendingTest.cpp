// Shear locking: a cantilever under a pure end couple. Euler–Bernoulli is exact for pure bending
// (no shear force), so the tip deflection is v = M L² / (2 E' I), I = h³/12, unit thickness,
// E' = E / (1 − ν²) in plane strain. Bilinear Q4 locks (spurious shear strain in bending); the EAS
// modes (Simo & Armero 1992) contain the bending mode and are exact on rectangles.
#include "MechanicsTestUtilities.hpp"

#include <cstdio>
#include <string>

namespace contessa::mechanics::test {
namespace {

/// Tip deflection over the beam-theory value for a L × h cantilever meshed nx × 1.
double tipDeflectionRatio(const std::string& element, double nu, int nx) {
  const double L = 10.0, h = 1.0, E = 1e4, couple = 1.0;
  const auto kernel = ElementFactory::create(element, "Test/Element");
  const auto material = makeMaterial("Linear Elastic", E, nu);
  const TestMesh m = rectangleMesh(nx, 1, L, h);
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

// ---- Hexahedra: a 3D cantilever L × b × h = 10 × 1 × 1 (x along the axis, z the bending direction) ----

namespace beam3d {

constexpr double L = 10.0, b = 1.0, h = 1.0, E = 1e4;
constexpr double I = b * h * h * h / 12.0, A = b * h;

/// Consistent nodal forces f_a += ∫ N_a t dA of a traction t(X) on the bilinear face with nodes
/// `face` (in order around it), 2 × 2 Gauss.
void addFaceTraction(const TestMesh& m, const std::array<int, 4>& face,
                     const std::function<std::array<double, 3>(const double*)>& traction, std::vector<double>& f) {
  const double g = 1.0 / std::sqrt(3.0), corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (double r : {-g, g})
    for (double s : {-g, g}) {
      double x[3] = {}, dr[3] = {}, ds[3] = {}, N[4];
      for (int a = 0; a < 4; ++a) {
        N[a] = 0.25 * (1 + corner[a][0] * r) * (1 + corner[a][1] * s);
        for (int i = 0; i < 3; ++i) {
          const double X = m.X[3 * face[a] + i];
          x[i] += N[a] * X;
          dr[i] += 0.25 * corner[a][0] * (1 + corner[a][1] * s) * X;
          ds[i] += 0.25 * corner[a][1] * (1 + corner[a][0] * r) * X;
        }
      }
      const double n[3] = {dr[1] * ds[2] - dr[2] * ds[1], dr[2] * ds[0] - dr[0] * ds[2], dr[0] * ds[1] - dr[1] * ds[0]};
      const double dA = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);  // Gauss weights are 1
      const auto t = traction(x);
      for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 3; ++i) f[3 * face[a] + i] += N[a] * t[i] * dA;
    }
}

enum class Load { Couple, TipShear };

struct Result {
  double tip = 0.0;  ///< u_z at the tip (on the axis, or the mean over the tip nodes)
  int iterations = -1;
};

/// The cantilever meshed nx × 1 × 1 over the whole section, root face clamped (every dof of its
/// nodes fixed), loaded on the tip face by a couple M = 1 (t_x = M z / I) or a shear force P = 1
/// (t_z = −P / A). Tip deflection: the mean u_z of the tip nodes.
Result clampedCantilever(const std::string& element, double nu, int nx, Load load) {
  const auto kernel = ElementFactory::create(element, "Test/Element");
  const auto material = makeMaterial("Linear Elastic", E, nu);
  const TestMesh m = brickMesh(nx, 1, 1, L, b, h, -0.5 * b, -0.5 * h);
  const auto id = [nx](int i, int j, int k) { return (k * 2 + j) * (nx + 1) + i; };
  std::vector<int> free;
  for (int n = 0; n < m.numNodes(); ++n)
    if (n % (nx + 1) != 0) free.insert(free.end(), {3 * n, 3 * n + 1, 3 * n + 2});
  std::vector<double> fExt(m.numDofs(), 0.0), u(m.numDofs(), 0.0), internal;
  const std::array<int, 4> tipFace = {id(nx, 0, 0), id(nx, 1, 0), id(nx, 1, 1), id(nx, 0, 1)};
  if (load == Load::Couple)
    addFaceTraction(m, tipFace, [](const double* x) { return std::array<double, 3>{x[2] / I, 0, 0}; }, fExt);
  else
    addFaceTraction(m, tipFace, [](const double*) { return std::array<double, 3>{0, 0, -1.0 / A}; }, fExt);
  Result r;
  r.iterations = solveEquilibrium(*kernel, *material, m, free, fExt, u, internal);
  for (int n : tipFace) r.tip += 0.25 * u[3 * n + 2];
  return r;
}

/// Pure bending by M = 1 with Saint-Venant's exact support, so that Poisson's anticlastic curvature
/// is free: the half y ≥ 0 of the section (symmetry: u_y = 0 on y = 0), meshed nx × 1 × 2 (a node
/// row on the axis z = 0), u_x = 0 on the root face (the exact u_x = κ x z vanishes there) and
/// u_z = 0 at the root axis node. The exact solution u_x = κ x z, u_y = −ν κ y z,
/// u_z = −κ/2 (x² + ν (z² − y²)), κ = M / (E I), then satisfies every constraint, for any ν.
/// Returns u_z at the tip axis node (exact: −κ L² / 2).
Result saintVenantBending(const std::string& element, double nu, int nx) {
  const auto kernel = ElementFactory::create(element, "Test/Element");
  const auto material = makeMaterial("Linear Elastic", E, nu);
  const TestMesh m = brickMesh(nx, 1, 2, L, 0.5 * b, h, 0.0, -0.5 * h);
  const auto id = [nx](int i, int j, int k) { return (k * 2 + j) * (nx + 1) + i; };
  std::vector<bool> fixed(m.numDofs(), false);
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 1; ++j) {
      fixed[3 * id(0, j, k)] = true;                 // u_x = 0 on the root face
      for (int i = 0; i <= nx; ++i) fixed[3 * id(i, 0, k) + 1] = true;  // u_y = 0 on y = 0
    }
  fixed[3 * id(0, 0, 1) + 2] = true;  // u_z = 0 at the root axis node
  std::vector<int> free;
  for (int d = 0; d < m.numDofs(); ++d)
    if (!fixed[d]) free.push_back(d);
  std::vector<double> fExt(m.numDofs(), 0.0), u(m.numDofs(), 0.0), internal;
  // The half section carries half the couple: t_x = M z / I with I of the whole section.
  for (int k = 0; k < 2; ++k)
    addFaceTraction(m, {id(nx, 0, k), id(nx, 1, k), id(nx, 1, k + 1), id(nx, 0, k + 1)},
                    [](const double* x) { return std::array<double, 3>{x[2] / I, 0, 0}; }, fExt);
  Result r;
  const double lambdaOverMu = 2.0 * nu / (1.0 - 2.0 * nu);
  r.iterations = solveEquilibrium(*kernel, *material, m, free, fExt, u, internal, std::max(1.0, lambdaOverMu));
  r.tip = u[3 * id(nx, 0, 1) + 2];
  return r;
}

/// Pure bending by M = 1 solved with Hex8 and Hex8 Enhanced (the case named by `what`): the enhanced element's
/// tip deflection the exact −M L² / (2 E I) to `tolerance`, the trilinear one's locked below 0.8 of it.
/// Returns Hex8's ratio to the exact deflection.
double expectEnhancedExactWhereHex8Locks(const Result& hex, const Result& eas, const std::string& what,
                                         double tolerance) {
  const double exact = -1.0 * L * L / (2.0 * E * I);
  EXPECT_GE(hex.iterations, 0);
  EXPECT_GE(eas.iterations, 0);
  std::printf("[measure] 3D pure bending %s: Hex8 ratio %.4f, Hex8 Enhanced ratio %.10f\n", what.c_str(),
              hex.tip / exact, eas.tip / exact);
  EXPECT_NEAR(eas.tip / exact, 1.0, tolerance);
  EXPECT_LT(hex.tip / exact, 0.8);
  return hex.tip / exact;
}

}  // namespace beam3d

TEST(Bending3D, EnhancedIsExactInPureBendingWhereHex8Locks) {
  // ν = 0 and a clamped root: the exact solution is Euler–Bernoulli's, v(L) = −M L² / (2 E I).
  using namespace beam3d;
  for (int nx : {4, 10}) {
    const double hexRatio = expectEnhancedExactWhereHex8Locks(
        clampedCantilever("Hex8", 0.0, nx, Load::Couple), clampedCantilever("Hex8 Enhanced", 0.0, nx, Load::Couple),
        "nu=0 (" + std::to_string(nx) + " x 1 x 1, clamped)", 1e-8);
    EXPECT_GT(hexRatio, 0.0);
  }
}

TEST(Bending3D, EnhancedIsExactInPureBendingWithAnticlasticCurvatureUpToNearIncompressibility) {
  // Saint-Venant's pure bending, u_z(L, 0, 0) = −M L² / (2 E I) for every ν: the nine modes contain
  // every quadratic term of u_z (x², y², z²), so the enhanced element is exact even at ν = 0.4999,
  // where the trilinear one locks in shear and volumetrically.
  using namespace beam3d;
  for (double nu : {0.3, 0.4999}) {
    char what[64];
    std::snprintf(what, sizeof what, "nu=%g (10 x 1 x 2 half section)", nu);
    expectEnhancedExactWhereHex8Locks(saintVenantBending("Hex8", nu, 10), saintVenantBending("Hex8 Enhanced", nu, 10),
                                      what, 1e-7);
  }
}

TEST(Bending3D, EnhancedWithinTwoPercentOfTimoshenkoUnderTipShear) {
  // End load P: the moment varies along the beam, so no element is exact. Timoshenko beam theory,
  // v(L) = P L³ / (3 E I) + P L / (κ G A), κ = 5/6 (ν = 0: Cowper's 10 (1 + ν) / (12 + 11 ν) too);
  // the shear term is 0.8 % of the total here.
  using namespace beam3d;
  const double nu = 0.0, G = E / (2.0 * (1.0 + nu)), kappa = 10.0 * (1.0 + nu) / (12.0 + 11.0 * nu);
  const double timoshenko = -(L * L * L / (3.0 * E * I) + L / (kappa * G * A));
  for (int nx : {4, 10}) {
    const auto hex = clampedCantilever("Hex8", nu, nx, Load::TipShear);
    const auto eas = clampedCantilever("Hex8 Enhanced", nu, nx, Load::TipShear);
    ASSERT_GE(hex.iterations, 0);
    ASSERT_GE(eas.iterations, 0);
    std::printf("[measure] 3D tip shear nu=0 (%d x 1 x 1, clamped): Hex8 ratio %.4f, Hex8 Enhanced ratio %.5f (Timoshenko)\n",
                nx, hex.tip / timoshenko, eas.tip / timoshenko);
    if (nx == 10) {
      EXPECT_NEAR(eas.tip / timoshenko, 1.0, 0.02);
      EXPECT_LT(hex.tip / timoshenko, 0.8);
    }
  }
}

// ---- Near incompressibility: Lamé's thick-walled cylinder under internal pressure ----

/// Radial displacement of the inner surface over Lamé's plane-strain value
/// u_r(a) = (1 + ν) p a / (E (b² − a²)) [(1 − 2ν) a² + b²], for a quarter of the ring a = 1 ≤ r ≤ b = 2
/// meshed nr × nθ × 1 (one layer, u_z = 0 everywhere: plane strain), symmetry on the cut planes,
/// pressure p on the inner face (traction p r̂ at its Gauss points).
double cylinderRatio(const std::string& element, double nu, int nr, int nTheta) {
  const double a = 1.0, bOut = 2.0, E = 1e3, p = 1.0, pi = std::acos(-1.0);
  const auto kernel = ElementFactory::create(element, "Test/Element");
  const auto material = makeMaterial("Linear Elastic", E, nu);
  TestMesh m;
  m.dimension = 3;
  const auto id = [&](int i, int j, int k) { return (k * (nTheta + 1) + j) * (nr + 1) + i; };
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= nTheta; ++j)
      for (int i = 0; i <= nr; ++i) {
        const double r = a + (bOut - a) * i / nr, theta = 0.5 * pi * j / nTheta;
        m.X.insert(m.X.end(), {r * std::cos(theta), r * std::sin(theta), 0.25 * k});
      }
  for (int j = 0; j < nTheta; ++j)
    for (int i = 0; i < nr; ++i)  // ξ radial, η circumferential, ζ axial: positively oriented
      m.cells.push_back({id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0), id(i, j, 1),
                         id(i + 1, j, 1), id(i + 1, j + 1, 1), id(i, j + 1, 1)});
  std::vector<int> free;
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= nTheta; ++j)
      for (int i = 0; i <= nr; ++i) {
        const int n = id(i, j, k);
        if (j != nTheta) free.push_back(3 * n);  // u_x = 0 on θ = 90°
        if (j != 0) free.push_back(3 * n + 1);   // u_y = 0 on θ = 0
      }
  std::sort(free.begin(), free.end());
  std::vector<double> fExt(m.numDofs(), 0.0), u(m.numDofs(), 0.0), internal;
  for (int j = 0; j < nTheta; ++j)
    beam3d::addFaceTraction(m, {id(0, j, 0), id(0, j + 1, 0), id(0, j + 1, 1), id(0, j, 1)},
                            [p](const double* x) {
                              const double r = std::hypot(x[0], x[1]);
                              return std::array<double, 3>{p * x[0] / r, p * x[1] / r, 0.0};
                            },
                            fExt);
  const double lambdaOverMu = 2.0 * nu / (1.0 - 2.0 * nu);
  EXPECT_GE(solveEquilibrium(*kernel, *material, m, free, fExt, u, internal, std::max(1.0, lambdaOverMu)), 0);
  const double exact = (1.0 + nu) * p * a / (E * (bOut * bOut - a * a)) * ((1.0 - 2.0 * nu) * a * a + bOut * bOut);
  return u[3 * id(0, 0, 0)] / exact;
}

TEST(NearIncompressibility, EnhancedHexahedronDoesNotLockInTheThickCylinder) {
  // ν = 0.4999 (λ/μ ≈ 5000): the trilinear element locks volumetrically (its 8 volume constraints per
  // element outnumber the dofs), the enhanced one stays within 2 % of Lamé, as at ν = 0.3 (the
  // remaining difference is the discretisation of the ring by 12 straight-sided sectors).
  const double hex3 = cylinderRatio("Hex8", 0.3, 4, 12), eas3 = cylinderRatio("Hex8 Enhanced", 0.3, 4, 12);
  const double hex = cylinderRatio("Hex8", 0.4999, 4, 12), eas = cylinderRatio("Hex8 Enhanced", 0.4999, 4, 12);
  std::printf("[measure] thick cylinder (4 x 12 x 1, plane strain) u_r(a) / Lame: nu=0.3: Hex8 %.4f, Hex8 Enhanced %.4f; "
              "nu=0.4999: Hex8 %.4f, Hex8 Enhanced %.4f\n", hex3, eas3, hex, eas);
  EXPECT_NEAR(eas3, 1.0, 0.02);
  EXPECT_NEAR(eas, 1.0, 0.02);
  EXPECT_LT(hex, 0.5);
}

}  // namespace
}  // namespace contessa::mechanics::test
