#pragma once
// The deck's loads on sets (Problem/Loads) on this rank's part of the mesh: the facets of each
// pressure and traction side set and the elements of each body-force block that the part holds (each
// facet and element is in exactly one rank's part, so each is assembled once), with their overlapped
// DOFs and reference coordinates, gathered once. The kernels are mechanics/DistributedLoads'.
//   - Dead loads (traction, body force) are integrated over the reference configuration into f_ext at a
//     load step's start and into its change over the step (BoundaryConditions keeps both and scales the
//     change by the step's amplitude a(λ)); without load steps: start 0, change the deck's loads.
//   - The follower pressure depends on the current configuration: with p = p_0 + a Δp (continuation::
//     LoadSchedule) it adds −f_p(x; p) to the residual forces, −a' f_p(x; Δp) to ∂f/∂λ and −∂f_p/∂x to
//     the Jacobian (docs/theory-solids.md §8; f_p is linear in p). A facet couples only DOFs of its own element's nodes, which the
//     element already couples in the graph.
// Knows nothing of Tpetra (raw overlapped arrays, a DOF lookup and a stiffness sink, like SolidAssembler).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "deck/ProblemDefinition.hpp"
#include "mechanics/DistributedLoads.hpp"

namespace contessa::model {

class ExternalLoads {
 public:
  /// `localDof` maps a global DOF (node·dim + c) to its index in the rank's overlapped arrays.
  ExternalLoads(const deck::ProblemDefinition& problem, const std::function<int(mesh::GlobalIndex)>& localDof);

  /// Every load's value at the start of a load step and its change over the step (by load name; the
  /// constructor sets start 0 and change the deck's value).
  void setStepValues(const std::function<std::vector<double>(const std::string& name)>& start,
                     const std::function<std::vector<double>(const std::string& name)>& change);
  /// Adds the dead loads (tractions, body forces) of this rank's facets and elements at the step's start
  /// values (`change` false) or of their change (true) into the overlapped array `f` (the caller exports
  /// it, adding, to owned rows).
  void addDeadLoads(double* f, bool change = true) const;

  /// Receives one facet's overlapped DOFs and its block of the Jacobian (n × n, row-major).
  using StiffnessSink = std::function<void(const int* dofs, int n, const double* k)>;
  /// The follower pressures at overlapped displacement `u` and the step's amplitude a (slope a' = da/dλ),
  /// in the residual's sense (f = f_int − f_ext): p = p_0 + a Δp, force −= f_p(p), dForcedLambda −=
  /// a' f_p(Δp), and with a sink −∂f_p(p)/∂u.
  void assembleFollowerLoads(const double* u, double a, double slope, double* force, double* dForcedLambda,
                             const StiffnessSink* stiffness) const;
  bool hasFollowerLoads() const { return !pressureFacets_.empty(); }

 private:
  /// Facets (or cells) of one load: nodes per entry, the overlapped DOFs and reference coordinates of
  /// every entry (dim values per node, node-major), and the load's value at λ = 1.
  struct Entries {
    std::string name;  ///< the deck's load name
    int nodes = 0;
    std::vector<int> dofs;
    std::vector<double> X;
    std::vector<double> start, change;  ///< pressure (one value) or a vector (dim values): step start, change
    std::size_t count = 0;
  };
  /// One facet's follower-pressure force (and with K, its stiffness) at current positions x, pressure p.
  void facetPressure(const double* x, double p, double* fe, double* K) const;

  int dim_;
  std::unique_ptr<mechanics::LoadMeasure> measure_;  ///< w = 1; 2πr in an axisymmetric problem
  std::vector<Entries> pressureFacets_, tractionFacets_, bodyCells_;
};

}  // namespace contessa::model
