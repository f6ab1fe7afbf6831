#pragma once
// The continuum part of the residual and tangent: loops over the elements this rank assembles and
// hands each element's force and stiffness to a sink. Knows elements, materials and the mesh; knows
// nothing of Tpetra or the solvers (keeps heavy headers out, docs/style.md §12).
#include <algorithm>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include "deck/ProblemDefinition.hpp"
#include "mechanics/Element.hpp"
#include "mesh/Mesh.hpp"

namespace contessa::model {

using mesh::GlobalIndex;

class SolidAssembler {
 public:
  /// Assembles the elements of this rank's part of the mesh (problem.mesh), block by block. `localDof`
  /// maps a global DOF (node·dim + c) to its index in the rank's overlapped displacement array.
  SolidAssembler(const deck::ProblemDefinition& problem, const std::function<int(GlobalIndex)>& localDof);

  /// Receives one element's local DOF indices (overlapped numbering), internal force and, when
  /// requested, stiffness (row-major).
  using Sink = std::function<void(const int* dofs, int numDofs, const double* force, const double* stiffness)>;

  /// The first element whose evaluation failed (the caller marks the evaluation failed), if any.
  struct Status {
    mechanics::ElementStatus status = mechanics::ElementStatus::Ok;
    GlobalIndex element = -1;  ///< global id of that element
    bool ok() const { return status == mechanics::ElementStatus::Ok; }
  };

  /// Assembles every element at the overlapped displacement `u`. Updates the trial internal variables.
  Status assemble(const double* u, bool withStiffness, const Sink& sink);

  /// Average Cauchy stress of each element (3 × 3), in the order of `elements()`.
  std::vector<mechanics::Tensor2> elementStresses(const double* u) const;

  /// Element states (internal variables and what warm-starts their local solves): the trial copy
  /// becomes the committed one after a converged increment, and is reset to it when an increment is
  /// abandoned.
  void commit() { committed_ = trial_; }
  void rollback() { trial_ = committed_; }
  /// The trial copy, to put back after evaluations that must leave no trace (ContactMechanicsModel::
  /// saveEvaluationState).
  const std::vector<double>& trialState() const { return trial_; }
  void restoreTrialState(const std::vector<double>& state) { trial_ = state; }

  /// Global ids of the elements, in the loop's order (the part's: block by block).
  const std::vector<GlobalIndex>& elements() const { return elements_; }

  /// Committed state of the element at index i of elements() (a restart file's record), and setting it
  /// back as both copies (the restarted run continues from the commit). Sizes differ: InputError.
  std::vector<double> committedState(std::size_t i) const;
  void restoreState(std::size_t i, const std::vector<double>& values);

 private:
  /// The elements of one mesh block on this rank: one kernel and material; the reference geometry of
  /// all of them computed once, here (shape-function gradients, weights × det J, ...).
  struct ElementSet {
    const deck::BlockPhysics* physics;
    std::unique_ptr<mechanics::ElementGeometry> geometry;
  };
  struct ElementData {
    int set;                  // index into sets_
    int indexInSet;           // the element's index in its set's geometry
    int numDofs;
    std::size_t dofOffset;    // into dofs_
    std::size_t stateOffset;  // into trial_/committed_
  };
  std::vector<GlobalIndex> elements_;
  std::vector<ElementSet> sets_;
  std::vector<ElementData> data_;
  std::vector<int> dofs_;                // overlapped local DOF indices of all elements, concatenated
  std::vector<double> trial_, committed_;  // element states (internal variables and warm-start data)
  std::size_t stateSize(std::size_t i) const {
    return (i + 1 < data_.size() ? data_[i + 1].stateOffset : committed_.size()) - data_[i].stateOffset;
  }
  int maxDofs_ = 0;
};

}  // namespace contessa::model
