#include "solvers/IterativeSolveMonitor.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <Thyra_LinearOpWithSolveBase.hpp>
#include <Thyra_MultiVectorStdOps.hpp>
#include <Thyra_PreconditionerFactoryBase.hpp>

#include "common/PhaseTimers.hpp"
#include "solvers/KrylovForcing.hpp"
#include "solvers/NewtonStatusTests.hpp"

namespace contessa::solvers {

using Teuchos::RCP;
using Teuchos::rcp;
using LOWS = Thyra::LinearOpWithSolveBase<double>;
using LOWSF = Thyra::LinearOpWithSolveFactoryBase<double>;
using Source = Thyra::LinearOpSourceBase<double>;

IterativeSolveLog& iterativeSolveLog() {
  static IterativeSolveLog log;
  return log;
}

namespace {

class MonitoredLinearOpWithSolve : public LOWS {
 public:
  MonitoredLinearOpWithSolve(RCP<LOWS> inner, std::string solverName, IterativeSolveLimits limits)
      : inner_(std::move(inner)), solverName_(std::move(solverName)), limits_(limits) {}
  LOWS& inner() const { return *inner_; }

  RCP<const Thyra::VectorSpaceBase<double>> range() const override { return inner_->range(); }
  RCP<const Thyra::VectorSpaceBase<double>> domain() const override { return inner_->domain(); }

 protected:
  bool opSupportedImpl(Thyra::EOpTransp t) const override { return Thyra::opSupported(*inner_, t); }
  void applyImpl(const Thyra::EOpTransp t, const Thyra::MultiVectorBase<double>& X,
                 const Teuchos::Ptr<Thyra::MultiVectorBase<double>>& Y, const double alpha,
                 const double beta) const override {
    Thyra::apply(*inner_, t, X, Y, alpha, beta);
  }
  bool solveSupportsImpl(Thyra::EOpTransp t) const override { return inner_->solveSupports(t); }
  bool solveSupportsSolveMeasureTypeImpl(Thyra::EOpTransp t, const Thyra::SolveMeasureType& m) const override {
    return inner_->solveSupportsSolveMeasureType(t, m);
  }
  Thyra::SolveStatus<double> solveImpl(const Thyra::EOpTransp t, const Thyra::MultiVectorBase<double>& B,
                                       const Teuchos::Ptr<Thyra::MultiVectorBase<double>>& X,
                                       const Teuchos::Ptr<const Thyra::SolveCriteria<double>>) const override {
    // The deck's tolerance, not the caller's (header), or the Newton step's tighter one (KrylovForcing.hpp).
    timers::Scope timed(timers::Phase::IterativeSolve);
    const double tolerance = krylovForcing().takeTolerance(limits_.tolerance, rhsNorm(B));
    const bool tightened = tolerance < limits_.tolerance;
    // ‖r‖ ≤ η ‖b‖: the forcing term's measure. Thyra sets it on the Belos solver (the tolerance for this
    // solve; the "Norm of RHS" scaling stays for later ones): with GMRES preconditioned on the right, as
    // Stratimikos does by default, it differs from Belos' default scaling (the initial residual) only when
    // the initial guess is not zero.
    const Thyra::SolveCriteria<double> criteria(
        Thyra::SolveMeasureType(Thyra::SOLVE_MEASURE_NORM_RESIDUAL, Thyra::SOLVE_MEASURE_NORM_RHS), tolerance);
    const auto status = inner_->solve(t, B, X, tightened ? Teuchos::ptrFromRef(criteria) : Teuchos::null);
    int iterations = -1;
    if (!status.extraParameters.is_null()) iterations = status.extraParameters->get("Iteration Count", -1);
    auto& log = iterativeSolveLog();
    ++log.solves;
    if (iterations > 0) log.iterations += iterations;
    if (tightened) ++krylovForcing().tightenedSolves;
    if (status.solveStatus == Thyra::SOLVE_STATUS_CONVERGED) return status;
    // A tightened solve that stopped short of the asked tolerance but within the deck's did what the deck
    // requires: its direction is taken, as at the deck's tolerance.
    if (tightened && status.achievedTol >= 0 && status.achievedTol <= limits_.tolerance) {
      ++krylovForcing().shortfalls;
      return status;
    }
    fail(status, iterations);
    return status;
  }

 private:
  static double rhsNorm(const Thyra::MultiVectorBase<double>& B) {
    std::vector<double> norms(static_cast<std::size_t>(B.domain()->dim()));
    Thyra::norms_2(B, Teuchos::arrayViewFromVector(norms));
    return norms.empty() ? 0.0 : *std::max_element(norms.begin(), norms.end());
  }

  // Records the failure and throws it (header).
  void fail(const Thyra::SolveStatus<double>& status, int iterations) const {
    auto& log = iterativeSolveLog();
    ++log.failures;
    const std::string residual = status.achievedTol >= 0 ? shortNumber(status.achievedTol) : std::string("unknown");
    // Either the iterations ran out, or Belos stopped early because the true residual cannot reach the
    // tolerance (its "loss of accuracy": the matrix is too ill-conditioned for it, e.g. stiff penalty rows).
    if (iterations >= limits_.maxIterations || iterations < 0)
      log.lastFailure = "the linear solver (" + solverName_ + ") did not converge in " + std::to_string(iterations) +
                        " iterations (Maximum Iterations; relative residual " + residual +
                        "; raise Maximum Iterations or use a stronger preconditioner, or MUMPS)";
    else
      log.lastFailure = "the linear solver (" + solverName_ + ") stopped after " + std::to_string(iterations) +
                        " iterations: the true residual does not reach Convergence Tolerance = " +
                        shortNumber(limits_.tolerance) +
                        " (Belos' loss of accuracy: the matrix is too ill-conditioned for that tolerance; loosen it, or use MUMPS)";
    throw std::runtime_error(log.lastFailure);
  }

 private:
  RCP<LOWS> inner_;
  std::string solverName_;
  IterativeSolveLimits limits_;
};

LOWS* innerOf(LOWS* op) { return &dynamic_cast<MonitoredLinearOpWithSolve&>(*op).inner(); }

// NOX's Thyra group builds the preconditioner itself, through the factory the solver factory hands out
// (getPreconditionerFactory), and then calls initializePreconditionedOp: MueLu's hierarchy and Ifpack2's
// factorisation are made here, so this is where the set-up timer must run.
class TimedPreconditionerFactory : public Thyra::PreconditionerFactoryBase<double> {
 public:
  using Factory = Thyra::PreconditionerFactoryBase<double>;
  explicit TimedPreconditionerFactory(RCP<Factory> inner) : inner_(std::move(inner)) {}
  const RCP<Factory>& inner() const { return inner_; }

  bool isCompatible(const Source& src) const override { return inner_->isCompatible(src); }
  RCP<Thyra::PreconditionerBase<double>> createPrec() const override { return inner_->createPrec(); }
  void initializePrec(const RCP<const Source>& src, Thyra::PreconditionerBase<double>* prec,
                      const Thyra::ESupportSolveUse use) const override {
    timers::Scope timed(timers::Phase::IterativeSetup);
    inner_->initializePrec(src, prec, use);
  }
  void uninitializePrec(Thyra::PreconditionerBase<double>* prec, RCP<const Source>* src,
                        Thyra::ESupportSolveUse* use) const override {
    inner_->uninitializePrec(prec, src, use);
  }
  void setParameterList(const RCP<Teuchos::ParameterList>& params) override { inner_->setParameterList(params); }
  RCP<Teuchos::ParameterList> getNonconstParameterList() override { return inner_->getNonconstParameterList(); }
  RCP<Teuchos::ParameterList> unsetParameterList() override { return inner_->unsetParameterList(); }
  RCP<const Teuchos::ParameterList> getParameterList() const override { return inner_->getParameterList(); }
  RCP<const Teuchos::ParameterList> getValidParameters() const override { return inner_->getValidParameters(); }
  std::string description() const override { return inner_->description(); }

 private:
  RCP<Factory> inner_;
};

class MonitoredLinearOpWithSolveFactory : public LOWSF {
 public:
  MonitoredLinearOpWithSolveFactory(RCP<LOWSF> inner, std::string solverName, IterativeSolveLimits limits)
      : inner_(std::move(inner)), solverName_(std::move(solverName)), limits_(limits) {}

  bool acceptsPreconditionerFactory() const override { return inner_->acceptsPreconditionerFactory(); }
  void setPreconditionerFactory(const RCP<Thyra::PreconditionerFactoryBase<double>>& factory,
                                const std::string& label) override {
    inner_->setPreconditionerFactory(factory, label);
  }
  RCP<Thyra::PreconditionerFactoryBase<double>> getPreconditionerFactory() const override {
    auto factory = inner_->getPreconditionerFactory();
    if (factory.is_null()) return factory;
    return rcp(new TimedPreconditionerFactory(factory));
  }
  void unsetPreconditionerFactory(RCP<Thyra::PreconditionerFactoryBase<double>>* factory, std::string* label) override {
    inner_->unsetPreconditionerFactory(factory, label);
  }
  bool isCompatible(const Source& src) const override { return inner_->isCompatible(src); }
  RCP<LOWS> createOp() const override { return rcp(new MonitoredLinearOpWithSolve(inner_->createOp(), solverName_, limits_)); }
  void initializeOp(const RCP<const Source>& src, LOWS* op, const Thyra::ESupportSolveUse use) const override {
    timers::Scope timed(timers::Phase::IterativeSetup);
    inner_->initializeOp(src, innerOf(op), use);
  }
  void initializeAndReuseOp(const RCP<const Source>& src, LOWS* op) const override {
    timers::Scope timed(timers::Phase::IterativeSetup);
    inner_->initializeAndReuseOp(src, innerOf(op));
  }
  void uninitializeOp(LOWS* op, RCP<const Source>* src, RCP<const Thyra::PreconditionerBase<double>>* prec,
                      RCP<const Source>* approx, Thyra::ESupportSolveUse* use) const override {
    inner_->uninitializeOp(innerOf(op), src, prec, approx, use);
  }
  bool supportsPreconditionerInputType(const Thyra::EPreconditionerInputType type) const override {
    return inner_->supportsPreconditionerInputType(type);
  }
  void initializePreconditionedOp(const RCP<const Source>& src, const RCP<const Thyra::PreconditionerBase<double>>& prec,
                                  LOWS* op, const Thyra::ESupportSolveUse use) const override {
    timers::Scope timed(timers::Phase::IterativeSetup);
    inner_->initializePreconditionedOp(src, prec, innerOf(op), use);
  }
  void initializeApproxPreconditionedOp(const RCP<const Source>& src, const RCP<const Source>& approx, LOWS* op,
                                        const Thyra::ESupportSolveUse use) const override {
    inner_->initializeApproxPreconditionedOp(src, approx, innerOf(op), use);
  }

  void setParameterList(const RCP<Teuchos::ParameterList>& params) override { inner_->setParameterList(params); }
  RCP<Teuchos::ParameterList> getNonconstParameterList() override { return inner_->getNonconstParameterList(); }
  RCP<Teuchos::ParameterList> unsetParameterList() override { return inner_->unsetParameterList(); }
  RCP<const Teuchos::ParameterList> getParameterList() const override { return inner_->getParameterList(); }
  RCP<const Teuchos::ParameterList> getValidParameters() const override { return inner_->getValidParameters(); }
  std::string description() const override { return solverName_; }

 private:
  RCP<LOWSF> inner_;
  std::string solverName_;
  IterativeSolveLimits limits_;
};

}  // namespace

RCP<Thyra::PreconditionerFactoryBase<double>> unmonitored(const RCP<Thyra::PreconditionerFactoryBase<double>>& factory) {
  const auto timed = Teuchos::rcp_dynamic_cast<TimedPreconditionerFactory>(factory);
  return timed.is_null() ? factory : timed->inner();
}

RCP<LOWSF> monitorIterativeSolver(const RCP<LOWSF>& inner, const std::string& solverName,
                                  const IterativeSolveLimits& limits) {
  return rcp(new MonitoredLinearOpWithSolveFactory(inner, solverName, limits));
}

}  // namespace contessa::solvers
