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

/// Every registered element with every registered law.
inline std::vector<Case> allCases() {
  std::vector<Case> cases;
  for (const auto& e : ElementFactory::names())
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

/// A 2D mesh of 4-node quadrilaterals (nodes counter-clockwise).
struct QuadMesh {
  std::vector<double> X;  ///< x0 y0 x1 y1 ...
  std::vector<std::array<int, 4>> cells;
  int numNodes() const { return static_cast<int>(X.size() / 2); }
  int numDofs() const { return static_cast<int>(X.size()); }
};

/// nx × ny rectangles on [0, lx] × [0, ly]; node (i, j) has id j (nx + 1) + i.
inline QuadMesh rectangleMesh(int nx, int ny, double lx, double ly) {
  QuadMesh m;
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

/// Element-local gather of a nodal field (2 values per node).
inline std::array<double, 8> gather(const std::vector<double>& field, const std::array<int, 4>& cell) {
  std::array<double, 8> local{};
  for (int a = 0; a < 4; ++a)
    for (int i = 0; i < 2; ++i) local[2 * a + i] = field[2 * cell[a] + i];
  return local;
}

/// Assembles f_int and (if K is not null) the tangent; `internal` holds numInternalVariables() per
/// element and is updated (the trial state). Returns false unless every element reports Ok.
inline bool assemble(const ElementKernel& kernel, const Material& material, const QuadMesh& mesh,
                     const std::vector<double>& u, std::vector<double>& internal, std::vector<double>& f,
                     std::vector<double>* K) {
  const int nd = mesh.numDofs(), ni = kernel.numInternalVariables();
  internal.resize(mesh.cells.size() * ni, 0.0);
  f.assign(nd, 0.0);
  if (K) K->assign(static_cast<std::size_t>(nd) * nd, 0.0);
  for (std::size_t e = 0; e < mesh.cells.size(); ++e) {
    const auto& cell = mesh.cells[e];
    const auto Xe = gather(mesh.X, cell), ue = gather(u, cell);
    std::array<double, 8> fe{};
    std::array<double, 64> Ke{};
    const auto status = kernel.evaluate(Xe.data(), ue.data(), ni ? &internal[e * ni] : nullptr, material,
                                        fe.data(), K ? Ke.data() : nullptr);
    if (status != ElementStatus::Ok) return false;
    for (int r = 0; r < 8; ++r) {
      const int gr = 2 * cell[r / 2] + r % 2;
      f[gr] += fe[r];
      if (K)
        for (int c = 0; c < 8; ++c) (*K)[static_cast<std::size_t>(gr) * nd + 2 * cell[c / 2] + c % 2] += Ke[r * 8 + c];
    }
  }
  return true;
}

/// Newton on the free dofs for f_int(u) = f_ext (u holds the prescribed values on the other dofs).
/// Returns the number of iterations, or −1 if it does not converge to a relative residual of 1e-10
/// (the round-off floor of the assembled residual is ~1e-12 of the load for the bending meshes).
inline int solveEquilibrium(const ElementKernel& kernel, const Material& material, const QuadMesh& mesh,
                            const std::vector<int>& freeDofs, const std::vector<double>& fExt, std::vector<double>& u,
                            std::vector<double>& internal, int maxIterations = 20) {
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
    if (maxAbs(r) <= 1e-10 * reference) return it;
    const auto du = solveDense(Kff, r);
    for (int a = 0; a < nf; ++a) u[freeDofs[a]] += du[a];
  }
  return -1;
}

}  // namespace contessa::mechanics::test
