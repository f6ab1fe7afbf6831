// element_kernel_bench: cost of the solid element kernels per element and evaluation, the hot path of
// every residual and Jacobian. Not a test; run it by hand (Release build):
//   build/bin/element_kernel_bench [--repeat N]
// For Q4 and Q4 Enhanced with Saint Venant-Kirchhoff and Neo-Hookean it prints the median (over N
// repetitions, default 7) wall time in ns per element of a residual pass (internal force only) and of
// a Jacobian pass (internal force and tangent), and for the enhanced element the local (enhanced
// parameter) Newton iterations per evaluation, i.e. material calls per evaluation (each call
// evaluates every Gauss point).
//
// The workload imitates what the model asks of each element during a load-stepped Newton solve:
// 64 distorted quadrilaterals of tube-element size (~1.6 mm, node positions jittered by ±15 %), each
// following its own finite-strain path u(t) (a rigid rotation of up to 0.4 rad, stretches and shear
// of up to 15 %, and an hourglass/bending pattern that the enhanced modes resist, so α ≠ 0), cut into
// 47 increments like the tube. In each increment the residual is evaluated at 6 Newton iterates
// u_k = u(t_n) + ε_k |Δu_n| r_k (ε_k = 1, 0.3, 3e-2, 1e-3, 1e-6, 1e-12; r_k a smooth pseudo-random
// correction field) and the Jacobian at the first 5, the same pattern as the tube's Newton loops.
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
constexpr int kNodes = 4, kDofs = 8;

/// One element: reference coordinates and the displacement at every (increment, iterate).
struct Workload {
  std::array<double, kDofs> X{};
  std::vector<std::array<double, kDofs>> u;  ///< [increment · kIterates + iterate]
};

std::array<double, kDofs> pathDisplacement(const std::array<double, kDofs>& X, double t, double theta, double size,
                                           const double (&H)[2][2]) {
  const double c = std::cos(theta * t), s = std::sin(theta * t);
  const double hourglass[4] = {1.0, -1.0, 1.0, -1.0};
  std::array<double, kDofs> u{};
  for (int a = 0; a < kNodes; ++a) {
    // F = R(θ t) (I + t H): x = F X, plus the bending pattern t · 0.04 size (1, ½) h_a.
    const double x = X[2 * a], y = X[2 * a + 1];
    const double ux = x + t * (H[0][0] * x + H[0][1] * y), uy = y + t * (H[1][0] * x + H[1][1] * y);
    u[2 * a] = c * ux - s * uy - x + t * 0.04 * size * hourglass[a];
    u[2 * a + 1] = s * ux + c * uy - y + t * 0.02 * size * hourglass[a];
  }
  return u;
}

std::vector<Workload> makeWorkload() {
  std::mt19937 gen(2024);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double size = 1.6;  // mm, as the tube's elements
  const std::array<double, kDofs> base = {0.0, 0.0, 1.0, 0.1, 1.15, 0.95, -0.1, 0.85};
  std::vector<Workload> work(kElements);
  for (auto& w : work) {
    for (int k = 0; k < kDofs; ++k) w.X[k] = size * (base[k] + 0.15 * unit(gen));
    const double theta = 0.4 * unit(gen);
    const double H[2][2] = {{0.15 * unit(gen), 0.1 * unit(gen)}, {0.1 * unit(gen), 0.15 * unit(gen)}};
    // Newton corrections are smooth fields: mostly a homogeneous gradient (translation, rotation,
    // stretch) plus a smaller hourglass part.
    std::vector<std::array<double, kDofs>> directions(kIterates);
    for (auto& r : directions) {
      const double G[2][2] = {{unit(gen), unit(gen)}, {unit(gen), unit(gen)}};
      const double t[2] = {unit(gen), unit(gen)}, hg[2] = {0.1 * unit(gen), 0.1 * unit(gen)};
      const double hourglass[4] = {1.0, -1.0, 1.0, -1.0};
      for (int a = 0; a < kNodes; ++a)
        for (int i = 0; i < 2; ++i)
          r[2 * a + i] = t[i] + (G[i][0] * w.X[2 * a] + G[i][1] * w.X[2 * a + 1]) / size + hg[i] * hourglass[a];
    }
    for (int n = 1; n <= kIncrements; ++n) {
      const auto target = pathDisplacement(w.X, double(n) / kIncrements, theta, size, H);
      const auto previous = pathDisplacement(w.X, double(n - 1) / kIncrements, theta, size, H);
      double step = 0.0;
      for (int k = 0; k < kDofs; ++k) step = std::max(step, std::fabs(target[k] - previous[k]));
      for (int it = 0; it < kIterates; ++it) {
        auto u = target;
        for (int k = 0; k < kDofs; ++k) u[k] += kErrors[it] * step * directions[it][k];
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

/// Counts the material calls of the kernels: one per local iteration (every Gauss point at once).
class CountingMaterial final : public cm::Material {
 public:
  explicit CountingMaterial(const cm::Material& law) : law_(law) {}
  bool firstPiolaKirchhoff(const cm::Tensor2& F, cm::Tensor2& P, cm::Tensor4* A) const override {
    ++calls;
    return law_.firstPiolaKirchhoff(F, P, A);
  }
  bool firstPiolaKirchhoffAtPoints(int count, const cm::Matrix<2>* F, cm::Matrix<2>* P,
                                   cm::Tangent<2>* A) const override {
    ++calls;
    return law_.firstPiolaKirchhoffAtPoints(count, F, P, A);
  }
  bool firstPiolaKirchhoffAtPoints(int count, const cm::Matrix<3>* F, cm::Matrix<3>* P,
                                   cm::Tangent<3>* A) const override {
    ++calls;
    return law_.firstPiolaKirchhoffAtPoints(count, F, P, A);
  }
  mutable long calls = 0;

 private:
  const cm::Material& law_;
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
  std::array<double, kDofs> f{};
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
  std::array<double, kDofs> f{};
  std::array<double, kDofs * kDofs> K{};
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
              long* residualCalls = nullptr, long* jacobianCalls = nullptr, const CountingMaterial* counter = nullptr) {
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
      start = Clock::now();
      sink += jacobianPass(kernel, *geometry, material, work, n, it, trial.data());
      t.jacobianSeconds += std::chrono::duration<double>(Clock::now() - start).count();
      t.jacobianEvaluations += kElements;
      if (counter && jacobianCalls) *jacobianCalls += counter->calls - before;
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

int main(int argc, char** argv) {
  int repeat = 7;
  std::string onlyElement, onlyMaterial;
  bool once = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--repeat") == 0 && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else if (std::strcmp(argv[i], "--case") == 0 && i + 2 < argc) {
      onlyElement = argv[++i];
      onlyMaterial = argv[++i];
    } else if (std::strcmp(argv[i], "--once") == 0) {
      once = true;
    } else {
      std::fprintf(stderr,
                   "usage: element_kernel_bench [--repeat N] [--case ELEMENT MATERIAL] [--once]\n"
                   "  --once: one untimed run of the workload (no warm-up, no counting run), for callgrind\n");
      return 2;
    }
  }
  const auto work = makeWorkload();
  std::printf("element_kernel_bench: %d distorted elements, %d increments x (%d residual + %d Jacobian passes), "
              "median of %d repetitions\n",
              kElements, kIncrements, kIterates, kIterates - 1, repeat);
  std::printf("%-12s %-24s %14s %14s %14s %14s\n", "element", "material", "residual ns", "jacobian ns",
              "local it./res", "local it./jac");
  for (const char* elementName : {"Q4", "Q4 Enhanced"}) {
    for (const char* model : {"Saint Venant-Kirchhoff", "Neo-Hookean"}) {
      if (!onlyElement.empty() && (onlyElement != elementName || onlyMaterial != model)) continue;
      const auto kernel = cm::ElementFactory::create(elementName, "bench");
      const auto material = makeMaterial(model);
      if (once) {
        const PassTimes t = run(*kernel, *material, work);
        std::printf("%-12s %-24s one run: %ld residual and %ld Jacobian element evaluations\n", elementName, model,
                    t.residualEvaluations, t.jacobianEvaluations);
        continue;
      }
      run(*kernel, *material, work);  // warm-up
      std::vector<double> residual, jacobian;
      for (int r = 0; r < repeat; ++r) {
        const PassTimes t = run(*kernel, *material, work);
        residual.push_back(1e9 * t.residualSeconds / t.residualEvaluations);
        jacobian.push_back(1e9 * t.jacobianSeconds / t.jacobianEvaluations);
      }
      // Local iterations from a separate (untimed) run with a counting material.
      const CountingMaterial counter(*material);
      long residualCalls = 0, jacobianCalls = 0;
      const PassTimes counted = run(*kernel, counter, work, &residualCalls, &jacobianCalls, &counter);
      char resIt[32] = "-", jacIt[32] = "-";
      if (kernel->numInternalVariables() > 0) {
        std::snprintf(resIt, sizeof resIt, "%.3f", double(residualCalls) / counted.residualEvaluations);
        std::snprintf(jacIt, sizeof jacIt, "%.3f", double(jacobianCalls) / counted.jacobianEvaluations);
      }
      std::printf("%-12s %-24s %14.1f %14.1f %14s %14s\n", elementName, model, median(residual), median(jacobian),
                  resIt, jacIt);
    }
  }
  return 0;
}
