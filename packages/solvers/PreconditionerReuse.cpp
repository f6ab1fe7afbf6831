#include "solvers/PreconditionerReuse.hpp"

#include <MueLu_Hierarchy.hpp>
#include <MueLu_XpetraOperator.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Thyra_DefaultPreconditioner.hpp>
#include <Thyra_TpetraLinearOp.hpp>
#include <Thyra_XpetraLinearOp.hpp>
#include <Xpetra_Matrix.hpp>

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

// Whether a coarse matrix of the MueLu hierarchy `prec` holds that enters a product of the next
// re-set-up as its left factor has a stored entry of value exactly zero on this rank: the coarse A of
// levels 1 to the last but one (A P skips its zeros; the coarsest A is only factorised, and the other
// left factor, R in R (A P), is kept as it is). True too when such a matrix cannot be read (then reuse is
// not risked); false for a preconditioner that is no MueLu hierarchy (nothing coarse to check).
bool coarseLevelsHoldZeros(const Thyra::PreconditionerBase<double>& prec) {
  const auto* defaultPrec = dynamic_cast<const Thyra::DefaultPreconditioner<double>*>(&prec);
  if (defaultPrec == nullptr) return false;
  const auto thyraOp = Teuchos::rcp_dynamic_cast<const ThyraXpetraOp>(defaultPrec->getUnspecifiedPrecOp());
  if (thyraOp.is_null()) return false;
  const auto muelu = Teuchos::rcp_dynamic_cast<const MueLuOperator>(thyraOp->getConstXpetraOperator());
  if (muelu.is_null()) return false;
  const auto hierarchy = muelu->GetHierarchy();
  for (int level = 1; level + 1 < hierarchy->GetNumLevels(); ++level) {
    const auto data = hierarchy->GetLevel(level);
    if (!data->IsAvailable("A")) return true;
    const auto A = Teuchos::rcp_dynamic_cast<XpetraMatrix>(data->Get<Teuchos::RCP<XpetraOperator>>("A"));
    if (A.is_null()) return true;
    Teuchos::ArrayView<const model::LO> columns;
    Teuchos::ArrayView<const double> values;
    for (std::size_t row = 0; row < A->getNodeNumRows(); ++row) {
      A->getLocalRowView(static_cast<model::LO>(row), columns, values);
      for (const double v : values)
        if (v == 0.0) return true;
    }
  }
  return false;
}

// Whether `flag` holds on any rank of `comm` (collective).
bool onAnyRank(bool flag, const Teuchos::Comm<int>& comm) {
  int local = flag ? 1 : 0, global = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &local, &global);
  return global != 0;
}

}  // namespace

std::vector<std::size_t> zeroEntryPositions(const model::CrsMatrix& matrix) {
  std::vector<std::size_t> out;
  const auto values = matrix.getLocalMatrixHost().values;
  for (std::size_t k = 0; k < values.extent(0); ++k)
    if (values(k) == 0.0) out.push_back(k);
  return out;
}

bool anyFilledIn(const model::CrsMatrix& matrix, const std::vector<std::size_t>& positions) {
  const auto values = matrix.getLocalMatrixHost().values;
  for (const std::size_t k : positions)
    if (k >= values.extent(0) || values(k) != 0.0) return true;
  return false;
}

PreconditionerSetUpCounts& GraphKeyedPreconditionerFactory::counts() {
  static PreconditionerSetUpCounts c;
  return c;
}

GraphKeyedPreconditionerFactory::Decision GraphKeyedPreconditionerFactory::decide(const model::CrsMatrix* matrix,
                                                                                  const SetUp& last) const {
  // Each rank's reason, then the first reason any rank has (ranks agree on the graph: a rebuild is collective).
  int reason = 0;
  if (matrix == nullptr || last.graph.is_null() || last.graph.get() != matrix->getCrsGraph().get())
    reason = static_cast<int>(Decision::NewGraph);
  else if (anyFilledIn(*matrix, last.zeroEntries))
    reason = static_cast<int>(Decision::PatternGrew);
  else if (last.coarseZeros)
    reason = static_cast<int>(Decision::CoarseZeros);
  if (matrix != nullptr && matrix->getComm()->getSize() > 1) {
    int any = 0;
    Teuchos::reduceAll(*matrix->getComm(), Teuchos::REDUCE_MAX, 1, &reason, &any);
    reason = any;
  } else if (reason == static_cast<int>(Decision::CoarseZeros)) {
    reason = 0;  // one rank: MueLu's refusal is caught and recovered alone (initializePrec)
  }
  return static_cast<Decision>(reason);
}

void GraphKeyedPreconditionerFactory::startOver(const Teuchos::RCP<const Source>& src,
                                                Thyra::PreconditionerBase<double>* prec, Thyra::ESupportSolveUse use,
                                                const model::CrsMatrix* matrix, SetUp& record) const {
  inner_->uninitializePrec(prec, nullptr, nullptr);
  inner_->initializePrec(src, prec, use);
  record = SetUp{};
  if (matrix == nullptr) return;
  record.graph = matrix->getCrsGraph();
  record.zeroEntries = zeroEntryPositions(*matrix);
  if (matrix->getComm()->getSize() > 1) record.coarseZeros = onAnyRank(coarseLevelsHoldZeros(*prec), *matrix->getComm());
}

void GraphKeyedPreconditionerFactory::initializePrec(const Teuchos::RCP<const Source>& src,
                                                     Thyra::PreconditionerBase<double>* prec,
                                                     const Thyra::ESupportSolveUse use) const {
  const auto matrix = matrixOf(*src);
  const bool known = setUps_.count(prec) != 0;
  auto& record = setUps_[prec];
  const Decision decision = decide(matrix.get(), record);
  auto& c = counts();
  if (decision != Decision::Reuse) {
    // A preconditioner's first set-up is no restart.
    if (known && decision == Decision::NewGraph) ++c.newGraph;
    if (decision == Decision::PatternGrew) ++c.patternGrew;
    if (decision == Decision::CoarseZeros) ++c.coarseZeros;
    startOver(src, prec, use, matrix.get(), record);
    return;
  }
  try {
    inner_->initializePrec(src, prec, use);
    ++c.reused;
  } catch (const std::exception&) {
    // One rank only (decide): e.g. an exact zero of a coarse matrix at the set-up that is nonzero now.
    ++c.refused;
    startOver(src, prec, use, matrix.get(), record);
  }
}

void GraphKeyedPreconditionerFactory::uninitializePrec(Thyra::PreconditionerBase<double>* prec,
                                                       Teuchos::RCP<const Source>* src,
                                                       Thyra::ESupportSolveUse* use) const {
  setUps_.erase(prec);
  inner_->uninitializePrec(prec, src, use);
}

}  // namespace contessa::solvers
