#pragma once
// MUMPS' distributed assembled input (ICNTL(18) = 3) of a Tpetra CrsMatrix: each rank gives its own
// rows as (row, column, value) triplets with global 1-based indices. The pattern depends only on the
// matrix graph, which a Newton run never changes, so it is built once per graph; afterwards only the
// values are copied, in the graph's own order (no index lookup, no pattern comparison).
#include <dmumps_c.h>
#include <mpi.h>

#include <vector>

#include "model/TpetraTypes.hpp"

namespace contessa::solvers {

class MumpsDistributedInput {
 public:
  /// Takes the values of `A` (fill complete); builds the pattern first when `A` has another graph
  /// object than the last call (or this is the first). Collective over `comm`: returns true on every
  /// rank when any rank built a new pattern (MUMPS then needs a new analysis, JOB = 1).
  bool update(const model::CrsMatrix& A, MPI_Comm comm);

  /// The next update() builds the pattern again (after a failed analysis).
  void forgetPattern() { graph_ = Teuchos::null; }

  MUMPS_INT order() const { return n_; }
  MUMPS_INT8 numEntries() const { return static_cast<MUMPS_INT8>(values_.size()); }
  MUMPS_INT* rows() { return rows_.data(); }
  MUMPS_INT* columns() { return cols_.data(); }
  double* values() { return values_.data(); }

 private:
  Teuchos::RCP<const model::CrsGraph> graph_;  // held, so that no other graph can take its address
  MUMPS_INT n_ = 0;
  std::vector<MUMPS_INT> rows_, cols_;
  std::vector<double> values_;
};

}  // namespace contessa::solvers
