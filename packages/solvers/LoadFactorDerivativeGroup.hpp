#pragma once
// LOCA's group over the model evaluator, with ∂f/∂λ taken from the model's own DfDp (OUT_ARG_DfDp)
// instead of a finite difference of f in λ.
//
// Why: LOCA::Thyra::Group (Trilinos 13.2) is built with `implement_dfdp = true`, but its
// computeDfDpMulti sets `implement_dfdp = false` on entry (its source says the Thyra path did not set
// the parameter names right for the EpetraExt adapter) and falls back to LOCA::Abstract::Group's, i.e.
// LOCA::DerivUtils::computeDfDp: a forward difference (f(λ + ε) − f(λ))/ε with ε = 1e-6 (1e-6 + |λ|).
// LOCA's tangent predictor (LOCA::MultiPredictor::Tangent::compute) asks exactly this of the underlying
// group before it solves W dx/dλ = −∂f/∂λ, so the predicted state carried the difference's error: the
// round-off of f divided by ε (1e-12 at λ = 0), and whatever moves f between the two evaluations
// (docs/theory-load-stepping.md §6.1). Natural continuation's Newton solves do not ask for ∂f/∂λ
// (Stepper/Skip Parameter Derivative, true by default), so only the predictor changes.
//
// The model's ∂f/∂λ is checked against central differences of f for every λ-dependent term (prescribed
// displacements, pressures, tractions, body forces, rigid master motion, load steps) in the model's unit
// tests; LoadFactorDerivativeGroupTest checks this group hands it to LOCA unchanged.
#include <vector>

#include <LOCA_Thyra_Group.H>

namespace contessa::solvers {

class LoadFactorDerivativeGroup : public LOCA::Thyra::Group {
 public:
  /// The model's parameter vector `pIndex` holds the LOCA parameters `p`, in order; the model must give
  /// DfDp of that vector by columns (DERIV_MV_BY_COL), else std::logic_error.
  LoadFactorDerivativeGroup(const Teuchos::RCP<LOCA::GlobalData>& globalData, const NOX::Thyra::Vector& initialGuess,
                            const Teuchos::RCP<::Thyra::ModelEvaluator<double>>& model, const LOCA::ParameterVector& p,
                            int pIndex = 0);
  LoadFactorDerivativeGroup(const LoadFactorDerivativeGroup& source, NOX::CopyType type = NOX::DeepCopy);

  /// LOCA clones its groups (the stepper's previous group, the predictor's, the Newton solver's): a clone
  /// must take ∂f/∂λ from the model too.
  Teuchos::RCP<NOX::Abstract::Group> clone(NOX::CopyType type = NOX::DeepCopy) const override;

  /// Column 0 of `fdfdp`: f (computed unless `isValidF`); column i + 1: ∂f/∂p_{paramIDs[i]} from the model
  /// at the group's (x, p). f comes from the group (its cached value when valid), so the model serves the
  /// derivative from the same evaluation pass and no residual is evaluated for it.
  NOX::Abstract::Group::ReturnType computeDfDpMulti(const std::vector<int>& paramIDs, NOX::Abstract::MultiVector& fdfdp,
                                                    bool isValidF) override;

  /// How many times computeDfDpMulti asked the model (for the tests).
  int modelDerivativeEvaluations() const { return modelDerivativeEvaluations_; }

 private:
  int modelIndex_;
  int modelDerivativeEvaluations_ = 0;
};

}  // namespace contessa::solvers
