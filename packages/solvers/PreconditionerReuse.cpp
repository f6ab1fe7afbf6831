#include "solvers/PreconditionerReuse.hpp"

#include <cmath>
#include <cstring>
#include <limits>

#include <MueLu_Factory.hpp>
#include <MueLu_FactoryManagerBase.hpp>
#include <MueLu_Hierarchy.hpp>
#include <MueLu_Level.hpp>
#include <MueLu_XpetraOperator.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_TimeMonitor.hpp>
#include <Thyra_DefaultPreconditioner.hpp>
#include <Thyra_TpetraLinearOp.hpp>
#include <Thyra_XpetraLinearOp.hpp>
#include <Teuchos_oblackholestream.hpp>
#include <Xpetra_Matrix.hpp>
#include <Xpetra_MatrixFactory.hpp>
#include <Xpetra_MatrixMatrix.hpp>

namespace contessa::solvers {
namespace {

using XpetraMatrix = Xpetra::Matrix<double, model::LO, model::GO, model::Node>;
using XpetraOperator = Xpetra::Operator<double, model::LO, model::GO, model::Node>;
using MueLuOperator = MueLu::XpetraOperator<double, model::LO, model::GO, model::Node>;
using ThyraXpetraOp = Thyra::XpetraLinearOp<double, model::LO, model::GO, model::Node>;

// The Tpetra matrix behind a Thyra operator; null for any other operator.
Teuchos::RCP<const model::CrsMatrix> matrixOf(const Thyra::LinearOpSourceBase<double>& src) {
  using TpetraOp = Thyra::TpetraLinearOp<double, model::LO, model::GO, model::Node>;
  const auto op = Teuchos::rcp_dynamic_cast<const TpetraOp>(src.getOp());
  if (op.is_null()) return Teuchos::null;
  return Teuchos::rcp_dynamic_cast<const model::CrsMatrix>(op->getConstTpetraOperator());
}

// Whether `flag` holds on any rank of `comm` (collective).
bool onAnyRank(bool flag, const Teuchos::Comm<int>& comm) {
  int local = flag ? 1 : 0, global = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &local, &global);
  return global != 0;
}

using Hierarchy = MueLu::Hierarchy<double, model::LO, model::GO, model::Node>;
using MatrixProduct = Xpetra::MatrixMatrix<double, model::LO, model::GO, model::Node>;
using MatrixFactory = Xpetra::MatrixFactory<double, model::LO, model::GO, model::Node>;

// The factory manager a level was set up with: Hierarchy keeps them for its re-set-ups but offers them to
// derived classes only, and a level forgets its own after the set-up. A member pointer formed through a
// derived class may be applied to any Hierarchy.
struct LevelManagers : Hierarchy {
  static auto getter() { return &LevelManagers::GetLevelManager; }
};

// Whether `A` holds a stored entry of value exactly zero on this rank.
bool holdsZeros(const XpetraMatrix& A) {
  Teuchos::ArrayView<const model::LO> columns;
  Teuchos::ArrayView<const double> values;
  for (std::size_t row = 0; row < A.getNodeNumRows(); ++row) {
    A.getLocalRowView(static_cast<model::LO>(row), columns, values);
    for (const double v : values)
      if (v == 0.0) return true;
  }
  return false;
}

// The product A P that MueLu's RAPFactory keeps on a coarse level for its re-set-ups ("AP reuse data"),
// found through the factories that make the level's A (RebalanceAc takes RAP's); null when there is none.
Teuchos::RCP<const XpetraMatrix> keptProductAP(MueLu::Level& level, const MueLu::FactoryManagerBase& manager) {
  Teuchos::RCP<const MueLu::FactoryBase> factory = manager.GetFactory("A");
  for (int depth = 0; depth < 4 && !factory.is_null(); ++depth) {
    if (level.IsAvailable("AP reuse data", factory.get())) {
      const auto data = level.Get<Teuchos::RCP<Teuchos::ParameterList>>("AP reuse data", factory.get());
      return data->isType<Teuchos::RCP<XpetraMatrix>>("graph") ? data->get<Teuchos::RCP<XpetraMatrix>>("graph") : Teuchos::null;
    }
    const auto* made = dynamic_cast<const MueLu::Factory*>(factory.get());
    factory = made == nullptr ? Teuchos::null : made->GetFactory("A");
  }
  return Teuchos::null;
}

// A level's matrix `name` on this rank; null where this rank holds no part of the level (a coarse level
// gathered onto other ranks) or it is not kept.
Teuchos::RCP<XpetraMatrix> levelMatrix(MueLu::Level& level, const std::string& name) {
  if (!level.IsAvailable(name)) return Teuchos::null;
  return Teuchos::rcp_dynamic_cast<XpetraMatrix>(level.Get<Teuchos::RCP<XpetraOperator>>(name));
}

// Whether the kept product `AP` holds every entry that A's stored pattern (zeros included) times P
// produces, on this rank: then a zero of A that fills in later lands inside the kept pattern. Collective
// over A's communicator (the ranks that hold the level).
bool keptProductCoversPattern(const XpetraMatrix& A, const XpetraMatrix& P, const XpetraMatrix& AP) {
  auto ones = MatrixFactory::Build(A.getCrsGraph());
  ones->setAllToScalar(1.0);
  ones->fillComplete(A.getDomainMap(), A.getRangeMap());
  Teuchos::FancyOStream quiet(Teuchos::rcp(new Teuchos::oblackholestream()));
  const auto full = MatrixProduct::Multiply(*ones, false, P, false, quiet);
  if (full->getNodeNumRows() != AP.getNodeNumRows()) return false;
  for (std::size_t row = 0; row < AP.getNodeNumRows(); ++row)
    if (full->getNumEntriesInLocalRow(static_cast<model::LO>(row)) != AP.getNumEntriesInLocalRow(static_cast<model::LO>(row)))
      return false;
  return true;
}

// The MueLu hierarchy a Thyra preconditioner holds; null for any other preconditioner.
Teuchos::RCP<Hierarchy> hierarchyOf(const Thyra::PreconditionerBase<double>& prec) {
  const auto* defaultPrec = dynamic_cast<const Thyra::DefaultPreconditioner<double>*>(&prec);
  const auto thyraOp = defaultPrec == nullptr ? Teuchos::null
                                              : Teuchos::rcp_dynamic_cast<const ThyraXpetraOp>(defaultPrec->getUnspecifiedPrecOp());
  const auto muelu = thyraOp.is_null() ? Teuchos::null
                                       : Teuchos::rcp_dynamic_cast<const MueLuOperator>(thyraOp->getConstXpetraOperator());
  return muelu.is_null() ? Teuchos::null : muelu->GetHierarchy();
}

// Whether a re-set-up of the MueLu hierarchy `prec` holds could meet a product pattern it cannot fill
// (header): a coarse A of levels 1 to the last but one (the coarsest is only factorised; R, the other left
// factor, is kept) holds exact zeros whose later fill-in would fall outside the kept A P. The same answer
// on every rank of `comm` (collective); false for a preconditioner that is no MueLu hierarchy.
bool coarseZerosMatter(const Thyra::PreconditionerBase<double>& prec, const Teuchos::Comm<int>& comm) {
  const auto hierarchy = hierarchyOf(prec);
  if (onAnyRank(hierarchy.is_null(), comm)) return false;
  // A rank left out of the coarse levels gathered onto others holds fewer levels: the count is the most
  // any rank holds. Every branch below is taken alike on every rank (the votes), so that the ranks holding
  // a level enter its product together; a rank that holds no part of a level votes "nothing to fear".
  const int local = hierarchy->GetNumLevels();
  int levels = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &local, &levels);
  for (int level = 1; level + 1 < levels; ++level) {
    const auto A = level < local ? levelMatrix(*hierarchy->GetLevel(level), "A") : Teuchos::null;
    if (!onAnyRank(!A.is_null() && holdsZeros(*A), comm)) continue;
    const bool holdsCoarse = !A.is_null() && level + 1 < local;
    const auto P = holdsCoarse ? levelMatrix(*hierarchy->GetLevel(level + 1), "P") : Teuchos::null;
    const auto AP = holdsCoarse ? keptProductAP(*hierarchy->GetLevel(level + 1), *((*hierarchy).*LevelManagers::getter())(level + 1))
                                : Teuchos::null;
    if (onAnyRank(!A.is_null() && (P.is_null() || AP.is_null()), comm)) return true;
    const bool covered = A.is_null() || keptProductCoversPattern(*A, *P, *AP);
    if (onAnyRank(!covered, comm)) return true;
  }
  return false;
}


// With the deck's MueLu "verbosity" at medium or above, MueLu times each of its factories in Teuchos timers
// named "MueLu: ..." (aggregation, prolongator smoothing, the products R A P, repartitioning, smoothers,
// the coarse factorisation) but prints only their total. Their sums over the run so far, least, mean and
// largest over the ranks, are printed after each set-up: the last table is the run's set-up phase by phase
// (bench/README.md, "Issue 23, sixth round"). Collective over `comm`.
bool mueLuTimersRequested(const Teuchos::ParameterList* muelu) {
  if (muelu == nullptr || !muelu->isType<std::string>("verbosity")) return false;
  const std::string level = muelu->get<std::string>("verbosity");
  return level == "medium" || level == "high" || level == "extreme" || level == "test";
}

void printMueLuTimers(const Teuchos::Comm<int>& comm) {
  Teuchos::TimeMonitor::summarize(Teuchos::ptrFromRef(comm), std::cout, false, true, false, Teuchos::Union, "MueLu: ", true);
}

}  // namespace

std::vector<std::size_t> zeroEntryPositions(const model::CrsMatrix& matrix, const std::vector<char>& skipRows) {
  std::vector<std::size_t> out;
  const auto local = matrix.getLocalMatrixHost();
  const auto& rowStart = local.graph.row_map;
  for (std::size_t row = 0; row + 1 < rowStart.extent(0); ++row) {
    if (row < skipRows.size() && skipRows[row]) continue;
    for (std::size_t k = rowStart(row); k < rowStart(row + 1); ++k)
      if (local.values(k) == 0.0) out.push_back(k);
  }
  return out;
}

std::vector<std::uint64_t> rowValueHashes(const model::CrsMatrix& matrix) {
  const auto local = matrix.getLocalMatrixHost();
  const auto& rowStart = local.graph.row_map;
  std::vector<std::uint64_t> out(rowStart.extent(0) > 0 ? rowStart.extent(0) - 1 : 0);
  for (std::size_t row = 0; row < out.size(); ++row) {
    std::uint64_t hash = 0xcbf29ce484222325ULL;  // FNV-1a over the values' bits
    for (std::size_t k = rowStart(row); k < rowStart(row + 1); ++k) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, &local.values(k), sizeof bits);
      hash = (hash ^ bits) * 0x100000001b3ULL;
    }
    out[row] = hash;
  }
  return out;
}

void flagChangedRows(const std::vector<std::uint64_t>& before, const std::vector<std::uint64_t>& now,
                     std::vector<char>& rows) {
  if (before.size() != now.size()) return;
  if (rows.size() != now.size()) rows.assign(now.size(), 0);
  for (std::size_t row = 0; row < now.size(); ++row)
    if (before[row] != now[row]) rows[row] = 1;
}

ZerosFilledInRows::ZerosFilledInRows(const model::CrsMatrix& matrix, const std::vector<char>& rows, double fill)
    : values_(matrix.getLocalMatrixHost().values) {
  const auto local = matrix.getLocalMatrixHost();
  const auto& rowStart = local.graph.row_map;
  const auto& columns = local.graph.entries;
  const auto& rowMap = *matrix.getRowMap();
  const auto& columnMap = *matrix.getColMap();
  for (std::size_t row = 0; row < rows.size() && row + 1 < rowStart.extent(0); ++row) {
    if (!rows[row]) continue;
    const model::GO globalRow = rowMap.getGlobalElement(static_cast<model::LO>(row));
    for (std::size_t k = rowStart(row); k < rowStart(row + 1); ++k)
      if (values_(k) == 0.0 && columnMap.getGlobalElement(columns(k)) != globalRow) {  // never a zero pivot made tiny
        values_(k) = fill;
        filled_.push_back(k);
      }
  }
}

ZerosFilledInRows::~ZerosFilledInRows() {
  for (const std::size_t k : filled_) values_(k) = 0.0;
}

std::uint64_t valuesHash(const model::CrsMatrix& matrix) {
  // Each value's bits mixed by splitmix64's finaliser into a running sum weighted by position, so that
  // moved and changed values alike change the hash.
  const auto values = matrix.getLocalMatrixHost().values;
  std::uint64_t hash = 0x9e3779b97f4a7c15ULL ^ values.extent(0);
  for (std::size_t k = 0; k < values.extent(0); ++k) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &values(k), sizeof bits);
    bits ^= k * 0x9e3779b97f4a7c15ULL;
    bits = (bits ^ (bits >> 30)) * 0xbf58476d1ce4e5b9ULL;
    bits = (bits ^ (bits >> 27)) * 0x94d049bb133111ebULL;
    hash = (hash ^ (bits ^ (bits >> 31))) * 0x100000001b3ULL;
  }
  return hash;
}

bool anyFilledIn(const model::CrsMatrix& matrix, const std::vector<std::size_t>& positions) {
  const auto values = matrix.getLocalMatrixHost().values;
  for (const std::size_t k : positions)
    if (k >= values.extent(0) || values(k) != 0.0) return true;
  return false;
}

void RowValues::hold(const model::CrsMatrix& matrix, const std::vector<char>& rows, std::vector<std::uint64_t> hashes) {
  rowHashes = std::move(hashes);
  rowOffset.assign(rowHashes.size(), kNotHeld);
  values.clear();
  const auto local = matrix.getLocalMatrixHost();
  const auto& rowStart = local.graph.row_map;
  for (std::size_t row = 0; row < rows.size() && row < rowOffset.size(); ++row) {
    if (!rows[row]) continue;
    rowOffset[row] = values.size();
    for (std::size_t k = rowStart(row); k < rowStart(row + 1); ++k) values.push_back(local.values(k));
  }
}

double RowValues::largestChange(const model::CrsMatrix& matrix, const std::vector<std::uint64_t>& now) const {
  constexpr double kUnknown = std::numeric_limits<double>::infinity();
  if (now.size() != rowHashes.size()) return kUnknown;
  const auto local = matrix.getLocalMatrixHost();
  const auto& rowStart = local.graph.row_map;
  const auto& columns = local.graph.entries;
  const auto& rowMap = *matrix.getRowMap();
  const auto& columnMap = *matrix.getColMap();
  double largest = 0.0;
  for (std::size_t row = 0; row < now.size(); ++row) {
    if (now[row] == rowHashes[row]) continue;
    if (rowOffset[row] == kNotHeld) return kUnknown;
    const model::GO globalRow = rowMap.getGlobalElement(static_cast<model::LO>(row));
    double diagonal = 0.0, change = 0.0;
    const double* held = values.data() + rowOffset[row];
    for (std::size_t k = rowStart(row); k < rowStart(row + 1); ++k) {
      const double before = held[k - rowStart(row)];
      // The smaller of the two diagonals: a penalty that switches on or off is a change of its own size.
      if (columnMap.getGlobalElement(columns(k)) == globalRow) diagonal = std::min(std::abs(local.values(k)), std::abs(before));
      change = std::max(change, std::abs(local.values(k) - before));
    }
    if (!(diagonal > 0.0)) return kUnknown;
    largest = std::max(largest, change / diagonal);
  }
  return largest;
}

bool GraphKeyedPreconditionerFactory::keepsCoarseLevels(const model::CrsMatrix* matrix,
                                                        const std::vector<char>& volatileRows) const {
  const auto params = inner_->getNonconstParameterList();
  if (params.is_null()) return false;
  if (chooseReuseType_ && matrix != nullptr) {
    double local[2] = {0.0, static_cast<double>(matrix->getNodeNumRows())}, total[2] = {0.0, 0.0};
    for (const char flag : volatileRows) local[0] += flag ? 1.0 : 0.0;
    Teuchos::reduceAll(*matrix->getComm(), Teuchos::REDUCE_SUM, 2, local, total);
    params->set("reuse: type", std::string(total[0] <= kCoarseKeptRowFraction * total[1] ? "RAP" : "RP"));
  }
  return params->isType<std::string>("reuse: type") && params->get<std::string>("reuse: type") == "RAP";
}

PreconditionerSetUpCounts& GraphKeyedPreconditionerFactory::counts() {
  static PreconditionerSetUpCounts c;
  return c;
}

GraphKeyedPreconditionerFactory::Decision GraphKeyedPreconditionerFactory::decide(
    const Teuchos::RCP<const model::CrsMatrix>& matrix, std::uint64_t hash, const std::vector<std::uint64_t>& rowHashes,
    const SetUp& last) const {
  // Each rank's reason, then the first reason any rank has (ranks agree on the graph: a rebuild is collective).
  int reason = static_cast<int>(Decision::Reuse);
  if (matrix.is_null() || last.graph.is_null() || last.graph.get() != matrix->getCrsGraph().get())
    reason = static_cast<int>(Decision::NewGraph);
  else if (anyFilledIn(*matrix, last.zeroEntries))
    reason = static_cast<int>(Decision::PatternGrew);
  else if (last.matrix.get() == matrix.get() && last.valuesHash == hash)
    reason = static_cast<int>(Decision::Unchanged);
  else if (last.coarseZeros)
    reason = static_cast<int>(Decision::CoarseZeros);
  else if (last.keepsCoarse && last.reference.largestChange(*matrix, rowHashes) > kCoarseKeptRowChange)
    reason = static_cast<int>(Decision::LargeChange);
  if (!matrix.is_null() && matrix->getComm()->getSize() > 1) {
    int any = 0;
    Teuchos::reduceAll(*matrix->getComm(), Teuchos::REDUCE_MAX, 1, &reason, &any);
    reason = any;
  } else if (reason == static_cast<int>(Decision::CoarseZeros)) {
    reason = static_cast<int>(Decision::Reuse);  // one rank: MueLu's refusal is caught and recovered alone (initializePrec)
  }
  return static_cast<Decision>(reason);
}

void GraphKeyedPreconditionerFactory::startOver(const Teuchos::RCP<const Source>& src,
                                                Thyra::PreconditionerBase<double>* prec, Thyra::ESupportSolveUse use,
                                                const model::CrsMatrix* matrix, SetUp& record,
                                                const std::vector<std::uint64_t>& rowHashes) const {
  // Volatile rows are known for the graph they were seen on only.
  std::vector<char> volatileRows;
  if (matrix != nullptr && record.graph.get() == matrix->getCrsGraph().get()) volatileRows = std::move(record.volatileRows);
  inner_->uninitializePrec(prec, nullptr, nullptr);
  if (matrix == nullptr) {
    inner_->initializePrec(src, prec, use);
    record = SetUp{};
    return;
  }
  const bool keepsCoarse = keepsCoarseLevels(matrix, volatileRows);
  {
    const ZerosFilledInRows filled(*matrix, volatileRows, kPatternFill);
    inner_->initializePrec(src, prec, use);
  }
  record = SetUp{};
  record.keepsCoarse = keepsCoarse;
  record.graph = matrix->getCrsGraph();
  record.zeroEntries = zeroEntryPositions(*matrix, volatileRows);
  record.volatileRows = std::move(volatileRows);
  record.reference.hold(*matrix, record.volatileRows, rowHashes);
  // A hierarchy that keeps its coarse levels multiplies nothing at a re-set-up: their zeros cannot matter.
  if (matrix->getComm()->getSize() > 1 && !keepsCoarse) record.coarseZeros = coarseZerosMatter(*prec, *matrix->getComm());
}

void GraphKeyedPreconditionerFactory::initializePrec(const Teuchos::RCP<const Source>& src,
                                                     Thyra::PreconditionerBase<double>* prec,
                                                     const Thyra::ESupportSolveUse use) const {
  const auto matrix = matrixOf(*src);
  const bool known = setUps_.count(prec) != 0;
  auto& record = setUps_[prec];
  const std::uint64_t hash = matrix.is_null() ? 0 : valuesHash(*matrix);
  std::vector<std::uint64_t> rowHashes;
  if (!matrix.is_null()) rowHashes = rowValueHashes(*matrix);
  const Decision decision = decide(matrix, hash, rowHashes, record);
  if (!matrix.is_null() && decision != Decision::Unchanged && decision != Decision::NewGraph)
    flagChangedRows(record.rowHashes, rowHashes, record.volatileRows);
  auto& c = counts();
  if (decision == Decision::Unchanged) {
    ++c.unchanged;
    return;
  }
  if (decision != Decision::Reuse) {
    // A preconditioner's first set-up is no restart.
    if (known && decision == Decision::NewGraph) ++c.newGraph;
    if (decision == Decision::PatternGrew) ++c.patternGrew;
    if (decision == Decision::CoarseZeros) ++c.coarseZeros;
    if (decision == Decision::LargeChange) ++c.largeChange;
    startOver(src, prec, use, matrix.get(), record, rowHashes);
  } else {
    try {
      record.matrix = Teuchos::null;  // until the re-set-up is done
      inner_->initializePrec(src, prec, use);
      ++c.reused;
    } catch (const std::exception&) {
      // One rank only (decide): e.g. an exact zero of a coarse matrix at the set-up that is nonzero now.
      ++c.refused;
      startOver(src, prec, use, matrix.get(), record, rowHashes);
    }
  }
  record.matrix = matrix;
  record.valuesHash = hash;
  record.rowHashes = std::move(rowHashes);
  if (!matrix.is_null() && mueLuTimersRequested(inner_->getParameterList().get())) printMueLuTimers(*matrix->getComm());
}

void GraphKeyedPreconditionerFactory::uninitializePrec(Thyra::PreconditionerBase<double>* prec,
                                                       Teuchos::RCP<const Source>* src,
                                                       Thyra::ESupportSolveUse* use) const {
  setUps_.erase(prec);
  inner_->uninitializePrec(prec, src, use);
}

}  // namespace contessa::solvers
