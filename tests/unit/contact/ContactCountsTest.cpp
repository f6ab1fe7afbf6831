// The contact counts of the history (ContactInterfaceBase::committedCounts): a closed node of a
// frictionless interface is active, neither sticking nor slipping (issue 25, point 4); with friction the
// active nodes are split into stick and slip. 2D and 3D through the same interface code.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "contact/ContactInterface.hpp"

namespace {

namespace cc = contessa::contact;

// One slave node (mesh node 3) and a rigid flat facet at height 0 (outward normal +y in 2D, +z in 3D), the
// node `depth` below it: penetrating when depth > 0.
cc::ContactInterfaceSpec nodeUnderAFlatFacet(int dimension, double mu) {
  cc::ContactInterfaceSpec spec;
  spec.name = "plate";
  spec.dimension = dimension;
  spec.slaveNodes = {3};
  spec.slaveAreas = {1.0};
  spec.slaveFacetLengths = {1.0};
  spec.rigidMaster = true;
  if (dimension == 2) {
    spec.rigidSurface.points = {1, 0, -1, 0};  // right to left: the normal (a_1y, −a_1x) is +y
    spec.rigidSurface.facets = {0, 1};
    spec.rigidSurface.motion = {0, 0};
  } else {
    spec.rigidSurface.points = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0};
    spec.rigidSurface.facets = {0, 1, 2, 3};
    spec.rigidSurface.motion = {0, 0, 0};
  }
  spec.law.normalPenalty = 1e3;
  spec.law.frictionCoefficient = mu;
  spec.law.tangentialPenalty = mu > 0 ? 1e3 : 0.0;
  return spec;
}

// The counts committed after one evaluation with the node at (x, −depth) / (x, 0, −depth).
cc::ContactCounts countsAt(int dimension, double mu, double x, double depth) {
  const auto interface = cc::makeContactInterface(nodeUnderAFlatFacet(dimension, mu), {1});
  const auto at = [&](cc::GlobalIndex, double* position) {
    position[0] = x;
    position[1] = dimension == 2 ? -depth : 0.0;
    if (dimension == 3) position[2] = -depth;
  };
  interface->evaluate(at, 0.0, true, [](const cc::GlobalIndex*, int, const double*, const double*, const double*) {});
  interface->commit();
  return interface->committedCounts();
}

class ContactCounts : public ::testing::TestWithParam<int> {};

TEST_P(ContactCounts, FrictionlessClosedNodeIsActiveNotSlipping) {
  const int dimension = GetParam();
  const cc::ContactCounts closed = countsAt(dimension, 0.0, 0.2, 0.01);
  EXPECT_EQ(closed.active, 1);
  EXPECT_EQ(closed.newlyActive, 1);
  EXPECT_EQ(closed.stick, 0);
  EXPECT_EQ(closed.slip, 0);
  const cc::ContactCounts open = countsAt(dimension, 0.0, 0.2, -0.01);
  EXPECT_EQ(open.active, 0);
  EXPECT_EQ(open.stick + open.slip, 0);
}

// With friction the first touch sticks (no slip yet): the active node is counted as stick.
TEST_P(ContactCounts, FrictionalClosedNodeIsSplitByStatus) {
  const int dimension = GetParam();
  const cc::ContactCounts closed = countsAt(dimension, 0.3, 0.2, 0.01);
  EXPECT_EQ(closed.active, 1);
  EXPECT_EQ(closed.stick + closed.slip, 1);
  EXPECT_EQ(closed.stick, 1);
}

INSTANTIATE_TEST_SUITE_P(Interface, ContactCounts, ::testing::Values(2, 3));

}  // namespace
