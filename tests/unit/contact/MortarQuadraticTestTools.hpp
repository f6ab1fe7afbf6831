#pragma once
// What the quadratic mortar pair tests share (MortarQuadraticFacetPairTest.cpp on 6-node triangles,
// MortarQuadraticQuadFacetPairTest.cpp on 8- and 9-node quadrilaterals): the pair's exact gradient and
// Hessian of its weighted gaps against central differences (the gradient over every coordinate, the
// Hessian over the given columns); the faces' points and orderings the friction tests share too.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "contact/MortarQuadraticFacetPair.hpp"

namespace contessa::contact::testing {

using Point = std::array<double, 3>;
using Face = std::vector<Point>;

inline Point mid(const Point& a, const Point& b) {
  return {0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2])};
}
// The same face ordered the other way round (its normal reversed).
inline Face reversed(const Face& f) {
  if (f.size() == 6) return {f[0], f[2], f[1], f[5], f[4], f[3]};
  Face r = {f[0], f[3], f[2], f[1]};
  if (f.size() >= 8) r.insert(r.end(), {f[7], f[6], f[5], f[4]});
  if (f.size() == 9) r.push_back(f[8]);
  return r;
}
inline MortarFaceNodes faceNodes(const Face& f) {
  MortarFaceNodes x{};
  std::copy(f.begin(), f.end(), x.begin());
  return x;
}

template <int Slots>
void expectDerivativesAreCentralDifferences(const QuadraticFacetPairCoordinates<double, Slots>& x,
                                            const MortarFacetPairShape& shape, double referenceArea,
                                            const std::vector<int>& hessianColumns) {
  constexpr int kM = 6 * Slots;
  const auto d = facetPairDerivatives(x, referenceArea, shape);
  ASSERT_TRUE(d.overlaps);
  const auto plain = facetPairGaps(x, referenceArea, shape);
  const double h = 1e-6;
  std::array<double, Slots> scale{}, gradientError{};
  for (int j = 0; j < kM; ++j) {
    auto plus = x, minus = x;
    plus[j] += h;
    minus[j] -= h;
    const auto gp = facetPairGaps(plus, referenceArea, shape), gm = facetPairGaps(minus, referenceArea, shape);
    for (int a = 0; a < shape.slaveNodes; ++a) {
      const double fd = (gp.weightedGap[a] - gm.weightedGap[a]) / (2 * h);
      scale[a] = std::max(scale[a], std::abs(d.gradient[a][j]));
      gradientError[a] = std::max(gradientError[a], std::abs(fd - d.gradient[a][j]));
    }
  }
  // A few Hessian columns (each a pair of nested-dual evaluations over 48 or 54 coordinates).
  std::array<double, Slots> hessianScale{}, hessianError{};
  for (int j : hessianColumns) {
    auto plus = x, minus = x;
    plus[j] += h;
    minus[j] -= h;
    const auto dp = facetPairDerivatives(plus, referenceArea, shape), dm = facetPairDerivatives(minus, referenceArea, shape);
    for (int a = 0; a < shape.slaveNodes; ++a)
      for (int i = 0; i < kM; ++i) {
        const double fd = (dp.gradient[a][i] - dm.gradient[a][i]) / (2 * h);
        hessianScale[a] = std::max(hessianScale[a], std::abs(d.hessian[a][i * kM + j]));
        hessianError[a] = std::max(hessianError[a], std::abs(fd - d.hessian[a][i * kM + j]));
        EXPECT_NEAR(d.hessian[a][i * kM + j], d.hessian[a][j * kM + i], 1e-12) << "a Hessian is symmetric";
      }
  }
  for (int a = 0; a < shape.slaveNodes; ++a) {
    EXPECT_NEAR(d.weightedGap[a], plain.weightedGap[a], 1e-17);
    EXPECT_GT(scale[a], 1e-3) << a;  // derivatives that are there
    EXPECT_GT(hessianScale[a], 1e-4) << a;
    EXPECT_LT(gradientError[a], 1e-8 * scale[a]) << "slave node " << a;
    EXPECT_LT(hessianError[a], 1e-7 * hessianScale[a]) << "slave node " << a;
  }
}

}  // namespace contessa::contact::testing
