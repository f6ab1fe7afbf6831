#pragma once
// Slave nodes for Contact Beta's unit tests: open nodes that close at a given fraction β^k of the planned
// step (ContactBetaControlTest, AutomaticContactsTest).
#include <vector>

#include "continuation/ContactEvents.hpp"

namespace contessa::continuation::testing {

/// Open node closing at β^k = b of the planned step (g_t = b, trial g = b − 1).
inline SlaveNodeIncrement closingAt(double b) {
  SlaveNodeIncrement n;
  n.committedGap = b;
  n.trialGap = b - 1.0;
  n.trialStatus = b <= 1.0 ? NodeStatus::Stick : NodeStatus::Open;
  return n;
}

/// One such node per entry of `b`.
inline std::vector<SlaveNodeIncrement> nodesAt(const std::vector<double>& b) {
  std::vector<SlaveNodeIncrement> out;
  for (double x : b) out.push_back(closingAt(x));
  return out;
}

}  // namespace contessa::continuation::testing
