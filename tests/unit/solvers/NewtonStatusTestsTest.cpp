// When NewtonStatusTests asks the augmented Lagrangian for an update before convergence (docs/theory-contact.md
// §15, "Updates before convergence"): only once two Newton steps of the same problem give a contraction, so
// not at the iterate right after one whose step belonged to another problem (a step control that held new
// contacts back or has just released them: updateMeaningful() false). A real NOX line-search Newton on the
// scalar f(x) = x² − 2 from x = 3 (steps 1.17, 0.371, 0.0472, 7.9e-4: contractions 0.32, 0.13, 0.017).
#include <gtest/gtest.h>

#include <vector>

#include <NOX_LAPACK_Group.H>
#include <NOX_LAPACK_Interface.H>
#include <NOX_Solver_Factory.H>
#include <NOX_Solver_Generic.H>
#include <NOX_StatusTest_Generic.H>
#include <Teuchos_ParameterList.hpp>

#include "model/ContactAugmentation.hpp"
#include "model/SolveDiagnostics.hpp"
#include "solvers/NewtonStatusTests.hpp"
#include "solvers/StepControl.hpp"

namespace {

using contessa::model::AugmentationPoint;

class SquareRootOfTwo : public NOX::LAPACK::Interface {
 public:
  SquareRootOfTwo() : start_(1) { start_(0) = 3.0; }
  const NOX::LAPACK::Vector& getInitialGuess() override { return start_; }
  bool computeF(NOX::LAPACK::Vector& f, const NOX::LAPACK::Vector& x) override {
    f(0) = x(0) * x(0) - 2.0;
    return true;
  }
  bool computeJacobian(NOX::LAPACK::Matrix<double>& jacobian, const NOX::LAPACK::Vector& x) override {
    jacobian(0, 0) = 2.0 * x(0);
    return true;
  }

 private:
  NOX::LAPACK::Vector start_;
};

// Never converges: the iterations run to the limit, every iterate is asked about.
class NeverConverged : public NOX::StatusTest::Generic {
 public:
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic&, NOX::StatusTest::CheckType) override {
    return NOX::StatusTest::Unconverged;
  }
  NOX::StatusTest::StatusType getStatus() const override { return NOX::StatusTest::Unconverged; }
  std::ostream& print(std::ostream& os, int) const override { return os; }
};

class NoDiagnostics : public contessa::model::SolveDiagnostics {
 public:
  std::string nonFiniteResidualCause() const override { return ""; }
  std::string contactTunnelling() const override { return ""; }
  std::string describeFreeMotion(const std::vector<std::vector<double>>&) const override { return ""; }
  bool hasContact() const override { return true; }
  int jacobianEvaluations() const override { return 0; }
};

// Records at which iterations an update is asked for; never updates.
class RecordingAugmentation : public contessa::model::ContactAugmentation {
 public:
  const NOX::Solver::Generic* solver = nullptr;
  std::vector<int> earlyAsks;
  std::vector<double> estimates;
  bool augmentContact(const AugmentationPoint& at) override {
    if (!at.converged) {
      earlyAsks.push_back(solver->getNumIterations());
      estimates.push_back(at.errorEstimate);
    }
    return false;
  }
  bool hasAugmentedContact() const override { return true; }
};

// A step control whose Newton update at iteration `heldAt` was computed for another residual.
class HoldsAt : public contessa::solvers::StepControl {
 public:
  explicit HoldsAt(int heldAt) : heldAt_(heldAt) {}
  const NOX::Solver::Generic* solver = nullptr;
  bool updateMeaningful() const override { return solver->getNumIterations() != heldAt_; }

 private:
  int heldAt_;
};

// Runs five Newton iterations; returns the augmentation's record.
RecordingAugmentation solve(int heldAt) {
  SquareRootOfTwo problem;
  NoDiagnostics diagnostics;
  HoldsAt control(heldAt);
  RecordingAugmentation augmentation;
  contessa::solvers::NewtonStatusTests tests(diagnostics, Teuchos::null, Teuchos::rcp(new NeverConverged), 5, &control);
  auto group = Teuchos::rcp(new NOX::LAPACK::Group(problem));
  auto params = Teuchos::rcp(new Teuchos::ParameterList);
  params->set("Nonlinear Solver", "Line Search Based");
  params->sublist("Line Search").set("Method", "Full Step");
  params->sublist("Printing").set("Output Information", 0);
  auto solver = NOX::Solver::buildSolver(group, tests.test(), params);
  control.solver = augmentation.solver = solver.get();
  tests.enableAugmentation(&augmentation, [&]() -> NOX::Abstract::Group& { return *group; });
  tests.startSolve();
  solver->solve();
  return augmentation;
}

TEST(NewtonStatusTests, AsksForAnEarlyUpdateOnceTwoStepsContract) {
  const auto record = solve(/*heldAt=*/-1);
  // Iteration 1 has no step before it; from 2 on every contraction is below 1/2.
  ASSERT_EQ(record.earlyAsks, (std::vector<int>{2, 3, 4, 5}));
  // Iteration 2: steps 3 → 11/6 → 1.462121..., ρ = 0.3182, estimate ρ/(1 − ρ) × 0.3712.
  const double x1 = 11.0 / 6.0, x2 = x1 / 2.0 + 1.0 / x1;
  const double rho = (x1 - x2) / (3.0 - x1);
  EXPECT_NEAR(record.estimates[0], rho / (1.0 - rho) * (x1 - x2), 1e-12);
}

TEST(NewtonStatusTests, ForgetsTheStepOfAnotherProblem) {
  // The step of iteration 2 was computed for another residual: iteration 3 has no step of its own problem
  // before it (comparing it with iteration 1's would mix two problems), so the first ask is at 4.
  const auto record = solve(/*heldAt=*/2);
  ASSERT_EQ(record.earlyAsks, (std::vector<int>{4, 5}));
}

}  // namespace
