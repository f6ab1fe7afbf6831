#include "solvers/LocaResume.hpp"

#include <LOCA.H>
#include <LOCA_Factory.H>
#include <LOCA_MultiContinuation_AbstractStrategy.H>
#include <LOCA_MultiContinuation_ExtendedVector.H>
#include <LOCA_Parameter_SublistParser.H>
#include <LOCA_StepSize_AbstractStrategy.H>
#include <NOX_Solver_Factory.H>
#include <NOX_Thyra_Vector.H>
#include <Thyra_TpetraThyraWrappers.hpp>

#include "solvers/ResumableStepSize.hpp"

namespace contessa::solvers {

using Teuchos::RCP;
using Teuchos::rcp;

namespace {

// The solver LOCA's step-size strategy reads when the first increment after a restart is planned: the
// new (unused) solver, reporting the Newton iterations of the increment the restart file was written at,
// as the uninterrupted run's solver would.
class ResumedSolver : public NOX::Solver::Generic {
 public:
  ResumedSolver(RCP<NOX::Solver::Generic> solver, int iterations) : solver_(std::move(solver)), iterations_(iterations) {}
  void reset() override { solver_->reset(); }
  void reset(const NOX::Abstract::Vector& x) override { solver_->reset(x); }
  void reset(const NOX::Abstract::Vector& x, const RCP<NOX::StatusTest::Generic>& tests) override { solver_->reset(x, tests); }
  NOX::StatusTest::StatusType step() override { return solver_->step(); }
  NOX::StatusTest::StatusType solve() override { return solver_->solve(); }
  const NOX::Abstract::Group& getSolutionGroup() const override { return solver_->getSolutionGroup(); }
  const NOX::Abstract::Group& getPreviousSolutionGroup() const override { return solver_->getPreviousSolutionGroup(); }
  NOX::StatusTest::StatusType getStatus() const override { return NOX::StatusTest::Converged; }
  int getNumIterations() const override { return iterations_; }
  const Teuchos::ParameterList& getList() const override { return solver_->getList(); }
  RCP<const NOX::Abstract::Group> getSolutionGroupPtr() const override { return solver_->getSolutionGroupPtr(); }
  RCP<const NOX::Abstract::Group> getPreviousSolutionGroupPtr() const override {
    return solver_->getPreviousSolutionGroupPtr();
  }
  RCP<const Teuchos::ParameterList> getListPtr() const override { return solver_->getListPtr(); }
  RCP<const NOX::SolverStats> getSolverStatistics() const override { return solver_->getSolverStatistics(); }

 private:
  RCP<NOX::Solver::Generic> solver_;
  int iterations_;
};

}  // namespace

NOX::Abstract::Group& ResumableStepper::solverGroup() { return *curGroupPtr; }

StateRecord ResumableStepper::stepSizeState() const {
  StateRecord out;
  if (const auto* resumable = dynamic_cast<const ResumableStepSize*>(stepSizeStrategyPtr.get()))
    resumable->saveState(out);
  return out;
}

LOCA::Abstract::Iterator::IteratorStatus ResumableStepper::start() {
  if (resume_ == nullptr) return LOCA::Stepper::start();
  const LocaResumePoint& p = *resume_;
  struct Quiet {
    const std::function<void(bool)>& set;
    explicit Quiet(const std::function<void(bool)>& f) : set(f) { set(true); }
    ~Quiet() { set(false); }
  } quiet(quiet_);
  // As LOCA::Stepper::start() after the initial solve, with x_k taken as converged (re-solving it would
  // move it: Newton iterates at least once where only the absolute tolerance can pass).
  auto underlying = curGroupPtr->getUnderlyingGroup();
  curGroupPtr = globalData->locaFactory->createContinuationStrategy(parsedParams, stepperList, underlying, predictor,
                                                                   conParamIDs);
  stepSize = p.stepSize;
  curGroupPtr->setStepSize(stepSize);
  prevGroupPtr = Teuchos::rcp_dynamic_cast<LOCA::MultiContinuation::AbstractStrategy>(curGroupPtr->clone());
  if (p.secantPredictor) {
    // The secant predictor's first step is LOCA's first-step predictor; later ones are (x_k − x_{k−1})
    // scaled. Its first-step flags are passed as in the run: one predictor at the start, then a
    // completed step (which LOCA marks with postProcessContinuationStep), then the secant of x_k and
    // x_{k−1} as the uninterrupted run computed it after increment k.
    auto previous = Teuchos::rcp_dynamic_cast<LOCA::MultiContinuation::ExtendedVector>(
        curGroupPtr->getX().clone(NOX::DeepCopy), true);
    auto thyraPrevious = Thyra::createConstVector(p.previousX);
    *previous->getXVec() = NOX::Thyra::Vector(*thyraPrevious);
    previous->getScalar(0) = p.previousLambda;
    curGroupPtr->setPrevX(*previous);
    globalData->locaErrorCheck->checkReturnType(curGroupPtr->computePredictor(), "contessa: resumed predictor");
    curGroupPtr->postProcessContinuationStep(LOCA::Abstract::Iterator::Successful);
  }
  globalData->locaErrorCheck->checkReturnType(curGroupPtr->computePredictor(), "contessa: resumed predictor");
  curPredictorPtr = Teuchos::rcp_dynamic_cast<LOCA::MultiContinuation::ExtendedVector>(
      curGroupPtr->getPredictorTangent()[0].clone(NOX::DeepCopy));
  prevPredictorPtr = Teuchos::rcp_dynamic_cast<LOCA::MultiContinuation::ExtendedVector>(
      curGroupPtr->getPredictorTangent()[0].clone(NOX::ShapeCopy));
  solverPtr = rcp(new ResumedSolver(
      NOX::Solver::buildSolver(curGroupPtr, noxStatusTestPtr, parsedParams->getSublist("NOX")), p.newtonIterations));
  // The step-size strategy past its first step: Contessa's restore their state; LOCA's Constant and
  // Adaptive keep only whether the first step was taken, which one call with a unit predictor sets
  // (their first call divides the start step by dλ/ds = 1: no change).
  if (auto* resumable = dynamic_cast<ResumableStepSize*>(stepSizeStrategyPtr.get())) {
    resumable->loadState(*p.stepSizeState);
    p.stepSizeState->requireAllRead();
  } else {
    auto unit = Teuchos::rcp_dynamic_cast<LOCA::MultiContinuation::ExtendedVector>(curPredictorPtr->clone(NOX::DeepCopy));
    unit->getScalar(0) = 1.0;
    double ignored = stepSize;
    stepSizeStrategyPtr->computeStepSize(*curGroupPtr, *unit, *solverPtr, LOCA::Abstract::Iterator::Successful, *this,
                                         ignored);
  }
  stepNumber = p.increments;
  numFailedSteps = p.failedAttempts;
  numTotalSteps = p.increments + p.failedAttempts;
  return LOCA::Abstract::Iterator::NotFinished;
}

}  // namespace contessa::solvers
