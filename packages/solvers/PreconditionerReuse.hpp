#pragma once
// MueLu's set-up reused across Newton iterations and increments while the matrix graph stays the same.
//
// Thyra's MueLu factory reuses the hierarchy a preconditioner already holds when its "reuse: type" is set
// (MueLu's user guide, "Reuse"): with "RP" the aggregates and the prolongator P and restriction R of the
// first set-up are kept and only the coarse matrices R A P and the smoothers are rebuilt from each new
// Jacobian (with "RAP", Contessa's default, the coarse matrices are kept too: below); the aggregation and the prolongator smoothing are skipped (on the 3D
// punch at 1.5·10^4 unknowns: 21 % less CPU per run, 7 % more Krylov iterations; bench/README.md). Where
// the values change on an unchanged pattern an older P costs iterations, not accuracy: the Krylov
// iteration checks the true residual.
//
// When a re-set-up cannot work. MueLu then multiplies A P and R (A P) into the patterns of the first
// set-up's products, and Tpetra's sparse products (TpetraExt_MatrixMatrix_def.hpp, serial kernels) skip
// the entries of their left factor whose value is exactly zero: the first product's pattern holds only
// the entries that the then nonzero entries of A produce (R is kept, so its zeros stay zeros). A stored entry that was zero at the set-up and is nonzero later (a contact coupling
// reserved in the graph that closes, a coupling that is zero by symmetry on the undeformed mesh) makes
// the re-set-up throw ("Trying to insert a new entry ... into a static graph"), and a rebuilt graph (new
// couplings) does too. On two ranks only the rank that holds such an entry throws, and its fallback then
// runs collectives the other rank does not: MPI_ERR_TRUNCATE (issue 23). So the wrapper decides before
// MueLu runs, from data every rank has, and every rank decides alike (one reduction):
// - a new graph, or an entry that was zero at the last fresh set-up and is nonzero now, on any rank:
//   every rank starts over;
// - a coarse matrix A (levels 1 to the last but one: the coarsest is only factorised) that held exact
//   zeros at the fresh set-up (cancellations; its A P skipped them, and the coarse values of a later
//   Jacobian cannot be seen before MueLu computes them) is harmless when the kept A P already holds every
//   entry that A's stored pattern times P gives (checked by that product, once per fresh set-up);
//   otherwise the hierarchy is never re-set-up on more than one rank. On one rank MueLu's refusal is
//   caught instead and the hierarchy started over.
// - rows whose values changed between two set-ups on one graph (contact rows: a linear solid's other rows
//   never change) are "volatile": at a fresh set-up their exact zeros (off the diagonal) hold a tiny value
//   (kPatternFill) while MueLu runs, so that the products' patterns already hold every entry those rows
//   can fill in later, and a later fill-in there needs no new set-up. The zeros are restored before the
//   solve: the linear system is the Jacobian as assembled, and the tiny values change no sum of the set-up
//   (they are 10^-250 against entries of 10^-20 and more). On the 3D punch on 2 ranks, the pattern
//   restart at LOCA's predictor after the first increment (an edge row whose tangential couplings fill in)
//   is a reused set-up since (bench/README.md, "Issue 23, sixth round"). Rows that never changed keep their
//   zeros out of the products: filled in everywhere, the uniform mesh's structural zeros (couplings that
//   cancel between neighbouring elements) would make P and A P denser at every set-up.
// - the same matrix with the same values as at the last set-up (fresh or reused) on every rank: nothing is
//   redone, the hierarchy and its smoothers are those of these very values. LOCA's tangent predictor
//   asks for the Jacobian at the converged state, which equals the last Newton iteration's when the
//   contact set did not change and the solid is linear (the 3D punch: 3 of 8 set-ups). The values are
//   recognised by a 64-bit hash (valuesHash): a collision, were one to happen, would keep an older
//   preconditioner, which costs Krylov iterations and never accuracy.
// - with "reuse: type = RAP" (Contessa's default) MueLu keeps the coarse matrices and their smoothers at a
//   re-set-up and recomputes only the fine level's smoother from the new Jacobian: the products R A P, 70–85
//   % of an "RP" re-set-up (bench/README.md, "Issue 23, sixth round"), are skipped. That serves while the
//   Jacobian differs from the one the coarse matrices were computed from (the reference, held at each fresh
//   set-up) only in volatile rows held then, and there by at most kCoarseKeptRowChange times the row's
//   smaller diagonal, on every rank: the coarse correction is then that of a nearby matrix, which costs
//   Krylov iterations, never accuracy. A penalty that switches on or off (a change of many diagonals), or a
//   change in a row not held, starts the hierarchy over on every rank. MueLu's "reuse: type = full" keeps the
//   fine smoother too, whatever the change: it failed the punch's first increment (sixth round). With
//   "RP" given, the coarse matrices are recomputed at every re-set-up as before (bench/README.md, "Eighth
//   round").
#include <cstdint>
#include <map>
#include <vector>

#include <Thyra_PreconditionerFactoryBase.hpp>

#include "model/TpetraTypes.hpp"

namespace contessa::solvers {

/// The MueLu reuse Contessa sets unless the deck gives "reuse: type" (header; bench/README.md, "Eighth round").
inline constexpr const char* kMueLuReuseType = "RAP";

/// The value a volatile row's exact zeros hold while MueLu sets up (header): nonzero for Tpetra's products,
/// and below the rounding of any sum it enters.
inline constexpr double kPatternFill = 1e-250;

/// The largest change of a Jacobian entry since the last fresh set-up, relative to the smaller of its row's
/// two diagonals, under which "reuse: type = RAP" keeps the coarse levels (header; on the 3D punch the
/// contact rows change by 0.14–0.71 between Newton iterations and increments, a penalty switching on by
/// about 100; bench/README.md, "Eighth round").
inline constexpr double kCoarseKeptRowChange = 1.0;

/// The largest share of the matrix's rows that may have changed between set-ups (the volatile rows) for
/// Contessa's own choice of "reuse: type" to be "RAP" (GraphKeyedPreconditionerFactory): the 3D punch's
/// contact rows are 1.4 % of its rows at 2·10^5 unknowns, a nonlinear solid's changed rows all of them.
inline constexpr double kCoarseKeptRowFraction = 0.1;

/// How the set-ups of a run went (process-wide; every rank counts alike).
struct PreconditionerSetUpCounts {
  long reused = 0;           ///< re-set-ups of a kept hierarchy (aggregates and P kept)
  long newGraph = 0;         ///< started over because the matrix graph was rebuilt
  long patternGrew = 0;      ///< started over because an entry zero at the set-up is nonzero now
  long coarseZeros = 0;      ///< started over: a coarse A's exact zeros were not covered (2+ ranks)
  long refused = 0;          ///< re-set-ups MueLu refused (one rank only), then started over
  long unchanged = 0;        ///< set-ups skipped: the matrix and its values as at the last set-up
  long largeChange = 0;      ///< started over: coarse levels kept ("RAP") and a row changed by more than allowed
};

/// The values of some local rows of a matrix and the hashes of all its rows (the coarse levels' reference,
/// header), and the largest change since, relative to each changed row's diagonal.
struct RowValues {
  std::vector<std::uint64_t> rowHashes;
  std::vector<std::size_t> rowOffset;  ///< per local row, where its values start in `values`; kNotHeld if not held
  std::vector<double> values;
  static constexpr std::size_t kNotHeld = static_cast<std::size_t>(-1);

  /// Holds `matrix`'s flagged rows (`rows`, one flag per local row) and the hashes `rowHashes` of all its rows.
  void hold(const model::CrsMatrix& matrix, const std::vector<char>& rows, std::vector<std::uint64_t> hashes);
  /// The largest |a_ij - held a_ij| / min(|a_ii|, |held a_ii|) over the rows whose hash in `now` differs from the held one;
  /// infinity where such a row is not held, its diagonal is zero, or the hashes are of another graph.
  double largestChange(const model::CrsMatrix& matrix, const std::vector<std::uint64_t>& now) const;
};

/// `inner` (MueLu's factory) that keeps a preconditioner's hierarchy while the Jacobians share its graph
/// and the nonzero entries of its set-up, and starts it over otherwise (header). Everything else passes
/// through. initializePrec is collective over the matrix's communicator.
class GraphKeyedPreconditionerFactory : public Thyra::PreconditionerFactoryBase<double> {
 public:
  using Factory = Thyra::PreconditionerFactoryBase<double>;
  using Source = Thyra::LinearOpSourceBase<double>;
  /// With `chooseReuseType` (the deck gave no "reuse: type"), each fresh set-up sets the inner factory's
  /// "reuse: type" itself: "RAP" while the rows that changed between set-ups are at most
  /// kCoarseKeptRowFraction of the matrix (contact rows), "RP" otherwise (a nonlinear solid, whose every
  /// row changes: its coarse levels would never be kept, and each Jacobian would start over).
  explicit GraphKeyedPreconditionerFactory(Teuchos::RCP<Factory> inner, bool chooseReuseType = false)
      : inner_(std::move(inner)), chooseReuseType_(chooseReuseType) {}
  const Teuchos::RCP<Factory>& inner() const { return inner_; }

  static PreconditionerSetUpCounts& counts();
  /// Set-ups started over because a preconditioner met another graph than its last (a rebuild).
  static long& freshSetUps() { return counts().newGraph; }
  /// Re-set-ups MueLu refused (one rank), each followed by a fresh set-up.
  static long& refusedReuses() { return counts().refused; }

  bool isCompatible(const Source& src) const override { return inner_->isCompatible(src); }
  Teuchos::RCP<Thyra::PreconditionerBase<double>> createPrec() const override { return inner_->createPrec(); }
  void initializePrec(const Teuchos::RCP<const Source>& src, Thyra::PreconditionerBase<double>* prec,
                      const Thyra::ESupportSolveUse use) const override;
  void uninitializePrec(Thyra::PreconditionerBase<double>* prec, Teuchos::RCP<const Source>* src,
                        Thyra::ESupportSolveUse* use) const override;
  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& params) override { inner_->setParameterList(params); }
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override { return inner_->getNonconstParameterList(); }
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override { return inner_->unsetParameterList(); }
  Teuchos::RCP<const Teuchos::ParameterList> getParameterList() const override { return inner_->getParameterList(); }
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override { return inner_->getValidParameters(); }
  std::string description() const override { return inner_->description(); }

 private:
  // What a preconditioner was last set up from afresh.
  struct SetUp {
    Teuchos::RCP<const model::CrsGraph> graph;  // held, so that a freed graph's address cannot pass for it
    std::vector<std::size_t> zeroEntries;       // local positions of the stored entries that were exactly 0
                                                // and not filled for the set-up (outside volatile rows)
    std::vector<std::uint64_t> rowHashes;       // each local row's values at the last set-up, fresh or reused
    std::vector<char> volatileRows;             // local rows whose values changed between set-ups on this graph
    bool coarseZeros = false;                   // a coarse matrix of the hierarchy held exact zeros
    bool keepsCoarse = false;                   // set up with "reuse: type" = "RAP": coarse levels kept
    // The matrix and the hash of its values at the last set-up, fresh or reused.
    Teuchos::RCP<const model::CrsMatrix> matrix;
    std::uint64_t valuesHash = 0;
    // The reference: the Jacobian the coarse matrices were last computed from, its row hashes and the
    // values of its volatile rows (the only rows whose later change is measured, header).
    RowValues reference;
  };
  enum class Decision { Unchanged, Reuse, LargeChange, CoarseZeros, PatternGrew, NewGraph };  // ranks take the largest
  Decision decide(const Teuchos::RCP<const model::CrsMatrix>& matrix, std::uint64_t hash,
                  const std::vector<std::uint64_t>& rowHashes, const SetUp& last) const;
  void startOver(const Teuchos::RCP<const Source>& src, Thyra::PreconditionerBase<double>* prec,
                 Thyra::ESupportSolveUse use, const model::CrsMatrix* matrix, SetUp& record,
                 const std::vector<std::uint64_t>& rowHashes) const;
  // Whether MueLu's next hierarchy keeps its coarse levels at a re-set-up ("reuse: type" = "RAP"), after
  // choosing the type from the volatile rows where the factory chooses it (constructor). Collective.
  bool keepsCoarseLevels(const model::CrsMatrix* matrix, const std::vector<char>& volatileRows) const;

  Teuchos::RCP<Factory> inner_;
  bool chooseReuseType_ = false;
  mutable std::map<const Thyra::PreconditionerBase<double>*, SetUp> setUps_;
};

/// The local positions of `matrix`'s stored entries whose value is exactly zero; with `skipRows` (one flag
/// per local row), those outside the flagged rows only.
std::vector<std::size_t> zeroEntryPositions(const model::CrsMatrix& matrix, const std::vector<char>& skipRows = {});

/// A 64-bit hash of each local row's stored values.
std::vector<std::uint64_t> rowValueHashes(const model::CrsMatrix& matrix);

/// Flags in `rows` (sized to `now` when empty) the rows whose hash differs between `before` and `now`;
/// nothing when the two differ in length (another graph).
void flagChangedRows(const std::vector<std::uint64_t>& before, const std::vector<std::uint64_t>& now,
                     std::vector<char>& rows);

/// Writes `fill` into the exact zeros off the diagonal of the flagged local rows of `matrix` for its lifetime
/// and the zeros back at its end (header: a volatile row's couplings in MueLu's product patterns).
class ZerosFilledInRows {
 public:
  ZerosFilledInRows(const model::CrsMatrix& matrix, const std::vector<char>& rows, double fill);
  ~ZerosFilledInRows();
  ZerosFilledInRows(const ZerosFilledInRows&) = delete;
  ZerosFilledInRows& operator=(const ZerosFilledInRows&) = delete;
  std::size_t count() const { return filled_.size(); }

 private:
  model::CrsMatrix::local_matrix_host_type::values_type values_;
  std::vector<std::size_t> filled_;
};

/// A 64-bit hash of `matrix`'s stored values on this rank (their bits, in storage order).
std::uint64_t valuesHash(const model::CrsMatrix& matrix);

/// Whether any of `positions` (from zeroEntryPositions on a matrix of the same graph) holds a nonzero now.
bool anyFilledIn(const model::CrsMatrix& matrix, const std::vector<std::size_t>& positions);

}  // namespace contessa::solvers
