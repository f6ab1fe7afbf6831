#pragma once
// Helpers shared by the mechanics unit tests: materials by name, random deformation gradients,
// rotations, and a tiny dense "model" (assembly, Dirichlet conditions, Newton) for patch and
// bending tests. Deliberately independent of the library's own dense solver.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cctype>
#include <cstdio>
#include <functional>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "mechanics/Element.hpp"
#include "mechanics/Material.hpp"
#include "mechanics/Tensor.hpp"

namespace contessa::mechanics::test {

inline std::unique_ptr<Material> makeMaterial(const std::string& model, double E, double nu) {
  Teuchos::ParameterList p;
  p.set<std::string>("Model", model);
  p.set<double>("Young's Modulus", E);
  p.set<double>("Poisson's Ratio", nu);
  return MaterialFactory::create(p, "Test/Materials/m");
}

/// An element kernel and a material law by name: the parameter of the element tests.
struct Case {
  std::string element, material;
};
inline void PrintTo(const Case& c, std::ostream* os) { *os << c.element << " / " << c.material; }

/// The registered elements of plane strain and 3D (`axisymmetric` false) or the axisymmetric ones.
inline std::vector<std::string> elementNames(bool axisymmetric) {
  std::vector<std::string> names;
  for (const auto& e : ElementFactory::names())
    if (ElementFactory::create(e, "Test/Element")->axisymmetric() == axisymmetric) names.push_back(e);
  return names;
}

/// Every registered element of plane strain and 3D with every registered law (the axisymmetric ones
/// have tests of their own: a rigid radial motion strains them, AxisymmetricTest.cpp).
inline std::vector<Case> allCases() {
  std::vector<Case> cases;
  for (const auto& e : elementNames(false))
    for (const auto& m : MaterialFactory::names()) cases.push_back({e, m});
  return cases;
}

inline std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  std::string s = info.param.element + "_" + info.param.material;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

/// The kernel and the law of a Case (E = 100, ν = 0.3).
class ElementMaterial : public ::testing::TestWithParam<Case> {
 protected:
  std::unique_ptr<ElementKernel> kernel = ElementFactory::create(GetParam().element, "Test/Element");
  std::unique_ptr<Material> material = makeMaterial(GetParam().material, 100.0, 0.3);
};

inline double maxAbs(const double* v, std::size_t n) {
  double m = 0.0;
  for (std::size_t k = 0; k < n; ++k) m = std::max(m, std::fabs(v[k]));
  return m;
}
template <class C>
double maxAbs(const C& c) {
  return maxAbs(c.data(), c.size());
}
template <class C>
double maxAbsDifference(const C& a, const C& b) {
  double m = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) m = std::max(m, std::fabs(a[k] - b[k]));
  return m;
}

/// Rotation by `angle` about the unit vector (ax, ay, az) (Rodrigues).
inline Tensor2 rotation(double angle, double ax, double ay, double az) {
  const double n = std::sqrt(ax * ax + ay * ay + az * az);
  ax /= n, ay /= n, az /= n;
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  return {t * ax * ax + c,      t * ax * ay - s * az, t * ax * az + s * ay,
          t * ax * ay + s * az, t * ay * ay + c,      t * ay * az - s * ax,
          t * ax * az - s * ay, t * ay * az + s * ax, t * az * az + c};
}

/// A random F = I + perturbation with det F ≥ 0.5; `planeStrain` keeps F_33 = 1, F_i3 = F_3i = 0.
inline Tensor2 randomDeformationGradient(unsigned seed, double amplitude, bool planeStrain) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(-amplitude, amplitude);
  for (;;) {
    Tensor2 F = identity2();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        if (planeStrain && (i == 2 || j == 2)) continue;
        F[idx2(i, j)] += dist(gen);
      }
    if (determinant(F) >= 0.5) return F;
  }
}

/// Three distorted hexahedra (about 2 × 1.5 × 1, no two faces parallel, non-planar faces), positively
/// oriented in the Exodus HEX8 order: the 3D counterparts of the tests' distorted quadrilaterals.
inline std::vector<std::vector<double>> distortedBricks() {
  const double node[8][3] = {{0, 0, 0}, {2, 0, 0}, {2, 1.5, 0}, {0, 1.5, 0}, {0, 0, 1}, {2, 0, 1}, {2, 1.5, 1}, {0, 1.5, 1}};
  const double jitter[3][8][3] = {
      {{0.05, -0.1, 0.02}, {0.2, 0.1, -0.05}, {-0.1, 0.15, 0.1}, {0.1, -0.05, -0.08},
       {-0.05, 0.1, 0.1}, {0.1, -0.1, 0.05}, {0.15, 0.2, -0.1}, {-0.1, 0.05, 0.15}},
      {{-0.1, 0.05, -0.1}, {0.1, -0.15, 0.1}, {0.2, 0.05, -0.1}, {-0.15, 0.1, 0.05},
       {0.1, -0.05, -0.15}, {-0.2, 0.1, 0.2}, {0.05, -0.1, 0.1}, {0.1, 0.15, -0.05}},
      {{0.15, 0.1, 0.05}, {-0.1, 0.2, -0.1}, {0.05, -0.2, 0.15}, {0.2, 0.05, 0.1},
       {-0.15, -0.1, -0.05}, {0.05, 0.15, -0.1}, {-0.2, -0.05, 0.05}, {0.15, -0.15, -0.1}}};
  std::vector<std::vector<double>> bricks;
  for (int e = 0; e < 3; ++e) {
    std::vector<double> X(24);
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i) X[3 * a + i] = node[a][i] + jitter[e][a][i] + 0.5 * e * (i == 0);
    bricks.push_back(X);
  }
  return bricks;
}

/// Three distorted quadrilaterals (no parallel sides, counter-clockwise): the 2D counterparts of
/// distortedBricks(); the first is the element tests' sample element.
inline const std::vector<std::vector<double>>& distortedQuads() {
  static const std::vector<std::vector<double>> quads = {{0.0, 0.0, 2.0, 0.3, 2.4, 1.8, -0.2, 1.5},
                                                         {1.0, -0.5, 2.6, 0.1, 2.2, 1.4, 0.8, 1.1},
                                                         {-1.0, 0.2, 0.1, -0.1, 0.3, 0.9, -0.8, 1.2}};
  return quads;
}

/// A deformation of quadrilateral X (8 values): the homogeneous stretch and shear H plus an
/// hourglass/bending pattern of size `hourglassSize` (which the EAS modes resist, so α ≠ 0), all
/// scaled by `amplitude`.
inline std::vector<double> quadDeformation(const std::vector<double>& X, const double (&H)[2][2], double hourglassSize,
                                           double amplitude) {
  const double hourglass[4] = {1, -1, 1, -1};
  std::vector<double> u(8);
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 2; ++i)
      u[2 * a + i] =
          amplitude * (H[i][0] * X[2 * a] + H[i][1] * X[2 * a + 1] + hourglassSize * hourglass[a] * (i ? 0.5 : 1.0));
  return u;
}

/// A finite deformation of hexahedron X (24 values): a rotation of 0.5 a rad about an oblique axis
/// of the homogeneous stretch and shear I + a H, plus a bending pattern u_x ∝ x (z − ½), u_z ∝ −x²
/// and an hourglass pattern (both resisted by the enhanced modes, so α ≠ 0), for amplitude a.
inline std::vector<double> brickDeformation(const std::vector<double>& X, double amplitude) {
  const double H[3][3] = {{0.12, 0.05, -0.04}, {-0.03, -0.08, 0.06}, {0.02, 0.04, 0.1}};
  const double hourglass[8] = {1, -1, 1, -1, -1, 1, -1, 1};  // ξηζ at the nodes
  const Tensor2 R = rotation(0.5 * amplitude, 1.0, -2.0, 3.0);
  std::vector<double> u(24);
  for (int a = 0; a < 8; ++a) {
    const double* x = &X[3 * a];
    double y[3];
    for (int i = 0; i < 3; ++i) y[i] = x[i] + amplitude * (H[i][0] * x[0] + H[i][1] * x[1] + H[i][2] * x[2]);
    for (int i = 0; i < 3; ++i) u[3 * a + i] = R[idx2(i, 0)] * y[0] + R[idx2(i, 1)] * y[1] + R[idx2(i, 2)] * y[2] - x[i];
    u[3 * a] += amplitude * (0.1 * (x[2] - 0.5) * x[0] + 0.05 * hourglass[a]);
    u[3 * a + 1] += amplitude * 0.03 * hourglass[a];
    u[3 * a + 2] -= amplitude * 0.05 * x[0] * x[0];
  }
  return u;
}

/// The sample elements of a kernel's family: for Q4 and Hex8 distortedQuads() / distortedBricks(); for
/// every other family its parent nodes mapped through each of those bilinear / trilinear maps (so the
/// quadratic elements get curved edges and off-centre mid-side nodes). Parent coordinates of triangles,
/// tetrahedra and the wedges' triangles (in [0, 1]) are first stretched to [−1, 1], so that the corner
/// nodes of a simplex land on corners of the carrier element.
inline std::vector<std::vector<double>> sampleElementsOf(const ElementKernel& kernel,
                                                         const std::vector<std::vector<double>>& carriers) {
  const int D = kernel.dimension(), n = kernel.numNodes();
  if ((D == 2 && n == 4) || (D == 3 && n == 8)) return carriers;
  const std::string name = kernel.name();
  const bool simplex = name.rfind("Tri", 0) == 0 || name.rfind("Tet", 0) == 0;
  const bool wedge = name.rfind("Wedge", 0) == 0;
  const auto xi = kernel.parentNodeCoordinates();
  std::vector<std::vector<double>> elements;
  for (const auto& carrier : carriers) {
    std::vector<double> X(n * D, 0.0);
    for (int a = 0; a < n; ++a) {
      double p[3] = {};
      for (int i = 0; i < D; ++i) {
        p[i] = xi[D * a + i];
        if (simplex || (wedge && i < 2)) p[i] = 2.0 * p[i] - 1.0;
      }
      // The carrier's multilinear map at p: corner c has parent signs (±1, ±1[, ±1]) in Exodus order.
      const double sign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                 {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
      for (int c = 0; c < (D == 2 ? 4 : 8); ++c) {
        double w = 1.0;
        for (int i = 0; i < D; ++i) w *= 0.5 * (1.0 + sign[c][i] * p[i]);
        for (int i = 0; i < D; ++i) X[D * a + i] += w * carrier[D * c + i];
      }
    }
    elements.push_back(X);
  }
  return elements;
}

inline std::vector<std::vector<double>> sampleElementsOf(const ElementKernel& kernel) {
  return sampleElementsOf(kernel, kernel.dimension() == 2 ? distortedQuads() : distortedBricks());
}

/// A finite deformation of an element of `kernel`'s family with reference coordinates X, scaled by
/// `amplitude`: for Q4 quadDeformation (with the given homogeneous part H2 and hourglass size), for
/// Hex8 brickDeformation; for the other families a smooth quadratic field with stretch, shear and
/// bending (which every family represents only approximately, so the stress varies in the element).
inline std::vector<double> familyDeformation(const std::vector<double>& X, const ElementKernel& kernel, double amplitude,
                                             const double (&H2)[2][2], double hourglassSize) {
  const int D = kernel.dimension(), n = kernel.numNodes();
  if (D == 2 && n == 4) return quadDeformation(X, H2, hourglassSize, amplitude);
  if (D == 3 && n == 8) return brickDeformation(X, amplitude);
  std::vector<double> u(X.size());
  for (int a = 0; a < n; ++a) {
    const double* x = &X[D * a];
    if (D == 2) {
      u[2 * a] = amplitude * (H2[0][0] * x[0] + H2[0][1] * x[1] + 0.08 * x[0] * x[1]);
      u[2 * a + 1] = amplitude * (H2[1][0] * x[0] + H2[1][1] * x[1] - 0.06 * x[0] * x[0]);
    } else {
      const double H[3][3] = {{0.12, 0.05, -0.04}, {-0.03, -0.08, 0.06}, {0.02, 0.04, 0.1}};
      const Tensor2 R = rotation(0.5 * amplitude, 1.0, -2.0, 3.0);
      double y[3];
      for (int i = 0; i < 3; ++i) y[i] = x[i] + amplitude * (H[i][0] * x[0] + H[i][1] * x[1] + H[i][2] * x[2]);
      for (int i = 0; i < 3; ++i) u[3 * a + i] = R[idx2(i, 0)] * y[0] + R[idx2(i, 1)] * y[1] + R[idx2(i, 2)] * y[2] - x[i];
      u[3 * a] += amplitude * 0.1 * (x[2] - 0.5) * x[0];
      u[3 * a + 2] -= amplitude * 0.05 * x[0] * x[0];
    }
  }
  return u;
}

/// Central differences (step h) of one element's internal force at u: the tangent its kernel must
/// match. Every evaluation re-solves the internal variables from `internal` (the converged ones of the
/// base state; empty for kernels without any).
inline std::vector<double> centralDifferenceTangent(const ElementKernel& kernel, const Material& material,
                                                    const std::vector<double>& X, const std::vector<double>& u,
                                                    const std::vector<double>& internal, double h) {
  const int nd = kernel.numDofs();
  std::vector<double> Kfd(nd * nd), fp(nd), fm(nd);
  for (int c = 0; c < nd; ++c) {
    auto up = u, um = u;
    up[c] += h;
    um[c] -= h;
    auto ap = internal, am = internal;
    EXPECT_EQ(kernel.evaluate(X.data(), up.data(), ap.data(), material, fp.data(), nullptr), ElementStatus::Ok);
    EXPECT_EQ(kernel.evaluate(X.data(), um.data(), am.data(), material, fm.data(), nullptr), ElementStatus::Ok);
    for (int r = 0; r < nd; ++r) Kfd[r * nd + c] = (fp[r] - fm[r]) / (2.0 * h);
  }
  return Kfd;
}

/// The coordinates of the nodes `side` lists (cell-local numbers) of a cell's X, D per node, in that order.
inline std::vector<double> sideCoordinates(const std::vector<double>& X, const std::vector<int>& side, int D) {
  std::vector<double> x;
  for (int a : side) x.insert(x.end(), X.begin() + D * a, X.begin() + D * (a + 1));
  return x;
}

/// A force f(x), and its stiffness K = ∂f/∂x (n × n, row-major) into *K when K is not null.
using ForceAndStiffness = std::function<std::vector<double>(const std::vector<double>& x, std::vector<double>* K)>;

/// How a stiffness K matches central differences (step 1e-6) of its force: max |K − K_FD| / max |K|, and
/// K's largest asymmetry max |K_ab − K_ba| / max |K|.
struct StiffnessCheck {
  double error;
  double asymmetry;
};

inline StiffnessCheck checkStiffness(const ForceAndStiffness& force, const std::vector<double>& x) {
  std::vector<double> K;
  force(x, &K);
  const std::size_t n = x.size();
  const double h = 1e-6;
  double worst = 0.0, asymmetry = 0.0;
  for (std::size_t b = 0; b < n; ++b) {
    auto plus = x, minus = x;
    plus[b] += h;
    minus[b] -= h;
    const auto fp = force(plus, nullptr), fm = force(minus, nullptr);
    for (std::size_t a = 0; a < n; ++a) {
      worst = std::max(worst, std::abs(K[a * n + b] - (fp[a] - fm[a]) / (2 * h)));
      asymmetry = std::max(asymmetry, std::abs(K[a * n + b] - K[b * n + a]));
    }
  }
  return {worst / maxAbs(K), asymmetry / maxAbs(K)};
}

/// Number of zero pivots (below 1e-10 of the largest) of a symmetric n × n matrix by Gaussian
/// elimination with full pivoting: the dimension of its null space.
inline int nullity(std::vector<double> K, int n) {
  double largest = maxAbs(K);
  for (int k = 0; k < n; ++k) {
    int pr = k, pc = k;
    for (int r = k; r < n; ++r)
      for (int c = k; c < n; ++c)
        if (std::fabs(K[r * n + c]) > std::fabs(K[pr * n + pc])) pr = r, pc = c;
    if (std::fabs(K[pr * n + pc]) <= 1e-10 * largest) return n - k;
    for (int c = 0; c < n; ++c) std::swap(K[k * n + c], K[pr * n + c]);
    for (int r = 0; r < n; ++r) std::swap(K[r * n + k], K[r * n + pc]);
    for (int r = k + 1; r < n; ++r) {
      const double f = K[r * n + k] / K[k * n + k];
      for (int c = k; c < n; ++c) K[r * n + c] -= f * K[k * n + c];
    }
  }
  return 0;
}

/// Reference element X mirrored through the plane y = 0: negatively oriented (a
/// clockwise quadrilateral, an inside-out hexahedron).
inline std::vector<double> mirroredElement(const std::vector<double>& X, int dimension) {
  std::vector<double> mirrored = X;
  for (std::size_t k = 1; k < mirrored.size(); k += dimension) mirrored[k] = -mirrored[k];
  return mirrored;
}

/// Solves A x = b (n × n, row-major) by Gaussian elimination with partial pivoting.
inline std::vector<double> solveDense(std::vector<double> A, std::vector<double> b) {
  const int n = static_cast<int>(b.size());
  for (int c = 0; c < n; ++c) {
    int p = c;
    for (int r = c + 1; r < n; ++r)
      if (std::fabs(A[r * n + c]) > std::fabs(A[p * n + c])) p = r;
    EXPECT_GT(std::fabs(A[p * n + c]), 0.0) << "singular test system";
    for (int k = 0; k < n; ++k) std::swap(A[c * n + k], A[p * n + k]);
    std::swap(b[c], b[p]);
    for (int r = c + 1; r < n; ++r) {
      const double f = A[r * n + c] / A[c * n + c];
      for (int k = c; k < n; ++k) A[r * n + k] -= f * A[c * n + k];
      b[r] -= f * b[c];
    }
  }
  std::vector<double> x(n);
  for (int r = n - 1; r >= 0; --r) {
    double s = b[r];
    for (int k = r + 1; k < n; ++k) s -= A[r * n + k] * x[k];
    x[r] = s / A[r * n + r];
  }
  return x;
}

/// A mesh of one element type in 2D (4-node quadrilaterals, counter-clockwise) or 3D (8-node
/// hexahedra, Exodus HEX8 order): the small dense "model" of the patch and bending tests.
struct TestMesh {
  int dimension = 2;
  std::vector<double> X;  ///< x0 y0 [z0] x1 y1 [z1] ...
  std::vector<std::vector<int>> cells;
  int numNodes() const { return static_cast<int>(X.size()) / dimension; }
  int numDofs() const { return static_cast<int>(X.size()); }
};

/// nx × ny rectangles on [0, lx] × [0, ly]; node (i, j) has id j (nx + 1) + i.
inline TestMesh rectangleMesh(int nx, int ny, double lx, double ly) {
  TestMesh m;
  m.dimension = 2;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      m.X.push_back(lx * i / nx);
      m.X.push_back(ly * j / ny);
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int n0 = j * (nx + 1) + i;
      m.cells.push_back({n0, n0 + 1, n0 + nx + 2, n0 + nx + 1});
    }
  return m;
}

/// nx × ny × nz bricks on [0, lx] × [y0, y0 + ly] × [z0, z0 + lz]; node (i, j, k) has id
/// (k (ny + 1) + j)(nx + 1) + i.
inline TestMesh brickMesh(int nx, int ny, int nz, double lx, double ly, double lz, double y0 = 0.0, double z0 = 0.0) {
  TestMesh m;
  m.dimension = 3;
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) m.X.insert(m.X.end(), {lx * i / nx, y0 + ly * j / ny, z0 + lz * k / nz});
  const auto id = [&](int i, int j, int k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        m.cells.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k), id(i, j, k + 1),
                           id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
  return m;
}

/// Element-local gather of a nodal field (`dimension` values per node).
inline std::vector<double> gather(const std::vector<double>& field, const std::vector<int>& cell, int dimension) {
  std::vector<double> local;
  for (int n : cell) local.insert(local.end(), field.begin() + dimension * n, field.begin() + dimension * (n + 1));
  return local;
}

/// Assembles f_int and (if K is not null) the tangent; `internal` holds numInternalVariables() per
/// element and is updated (the trial state). Returns false unless every element reports Ok.
inline bool assemble(const ElementKernel& kernel, const Material& material, const TestMesh& mesh,
                     const std::vector<double>& u, std::vector<double>& internal, std::vector<double>& f,
                     std::vector<double>* K) {
  const int nd = mesh.numDofs(), ni = kernel.numInternalVariables(), ne = kernel.numDofs(), D = mesh.dimension;
  EXPECT_EQ(kernel.dimension(), D);
  internal.resize(mesh.cells.size() * ni, 0.0);
  f.assign(nd, 0.0);
  if (K) K->assign(static_cast<std::size_t>(nd) * nd, 0.0);
  std::vector<double> fe(ne), Ke(static_cast<std::size_t>(ne) * ne);
  for (std::size_t e = 0; e < mesh.cells.size(); ++e) {
    const auto& cell = mesh.cells[e];
    const auto Xe = gather(mesh.X, cell, D), ue = gather(u, cell, D);
    const auto status = kernel.evaluate(Xe.data(), ue.data(), ni ? &internal[e * ni] : nullptr, material,
                                        fe.data(), K ? Ke.data() : nullptr);
    if (status != ElementStatus::Ok) return false;
    for (int r = 0; r < ne; ++r) {
      const int gr = D * cell[r / D] + r % D;
      f[gr] += fe[r];
      if (K)
        for (int c = 0; c < ne; ++c)
          (*K)[static_cast<std::size_t>(gr) * nd + D * cell[c / D] + c % D] += Ke[static_cast<std::size_t>(r) * ne + c];
    }
  }
  return true;
}

/// Newton on the free dofs for f_int(u) = f_ext (u holds the prescribed values on the other dofs).
/// Returns the number of iterations, or −1 if it does not converge. Converged: a relative residual
/// of 1e-10 · roundOff (the round-off floor of the assembled residual is ~1e-12 of the load for the
/// bending meshes), or a Newton correction below 1e-12 · roundOff of u. `roundOff` is 1 except for
/// nearly incompressible laws, where it is λ/μ: f_int then sums λ tr ε with tr ε ~ (1 − 2ν) ε, and
/// that cancellation raises the floor of the residual (and of the enhanced element's local solve,
/// hence of the Newton corrections) by λ/μ.
inline int solveEquilibrium(const ElementKernel& kernel, const Material& material, const TestMesh& mesh,
                            const std::vector<int>& freeDofs, const std::vector<double>& fExt, std::vector<double>& u,
                            std::vector<double>& internal, double roundOff = 1.0, int maxIterations = 20) {
  const int nd = mesh.numDofs(), nf = static_cast<int>(freeDofs.size());
  double reference = 0.0;
  for (int it = 0; it <= maxIterations; ++it) {
    std::vector<double> f, K;
    if (!assemble(kernel, material, mesh, u, internal, f, &K)) return -1;
    // Scale: the largest nodal force anywhere (reactions included) or applied load.
    reference = std::max({reference, maxAbs(f), maxAbs(fExt)});
    std::vector<double> r(nf), Kff(static_cast<std::size_t>(nf) * nf);
    for (int a = 0; a < nf; ++a) {
      r[a] = fExt[freeDofs[a]] - f[freeDofs[a]];
      for (int b = 0; b < nf; ++b) Kff[a * nf + b] = K[static_cast<std::size_t>(freeDofs[a]) * nd + freeDofs[b]];
    }
    if (maxAbs(r) <= 1e-10 * roundOff * reference) return it;
    const auto du = solveDense(Kff, r);
    for (int a = 0; a < nf; ++a) u[freeDofs[a]] += du[a];
    if (it > 0 && maxAbs(du) <= 1e-12 * roundOff * maxAbs(u)) return it + 1;
  }
  return -1;
}

}  // namespace contessa::mechanics::test
