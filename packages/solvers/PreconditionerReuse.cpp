#include "solvers/PreconditionerReuse.hpp"

#include <Thyra_TpetraLinearOp.hpp>

namespace contessa::solvers {
namespace {

// The graph of the Tpetra matrix behind a Thyra operator; null for any other operator.
Teuchos::RCP<const model::CrsGraph> graphOf(const Thyra::LinearOpSourceBase<double>& src) {
  using TpetraOp = Thyra::TpetraLinearOp<double, model::LO, model::GO, model::Node>;
  const auto op = Teuchos::rcp_dynamic_cast<const TpetraOp>(src.getOp());
  if (op.is_null()) return Teuchos::null;
  const auto matrix = Teuchos::rcp_dynamic_cast<const model::CrsMatrix>(op->getConstTpetraOperator());
  return matrix.is_null() ? Teuchos::null : matrix->getCrsGraph();
}

}  // namespace

long& GraphKeyedPreconditionerFactory::freshSetUps() {
  static long count = 0;
  return count;
}

void GraphKeyedPreconditionerFactory::initializePrec(const Teuchos::RCP<const Source>& src,
                                                     Thyra::PreconditionerBase<double>* prec,
                                                     const Thyra::ESupportSolveUse use) const {
  const auto graph = graphOf(*src);
  auto& last = graphs_[prec];
  // Another graph (or one this wrapper cannot see): the hierarchy is dropped and MueLu starts over.
  const bool fresh = graph.is_null() || last.get() != graph.get();
  if (fresh) {
    if (!last.is_null()) ++freshSetUps();
    inner_->uninitializePrec(prec, nullptr, nullptr);
  }
  last = graph;
  if (fresh) {
    inner_->initializePrec(src, prec, use);
    return;
  }
  try {
    inner_->initializePrec(src, prec, use);
  } catch (const std::exception&) {
    // MueLu 13.2 refuses some re-set-ups of a kept hierarchy ("Level::Clear found Internal data
    // inconsistency", e.g. at LOCA's tangent predictor after a converged increment): start over then.
    ++refusedReuses();
    inner_->uninitializePrec(prec, nullptr, nullptr);
    inner_->initializePrec(src, prec, use);
  }
}

long& GraphKeyedPreconditionerFactory::refusedReuses() {
  static long count = 0;
  return count;
}

void GraphKeyedPreconditionerFactory::uninitializePrec(Thyra::PreconditionerBase<double>* prec,
                                                       Teuchos::RCP<const Source>* src,
                                                       Thyra::ESupportSolveUse* use) const {
  graphs_.erase(prec);
  inner_->uninitializePrec(prec, src, use);
}

}  // namespace contessa::solvers
