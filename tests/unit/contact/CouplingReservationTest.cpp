// The matrix graph's contact couplings (CouplingReservation): linear in the surface, covering every facet
// the run-time search can pair a slave node with inside the reach, the whole surface when small.
#include "contact/CouplingReservation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "contact/BoundingBoxTree.hpp"

namespace cc = contessa::contact;

namespace {

/// A 3D interface: a master grid of n × n unit quads at z = 0 (nodes 0 … (n+1)² − 1) and a slave grid of
/// n × n nodes at z = 0.01 offset by half a facet; reference coordinates of both.
struct SyntheticSurface {
  cc::ContactInterfaceSpec spec;
  std::vector<double> X;
};

SyntheticSurface makeSurface(int n, double searchReach = -1.0) {
  SyntheticSurface s;
  s.spec.name = "synthetic";
  s.spec.dimension = 3;
  s.spec.searchReach = searchReach;
  const int m = n + 1;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) s.X.insert(s.X.end(), {double(i), double(j), 0.0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const long long a = j * m + i;
      s.spec.masterFacets.insert(s.spec.masterFacets.end(), {a, a + 1, a + 1 + m, a + m});
    }
  const long long first = static_cast<long long>(m) * m;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      s.X.insert(s.X.end(), {i + 0.5, j + 0.5, 0.01});
      s.spec.slaveNodes.push_back(first + j * n + i);
    }
  return s;
}

}  // namespace

TEST(CouplingReservation, GrowsLinearlyWithTheSurface) {
  // n and 4n slave nodes: the reserved (slave, master) pairs — 2 · dim² matrix entries each — grow by ~4,
  // where the all-to-all reservation grows by 16.
  std::vector<std::size_t> pairs, allToAll;
  for (int n : {40, 80}) {
    const auto s = makeSurface(n);
    const std::vector<char> all(s.spec.slaveNodes.size(), 1);
    const auto r = cc::reserveCouplings(s.spec, s.X, all);
    ASSERT_FALSE(r.wholeSurface);
    EXPECT_DOUBLE_EQ(r.reach, 2.0 * std::sqrt(2.0));  // h = the unit quad's diagonal
    pairs.push_back(r.numPairs(all));
    allToAll.push_back(s.spec.slaveNodes.size() * r.allMasterNodes.size());
    // Each slave node reserves a patch of bounded size: (2 ⌈reach⌉ + 2)² nodes at most.
    for (std::size_t k = 0; k < s.spec.slaveNodes.size(); ++k)
      EXPECT_LE(r.end(k) - r.begin(k), 64) << "slave " << k;
  }
  const double growth = double(pairs[1]) / double(pairs[0]);
  EXPECT_GT(growth, 3.6);
  EXPECT_LT(growth, 4.4);
  EXPECT_LT(pairs[1] * 20, allToAll[1]);
}

TEST(CouplingReservation, CoversEveryFacetTheSearchCanFindWithinTheReach) {
  // A slave node moved by d (|d_c| ≤ h + Search Reach) relative to the master: every facet whose box,
  // enlarged by h as the run-time search does (ContactInterface::evaluate), contains it is reserved.
  const double searchReach = 1.7;
  const auto s = makeSurface(24, searchReach);
  const std::vector<char> all(s.spec.slaveNodes.size(), 1);
  const auto r = cc::reserveCouplings(s.spec, s.X, all);
  ASSERT_FALSE(r.wholeSurface);
  const double h = std::sqrt(2.0);
  EXPECT_DOUBLE_EQ(r.reach, 2 * h + searchReach);
  std::vector<cc::BoundingBox<3>> boxes(s.spec.numMasterFacets());
  for (std::size_t f = 0; f < boxes.size(); ++f) {
    for (int a = 0; a < 4; ++a) {
      const auto node = static_cast<std::size_t>(s.spec.masterFacets[4 * f + a]);
      boxes[f].include({s.X[3 * node], s.X[3 * node + 1], s.X[3 * node + 2]});
    }
    boxes[f].enlarge(h);
  }
  std::mt19937 random(7);
  std::uniform_real_distribution<double> shift(-(h + searchReach), h + searchReach);
  std::size_t checked = 0, notReservedOutside = 0;
  for (std::size_t k = 0; k < s.spec.slaveNodes.size(); ++k)
    for (int trial = 0; trial < 20; ++trial) {
      const auto node = static_cast<std::size_t>(s.spec.slaveNodes[k]);
      const cc::Vector<3> x{s.X[3 * node] + shift(random), s.X[3 * node + 1] + shift(random), s.X[3 * node + 2]};
      for (std::size_t f = 0; f < boxes.size(); ++f)
        if (boxes[f].contains(x))
          for (int a = 0; a < 4; ++a) {
            ++checked;
            ASSERT_TRUE(cc::isReserved(r, k, s.spec.masterFacets[4 * f + a])) << "slave " << k << " facet " << f;
          }
    }
  EXPECT_GT(checked, 10000u);
  // And it is not the whole surface: far facets are not reserved.
  for (std::size_t k = 0; k < s.spec.slaveNodes.size(); ++k)
    notReservedOutside += r.allMasterNodes.size() - static_cast<std::size_t>(r.end(k) - r.begin(k));
  EXPECT_GT(notReservedOutside, s.spec.slaveNodes.size() * r.allMasterNodes.size() / 2);
}

TEST(CouplingReservation, OnlyTheSlaveNodesAskedFor) {
  const auto s = makeSurface(30);
  std::vector<char> some(s.spec.slaveNodes.size(), 0);
  for (std::size_t k = 0; k < some.size(); k += 3) some[k] = 1;
  const auto r = cc::reserveCouplings(s.spec, s.X, some);
  for (std::size_t k = 0; k < some.size(); ++k) EXPECT_EQ(r.end(k) == r.begin(k), some[k] == 0) << k;
}

TEST(CouplingReservation, SmallInterfaceReservesTheWholeSurface) {
  const auto s = makeSurface(10);  // 100 slave × 121 master nodes ≤ kWholeSurfacePairs
  const std::vector<char> all(s.spec.slaveNodes.size(), 1);
  const auto r = cc::reserveCouplings(s.spec, s.X, all);
  EXPECT_TRUE(r.wholeSurface);
  EXPECT_EQ(r.numPairs(all), 100u * 121u);
  // Forced to search (threshold 0), the same surface reserves less.
  const auto searched = cc::reserveCouplings(s.spec, s.X, all, 0);
  EXPECT_FALSE(searched.wholeSurface);
  EXPECT_LT(searched.numPairs(all), r.numPairs(all));
}

TEST(CouplingReservation, RigidMasterReservesNothing) {
  auto s = makeSurface(4);
  s.spec.rigidMaster = true;
  s.spec.masterFacets.clear();
  s.spec.rigidSurface.points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  s.spec.rigidSurface.facets = {0, 1, 2, 3};
  const std::vector<char> all(s.spec.slaveNodes.size(), 1);
  const auto r = cc::reserveCouplings(s.spec, s.X, all);
  EXPECT_TRUE(r.rigidMaster);
  EXPECT_EQ(r.numPairs(all), 0u);
  EXPECT_TRUE(cc::isReserved(r, 0, -1));  // rigid points (negative ids) are not unknowns
}

TEST(CouplingReservation, AroundTheCurrentConfiguration) {
  // The rebuild's reservation (ContactMechanicsModel::rebuildGraph): the slave grid slid 6.3 facets along x
  // and 2.2 along y over a master stretched by 10 % in x. Around the current positions, every facet whose
  // current box, enlarged by the current h as the run-time search does, contains a slave node's current
  // position is reserved for it; around the reference positions most of them are not; and h (so the
  // reach) is the current one.
  const auto s = makeSurface(24, 0.0);
  const std::vector<char> all(s.spec.slaveNodes.size(), 1);
  const std::size_t numMaster = 25 * 25;
  std::vector<double> current = s.X;
  for (std::size_t node = 0; node < current.size() / 3; ++node) {
    if (node < numMaster) {
      current[3 * node] *= 1.1;
    } else {
      current[3 * node] += 6.3;
      current[3 * node + 1] += 2.2;
    }
  }
  const auto atReference = cc::reserveCouplings(s.spec, s.X, all);
  const auto atCurrent = cc::reserveCouplings(s.spec, current, all);
  ASSERT_FALSE(atCurrent.wholeSurface);
  const double h = std::sqrt(1.1 * 1.1 + 1.0);  // the stretched quad's diagonal
  EXPECT_DOUBLE_EQ(atReference.reach, 2.0 * std::sqrt(2.0));
  EXPECT_NEAR(atCurrent.reach, 2.0 * h, 1e-12);
  std::vector<cc::BoundingBox<3>> boxes(s.spec.numMasterFacets());
  for (std::size_t f = 0; f < boxes.size(); ++f) {
    for (int a = 0; a < 4; ++a) {
      const auto node = static_cast<std::size_t>(s.spec.masterFacets[4 * f + a]);
      boxes[f].include({current[3 * node], current[3 * node + 1], current[3 * node + 2]});
    }
    boxes[f].enlarge(h);
  }
  std::size_t found = 0, missingAtReference = 0;
  for (std::size_t k = 0; k < s.spec.slaveNodes.size(); ++k) {
    const auto node = static_cast<std::size_t>(s.spec.slaveNodes[k]);
    const cc::Vector<3> x{current[3 * node], current[3 * node + 1], current[3 * node + 2]};
    for (std::size_t f = 0; f < boxes.size(); ++f)
      if (boxes[f].contains(x))
        for (int a = 0; a < 4; ++a) {
          ++found;
          ASSERT_TRUE(cc::isReserved(atCurrent, k, s.spec.masterFacets[4 * f + a])) << "slave " << k << " facet " << f;
          missingAtReference += cc::isReserved(atReference, k, s.spec.masterFacets[4 * f + a]) ? 0 : 1;
        }
  }
  EXPECT_GT(found, 10000u);
  EXPECT_GT(missingAtReference, found / 2);  // what the rebuild is for
  // Still a bounded patch per slave node (the graph stays linear in the surface).
  for (std::size_t k = 0; k < s.spec.slaveNodes.size(); ++k) EXPECT_LE(atCurrent.end(k) - atCurrent.begin(k), 64) << k;
}
