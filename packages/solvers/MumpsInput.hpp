#pragma once
// MUMPS' assembled input of a Tpetra CrsMatrix: each rank gives its own rows as (row, column, value)
// triplets with global 1-based indices (distributed input, ICNTL(18) = 3; on one rank the same triplets
// are the centralised input, ICNTL(18) = 0). The pattern depends only on the
// matrix graph, which changes only when the model rebuilds it (contact beyond its reserved couplings: a
// new graph object, and a matrix on it), so it is built once per graph, recognised by identity; afterwards
// only the values are copied, in the graph's own order (no index lookup, no pattern comparison).
#include <dmumps_c.h>
#include <mpi.h>

#include <vector>

#include "model/TpetraTypes.hpp"

namespace contessa::solvers {

/// What MUMPS is given: order, triplets and the pattern's generation (a new generation needs a new
/// analysis, JOB = 1).
struct MumpsMatrixView {
  MUMPS_INT order = 0;
  MUMPS_INT8 numEntries = 0;
  MUMPS_INT* rows = nullptr;
  MUMPS_INT* columns = nullptr;
  double* values = nullptr;
  long patternGeneration = 0;
};

class MumpsDistributedInput {
 public:
  /// Takes the values of `A` (fill complete); builds the pattern first when `A` has another graph
  /// object than the last call (or this is the first). Collective over `comm`: returns true on every
  /// rank when any rank built a new pattern (MUMPS then needs a new analysis, JOB = 1).
  bool update(const model::CrsMatrix& A, MPI_Comm comm);

  MumpsMatrixView view() {
    return {n_, static_cast<MUMPS_INT8>(values_.size()), rows_.data(), cols_.data(), values_.data(), generation_};
  }

 private:
  Teuchos::RCP<const model::CrsGraph> graph_;  // held, so that no other graph can take its address
  MUMPS_INT n_ = 0;
  long generation_ = 0;
  std::vector<MUMPS_INT> rows_, cols_;
  std::vector<double> values_;
};

/// The whole matrix on rank 0, for MUMPS run there alone (`Reproducible`): the ranks' triplets gathered in
/// rank order. MUMPS on several ranks adds the contributions of the other ranks' fronts, in the
/// factorisation and in the forward solve, in the order their messages arrive, so its answer changes in
/// the last bits from run to run; on one rank the order is fixed. The pattern is gathered once per
/// pattern generation (the same on every rank: MumpsDistributedInput::update), the values at every call.
class MumpsHostInput {
 public:
  /// Collective over `comm`. Afterwards view() is the whole matrix on rank 0 and empty on the others.
  void update(const MumpsMatrixView& local, MPI_Comm comm);

  MumpsMatrixView view() {
    return {n_, static_cast<MUMPS_INT8>(values_.size()), rows_.data(), cols_.data(), values_.data(), generation_};
  }

 private:
  long generation_ = -1;
  MUMPS_INT n_ = 0;
  int localEntries_ = 0;
  std::vector<int> counts_, offsets_;  ///< per rank, on rank 0: its number of entries, its first entry
  std::vector<MUMPS_INT> rows_, cols_;
  std::vector<double> values_;
};

/// The same matrix as MUMPS' symmetric input (SYM = 2: LDLᵀ, about half the operations of LU), on one
/// rank, when it is symmetric apart from decoupled rows. A decoupled row has every off-diagonal value
/// zero: the identity row of a prescribed DOF, which leaves the matrix unsymmetric because its column
/// keeps the stiffness. Its column is moved to the right-hand side (symmetric elimination), which is
/// exact: x_j = b_j / a_jj, and b_i −= a_ij x_j in every other row. Symmetric means
/// |a_ij − a_ji| ≤ kSymmetryTolerance · max(‖row i‖∞, ‖row j‖∞) for every other pair: round-off of
/// a symmetric tangent (hyperelastic solids, frictionless penalty contact: the second derivative of a
/// potential) passes by orders of magnitude, a Coulomb slip tangent (eq. 26) fails by orders.
/// MUMPS is given only the diagonal of a decoupled row and column: their other entries are zero after
/// the elimination, and left in the pattern they would be fill-in for the ordering and the symbolic
/// factorisation (the one-layer 3D tube, all u_z prescribed: 9.9·10^7 operations per factorisation with
/// them, bench/README.md, "Fill-reducing orderings"). The entries kept change, and MUMPS analyses anew,
/// only when the set of decoupled rows does.
class MumpsSymmetricInput {
 public:
  static constexpr double kSymmetryTolerance = 1e-10;

  /// Builds the lower triangle of `general` (all rows of the matrix, as on one rank) when its values
  /// are symmetric in the sense above; returns false when they are not. The pattern is built again when
  /// `general` has another pattern generation than the last call.
  bool update(const MumpsMatrixView& general);

  /// b −= the eliminated columns times their rows' solution values: call before the solve.
  void eliminateColumns(std::vector<double>& rhs) const;

  MumpsMatrixView view() {
    return {n_, static_cast<MUMPS_INT8>(values_.size()), rows_.data(), cols_.data(), values_.data(), generation_};
  }

 private:
  void buildPattern(const MumpsMatrixView& general);
  void keepCoupledEntries();  ///< kept_, rows_, cols_ for the present decoupled_; a new generation

  long generalGeneration_ = -1;  ///< the general input's pattern this one was built from
  long generation_ = 0;
  MUMPS_INT n_ = 0;
  std::vector<std::size_t> lower_;      ///< general entries with row ≥ column, in the order given to MUMPS
  std::vector<long> transposeOf_;       ///< per lower entry: the general entry (j, i), −1 when absent
  std::vector<MUMPS_INT> lowerRows_, lowerColumns_;  ///< 1-based, the whole lower triangle
  std::vector<double> lowerValues_;                  ///< per lower entry, after the elimination
  std::vector<std::size_t> kept_;                    ///< lower entries given to MUMPS
  std::vector<char> patternDecoupled_;               ///< decoupled_ when kept_ was chosen
  std::vector<MUMPS_INT> rows_, cols_;               ///< 1-based, the kept entries
  std::vector<double> values_;
  std::vector<double> diagonal_;        ///< a_jj of each row (0-based)
  std::vector<char> decoupled_;         ///< per row (0-based)
  struct EliminatedEntry {
    MUMPS_INT row, column;  ///< 0-based: a_row,column with `column` decoupled and `row` not
    double value;
  };
  std::vector<EliminatedEntry> eliminated_;
};

}  // namespace contessa::solvers
