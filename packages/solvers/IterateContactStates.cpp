#include "solvers/IterateContactStates.hpp"

#include <cstdint>

#include <NOX_Solver_Generic.H>

namespace contessa::solvers {

void IterateContactStates::runPreIterate(const NOX::Solver::Generic& solver) {
  if (solver.getNumIterations() == 0) report(0);
}

void IterateContactStates::runPostIterate(const NOX::Solver::Generic& solver) { report(solver.getNumIterations()); }

void IterateContactStates::report(int iterate) {
  const auto nodes = events_.trialIncrement();  // collective: every rank gathers
  int count[3] = {0, 0, 0};
  std::uint64_t signature = 1469598103934665603ULL;  // FNV-1a over (status, facet) of every node
  const auto mix = [&signature](std::int64_t value) {
    for (int byte = 0; byte < 8; ++byte) {
      signature ^= static_cast<std::uint64_t>(value >> (8 * byte)) & 0xffU;
      signature *= 1099511628211ULL;
    }
  };
  for (const auto& node : nodes) {
    ++count[static_cast<int>(node.trialStatus)];
    mix(static_cast<int>(node.trialStatus));
    // The facet of a node in contact only: an open node's nearest facet does not enter the residual.
    mix(node.trialStatus != continuation::NodeStatus::Open ? node.trialFacet : -2);
  }
  if (print_)
    out_ << "contessa: iterate " << iterate << ": open " << count[0] << ", stick " << count[1] << ", slip " << count[2]
         << ", signature " << std::hex << signature << std::dec << std::endl;
}

}  // namespace contessa::solvers
