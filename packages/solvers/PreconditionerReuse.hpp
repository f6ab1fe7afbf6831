#pragma once
// MueLu's set-up reused across Newton iterations and increments while the matrix graph stays the same.
//
// Thyra's MueLu factory reuses the hierarchy a preconditioner already holds when its "reuse: type" is set
// (MueLu's user guide, "Reuse"): with "RP", Contessa's default, the aggregates and the prolongator P and
// restriction R of the first set-up are kept and only the coarse matrices R A P and the smoothers are
// rebuilt from each new Jacobian; the aggregation and the prolongator smoothing are skipped (on the 3D
// punch at 1.5·10^4 unknowns: 21 % less CPU per run, 7 % more Krylov iterations; bench/README.md). MueLu
// then multiplies R A P along the pattern of the first set-up, so a hierarchy belongs to one matrix graph:
// when contact rebuilds the graph (new couplings), this wrapper drops the preconditioner's hierarchy first
// and MueLu sets up afresh. Where the graph is unchanged the values may change freely: the Krylov
// iteration checks the true residual, so an older P costs iterations, not accuracy.
#include <map>

#include <Thyra_PreconditionerFactoryBase.hpp>

#include "model/TpetraTypes.hpp"

namespace contessa::solvers {

/// The MueLu reuse Contessa sets on one rank unless the deck gives "reuse: type" (bench/README.md, "MueLu
/// reuse"); on more ranks a re-set-up MueLu refuses on one rank only cannot be recovered (the fallback in
/// initializePrec is per rank), so none is set there.
inline constexpr const char* kMueLuReuseType = "RP";

/// `inner` (MueLu's factory) that starts a preconditioner over whenever the matrix it is given has another
/// graph than the one it was last set up with. Everything else passes through.
class GraphKeyedPreconditionerFactory : public Thyra::PreconditionerFactoryBase<double> {
 public:
  using Factory = Thyra::PreconditionerFactoryBase<double>;
  using Source = Thyra::LinearOpSourceBase<double>;
  explicit GraphKeyedPreconditionerFactory(Teuchos::RCP<Factory> inner) : inner_(std::move(inner)) {}
  const Teuchos::RCP<Factory>& inner() const { return inner_; }

  /// Set-ups started over because a preconditioner met another graph than its last (a rebuild).
  static long& freshSetUps();
  /// Re-set-ups MueLu refused, each followed by a fresh set-up (PreconditionerReuse.cpp).
  static long& refusedReuses();

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
  Teuchos::RCP<Factory> inner_;
  // The graph each preconditioner was last set up with (held, so that a freed graph's address cannot
  // pass for it).
  mutable std::map<const Thyra::PreconditionerBase<double>*, Teuchos::RCP<const model::CrsGraph>> graphs_;
};

}  // namespace contessa::solvers
