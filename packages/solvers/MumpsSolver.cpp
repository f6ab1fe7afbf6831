#include "solvers/MumpsSolver.hpp"

#include <dmumps_c.h>
#include <mpi.h>

#include <algorithm>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <vector>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Thyra_LinearOpWithSolveBase.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_MultiVectorStdOps.hpp>

#include "common/PhaseTimers.hpp"
#include "model/TpetraTypes.hpp"
#include "solvers/MumpsInput.hpp"
#include "solvers/MumpsOrdering.hpp"

namespace contessa::solvers {

using Teuchos::RCP;
using Teuchos::rcp;
using namespace contessa::model;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>;

MumpsCounters& mumpsCounters() {
  static MumpsCounters counters;
  return counters;
}

namespace {

// MUMPS' control arrays are documented 1-based: ICNTL(k) is icntl[k-1] (likewise CNTL, INFOG).
constexpr int icntl(int k) { return k - 1; }
constexpr int cntl(int k) { return k - 1; }
constexpr int infog(int k) { return k - 1; }

constexpr int kDescribedNullVectors = 12;

// ICNTL(7) = 1: the ordering is the user's (PERM_IN); Contessa gives METIS' nested dissection.
constexpr int kGivenOrdering = 1;
constexpr int kAmd = 0;
// Not an ICNTL(7) code: analyse with AMD and with METIS, keep the order MUMPS estimates cheaper.
constexpr int kFewestOperations = -1;

struct MumpsSettings {
  int memoryRelaxation = 50;
  int ordering = 0;
  double nullPivotThreshold = 1e-11;
  bool verbose = false;
  bool exploitSymmetry = true;
  bool reproducible = false;
};

// One MUMPS instance of one symmetry: analysis once per pattern, factorization per matrix.
class MumpsContext {
 public:
  MumpsContext(MPI_Comm comm, bool symmetric, int memoryRelaxation, int ordering, double nullPivotThreshold,
               bool verbose, std::shared_ptr<MumpsFailures> failures)
      : comm_(comm), failures_(std::move(failures)), ordering_(ordering) {
    id_.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(comm));
    id_.par = 1;  // the host takes part in the factorization
    // General unsymmetric (LU; the slip tangent of eq. (26) is non-symmetric), or symmetric indefinite
    // (LDLᵀ, SYM = 2: a tangent stiffness need not be positive definite).
    id_.sym = symmetric ? 2 : 0;
    id_.job = -1;
    dmumps_c(&id_);
    if (!verbose) {
      id_.icntl[icntl(1)] = -1;
      id_.icntl[icntl(2)] = -1;
      id_.icntl[icntl(3)] = -1;
      id_.icntl[icntl(4)] = 0;
    }
    id_.icntl[icntl(5)] = 0;    // assembled matrix
    // Distributed entries, each rank giving its own rows; on one rank the same triplets as centralised
    // input, which spares MUMPS redistributing them at every factorisation (4 % of the tube's run).
    int ranks = 1;
    MPI_Comm_size(comm, &ranks);
    id_.icntl[icntl(18)] = ranks > 1 ? 3 : 0;
    id_.icntl[icntl(20)] = 0;   // dense right-hand side on the host
    id_.icntl[icntl(21)] = 0;   // centralised solution on the host
    id_.icntl[icntl(7)] = ordering;
    id_.icntl[icntl(14)] = memoryRelaxation;
    // A singular stiffness (a rigid-body mode: too few supports) must stop the solve, not return one of
    // infinitely many solutions: null pivot detection, a pivot row being null when its infinity norm is
    // below CNTL(3) · ||A_pre|| (A_pre the scaled, permuted matrix). The root node is factorised
    // sequentially (ICNTL(13) = 1), since ScaLAPACK there would factorise tiny pivots instead of
    // detecting them, differently on different rank counts.
    id_.icntl[icntl(24)] = 1;
    id_.icntl[icntl(13)] = 1;
    id_.cntl[cntl(3)] = nullPivotThreshold;
  }
  ~MumpsContext() {
    id_.job = -2;
    dmumps_c(&id_);
  }
  MumpsContext(const MumpsContext&) = delete;
  MumpsContext& operator=(const MumpsContext&) = delete;

  // Factorizes the matrix (each rank's triplets; collective). Returns false when MUMPS reports an error
  // (e.g. singular).
  bool factorize(const MumpsMatrixView& matrix) {
    id_.n = matrix.order;
    id_.nnz_loc = matrix.numEntries;  // distributed input: this rank's rows
    id_.irn_loc = matrix.rows;
    id_.jcn_loc = matrix.columns;
    id_.a_loc = matrix.values;
    id_.nnz = matrix.numEntries;  // centralised input (one rank): the same triplets, the whole matrix
    id_.irn = matrix.rows;
    id_.jcn = matrix.columns;
    id_.a = matrix.values;
    n_ = matrix.order;
    if (matrix.patternGeneration != analysedGeneration_) {  // the analysis (ordering, symbolic) once per pattern
      timers::Scope scope(timers::Phase::MumpsAnalysis);
      if (!analyse(matrix)) {
        analysedGeneration_ = -1;
        return false;
      }
      analysedGeneration_ = matrix.patternGeneration;
    }
    // Penalty contact makes pivoting unpredictable: on a workspace shortfall (INFOG(1) = -8/-9),
    // relax the memory estimate and try again.
    timers::Scope scope(timers::Phase::MumpsFactorization);
    for (int attempt = 0; attempt < 4; ++attempt) {
      id_.job = 2;
      dmumps_c(&id_);
      if (id_.infog[0] != -8 && id_.infog[0] != -9) break;
      id_.icntl[icntl(14)] *= 2;
    }
    const int nullPivots = id_.infog[0] >= 0 ? id_.infog[infog(28)] : 0;
    if (id_.infog[0] >= 0 && nullPivots == 0) return true;
    // INFOG(1) and INFOG(28) are global: every rank takes this branch.
    MumpsFailures& f = *failures_;
    ++f.count;
    f.info = id_.infog[0];
    f.nullPivots = nullPivots;
    f.nullSpace = nullPivots > 0 ? nullSpace(nullPivots) : std::vector<std::vector<double>>{};
    return false;
  }

  // The ordering and symbolic factorisation (JOB = 1) of the pattern set in id_. With kFewestOperations,
  // AMD's analysis and METIS' both, and the one with fewer estimated operations (RINFOG(1), the same on
  // every rank) analysed again if it was not the last: on 2D meshes and the one-layer 3D tube AMD needs
  // fewer, on 3D bulk meshes METIS 2.7 times fewer at 1.5·10^4 unknowns (bench/README.md, "Fill-reducing
  // orderings" under issue 23); an extra analysis costs a fraction of one factorisation.
  bool analyse(const MumpsMatrixView& matrix) {
    if (ordering_ == kGivenOrdering) giveNestedDissectionOrder(matrix);
    if (ordering_ != kFewestOperations) return runAnalysis();
    useOrdering(kAmd);
    if (!runAnalysis()) return false;
    const double amdOperations = id_.rinfog[0];
    giveNestedDissectionOrder(matrix);
    if (id_.icntl[icntl(7)] != kGivenOrdering) return runAnalysis();  // METIS gave none: AMD again
    if (!runAnalysis()) return false;
    if (id_.rinfog[0] <= amdOperations) return true;
    useOrdering(kAmd);
    return runAnalysis();
  }

  bool runAnalysis() {
    id_.job = 1;
    dmumps_c(&id_);
    return id_.infog[0] >= 0;
  }

  void useOrdering(int code) {
    id_.icntl[icntl(7)] = code;
    id_.perm_in = nullptr;
  }

  // METIS' order of this pattern as PERM_IN on the host, for a sequential analysis (ICNTL(28) = 1:
  // MUMPS reads PERM_IN only there; with distributed input it gathers the pattern on the host itself).
  // Where METIS gives none (no off-diagonal entry), AMD.
  void giveNestedDissectionOrder(const MumpsMatrixView& matrix) {
    givenOrder_ = nestedDissectionOrder(matrix, comm_);
    int given = givenOrder_.empty() ? 0 : 1;
    MPI_Bcast(&given, 1, MPI_INT, 0, comm_);
    id_.icntl[icntl(28)] = 1;
    id_.icntl[icntl(7)] = given ? kGivenOrdering : 0;
    id_.perm_in = givenOrder_.empty() ? nullptr : givenOrder_.data();
  }

  // Solves in place: `rhs` holds the right-hand side on the host on entry, the solution on exit.
  bool solve(std::vector<double>& rhs) {
    id_.job = 3;
    id_.nrhs = 1;
    id_.lrhs = static_cast<MUMPS_INT>(n_);
    id_.rhs = rhs.empty() ? nullptr : rhs.data();
    dmumps_c(&id_);
    return id_.infog[0] >= 0;
  }

  // The first vectors of the null space basis of the last factorization (ICNTL(25) = i), on every rank.
  // At most kDescribedNullVectors: enough for every rigid-body mode of a 3D body, and bounded memory
  // when a broken mesh has thousands of null pivots.
  std::vector<std::vector<double>> nullSpace(int count) {
    int rank = 0;
    MPI_Comm_rank(comm_, &rank);
    std::vector<std::vector<double>> basis;
    for (int i = 1; i <= std::min(count, kDescribedNullVectors); ++i) {
      std::vector<double> v(rank == 0 ? static_cast<std::size_t>(n_) : 0);
      id_.job = 3;
      id_.icntl[icntl(25)] = i;
      id_.nrhs = 1;
      id_.lrhs = static_cast<MUMPS_INT>(n_);
      id_.rhs = v.empty() ? nullptr : v.data();
      dmumps_c(&id_);
      id_.icntl[icntl(25)] = 0;
      if (id_.infog[0] < 0) break;  // global: every rank stops here
      v.resize(static_cast<std::size_t>(n_));
      MPI_Bcast(v.data(), static_cast<int>(v.size()), MPI_DOUBLE, 0, comm_);
      basis.push_back(std::move(v));
    }
    return basis;
  }

 private:
  MPI_Comm comm_;
  std::shared_ptr<MumpsFailures> failures_;
  DMUMPS_STRUC_C id_{};
  GO n_ = 0;
  long analysedGeneration_ = -1;
  int ordering_ = 0;                   // ICNTL(7) asked for, or kFewestOperations
  std::vector<MUMPS_INT> givenOrder_;  // PERM_IN of the last METIS order (rank 0 of comm_)
};

class MumpsLinearOpWithSolve : public Thyra::LinearOpWithSolveBase<double> {
 public:
  void initialize(const RCP<const Thyra::LinearOpSourceBase<double>>& src, const MumpsSettings& settings,
                  const std::shared_ptr<MumpsFailures>& failures) {
    src_ = src;
    op_ = src->getOp();
    auto A = Teuchos::rcp_dynamic_cast<const CrsMatrix>(Extract::getConstTpetraOperator(op_), true);
    if (comm_ == MPI_COMM_NULL) {
      auto mpiComm = Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(A->getComm(), true);
      comm_ = (*mpiComm->getRawMpiComm())();
      settings_ = settings;
      failures_ = failures;
      // LDLᵀ only on one rank: there every row is at hand to check the symmetry and move the prescribed
      // columns to the right-hand side (docs/architecture.md, MUMPS).
      exploitSymmetry_ = settings.exploitSymmetry && A->getComm()->getSize() == 1;
      // Reproducible on several ranks: MUMPS runs on rank 0 alone (MumpsHostInput says why).
      onHostAlone_ = settings.reproducible && A->getComm()->getSize() > 1;
      rank_ = A->getComm()->getRank();
      const GO n = static_cast<GO>(A->getGlobalNumRows());
      TEUCHOS_TEST_FOR_EXCEPTION(A->getRowMap()->getMaxAllGlobalIndex() != n - 1 || A->getRowMap()->getMinAllGlobalIndex() != 0,
                                 std::logic_error, "MUMPS solver: row ids must be 0 .. n-1");
      // The host holds the whole right-hand side: an import to a map with every row on rank 0.
      const int rank = A->getComm()->getRank();
      std::vector<GO> all;
      if (rank == 0) {
        all.resize(n);
        for (GO i = 0; i < n; ++i) all[i] = i;
      }
      hostMap_ = rcp(new Map(n, Teuchos::ArrayView<const GO>(all), 0, A->getComm()));
      toHost_ = rcp(new Import(A->getRowMap(), hostMap_));
      fromHost_ = rcp(new Import(hostMap_, A->getRowMap()));
    }
    std::optional<timers::Scope> inputScope(std::in_place, timers::Phase::MumpsInput);
    input_.update(*A, comm_);
    // The last factors serve a matrix equal to the one they came from (MumpsUnchangedMatrix).
    if (factorized_ && lastFactorized_.matches(input_.view(), comm_)) {
      ++mumpsCounters().reusedFactorizations;
      return;
    }
    lastFactorized_.remember(input_.view());
    if (onHostAlone_) hostInput_.update(input_.view(), comm_);
    const MumpsMatrixView general = onHostAlone_ ? hostInput_.view() : input_.view();
    symmetricNow_ = exploitSymmetry_ && symmetricInput_.update(general);
    inputScope.reset();
    factorize(general);
    if (!factorized_) lastFactorized_.forget();
  }

  // Factorises `general` (symmetric or not, on every rank or on rank 0 alone); sets factorized_ alike on
  // every rank.
  void factorize(const MumpsMatrixView& general) {
    ++mumpsCounters().factorizations;
    if (symmetricNow_) ++mumpsCounters().symmetricFactorizations;
    if (symmetricNow_) {
      factorizeSymmetric();
      return;
    }
    if (!onHostAlone_) {
      factorized_ = context(false).factorize(general);
      return;
    }
    // MUMPS on rank 0 alone: its verdict, and what a failure found, to every rank.
    int factorized = rank_ == 0 ? static_cast<int>(context(false).factorize(general)) : 0;
    MPI_Bcast(&factorized, 1, MPI_INT, 0, comm_);
    factorized_ = factorized != 0;
    if (!factorized_) broadcastFailures(static_cast<int>(general.order));
  }
  void uninitialize() {
    src_ = Teuchos::null;
    op_ = Teuchos::null;
  }
  RCP<const Thyra::LinearOpSourceBase<double>> source() const { return src_; }

  RCP<const Thyra::VectorSpaceBase<double>> range() const override { return op_->range(); }
  RCP<const Thyra::VectorSpaceBase<double>> domain() const override { return op_->domain(); }

 protected:
  bool opSupportedImpl(Thyra::EOpTransp t) const override { return Thyra::opSupported(*op_, t); }
  void applyImpl(const Thyra::EOpTransp t, const Thyra::MultiVectorBase<double>& X,
                 const Teuchos::Ptr<Thyra::MultiVectorBase<double>>& Y, const double alpha,
                 const double beta) const override {
    Thyra::apply(*op_, t, X, Y, alpha, beta);
  }
  bool solveSupportsImpl(Thyra::EOpTransp t) const override { return t == Thyra::NOTRANS; }
  bool solveSupportsSolveMeasureTypeImpl(Thyra::EOpTransp t, const Thyra::SolveMeasureType&) const override {
    return t == Thyra::NOTRANS;
  }
  Thyra::SolveStatus<double> solveImpl(const Thyra::EOpTransp, const Thyra::MultiVectorBase<double>& B,
                                       const Teuchos::Ptr<Thyra::MultiVectorBase<double>>& X,
                                       const Teuchos::Ptr<const Thyra::SolveCriteria<double>>) const override {
    Thyra::SolveStatus<double> status;
    status.solveStatus = Thyra::SOLVE_STATUS_UNCONVERGED;
    // No solution exists (or infinitely many): throw, so that no caller can use a direction that was
    // never computed (NOX "rescues" unconverged solves, and a zero update would pass its update test).
    // NOX catches it and fails the solve; the failure is in MumpsFailures for the message.
    if (!factorized_) throw std::runtime_error("MUMPS: the factorization failed (singular matrix, or a MUMPS error)");
    timers::Scope scope(timers::Phase::MumpsSolve);
    auto b = Extract::getConstTpetraMultiVector(Teuchos::rcpFromRef(B));
    auto x = Extract::getTpetraMultiVector(Teuchos::rcpFromPtr(X));
    MultiVector host(hostMap_, 1);
    bool ok = true;
    for (std::size_t j = 0; j < b->getNumVectors(); ++j) {
      host.doImport(*b->getVector(j), *toHost_, Tpetra::INSERT);
      std::vector<double> rhs;
      {
        auto hv = host.getData(0);
        rhs.assign(hv.begin(), hv.end());
      }
      ++mumpsCounters().solves;
      if (symmetricNow_) {
        std::vector<double> reduced;
        symmetricInput_.reduce(rhs, reduced);
        if (!reduced.empty()) ok = context(true).solve(reduced) && ok;
        symmetricInput_.expand(reduced, rhs);
      } else if (onHostAlone_) {
        int solved = rank_ == 0 ? static_cast<int>(context(false).solve(rhs)) : 0;
        MPI_Bcast(&solved, 1, MPI_INT, 0, comm_);
        ok = solved != 0 && ok;
      } else {
        ok = context(false).solve(rhs) && ok;
      }
      {
        auto hv = host.getDataNonConst(0);
        std::copy(rhs.begin(), rhs.end(), hv.begin());
      }
      x->getVectorNonConst(j)->doImport(host, *fromHost_, Tpetra::INSERT);
    }
    if (ok) {
      status.solveStatus = Thyra::SOLVE_STATUS_CONVERGED;
      status.achievedTol = 0.0;
    } else {
      status.message = "MUMPS solve failed";
    }
    return status;
  }

 private:
  // LDLᵀ of the coupled rows (MumpsSymmetricInput: one rank); a failure's null space over all rows.
  void factorizeSymmetric() {
    MumpsMatrixView coupled = symmetricInput_.view();
    if (coupled.order == 0) {  // every row decoupled (prescribed): nothing for MUMPS
      factorized_ = true;
      return;
    }
    factorized_ = context(true).factorize(coupled);
    if (!factorized_)
      for (auto& v : failures_->nullSpace) v = symmetricInput_.expandNullVector(v);
  }

  // Rank 0's failure record (count, INFOG(1), null pivots, null space of `order` values) to every rank.
  void broadcastFailures(int order) const {
    MumpsFailures& f = *failures_;
    long header[4] = {f.count, f.info, f.nullPivots, static_cast<long>(f.nullSpace.size())};
    MPI_Bcast(header, 4, MPI_LONG, 0, comm_);
    f.count = header[0];
    f.info = static_cast<int>(header[1]);
    f.nullPivots = static_cast<int>(header[2]);
    f.nullSpace.resize(static_cast<std::size_t>(header[3]));
    for (auto& v : f.nullSpace) {
      v.resize(static_cast<std::size_t>(order));
      MPI_Bcast(v.data(), order, MPI_DOUBLE, 0, comm_);
    }
  }

  // The MUMPS instance of one symmetry, made at its first use (each keeps its own analysis); with
  // onHostAlone_, on rank 0 only, over that rank alone.
  MumpsContext& context(bool symmetric) const {
    auto& c = symmetric ? symmetricContext_ : generalContext_;
    if (c == nullptr)
      c = std::make_unique<MumpsContext>(onHostAlone_ ? MPI_COMM_SELF : comm_, symmetric, settings_.memoryRelaxation, settings_.ordering,
                                         settings_.nullPivotThreshold, settings_.verbose, failures_);
    return *c;
  }

  RCP<const Thyra::LinearOpSourceBase<double>> src_;
  RCP<const Thyra::LinearOpBase<double>> op_;
  MPI_Comm comm_ = MPI_COMM_NULL;
  MumpsSettings settings_;
  std::shared_ptr<MumpsFailures> failures_;
  bool exploitSymmetry_ = false, symmetricNow_ = false;
  bool onHostAlone_ = false;
  int rank_ = 0;
  MumpsDistributedInput input_;
  MumpsHostInput hostInput_;
  MumpsUnchangedMatrix lastFactorized_;
  mutable MumpsSymmetricInput symmetricInput_;
  mutable std::unique_ptr<MumpsContext> generalContext_, symmetricContext_;
  RCP<const Map> hostMap_;
  RCP<const Import> toHost_, fromHost_;
  bool factorized_ = false;
};

}  // namespace

namespace {
// The orderings every MUMPS build has (ICNTL(7) codes), METIS' given by Contessa, and the choice between
// AMD and METIS by MUMPS' operation estimate.
const std::map<std::string, int>& mumpsOrderings() {
  static const std::map<std::string, int> orderings = {{"Automatic", 7}, {"AMD", kAmd},         {"AMF", 2},
                                                       {"PORD", 4},      {"QAMD", 6},           {"METIS", kGivenOrdering},
                                                       {"Fewest Operations", kFewestOperations}};
  return orderings;
}
}  // namespace

MumpsLinearOpWithSolveFactory::MumpsLinearOpWithSolveFactory() = default;

bool MumpsLinearOpWithSolveFactory::isCompatible(const Thyra::LinearOpSourceBase<double>& fwdOpSrc) const {
  auto op = fwdOpSrc.getOp();
  return !Teuchos::rcp_dynamic_cast<const CrsMatrix>(Extract::getConstTpetraOperator(op), false).is_null();
}

RCP<Thyra::LinearOpWithSolveBase<double>> MumpsLinearOpWithSolveFactory::createOp() const {
  return rcp(new MumpsLinearOpWithSolve());
}

void MumpsLinearOpWithSolveFactory::initializeOp(const RCP<const Thyra::LinearOpSourceBase<double>>& fwdOpSrc,
                                                 Thyra::LinearOpWithSolveBase<double>* op,
                                                 const Thyra::ESupportSolveUse) const {
  auto params = params_.is_null() ? Teuchos::rcp(new Teuchos::ParameterList(*getValidParameters())) : params_;
  params->validateParametersAndSetDefaults(*getValidParameters());
  const std::string ordering = params->get<std::string>("Ordering");
  const int orderingCode = mumpsOrderings().at(ordering);
  MumpsSettings settings;
  settings.memoryRelaxation = params->get<int>("Memory Relaxation Percent");
  settings.ordering = orderingCode;
  settings.nullPivotThreshold = params->get<double>("Null Pivot Threshold");
  settings.verbose = params->get<bool>("Verbose");
  settings.exploitSymmetry = params->get<bool>("Exploit Symmetry");
  settings.reproducible = params->get<bool>("Reproducible");
  dynamic_cast<MumpsLinearOpWithSolve&>(*op).initialize(fwdOpSrc, settings, failures_);
}

void MumpsLinearOpWithSolveFactory::uninitializeOp(Thyra::LinearOpWithSolveBase<double>* op,
                                                   RCP<const Thyra::LinearOpSourceBase<double>>* fwdOpSrc,
                                                   RCP<const Thyra::PreconditionerBase<double>>* prec,
                                                   RCP<const Thyra::LinearOpSourceBase<double>>* approxFwdOpSrc,
                                                   Thyra::ESupportSolveUse* supportSolveUse) const {
  auto& lows = dynamic_cast<MumpsLinearOpWithSolve&>(*op);
  if (fwdOpSrc) *fwdOpSrc = lows.source();
  if (prec) *prec = Teuchos::null;
  if (approxFwdOpSrc) *approxFwdOpSrc = Teuchos::null;
  if (supportSolveUse) *supportSolveUse = Thyra::SUPPORT_SOLVE_UNSPECIFIED;
  lows.uninitialize();
}

void MumpsLinearOpWithSolveFactory::setParameterList(const RCP<Teuchos::ParameterList>& params) {
  params->validateParametersAndSetDefaults(*getValidParameters());
  params_ = Teuchos::rcp(new Teuchos::ParameterList(*params));
}

RCP<Teuchos::ParameterList> MumpsLinearOpWithSolveFactory::getNonconstParameterList() { return params_; }

RCP<Teuchos::ParameterList> MumpsLinearOpWithSolveFactory::unsetParameterList() {
  auto old = params_;
  params_ = Teuchos::null;
  return old;
}

RCP<const Teuchos::ParameterList> MumpsLinearOpWithSolveFactory::getValidParameters() const {
  static RCP<Teuchos::ParameterList> valid;
  if (valid.is_null()) {
    valid = rcp(new Teuchos::ParameterList("MUMPS"));
    Teuchos::Array<std::string> names;
    for (const auto& [name, code] : mumpsOrderings()) names.push_back(name);
    Teuchos::setStringToIntegralParameter<int>(
        "Ordering", "Fewest Operations",
        "Fill-reducing ordering (ICNTL(7)). Fewest Operations: analyse with AMD and with METIS and keep the one "
        "MUMPS estimates cheaper to factorise (AMD on 2D meshes, METIS on 3D ones; bench/README.md, Fill-reducing "
        "orderings). METIS: nested dissection from the METIS Contessa links (METIS_NodeND), given to MUMPS as its "
        "ordering; AMD, AMF, PORD, QAMD: MUMPS' own; Automatic: MUMPS' choice (AMF or PORD here: Debian's MUMPS is "
        "built without METIS and SCOTCH)",
        names(), valid.get());
    valid->set("Memory Relaxation Percent", 50, "Extra workspace over MUMPS' estimate, percent (ICNTL(14)); doubled on a shortfall");
    // Measured (docs/user-guide.md, Linear solver): the null pivot of a missing support is below 1e-15 on
    // the test decks; pivots of every regression deck, penalty contact included, stay above 1e-3; a
    // cantilever 1000 times longer than thick is flagged from 1e-6.
    valid->set("Null Pivot Threshold", 1e-11,
               "A pivot row is null (the matrix singular: a rigid-body mode) when its infinity norm is below this "
               "times that of the scaled matrix (CNTL(3), in (0, 1)); the solve then fails and names the free "
               "direction",
               rcp(new Teuchos::EnhancedNumberValidator<double>(std::numeric_limits<double>::min(), 1.0)));
    // Booleans also as the text "true"/"false", as --set gives a parameter the deck does not have.
    valid->set("Verbose", false, "Print MUMPS' own diagnostics", rcp(new Teuchos::BoolParameterEntryValidator));
    valid->set("Exploit Symmetry", true,
               "On one rank, factorise with LDLᵀ (MUMPS SYM = 2, about half the operations of LU) whenever the Jacobian "
               "is symmetric apart from the prescribed rows, checked at every factorisation (hyperelastic solids with "
               "frictionless contact are; a slipping Coulomb contact is not, and gets LU)",
               rcp(new Teuchos::BoolParameterEntryValidator));
    valid->set("Reproducible", false,
               "On more than one rank, gather the matrix on rank 0 and factorise and solve it there alone, so that "
               "two runs on the same number of ranks agree bit for bit (MUMPS on several ranks adds the ranks' "
               "contributions in the order its messages arrive: runs then differ in the last digits); costs the "
               "parallel factorisation's speed-up and rank 0 holds the whole factor. No effect on one rank",
               rcp(new Teuchos::BoolParameterEntryValidator));
  }
  return valid;
}

}  // namespace contessa::solvers
