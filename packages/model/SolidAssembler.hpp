#pragma once
// The continuum part of the residual and tangent: loops over the elements this rank assembles and
// hands each element's force and stiffness to a sink. Knows elements, materials and the mesh; knows
// nothing of Tpetra or the solvers (keeps heavy headers out, STYLE.md §12).
#include <algorithm>
#include <functional>
#include <limits>
#include <vector>

#include "deck/ProblemDefinition.hpp"
#include "mechanics/Element.hpp"
#include "mesh/Mesh.hpp"

namespace contessa::model {

using mesh::GlobalIndex;

class SolidAssembler {
 public:
  /// `elements`: the global ids this rank assembles. `localDof` maps a global DOF (node·dim + c)
  /// to its index in the rank's overlapped displacement array.
  SolidAssembler(const deck::ProblemDefinition& problem, std::vector<GlobalIndex> elements,
                 const std::function<int(GlobalIndex)>& localDof);

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

  /// Internal variables: the trial copy becomes the committed one after a converged increment, and is
  /// reset to it when an increment is abandoned.
  void commit() { committed_ = trial_; }
  void rollback() { trial_ = committed_; }

  const std::vector<GlobalIndex>& elements() const { return elements_; }

 private:
  struct ElementData {
    const deck::BlockPhysics* physics;
    std::vector<double> X;      // reference coordinates
    std::vector<int> dofs;      // overlapped local DOF indices
    std::size_t internalOffset; // into trial_/committed_
  };
  std::vector<GlobalIndex> elements_;
  std::vector<ElementData> data_;
  std::vector<double> trial_, committed_;
  int maxDofs_ = 0;
};

}  // namespace contessa::model
