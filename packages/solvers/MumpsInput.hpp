#pragma once
// MUMPS' assembled input of a Tpetra CrsMatrix: each rank gives its own rows as (row, column, value)
// triplets with global 1-based indices (distributed input, ICNTL(18) = 3; on one rank the same triplets
// are the centralised input, ICNTL(18) = 0). The pattern depends only on the
// matrix graph, which changes only when the model rebuilds it (contact beyond its reserved couplings: a
// new graph object, and a matrix on it), so it is built once per graph, recognised by identity; the
// values are the matrix's own, in the graph's order (not copied: no index lookup, no pattern comparison).
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

  /// The values are `A`'s own storage (MUMPS and the other inputs only read them): valid until `A`'s
  /// values change, i.e. for the factorisation that follows update().
  MumpsMatrixView view() {
    return {n_, static_cast<MUMPS_INT8>(numValues_), rows_.data(), cols_.data(), values_, generation_};
  }

 private:
  Teuchos::RCP<const model::CrsGraph> graph_;  // held, so that no other graph can take its address
  MUMPS_INT n_ = 0;
  long generation_ = 0;
  std::vector<MUMPS_INT> rows_, cols_;
  double* values_ = nullptr;  ///< `A`'s values at the last update (MUMPS' C interface takes them non-const)
  std::size_t numValues_ = 0;
};

/// Whether a matrix is, bit for bit, the one of the last factorisation, so that its factors still
/// serve. LOCA's tangent predictor asks for the Jacobian at the converged state, which is the last
/// Newton iteration's whenever the contact set did not change in that iteration and the solid is linear
/// (the punch: 3 of its 7 Jacobians; bench/README.md, "Issue 23, fifth round"); a factorisation costs
/// 10^2 to 10^4 times the comparison. Holds a copy of the values (8 bytes per stored entry).
class MumpsUnchangedMatrix {
 public:
  /// Collective over `comm`: true on every rank when every rank's `local` has the pattern generation and
  /// the values remembered last.
  bool matches(const MumpsMatrixView& local, MPI_Comm comm) const;
  /// Remembers `local`'s pattern generation and values (before it is factorised).
  void remember(const MumpsMatrixView& local);
  /// Forgets them (a failed factorisation: nothing to reuse).
  void forget() { generation_ = -1; }

 private:
  long generation_ = -1;
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
/// MUMPS is given the coupled rows only, renumbered 1 .. m in their order: a decoupled row left in
/// its matrix, even as its diagonal alone, is a tree of its own in MUMPS' elimination forest, and
/// MUMPS' cost per tree node (arrowheads, front assembly, the solve's per-node work) made the 2 856
/// prescribed u_z of the one-layer 3D tube a third of every factorisation and solve (bench/README.md,
/// "Issue 23, fourth round"); their couplings, left in the pattern, were fill-in for the ordering
/// (9.9·10^7 operations per factorisation with them, "Fill-reducing orderings"). The entries kept
/// change, and MUMPS analyses anew, only when the set of decoupled rows does.
class MumpsSymmetricInput {
 public:
  static constexpr double kSymmetryTolerance = 1e-10;

  /// Builds the lower triangle of `general` (all rows of the matrix, as on one rank) when its values
  /// are symmetric in the sense above; returns false when they are not. The pattern is built again when
  /// `general` has another pattern generation than the last call.
  bool update(const MumpsMatrixView& general);

  /// The right-hand side of the coupled rows (what MUMPS solves for, in its numbering) from the whole
  /// `rhs`, the eliminated columns moved into it: b_i − Σ_j a_ij b_j / a_jj over decoupled j.
  void reduce(const std::vector<double>& rhs, std::vector<double>& reduced) const;
  /// The whole solution: the coupled rows from MUMPS' `reduced` solution, x_j = b_j / a_jj for the
  /// decoupled ones (`rhs` holds b on entry, x on exit).
  void expand(const std::vector<double>& reduced, std::vector<double>& rhs) const;
  /// A vector over MUMPS' rows (a null space vector) over all rows, zero in the decoupled ones.
  std::vector<double> expandNullVector(const std::vector<double>& reduced) const;

  /// The coupled rows' lower triangle in MUMPS' numbering (order m: the coupled rows; 0 when every row
  /// is decoupled, and MUMPS is then not needed).
  MumpsMatrixView view() {
    return {coupledOrder_, static_cast<MUMPS_INT8>(values_.size()), rows_.data(), cols_.data(), values_.data(),
            generation_};
  }

 private:
  /// What the lower entries become for the present decoupled rows (planEntries), one list per role so
  /// that the per-call loops do not branch on it: a coupled row's diagonal (given to MUMPS), the pair
  /// a_ij, a_ji of two coupled rows (checked, their mean given to MUMPS), an entry of a coupled row in a
  /// decoupled column (moved to the right-hand side); entries between decoupled rows are left out.
  struct DiagonalEntry {
    long entry;        ///< the general entry
    std::size_t slot;  ///< in values_
  };
  struct PairEntry {
    long a, b;         ///< the general entries a_ij, a_ji (i > j), −1 for a zero
    MUMPS_INT i, j;    ///< 0-based rows
    std::size_t slot;  ///< in values_
  };
  struct EliminatedSource {
    long entry;  ///< the general entry, −1 for a zero
  };
  void buildPattern(const MumpsMatrixView& general);
  void measureRows(const MumpsMatrixView& general);  ///< rowNorm_, diagonal_, decoupled_
  /// The lists per role, the kept entries (rows_, cols_) and eliminated_ for the present decoupled_; a
  /// new generation.
  void planEntries();

  long generalGeneration_ = -1;  ///< the general input's pattern this one was built from
  long generation_ = 0;
  MUMPS_INT n_ = 0;
  /// Per lower entry (general entries with row ≥ column, and upper entries without a lower partner):
  /// where its a_ij (i > j, i = lowerRows_) and a_ji are among the general entries, −1 for a zero.
  std::vector<long> entryA_, entryB_;
  std::vector<MUMPS_INT> lowerRows_, lowerColumns_;  ///< 1-based, the whole lower triangle
  std::vector<DiagonalEntry> diagonalEntries_;
  std::vector<PairEntry> pairEntries_;
  std::vector<EliminatedSource> eliminatedSources_;  ///< per eliminated_ entry
  std::vector<char> patternDecoupled_;               ///< decoupled_ when the roles were chosen
  MUMPS_INT coupledOrder_ = 0;                      ///< m: the rows given to MUMPS
  std::vector<MUMPS_INT> coupledRows_;               ///< per MUMPS row (0-based): its row (0-based)
  std::vector<MUMPS_INT> rows_, cols_;               ///< 1-based in MUMPS' numbering, the kept entries
  std::vector<double> values_;
  /// The general input's runs of one row's entries (each row's entries come together), and where
  /// each run's diagonal entries are (in diagonalPositions_[diagonalBegin, diagonalEnd)): measureRows
  /// then reads the values without comparing indices (buildPattern).
  struct RowRun {
    std::size_t row, begin, end, diagonalBegin, diagonalEnd;
  };
  std::vector<RowRun> runs_;
  std::vector<std::size_t> diagonalPositions_;
  std::vector<double> rowNorm_;         ///< ‖row i‖∞ (0-based)
  std::vector<double> diagonal_;        ///< a_jj of each row (0-based)
  std::vector<char> offDiagonal_;       ///< per row: some off-diagonal value is not zero
  std::vector<char> decoupled_;         ///< per row (0-based)
  struct EliminatedEntry {
    MUMPS_INT row, column;  ///< 0-based: a_row,column with `column` decoupled and `row` not
    double value;
  };
  std::vector<EliminatedEntry> eliminated_;
};

}  // namespace contessa::solvers
