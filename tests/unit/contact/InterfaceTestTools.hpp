#pragma once
// The contact interface tests' 2D set-up: three slave nodes on a line under a moving rigid master.
#include "contact/ContactInterface.hpp"

#include <vector>

namespace contessa::contact::testing {

/// Three slave nodes on y = 0 at x = 0, 1, 2 (tributary lengths 0.5, 1, 0.5; facet lengths 1) under a rigid
/// master, the polyline through `points`, that moves by λ `motion`; normal penalty 1e6.
inline ContactInterfaceSpec threeNodesUnderRigidLine(const std::vector<Vector<2>>& points, Vector<2> motion) {
  ContactInterfaceSpec spec;
  spec.name = "plate";
  spec.dimension = 2;
  spec.slaveNodes = {0, 1, 2};
  spec.slaveAreas = {0.5, 1.0, 0.5};
  spec.slaveFacetLengths = {1.0, 1.0, 1.0};
  spec.rigidMaster = true;
  for (std::size_t i = 0; i < points.size(); ++i) {
    spec.rigidSurface.points.insert(spec.rigidSurface.points.end(), {points[i][0], points[i][1]});
    if (i + 1 < points.size()) spec.rigidSurface.facets.insert(spec.rigidSurface.facets.end(), {int(i), int(i + 1)});
  }
  spec.rigidSurface.motion = {motion[0], motion[1]};
  spec.law.normalPenalty = 1e6;
  return spec;
}

/// Where those slave nodes are: node k at (k, 0).
inline void threeNodesOnXAxis(GlobalIndex node, double* x) {
  x[0] = static_cast<double>(node);
  x[1] = 0.0;
}

}  // namespace contessa::contact::testing
