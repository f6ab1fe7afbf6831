// CPU time of one 3D mortar facet pair's derivatives (facetPairDerivatives: weighted gaps, gradients and
// Hessians), on the pairs of the cost cases of issue 25, and a fingerprint of every number they give, so
// that a change to the kernel can be checked to give the same bits (run before and after, compare).
//
//   build/bin/mortar_pair_bench [--calls N] [--repeat R] [--case NAME]
//
// --case runs one pair only (under callgrind: its instructions per call, the total over the R x N + R
// calls).
//
// Pairs (slave Quad4 slightly warped and tilted, as a deformed block's face is):
//   block      a slave Quad4 inside a motionless rigid quadrilateral (the block on its rigid base)
//   tube       the same slave on a rigid quadrilateral moving along a motion (the tube on its plate)
//   deformable a slave Quad4 cut by a deformable Quad4 master (the block on a deformable base)
//   friction   the block pair with committed positions (the frictional kernel: slips and virtual slips)
//   apart      a slave Quad4 whose box meets a master facet that it does not overlap
// For each: CPU microseconds per pair (std::clock, the median of R repeats of N calls) and the FNV-1a
// hash of the bits of every output entry of the first call (zeros hashed as +0).
#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

#include "contact/MortarFacetPair.hpp"

using namespace contessa::contact;

namespace {

std::uint64_t hashBits(std::uint64_t h, const double* v, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    const double x = v[i] == 0.0 ? 0.0 : v[i];  // a zero's sign is not a different number
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    for (int b = 0; b < 8; ++b) {
      h ^= (bits >> (8 * b)) & 0xffu;
      h *= 1099511628211ull;
    }
  }
  return h;
}

std::uint64_t fingerprint(const MortarFacetPairDerivatives& d) {
  std::uint64_t h = 1469598103934665603ull ^ static_cast<std::uint64_t>(d.overlaps);
  h = hashBits(h, d.weightedGap.data(), d.weightedGap.size());
  h = hashBits(h, d.mortarArea.data(), d.mortarArea.size());
  for (const auto& g : d.gradient) h = hashBits(h, g.data(), g.size());
  for (const auto& g : d.hessian) h = hashBits(h, g.data(), g.size());
  for (const auto& s : d.weightedSlip) h = hashBits(h, s.data(), s.size());
  for (const auto& g : d.slipGradient) h = hashBits(h, g.data(), g.size());
  for (const auto& g : d.slipHessian) h = hashBits(h, g.data(), g.size());
  for (const auto& g : d.slipVariation) h = hashBits(h, g.data(), g.size());
  for (const auto& g : d.slipVariationGradient) h = hashBits(h, g.data(), g.size());
  return h;
}

struct Case {
  std::string name;
  FacetPairCoordinates<double> x{};
  bool rigid = false;
  std::array<double, 12> motion{};
  bool withCommitted = false;
  FacetPairCommitted committed{};
};

// A slave Quad4 of side h at height z above z = 0, its normal down (towards the master), warped by w
// and tilted; the master below, normal up.
FacetPairCoordinates<double> pair(double h, double shiftX, double shiftY, double masterSize) {
  FacetPairCoordinates<double> x{};
  const double slave[4][3] = {{0.0, 0.0, -1.0e-4}, {0.0, h, 1.0e-4}, {h, h, -2.0e-4}, {h, 0.0, 0.5e-4}};
  for (int a = 0; a < 4; ++a) {
    x[3 * a] = slave[a][0] + 0.013 * h * a;
    x[3 * a + 1] = slave[a][1] - 0.007 * h * (a % 2);
    x[3 * a + 2] = slave[a][2] + 0.002 * h * slave[a][0] / h;
  }
  const double L = masterSize;
  const double master[4][3] = {{shiftX, shiftY, 0.0}, {shiftX + L, shiftY, 0.0}, {shiftX + L, shiftY + L, 0.0},
                               {shiftX, shiftY + L, 0.0}};
  for (int b = 0; b < 4; ++b)
    for (int c = 0; c < 3; ++c) x[12 + 3 * b + c] = master[b][c];
  return x;
}

std::vector<Case> cases() {
  std::vector<Case> out;
  Case block{"block", pair(0.5, -2.0, -2.0, 5.0), true, {}, false, {}};
  out.push_back(block);
  Case tube = block;
  tube.name = "tube";
  for (int b = 0; b < 4; ++b) tube.motion[3 * b + 2] = 1.0;  // the plate pressed up
  out.push_back(tube);
  Case deformable{"deformable", pair(0.5, 0.2, -0.1, 0.6), false, {}, false, {}};
  deformable.x[12 + 3 * 2 + 2] = 3.0e-4;  // a warped master
  out.push_back(deformable);
  Case friction = block;
  friction.name = "friction";
  friction.withCommitted = true;
  friction.committed = friction.x;
  for (int a = 0; a < 4; ++a) friction.committed[3 * a] -= 1.0e-3;  // slid by 1e-3 along x since the commit
  out.push_back(friction);
  Case apart{"apart", pair(0.5, 0.52, 0.0, 0.5), false, {}, false, {}};
  out.push_back(apart);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  int calls = 200, repeat = 5;
  std::string only;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--calls")
      calls = std::atoi(argv[i + 1]);
    else if (flag == "--repeat")
      repeat = std::atoi(argv[i + 1]);
    else if (flag == "--case")
      only = argv[i + 1];
    else {
      std::fprintf(stderr, "mortar_pair_bench: unknown option %s (expected --calls N, --repeat R, --case NAME)\n",
                   argv[i]);
      return 1;
    }
  }
  if (calls < 1 || repeat < 1) {
    std::fprintf(stderr, "mortar_pair_bench: --calls and --repeat must be positive integers\n");
    return 1;
  }
  std::printf("| pair | overlaps | us / pair (median of %d x %d calls) | fingerprint |\n|---|---|---|---|\n", repeat, calls);
  bool found = only.empty();
  for (const Case& c : cases()) {
    if (!only.empty() && c.name != only) continue;
    found = true;
    std::vector<double> times;
    std::uint64_t print = 0;
    bool overlaps = false;
    for (int r = 0; r < repeat; ++r) {
      double sum = 0.0;
      const std::clock_t start = std::clock();
      for (int k = 0; k < calls; ++k) {
        const MortarFacetPairDerivatives d = facetPairDerivatives(c.x, 0.25, MortarFacetPairShape{},
                                                                  c.rigid ? c.motion.data() : nullptr,
                                                                  c.withCommitted ? &c.committed : nullptr);
        sum += d.hessian[0][0] + d.gradient[3][2];
        overlaps = d.overlaps;
      }
      times.push_back(1e6 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC / calls);
      if (sum == 42.0) std::printf(" ");  // keep the calls
      print = fingerprint(facetPairDerivatives(c.x, 0.25, MortarFacetPairShape{}, c.rigid ? c.motion.data() : nullptr,
                                               c.withCommitted ? &c.committed : nullptr));
    }
    std::sort(times.begin(), times.end());
    std::printf("| %s | %s | %.1f | %016llx |\n", c.name.c_str(), overlaps ? "yes" : "no", times[times.size() / 2],
                static_cast<unsigned long long>(print));
  }
  if (!found) {
    std::fprintf(stderr, "mortar_pair_bench: --case %s is not a pair (expected block, tube, deformable, friction, apart)\n",
                 only.c_str());
    return 1;
  }
  return 0;
}
