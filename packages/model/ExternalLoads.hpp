#pragma once
// The deck's loads on sets (Problem/Loads) on this rank's part of the mesh: the facets of each
// pressure and traction side set and the elements of each body-force block that the part holds (each
// facet and element is in exactly one rank's part, so each is assembled once), with their overlapped
// DOFs and reference coordinates, gathered once. The kernels are mechanics/DistributedLoads'.
//   - Dead loads (traction, body force) are integrated once over the reference configuration into f_ext
//     at λ = 1 (BoundaryConditions keeps f_ext and scales it by λ).
//   - The follower pressure depends on the current configuration: at every assembly pass it adds
//     −λ f_p(x) to the residual forces, −f_p(x) to ∂f/∂λ and −λ ∂f_p/∂x to the Jacobian
//     (docs/theory-solids.md §8). A facet couples only DOFs of its own element's nodes, which the
//     element already couples in the graph.
// Knows nothing of Tpetra (raw overlapped arrays, a DOF lookup and a stiffness sink, like SolidAssembler).
#include <functional>
#include <memory>
#include <vector>

#include "deck/ProblemDefinition.hpp"
#include "mechanics/DistributedLoads.hpp"

namespace contessa::model {

class ExternalLoads {
 public:
  /// `localDof` maps a global DOF (node·dim + c) to its index in the rank's overlapped arrays.
  ExternalLoads(const deck::ProblemDefinition& problem, const std::function<int(mesh::GlobalIndex)>& localDof);

  /// Adds the dead loads at λ = 1 (tractions, body forces) of this rank's facets and elements into the
  /// overlapped array `f` (the caller exports it, adding, to owned rows).
  void addDeadLoads(double* f) const;

  /// Receives one facet's overlapped DOFs and its block of the Jacobian (n × n, row-major).
  using StiffnessSink = std::function<void(const int* dofs, int n, const double* k)>;
  /// The follower pressures at overlapped displacement `u` and load factor λ, in the residual's sense
  /// (f = f_int − f_ext): force −= λ f_p, dForcedLambda −= f_p, and with a sink −λ ∂f_p/∂u.
  void assembleFollowerLoads(const double* u, double lambda, double* force, double* dForcedLambda,
                             const StiffnessSink* stiffness) const;
  bool hasFollowerLoads() const { return !pressureFacets_.empty(); }

 private:
  /// Facets (or cells) of one load: nodes per entry, the overlapped DOFs and reference coordinates of
  /// every entry (dim values per node, node-major), and the load's value at λ = 1.
  struct Entries {
    int nodes = 0;
    std::vector<int> dofs;
    std::vector<double> X;
    std::vector<double> value;  ///< pressure (one value) or a vector (dim values)
    std::size_t count = 0;
  };
  int dim_;
  std::unique_ptr<mechanics::LoadMeasure> measure_;  ///< w = 1; 2πr in an axisymmetric problem
  std::vector<Entries> pressureFacets_, tractionFacets_, bodyCells_;
};

}  // namespace contessa::model
