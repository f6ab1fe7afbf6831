// element_kernel_bench: cost of the solid element kernels per element and evaluation, the hot path of
// every residual and Jacobian. Not a test; run it by hand (Release build):
//   build/bin/element_kernel_bench [--repeat N] [--all]
// For Q4, Q4 Enhanced, Hex8 and Hex8 Enhanced (with --all: every element family of the factory) with
// Saint Venant-Kirchhoff and Neo-Hookean it prints the median (over N repetitions, default 7) wall time
// in ns per element of a residual pass (internal force only) and of a Jacobian pass (internal force and
// tangent), the same per quadrature point, and for the enhanced elements the local (enhanced parameter)
// Newton iterations per evaluation, i.e. material calls per evaluation (each call evaluates every Gauss
// point).
//
// The workload imitates what the model asks of each element during a load-stepped Newton solve:
// 64 distorted quadrilaterals (or hexahedra: a cube) of tube-element size (~1.6 mm, corner positions
// jittered by ±15 %), each following its own finite-strain path u(t) (a rigid rotation of up to
// 0.4 rad, about z in 2D and a random axis in 3D, stretches and shear of up to 15 %, and an
// hourglass/bending pattern ξ_a η_a that the enhanced modes resist, so α ≠ 0), cut into
// 47 increments like the tube. In each increment the residual is evaluated at 6 Newton iterates
// u_k = u(t_n) + ε_k |Δu_n| r_k (ε_k = 1, 0.3, 3e-2, 1e-3, 1e-6, 1e-12; r_k a smooth pseudo-random
// correction field) and the Jacobian at the first 5, the same pattern as the tube's Newton loops.
// The other families take their nodes at their parent coordinates mapped into the same jittered
// quadrilateral or hexahedron (a simplex or wedge coordinate s ∈ [0, 1] as 2s − 1), so every family
// sees the same shapes and paths (the Q4 and Hex8 workloads are the ones of the tables in
// bench/README.md, draw for draw).
// Element states (internal variables and warm-start data) are carried from evaluation to
// evaluation exactly as SolidAssembler carries them, so local solves start where they would in a
// real run; the reference geometry is computed once per element before the timed passes, as the
// model does at setup.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "mechanics/Element.hpp"
#include "mechanics/Material.hpp"

namespace cm = contessa::mechanics;

namespace {

constexpr int kElements = 64;
constexpr int kIncrements = 47;
constexpr int kIterates = 6;  // residual passes per increment; Jacobian passes: kIterates − 1
constexpr double kErrors[kIterates] = {1.0, 0.3, 3e-2, 1e-3, 1e-6, 1e-12};
constexpr int kMaxDofs = 81;  // Hex27

/// One element: reference coordinates and the displacement at every (increment, iterate).
struct Workload {
  std::vector<double> X;
  std::vector<std::vector<double>> u;  ///< [increment · kIterates + iterate]
};

/// Parent coordinates of the corners of the jittered cell (Q4 counter-clockwise; Hex8 in the Exodus order).
const double kQuadNodes[4][3] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
const double kHexNodes[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

/// The family's nodes in the cell's parent cube [−1, 1]^D: a coordinate of a simplex or wedge
/// direction (range [0, 1]) becomes 2s − 1.
std::vector<double> cubeCoordinates(const cm::ElementKernel& kernel) {
  const int D = kernel.dimension(), N = kernel.numNodes();
  auto xi = kernel.parentNodeCoordinates();
  for (int i = 0; i < D; ++i) {
    double low = 1.0;
    for (int a = 0; a < N; ++a) low = std::min(low, xi[D * a + i]);
    if (low > -0.5)
      for (int a = 0; a < N; ++a) xi[D * a + i] = 2.0 * xi[D * a + i] - 1.0;
  }
  return xi;
}

/// The hourglass/bending pattern h_a = ξ_a η_a that the enhanced modes resist.
double hourglass(int D, const std::vector<double>& cube, int a) { return cube[D * a] * cube[D * a + 1]; }

/// x(ξ) of the (bi/tri)linear cell with corners `corners` (Q4/Hex8 order).
void mapIntoCell(int D, const std::vector<double>& corners, const double* xi, double* x) {
  const int N = D == 2 ? 4 : 8;
  for (int i = 0; i < D; ++i) x[i] = 0.0;
  for (int c = 0; c < N; ++c) {
    const auto& n = D == 2 ? kQuadNodes[c] : kHexNodes[c];
    double shape = 1.0;
    for (int k = 0; k < D; ++k) shape *= 0.5 * (1.0 + n[k] * xi[k]);
    for (int i = 0; i < D; ++i) x[i] += shape * corners[D * c + i];
  }
}

/// F = R(θ t) (I + t H): x = F X, plus the bending pattern t · size · (0.04, 0.02, 0.03) h_a. R turns
/// about z in 2D and about `axis` in 3D.
std::vector<double> pathDisplacement(int D, const std::vector<double>& cube, const std::vector<double>& X, double t,
                                     double theta, double size, const double (&H)[3][3], const double (&axis)[3]) {
  const double c = std::cos(theta * t), s = std::sin(theta * t), omc = 1.0 - c;
  double R[3][3];
  if (D == 2) {
    R[0][0] = c, R[0][1] = -s, R[1][0] = s, R[1][1] = c;
  } else {
    const double x = axis[0], y = axis[1], z = axis[2];  // unit vector; Rodrigues
    const double r[3][3] = {{omc * x * x + c, omc * x * y - s * z, omc * x * z + s * y},
                            {omc * x * y + s * z, omc * y * y + c, omc * y * z - s * x},
                            {omc * x * z - s * y, omc * y * z + s * x, omc * z * z + c}};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) R[i][j] = r[i][j];
  }
  const double amplitude[3] = {0.04, 0.02, 0.03};
  const int N = static_cast<int>(X.size()) / D;
  std::vector<double> u(X.size());
  for (int a = 0; a < N; ++a) {
    double y[3] = {};
    for (int i = 0; i < D; ++i) {
      double hx = 0.0;
      for (int J = 0; J < D; ++J) hx += H[i][J] * X[D * a + J];
      y[i] = X[D * a + i] + t * hx;
    }
    for (int i = 0; i < D; ++i) {
      double rx = 0.0;
      for (int J = 0; J < D; ++J) rx += R[i][J] * y[J];
      u[D * a + i] = rx - X[D * a + i] + t * amplitude[i] * size * hourglass(D, cube, a);
    }
  }
  return u;
}

std::vector<Workload> makeWorkload(const cm::ElementKernel& kernel) {
  const int D = kernel.dimension();
  std::mt19937 gen(D == 2 ? 2024 : 3024);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double size = 1.6;  // mm, as the tube's elements
  const int C = D == 2 ? 4 : 8, DC = D * C;  // the jittered cell's corners
  const auto cube = cubeCoordinates(kernel);
  const int N = kernel.numNodes(), ND = D * N;
  // A slightly irregular parallelogram (2D) or the unit cube (3D), before jitter.
  const std::vector<double> quad = {0.0, 0.0, 1.0, 0.1, 1.15, 0.95, -0.1, 0.85};
  std::vector<double> base(DC);
  for (int a = 0; a < C; ++a)
    for (int i = 0; i < D; ++i) base[D * a + i] = D == 2 ? quad[D * a + i] : 0.5 * (1.0 + kHexNodes[a][i]);
  std::vector<Workload> work(kElements);
  for (auto& w : work) {
    std::vector<double> corners(DC);
    for (int k = 0; k < DC; ++k) corners[k] = size * (base[k] + 0.15 * unit(gen));
    w.X.resize(ND);
    for (int a = 0; a < N; ++a) mapIntoCell(D, corners, &cube[D * a], &w.X[D * a]);
    const double theta = 0.4 * unit(gen);
    double H[3][3] = {}, axis[3] = {0.0, 0.0, 1.0};
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) H[i][j] = (i == j ? 0.15 : 0.1) * unit(gen);
    if (D == 3) {
      for (double& v : axis) v = unit(gen);
      const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
      for (double& v : axis) v /= n;
    }
    // Newton corrections are smooth fields: mostly a homogeneous gradient (translation, rotation,
    // stretch) plus a smaller hourglass part.
    std::vector<std::vector<double>> directions(kIterates, std::vector<double>(ND));
    for (auto& r : directions) {
      double G[3][3] = {}, t[3] = {}, hg[3] = {};
      for (int i = 0; i < D; ++i)
        for (int j = 0; j < D; ++j) G[i][j] = unit(gen);
      for (int i = 0; i < D; ++i) t[i] = unit(gen);
      for (int i = 0; i < D; ++i) hg[i] = 0.1 * unit(gen);
      for (int a = 0; a < N; ++a)
        for (int i = 0; i < D; ++i) {
          double gx = 0.0;
          for (int J = 0; J < D; ++J) gx += G[i][J] * w.X[D * a + J];
          r[D * a + i] = t[i] + gx / size + hg[i] * hourglass(D, cube, a);
        }
    }
    for (int n = 1; n <= kIncrements; ++n) {
      const auto target = pathDisplacement(D, cube, w.X, double(n) / kIncrements, theta, size, H, axis);
      const auto previous = pathDisplacement(D, cube, w.X, double(n - 1) / kIncrements, theta, size, H, axis);
      double step = 0.0;
      for (int k = 0; k < ND; ++k) step = std::max(step, std::fabs(target[k] - previous[k]));
      for (int it = 0; it < kIterates; ++it) {
        auto u = target;
        for (int k = 0; k < ND; ++k) u[k] += kErrors[it] * step * directions[it][k];
        w.u.push_back(u);
      }
    }
  }
  return work;
}

std::unique_ptr<cm::Material> makeMaterial(const std::string& model) {
  Teuchos::ParameterList p;
  p.set<std::string>("Model", model);
  p.set<double>("Young's Modulus", 400.0);  // the tube's material
  p.set<double>("Poisson's Ratio", 0.25);
  return cm::MaterialFactory::create(p, "bench");
}

/// Counts the local iterations of the kernels: material calls at a new F (every Gauss point at once).
/// A residual evaluation of the enhanced elements asks for P alone and adds A at the same F only where
/// a Newton step needs it (issue 23, fifth round): that second call is not an iteration.
class CountingMaterial final : public cm::Material {
 public:
  explicit CountingMaterial(const cm::Material& law) : law_(law) {}
  bool firstPiolaKirchhoff(const cm::Tensor2& F, cm::Tensor2& P, cm::Tensor4* A) const override {
    count(1, F.data(), A != nullptr);
    return law_.firstPiolaKirchhoff(F, P, A);
  }
  bool firstPiolaKirchhoffAtPoints(int count, const cm::Matrix<2>* F, cm::Matrix<2>* P,
                                   cm::Tangent<2>* A) const override {
    this->count(count, F[0].data(), A != nullptr);
    return law_.firstPiolaKirchhoffAtPoints(count, F, P, A);
  }
  bool firstPiolaKirchhoffAtPoints(int count, const cm::Matrix<3>* F, cm::Matrix<3>* P,
                                   cm::Tangent<3>* A) const override {
    this->count(count, F[0].data(), A != nullptr);
    return law_.firstPiolaKirchhoffAtPoints(count, F, P, A);
  }
  mutable long calls = 0;
  mutable long points = 0;  ///< material points evaluated (per Jacobian evaluation: the quadrature points)

 private:
  void count(int n, const double* F0, bool withTangent) const {
    if (!(withTangent && lastWithoutTangent_ && std::equal(F0, F0 + 4, lastF_))) {
      ++calls;
      points += n;
    }
    lastWithoutTangent_ = !withTangent;
    std::copy(F0, F0 + 4, lastF_);
  }
  const cm::Material& law_;
  mutable bool lastWithoutTangent_ = false;
  mutable double lastF_[4] = {};
};

struct PassTimes {
  double residualSeconds = 0.0, jacobianSeconds = 0.0;
  long residualEvaluations = 0, jacobianEvaluations = 0;
};

/// One pass over every element at iterate `it` of increment `n`; `states` holds the trial states of
/// all elements. Separate functions for the two passes so that callgrind can count the
/// instructions of each (element_kernel_callgrind.sh).
__attribute__((noinline)) double residualPass(const cm::ElementKernel& kernel, const cm::ElementGeometry& geometry,
                                              const cm::Material& material, const std::vector<Workload>& work,
                                              int n, int it, double* states) {
  const int ns = kernel.numStateValues();
  std::array<double, kMaxDofs> f{};
  double sink = 0.0;
  for (int e = 0; e < kElements; ++e) {
    if (kernel.evaluate(geometry, e, work[e].u[n * kIterates + it].data(), states + e * ns, material, f.data(),
                        nullptr) != cm::ElementStatus::Ok) {
      std::fprintf(stderr, "element_kernel_bench: element %d failed at increment %d\n", e, n);
      std::exit(1);
    }
    sink += f[0];
  }
  return sink;
}

__attribute__((noinline)) double jacobianPass(const cm::ElementKernel& kernel, const cm::ElementGeometry& geometry,
                                              const cm::Material& material, const std::vector<Workload>& work,
                                              int n, int it, double* states) {
  const int ns = kernel.numStateValues();
  std::array<double, kMaxDofs> f{};
  std::array<double, kMaxDofs * kMaxDofs> K{};
  double sink = 0.0;
  for (int e = 0; e < kElements; ++e) {
    if (kernel.evaluate(geometry, e, work[e].u[n * kIterates + it].data(), states + e * ns, material, f.data(),
                        K.data()) != cm::ElementStatus::Ok) {
      std::fprintf(stderr, "element_kernel_bench: element %d failed at increment %d\n", e, n);
      std::exit(1);
    }
    sink += f[0] + K[9];
  }
  return sink;
}

/// Runs the whole workload once: per increment, residual and Jacobian at each iterate (no Jacobian at
/// the converged last one). The element states carry over between evaluations as in the model; the
/// reference geometry is computed once, before (as the model does), and not timed.
PassTimes run(const cm::ElementKernel& kernel, const cm::Material& material, const std::vector<Workload>& work,
              long* residualCalls = nullptr, long* jacobianCalls = nullptr, const CountingMaterial* counter = nullptr,
              long* jacobianPoints = nullptr) {
  using Clock = std::chrono::steady_clock;
  std::vector<double> X;
  for (const auto& w : work) X.insert(X.end(), w.X.begin(), w.X.end());
  const auto geometry = kernel.referenceGeometry(kElements, X.data());
  std::vector<double> trial(static_cast<std::size_t>(kElements) * kernel.numStateValues() + 1, 0.0);
  PassTimes t;
  double sink = 0.0;
  for (int n = 0; n < kIncrements; ++n) {
    for (int it = 0; it < kIterates; ++it) {
      long before = counter ? counter->calls : 0;
      auto start = Clock::now();
      sink += residualPass(kernel, *geometry, material, work, n, it, trial.data());
      t.residualSeconds += std::chrono::duration<double>(Clock::now() - start).count();
      t.residualEvaluations += kElements;
      if (counter && residualCalls) *residualCalls += counter->calls - before;
      if (it == kIterates - 1) break;  // converged: no Jacobian at the last iterate
      before = counter ? counter->calls : 0;
      const long pointsBefore = counter ? counter->points : 0;
      start = Clock::now();
      sink += jacobianPass(kernel, *geometry, material, work, n, it, trial.data());
      t.jacobianSeconds += std::chrono::duration<double>(Clock::now() - start).count();
      t.jacobianEvaluations += kElements;
      if (counter && jacobianCalls) *jacobianCalls += counter->calls - before;
      if (counter && jacobianPoints) *jacobianPoints += counter->points - pointsBefore;
    }
  }
  if (!std::isfinite(sink)) std::printf("(non-finite results)\n");
  return t;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

/// The elements timed: the four of the tables in bench/README.md, or with --all every family of the
/// factory but the axisymmetric ones (their workload would need r = x > 0).
std::vector<std::string> elementsToTime(bool all) {
  if (!all) return {"Q4", "Q4 Enhanced", "Hex8", "Hex8 Enhanced"};
  std::vector<std::string> names;
  for (const auto& name : cm::ElementFactory::names())
    if (name.find("Axisymmetric") == std::string::npos) names.push_back(name);
  return names;
}

int main(int argc, char** argv) {
  int repeat = 7;
  std::string onlyElement, onlyMaterial;
  bool once = false, all = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--case") == 0 && i + 2 < argc) {
      onlyElement = argv[++i];
      onlyMaterial = argv[++i];
      all = true;
    } else if (std::strcmp(argv[i], "--once") == 0) {
      once = true;
    } else if (std::strcmp(argv[i], "--all") == 0) {
      all = true;
    } else {
      std::fprintf(stderr,
                   "usage: element_kernel_bench [--repeat N] [--all] [--case ELEMENT MATERIAL] [--once]\n"
                   "  --all: every element family (default: Q4, Q4 Enhanced, Hex8, Hex8 Enhanced)\n"
                   "  --once: one untimed run of the workload (no warm-up, no counting run), for callgrind\n");
      return 2;
    }
  }
  std::printf("element_kernel_bench: %d distorted elements, %d increments x (%d residual + %d Jacobian passes), "
              "median of %d repetitions\n",
              kElements, kIncrements, kIterates, kIterates - 1, repeat);
  std::printf("%-14s %-24s %12s %12s %6s %10s %10s %14s %14s\n", "element", "material", "residual ns", "jacobian ns",
              "points", "res ns/pt", "jac ns/pt", "local it./res", "local it./jac");
  for (const auto& elementName : elementsToTime(all)) {
    const auto kernel = cm::ElementFactory::create(elementName, "bench");
    const auto work = makeWorkload(*kernel);
    for (const char* model : {"Saint Venant-Kirchhoff", "Neo-Hookean"}) {
      if (!onlyElement.empty() && (onlyElement != elementName || onlyMaterial != model)) continue;
      const auto material = makeMaterial(model);
      if (once) {
        const PassTimes t = run(*kernel, *material, work);
        std::printf("%-14s %-24s one run: %ld residual and %ld Jacobian element evaluations\n", elementName.c_str(),
                    model, t.residualEvaluations, t.jacobianEvaluations);
        continue;
      }
      run(*kernel, *material, work);  // warm-up
      std::vector<double> residual, jacobian;
      for (int r = 0; r < repeat; ++r) {
        const PassTimes t = run(*kernel, *material, work);
        residual.push_back(1e9 * t.residualSeconds / t.residualEvaluations);
        jacobian.push_back(1e9 * t.jacobianSeconds / t.jacobianEvaluations);
      }
      // Local iterations and quadrature points from a separate (untimed) run with a counting material: a
      // Jacobian evaluation makes one material pass over the points (the enhanced elements' local
      // iteration count there is 1).
      const CountingMaterial counter(*material);
      long residualCalls = 0, jacobianCalls = 0, jacobianPoints = 0;
      const PassTimes counted = run(*kernel, counter, work, &residualCalls, &jacobianCalls, &counter, &jacobianPoints);
      const double points = double(jacobianPoints) / double(jacobianCalls);
      char resIt[32] = "-", jacIt[32] = "-";
      if (kernel->numInternalVariables() > 0) {
        std::snprintf(resIt, sizeof resIt, "%.3f", double(residualCalls) / counted.residualEvaluations);
        std::snprintf(jacIt, sizeof jacIt, "%.3f", double(jacobianCalls) / counted.jacobianEvaluations);
      }
      const double res = median(residual), jac = median(jacobian);
      std::printf("%-14s %-24s %12.1f %12.1f %6.0f %10.1f %10.1f %14s %14s\n", elementName.c_str(), model, res, jac,
                  points, res / points, jac / points, resIt, jacIt);
    }
  }
  return 0;
}
