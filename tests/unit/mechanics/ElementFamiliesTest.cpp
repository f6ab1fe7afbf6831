// The element families beyond Q4 / Hex8 on meshes of several elements: the patch test (a linear field
// reproduced exactly by the free interior nodes of a distorted patch, small strain, and a homogeneous
// finite deformation as an exact equilibrium state) and the bending field (Saint-Venant's pure bending,
// an exact elasticity solution quadratic in x, which every quadratic family contains on straight-sided
// meshes and so must reproduce to round-off, while the linear ones lock). The single-element checks
// (finite-difference tangents, objectivity, zero-energy modes) run for every family in ElementTest.cpp.
#include <algorithm>
#include <cmath>
#include <map>

#include "MechanicsTestUtilities.hpp"

namespace contessa::mechanics::test {
namespace {

/// Whether parent node a lies at the average of the parent corners `parents` (parent coordinates xi).
bool isAverage(const std::vector<int>& parents, const std::vector<double>& xi, int D, int a) {
  for (int i = 0; i < D; ++i) {
    double s = 0.0;
    for (int p : parents) s += xi[D * p + i];
    if (std::fabs(s / parents.size() - xi[D * a + i]) > 1e-14) return false;
  }
  return true;
}

/// A mesh of `element` made from a Q4 / Hex8 TestMesh: each cell split into triangles (2), tetrahedra
/// (6, around its diagonal 0–6, conforming between translated cells) or wedges (2, the bottom split
/// along 0–2), and for the quadratic families a node added at the midpoint of every edge (shared by the
/// cells around it) and, for Q9 and Hex27, at every face's and cell's centre. Node orders as the kernels' (Exodus).
TestMesh familyMesh(const TestMesh& base, const std::string& element) {
  const auto kernel = ElementFactory::create(element, "Test/Element");
  const int D = base.dimension;
  std::vector<std::vector<int>> corners;  // the linear cells, corners in Exodus order
  for (const auto& c : base.cells) {
    if (element.rfind("Tri", 0) == 0) {
      corners.push_back({c[0], c[1], c[2]});
      corners.push_back({c[0], c[2], c[3]});
    } else if (element.rfind("Tet", 0) == 0) {
      for (const auto& t : std::vector<std::array<int, 3>>{{1, 2, 6}, {2, 3, 6}, {3, 7, 6}, {7, 4, 6}, {4, 5, 6}, {5, 1, 6}})
        corners.push_back({c[0], c[t[0]], c[t[1]], c[t[2]]});
    } else if (element.rfind("Wedge", 0) == 0) {
      corners.push_back({c[0], c[1], c[2], c[4], c[5], c[6]});
      corners.push_back({c[0], c[2], c[3], c[4], c[6], c[7]});
    } else {
      corners.push_back(c);
    }
  }
  TestMesh m = base;
  m.cells.clear();
  // Every further node (mid-edge, Q9's and Hex27's face and cell centres) is the average of the corners
  // nearest to it in the kernel's parent coordinates (2 for an edge, 4 for a face, all for the centre):
  // that corner set, by global node, names the node, so cells that share an edge or a face share it.
  const auto xi = kernel->parentNodeCoordinates();
  const int n = kernel->numNodes(), numCorners = static_cast<int>(corners.front().size());
  std::map<std::vector<int>, int> sharedNode;
  for (const auto& cell : corners) {
    std::vector<int> nodes = cell;
    for (int a = numCorners; a < n; ++a) {
      std::vector<double> distance(numCorners);
      for (int p = 0; p < numCorners; ++p) {
        double d2 = 0.0;
        for (int i = 0; i < D; ++i) d2 += std::pow(xi[D * a + i] - xi[D * p + i], 2);
        distance[p] = std::sqrt(d2);
      }
      const double nearest = *std::min_element(distance.begin(), distance.end());
      std::vector<int> parents;
      for (int p = 0; p < numCorners; ++p)
        if (distance[p] < nearest + 1e-12) parents.push_back(p);
      if (!isAverage(parents, xi, D, a)) {  // a simplex's hypotenuse middle is as near to the third corner
        parents.clear();
        for (int p = 0; p < numCorners && parents.empty(); ++p)
          for (int q = p + 1; q < numCorners && parents.empty(); ++q)
            if (isAverage({p, q}, xi, D, a)) parents = {p, q};
      }
      std::vector<int> key;
      for (int p : parents) key.push_back(cell[p]);
      std::sort(key.begin(), key.end());
      auto it = sharedNode.find(key);
      if (it == sharedNode.end()) {
        for (int i = 0; i < D; ++i) {
          double s = 0.0;
          for (int c : key) s += m.X[D * c + i];
          m.X.push_back(s / key.size());
        }
        it = sharedNode.emplace(key, m.numNodes() - 1).first;
      }
      nodes.push_back(it->second);
    }
    m.cells.push_back(nodes);
  }
  return m;
}

/// The distorted base patches: 2 × 2 on the unit square, 2 × 2 × 2 on the unit cube, the centre node
/// moved off-centre (so every cell is distorted and its faces warped in 3D).
TestMesh distortedBase(int D) {
  if (D == 2) {
    TestMesh m = rectangleMesh(2, 2, 1.0, 1.0);
    m.X[2 * 4] = 0.62, m.X[2 * 4 + 1] = 0.33;
    return m;
  }
  TestMesh m = brickMesh(2, 2, 2, 1.0, 1.0, 1.0);
  m.X[3 * 13] = 0.58, m.X[3 * 13 + 1] = 0.41, m.X[3 * 13 + 2] = 0.55;
  return m;
}

/// Free DOFs: every component of the nodes strictly inside the box [0, L]^D.
std::vector<int> interiorDofs(const TestMesh& m, const std::vector<double>& length) {
  std::vector<int> free;
  for (int a = 0; a < m.numNodes(); ++a) {
    bool inside = true;
    for (int i = 0; i < m.dimension; ++i) {
      const double x = m.X[m.dimension * a + i];
      inside = inside && x > 1e-12 && x < length[i] - 1e-12;
    }
    if (inside)
      for (int i = 0; i < m.dimension; ++i) free.push_back(m.dimension * a + i);
  }
  return free;
}

class Family : public ::testing::TestWithParam<std::string> {
 protected:
  const std::unique_ptr<ElementKernel> kernel = ElementFactory::create(GetParam(), "Test/Element");
  const int D = kernel->dimension();
};

TEST_P(Family, DistortedPatchReproducesALinearField) {
  const TestMesh mesh = familyMesh(distortedBase(D), GetParam());
  const auto material = makeMaterial("Linear Elastic", 100.0, 0.3);
  const double A[3][3] = {{2e-3, 1e-3, -5e-4}, {-1e-3, 3e-3, 8e-4}, {6e-4, -7e-4, -2e-3}};
  std::vector<double> exact(mesh.numDofs()), u(mesh.numDofs(), 0.0), fExt(mesh.numDofs(), 0.0), internal;
  for (int a = 0; a < mesh.numNodes(); ++a)
    for (int i = 0; i < D; ++i) {
      double s = 1e-3 * (i + 1);
      for (int J = 0; J < D; ++J) s += A[i][J] * mesh.X[D * a + J];
      exact[D * a + i] = s;
    }
  const auto free = interiorDofs(mesh, std::vector<double>(D, 1.0));
  ASSERT_FALSE(free.empty());
  u = exact;
  for (int k : free) u[k] = 0.0;
  ASSERT_GE(solveEquilibrium(*kernel, *material, mesh, free, fExt, u, internal), 0);
  const double err = maxAbsDifference(u, exact) / maxAbs(exact);
  std::printf("[measure] patch %s: %zu cells, %d free DOFs, max error %.2e of max |u|\n", GetParam().c_str(),
              mesh.cells.size(), static_cast<int>(free.size()), err);
  EXPECT_LT(err, 1e-10);
}

TEST_P(Family, DistortedPatchKeepsAHomogeneousFiniteDeformation) {
  // F = I + H with |H| ~ 0.2, Neo-Hookean: the homogeneous state is an equilibrium, and Newton must find
  // it from the interior nodes of the previous load level (H in four steps: a full step would leave the
  // interior mid-side nodes of the quadratic cells behind and invert them).
  const TestMesh mesh = familyMesh(distortedBase(D), GetParam());
  const auto material = makeMaterial("Neo-Hookean", 100.0, 0.3);
  const Tensor2 F = randomDeformationGradient(5, 0.2, D == 2);
  const auto free = interiorDofs(mesh, std::vector<double>(D, 1.0));
  std::vector<double> exact(mesh.numDofs()), u(mesh.numDofs(), 0.0), fExt(mesh.numDofs(), 0.0), internal;
  for (double t : {0.25, 0.5, 0.75, 1.0}) {
    for (int a = 0; a < mesh.numNodes(); ++a)
      for (int i = 0; i < D; ++i) {
        double s = 0.0;
        for (int J = 0; J < D; ++J) s += t * (F[idx2(i, J)] - (i == J)) * mesh.X[D * a + J];
        exact[D * a + i] = s;
      }
    const auto interior = u;
    u = exact;
    for (int k : free) u[k] = interior[k];
    ASSERT_GE(solveEquilibrium(*kernel, *material, mesh, free, fExt, u, internal), 0) << "at t = " << t;
  }
  EXPECT_LT(maxAbsDifference(u, exact), 1e-10 * maxAbs(exact));
}

/// Saint-Venant's pure bending of the box [0, 4] × [−½, ½] (× [−½, ½]) on a straight-sided 4 × 2 (× 2)
/// mesh: the exact field prescribed on the end faces x = 0 and x = 4 only, the sides traction free (as
/// they are in the exact solution). Returns the largest error of the finite element solution relative to
/// the largest displacement, and the bending moment the mesh needs for the curvature κ (the reactions of
/// the end x = 4 times their lever arm) over the exact one, E' κ I (E' = E / (1 − ν²) in plane strain,
/// E in 3D; I = h³/12 b, h = b = 1). Plane strain in 2D: u_x = κ x y, u_y = −κ/2 (x² + ν' y²), ν' = ν / (1 − ν);
/// 3D: u_x = κ x z, u_y = −ν κ y z, u_z = −κ/2 (x² + ν (z² − y²)). Quadratic in x: every quadratic family
/// contains it on straight-sided cells (so reproduces it to round-off); constant-strain cells cannot bend
/// and lock.
struct BendingResult {
  double error, momentRatio;
};
BendingResult bending(const std::string& element, double nu) {
  const auto kernel = ElementFactory::create(element, "Test/Element");
  const int D = kernel->dimension();
  const double length = 4.0;
  TestMesh base = D == 2 ? rectangleMesh(4, 2, length, 1.0) : brickMesh(4, 2, 2, length, 1.0, 1.0);
  const TestMesh mesh = familyMesh(base, element);
  const double E = 100.0, kappa = 1e-3;
  const auto material = makeMaterial("Linear Elastic", E, nu);
  std::vector<double> exact(mesh.numDofs()), fExt(mesh.numDofs(), 0.0), internal;
  std::vector<int> free;
  for (int a = 0; a < mesh.numNodes(); ++a) {
    const double x = mesh.X[D * a], y = mesh.X[D * a + 1] - 0.5;
    if (D == 2) {
      const double nuPrime = nu / (1.0 - nu);
      exact[2 * a] = kappa * x * y;
      exact[2 * a + 1] = -0.5 * kappa * (x * x + nuPrime * y * y);
    } else {
      const double z = mesh.X[3 * a + 2] - 0.5;
      exact[3 * a] = kappa * x * z;
      exact[3 * a + 1] = -nu * kappa * y * z;
      exact[3 * a + 2] = -0.5 * kappa * (x * x + nu * (z * z - y * y));
    }
    if (x > 1e-12 && x < length - 1e-12)
      for (int i = 0; i < D; ++i) free.push_back(D * a + i);
  }
  auto u = exact;
  for (int k : free) u[k] = 0.0;
  EXPECT_GE(solveEquilibrium(*kernel, *material, mesh, free, fExt, u, internal), 0);
  std::vector<double> f;
  EXPECT_TRUE(assemble(*kernel, *material, mesh, u, internal, f, nullptr));
  double moment = 0.0;
  for (int a = 0; a < mesh.numNodes(); ++a)
    if (mesh.X[D * a] > length - 1e-12) moment += f[D * a] * (mesh.X[D * a + D - 1] - 0.5);
  const double exactMoment = (D == 2 ? E / (1.0 - nu * nu) : E) * kappa / 12.0;
  return {maxAbsDifference(u, exact) / maxAbs(exact), moment / exactMoment};
}

TEST_P(Family, BendingFieldExactForQuadraticFamiliesLinearOnesLock) {
  const std::string& name = GetParam();
  const bool quadratic = name == "Tri6" || name == "Q8" || name == "Q9" || name == "Tet10" || name == "Hex20" ||
                         name == "Hex27" || name == "Wedge15";
  const auto r = bending(name, 0.3);
  std::printf("[measure] pure bending %s (nu = 0.3): max error %.2e of max |u|, moment / exact %.6f\n", name.c_str(),
              r.error, r.momentRatio);
  if (quadratic) {
    EXPECT_LT(r.error, 1e-10);
    EXPECT_NEAR(r.momentRatio, 1.0, 1e-10);
  } else {
    EXPECT_GT(r.momentRatio, 1.05);  // constant-strain cells lock: they need a larger moment to bend
  }
}

INSTANTIATE_TEST_SUITE_P(Families, Family,
                         ::testing::Values("Tri3", "Tri6", "Q8", "Q9", "Tet4", "Tet10", "Hex20", "Hex27", "Wedge6",
                                           "Wedge15"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace contessa::mechanics::test
