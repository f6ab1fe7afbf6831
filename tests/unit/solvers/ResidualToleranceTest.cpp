// The Newton residual test's absolute bound (solvers/ResidualTolerance.hpp, ResidualTest.hpp): the deck's
// absolute tolerance or c · F; the decision on either side of the bound; the loose acceptance said once; a
// NOX Newton whose iterations do not depend on the unit of force under the force-scaled bound (and stops at
// its predictor under a small absolute one, the audit's soft inflation); the two round-off floors of the
// force-scaled test (an update at the positions' round-off, the out-of-balance force's own rounding) on
// NOX Newtons that cannot converge without them; F = ||f_int|| of the model at a homogeneous state whose
// nodal forces are known in closed form, and the model's rounding level against the rounding it measures
// at an exact linear state, on 1 and 2 ranks.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include <NOX_LAPACK_Group.H>
#include <NOX_LAPACK_Interface.H>
#include <NOX_Solver_Factory.H>
#include <NOX_Solver_Generic.H>
#include <NOX_StatusTest_Combo.H>
#include <NOX_StatusTest_MaxIters.H>
#include <Teuchos_ParameterList.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include "../model/ModelHarness.hpp"
#include "TestDeck.hpp"
#include "model/ForceScale.hpp"
#include "solvers/ResidualTest.hpp"
#include "solvers/ResidualTolerance.hpp"

namespace {

using contessa::solvers::ResidualTest;
using contessa::solvers::ResidualTolerance;
using contessa::solvers::ResidualToleranceRecord;

TEST(ResidualTolerance, TheDeckChoosesTheRule) {
  Teuchos::ParameterList tests;
  tests.set("Force-Scaled Residual Tolerance", 1e-9);
  const auto scaled = ResidualTolerance::fromDeck(tests);
  EXPECT_TRUE(scaled.isForceScaled());
  EXPECT_DOUBLE_EQ(scaled.boundAt(2.0e6), 2.0e-3);  // c · F: follows the force scale
  EXPECT_DOUBLE_EQ(scaled.boundAt(2.0e-6), 2.0e-15);
  EXPECT_EQ(scaled.boundAt(0.0), 0.0);  // no force, no absolute bound: the relative and update tests decide

  tests.set("Absolute Residual Tolerance", 1e-8);  // given by the deck: in its force unit, whatever F is
  const auto absolute = ResidualTolerance::fromDeck(tests);
  EXPECT_FALSE(absolute.isForceScaled());
  EXPECT_DOUBLE_EQ(absolute.boundAt(2.0e6), 1e-8);
  EXPECT_DOUBLE_EQ(absolute.boundAt(2.0e-6), 1e-8);
}

TEST(ResidualTolerance, LooseOnlyAboveTheFractionOfTheForceScale) {
  const double fraction = ResidualTolerance::kLooseFraction;
  const auto absolute = ResidualTolerance::absolute(1e-8);
  EXPECT_TRUE(absolute.looseAt(1e-8 / fraction * 0.99));
  EXPECT_FALSE(absolute.looseAt(1e-8 / fraction * 1.01));
  EXPECT_FALSE(ResidualTolerance::forceScaled(ResidualTolerance::kDefaultFactor).looseAt(1e-20));
  EXPECT_FALSE(ResidualTolerance::forceScaled(ResidualTolerance::kDefaultFactor).looseAt(1e20));
}

TEST(ResidualToleranceRecord, WarnsOnceAboutALooseAcceptance) {
  const auto absolute = ResidualTolerance::absolute(1e-8);
  ResidualToleranceRecord record;
  const double F = 1e-5;  // the soft inflation's force scale order: 1e-8 is 1e-3 of it
  record.accepted(absolute, F, 1e-13, 1e-8, true);  // ||f|| far below the fraction: Newton did its work
  EXPECT_TRUE(record.warning.empty());
  record.accepted(absolute, F, 5e-9, 1e-8, false);  // the relative test decided: not the absolute bound's doing
  EXPECT_TRUE(record.warning.empty());
  record.accepted(absolute, F, 5e-9, 1e-8, true);
  EXPECT_NE(record.warning.find("Absolute Residual Tolerance"), std::string::npos) << record.warning;
  const std::string first = record.warning;
  record.accepted(absolute, 2 * F, 9e-9, 1e-8, true);
  EXPECT_EQ(record.warning, first) << "said once";
  EXPECT_DOUBLE_EQ(record.lastForceScale, 2 * F);
  EXPECT_DOUBLE_EQ(record.largestForceScale, 2 * F);

  ResidualToleranceRecord scaled;
  scaled.accepted(ResidualTolerance::forceScaled(1e-10), F, 1e-15, 1e-15, true);
  EXPECT_TRUE(scaled.warning.empty());
}

// f(x) = s (x³ + x − 2): "internal force" s (x³ + x) against the load 2 s, the unit of force s. The force
// scale is |f_int| at the last evaluated x, as the model's.
class ScaledCubic : public NOX::LAPACK::Interface, public contessa::model::ForceScale {
 public:
  ScaledCubic(double unit, double start) : unit_(unit), start_(1) { start_(0) = start; }
  const NOX::LAPACK::Vector& getInitialGuess() override { return start_; }
  bool computeF(NOX::LAPACK::Vector& f, const NOX::LAPACK::Vector& x) override {
    internal_ = unit_ * (x(0) * x(0) * x(0) + x(0));
    f(0) = internal_ - 2.0 * unit_;
    residual_ = std::abs(f(0));
    return true;
  }
  bool computeJacobian(NOX::LAPACK::Matrix<double>& jacobian, const NOX::LAPACK::Vector& x) override {
    jacobian(0, 0) = unit_ * (3.0 * x(0) * x(0) + 1.0);
    return true;
  }
  double forceScale() const override { return std::abs(internal_); }
  double outOfBalanceNorm() const override { return residual_; }

 private:
  double unit_, internal_ = 0, residual_ = 0;
  NOX::LAPACK::Vector start_;
};

struct Solve {
  int iterations = 0;
  double x = 0;
  NOX::StatusTest::StatusType status = NOX::StatusTest::Unevaluated;
};

// A NOX full-step Newton on `problem` from its initial guess with ResidualTest alone (no relative test; the
// update test at `update`, 0: off) under `bound`, at most 30 iterations.
template <class Problem>
Solve newtonOn(Problem& problem, const ResidualTolerance& bound, double update = 0.0,
               ResidualToleranceRecord* record = nullptr) {
  auto group = Teuchos::rcp(new NOX::LAPACK::Group(problem));
  auto residual = Teuchos::rcp(new ResidualTest(bound, &problem, 0.0, update, nullptr, record));
  auto combo = Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
  combo->addStatusTest(residual);
  combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::MaxIters(30)));
  auto params = Teuchos::rcp(new Teuchos::ParameterList);
  params->set("Nonlinear Solver", "Line Search Based");
  params->sublist("Printing").set("Output Information", 0);
  auto solver = NOX::Solver::buildSolver(group, combo, params);
  const auto status = solver->solve();
  const auto& x = dynamic_cast<const NOX::LAPACK::Vector&>(solver->getSolutionGroup().getX());
  return {solver->getNumIterations(), x(0), status};
}

// The scaled cubic from x = 1.05 (a predictor near the root 1), converged.
Solve newton(double unit, const ResidualTolerance& bound) {
  ScaledCubic problem(unit, 1.05);
  const Solve solve = newtonOn(problem, bound);
  EXPECT_EQ(solve.status, NOX::StatusTest::Converged);
  return solve;
}

TEST(ResidualTest, TheForceScaledBoundTakesTheSameIterationsInAnyUnit) {
  const auto scaled = ResidualTolerance::forceScaled(ResidualTolerance::kDefaultFactor);
  const Solve reference = newton(1.0, scaled);
  EXPECT_GE(reference.iterations, 3);
  EXPECT_NEAR(reference.x, 1.0, 1e-10);
  for (double unit : {1e-12, 1e-6, 1e-2, 1e4, 1e9}) {
    const Solve other = newton(unit, scaled);
    EXPECT_EQ(other.iterations, reference.iterations) << "unit " << unit;
    EXPECT_NEAR(other.x, 1.0, 1e-10) << "unit " << unit;
  }
}

TEST(ResidualTest, AnAbsoluteBoundIsInTheDecksUnit) {
  // The defect the force-scaled default removes: in a small unit the predictor's residual is already
  // below 1e-8 and Newton does not iterate (x stays 5 % off); in a large one 1e-8 takes more iterations.
  const auto absolute = ResidualTolerance::absolute(1e-8);
  const Solve small = newton(1e-9, absolute);
  EXPECT_EQ(small.iterations, 0);
  EXPECT_NEAR(small.x, 1.05, 1e-15);
  EXPECT_GT(newton(1e6, absolute).iterations, newton(1.0, absolute).iterations);
}

// One unknown x on a spring of stiffness k loaded to k·target: the internal force is computed as the
// derived problem says (where its rounding comes from); force scale, out-of-balance norm and the Jacobian
// are the spring's.
class RoundedSpring : public NOX::LAPACK::Interface, public contessa::model::ForceScale {
 public:
  RoundedSpring(double stiffness, double target, double start) : stiffness_(stiffness), target_(target), start_(1) {
    start_(0) = start;
  }
  const NOX::LAPACK::Vector& getInitialGuess() override { return start_; }
  bool computeF(NOX::LAPACK::Vector& f, const NOX::LAPACK::Vector& x) override {
    internal_ = internalForce(x(0));
    f(0) = internal_ - stiffness_ * target_;
    residual_ = std::abs(f(0));
    return true;
  }
  bool computeJacobian(NOX::LAPACK::Matrix<double>& jacobian, const NOX::LAPACK::Vector&) override {
    jacobian(0, 0) = stiffness_;
    return true;
  }
  double forceScale() const override { return std::abs(internal_); }
  double outOfBalanceNorm() const override { return residual_; }

 protected:
  virtual double internalForce(double x) const = 0;

 private:
  double stiffness_, target_, internal_ = 0, residual_ = 0;
  NOX::LAPACK::Vector start_;
};

// One DOF of a node at X = 1000 displaced by x, its internal force computed from positions as a contact gap
// is, k ((X + x) − X), against the load k u*: the position X + x is rounded to the spacing of doubles at
// X (1.1e-13), so the residual never goes below k · 3.2e-14 (u* = π · 1e-9) while the force-scaled bound
// is 1e-10 k u* and the update test's 1e-10 |x| is 3e-19: only the update's floor at the positions'
// round-off (ResidualTest::kPositionRoundOff · largest |X|) stops Newton. `length`: the mesh's largest |X|
// the problem reports (0: none known).
class FarFromOrigin : public RoundedSpring {
 public:
  static constexpr double kPosition = 1000.0, kStiffness = 1e3, kTarget = 3.14159265358979e-9;
  explicit FarFromOrigin(double length) : RoundedSpring(kStiffness, kTarget, 0.0), length_(length) {}
  double lengthScale() const override { return length_; }

 protected:
  double internalForce(double x) const override { return kStiffness * ((kPosition + x) - kPosition); }

 private:
  double length_;
};

TEST(ResidualTest, AnUpdateAtThePositionsRoundOffConvergesUnderTheForceScaledBound) {
  const auto scaled = ResidualTolerance::forceScaled(ResidualTolerance::kDefaultFactor);
  FarFromOrigin measured(FarFromOrigin::kPosition);
  const Solve solve = newtonOn(measured, scaled, 1e-10);
  EXPECT_EQ(solve.status, NOX::StatusTest::Converged);
  EXPECT_EQ(solve.iterations, 2);  // the step to u*, then one update at the rounding of X + x
  EXPECT_NEAR(solve.x, FarFromOrigin::kTarget, 2.3e-13);
  // The same solve knowing no length (0) has no floor and iterates on the rounding until MaxIters.
  FarFromOrigin unknown(0.0);
  EXPECT_EQ(newtonOn(unknown, scaled, 1e-10).status, NOX::StatusTest::Failed);
  // A deck's absolute tolerance keeps the update test as it is: no floor there either.
  FarFromOrigin absolute(FarFromOrigin::kPosition);
  EXPECT_EQ(newtonOn(absolute, ResidualTolerance::absolute(1e-20), 1e-10).status, NOX::StatusTest::Failed);
}

TEST(ResidualTolerance, TheRoundOffFloorIsForceScaledAndAtMostTheLooseFraction) {
  const auto scaled = ResidualTolerance::forceScaled(ResidualTolerance::kDefaultFactor);
  const double F = 3e-5;
  EXPECT_DOUBLE_EQ(scaled.floorAt(F, 2e-12), 2e-12);
  EXPECT_DOUBLE_EQ(scaled.floorAt(F, 1.0), ResidualTolerance::kLooseFraction * F);  // never a loose acceptance
  EXPECT_EQ(scaled.floorAt(0.0, 2e-12), 0.0);  // a state carrying no force: still no absolute bound
  EXPECT_EQ(ResidualTolerance::absolute(1e-8).floorAt(F, 2e-12), 0.0);  // the deck's tolerance decides alone
}

// A strain formed as a solid kernel forms it, (1 + x) − 1 (F − I with F = I + GRAD u), times E against the
// load E u*: the sum 1 + x is rounded to 1.1e-16 whatever x is, so at u* = 1e-9 the internal force carries
// 8.3e-8 of itself as rounding (measured here: (1 + 1e-9) − 1 − 1e-9 = 8.27e-17), above the force-scaled
// bound 1e-10 E u*. The problem reports `roundOff` as the rounding level of its force (the model's
// ForceRoundOff: ε |K| δX = E ε here).
class TinyStrain : public RoundedSpring {
 public:
  static constexpr double kModulus = 1e3, kTarget = 1e-9;
  explicit TinyStrain(double roundOff) : RoundedSpring(kModulus, kTarget, kTarget), roundOff_(roundOff) {}  // the exact predictor
  double lengthScale() const override { return 1.0; }
  double forceRoundOff() const override { return roundOff_; }

 protected:
  double internalForce(double x) const override { return kModulus * ((1.0 + x) - 1.0); }

 private:
  double roundOff_;
};

TEST(ResidualTest, TheRoundOffFloorAcceptsAnExactPredictorUntouched) {
  const auto scaled = ResidualTolerance::forceScaled(ResidualTolerance::kDefaultFactor);
  ResidualToleranceRecord record;
  TinyStrain floored(TinyStrain::kModulus * std::numeric_limits<double>::epsilon());
  const Solve solve = newtonOn(floored, scaled, 1e-10, &record);
  EXPECT_EQ(solve.status, NOX::StatusTest::Converged);
  EXPECT_EQ(solve.iterations, 0);
  EXPECT_EQ(solve.x, TinyStrain::kTarget);  // bit for bit: no step taken from the rounding
  EXPECT_EQ(record.floorAcceptances, 1);
  EXPECT_NE(record.floorSummary().find("round-off floor decided 1 Newton solve"), std::string::npos)
      << record.floorSummary();
  EXPECT_GT(record.lastBound, ResidualTolerance::kDefaultFactor * record.lastForceScale);
  // Without it (a force scale that knows no rounding level) Newton steps on the rounding, and the update
  // at the positions' round-off then stops it 8.3e-8 away from the exact predictor it started from.
  ResidualToleranceRecord none;
  TinyStrain unfloored(0.0);
  const Solve moved = newtonOn(unfloored, scaled, 1e-10, &none);
  EXPECT_EQ(moved.status, NOX::StatusTest::Converged);
  EXPECT_GE(moved.iterations, 1);
  EXPECT_GT(std::abs(moved.x - TinyStrain::kTarget), 5e-8 * TinyStrain::kTarget);
  EXPECT_EQ(none.floorAcceptances, 0);
  EXPECT_TRUE(none.floorSummary().empty());
  // A deck's absolute tolerance is not floored: 1e-20 is not reached, and the update test alone stops.
  ResidualToleranceRecord deck;
  TinyStrain withDeckTolerance(TinyStrain::kModulus * std::numeric_limits<double>::epsilon());
  newtonOn(withDeckTolerance, ResidualTolerance::absolute(1e-20), 1e-10, &deck);
  EXPECT_EQ(deck.floorAcceptances, 0);
}

// A linear elastic Q4 rectangle W × H (nx × ny cells), held in x on its left side and in y at its bottom.
auto heldRectangle(int nx, int ny, double W, double H, double E, double nu) {
  using namespace contessa;
  auto deck = test::newProblem();
  test::setGrid(deck->sublist("Mesh"), "Rectangle", {nx, ny}, {W, H});
  test::addBlock(*deck, "block_1", "Q4", "steel");
  test::addMaterial(*deck, "steel", "Linear Elastic", E, nu);
  test::addDirichlet(*deck, "hold x", "left", "x");
  test::addDirichlet(*deck, "hold y", "bottom", "y");
  return deck;
}

// F of the model at a homogeneous state: x = (e X, 0) on a W × H rectangle of nx × ny Q4 of linear elastic
// material (plane strain), σxx = (λ + 2μ) e, σyy = λ e, σxy = 0: the internal force is σ·n over the
// boundary, lumped to the nodes (σxx hy on a right or left edge node, half at a corner; σyy hx on a top or
// bottom node, half at a corner), zero inside; so F² = 2[(ny − 1)(σxx hy)² + 2(σxx hy / 2)²] +
// 2[(nx − 1)(σyy hx)² + 2(σyy hx / 2)²], whatever the partition.
TEST(ForceScale, IsTheNormOfTheInternalForcesAtAKnownState) {
  using namespace contessa;
  const int nx = 4, ny = 3;
  const double W = 4.0, H = 1.5, E = 200.0, nu = 0.3, e = 1e-3;
  auto deck = heldRectangle(nx, ny, W, H, E, nu);
  const auto problem = test::buildOn(*deck, test::everyRank());
  auto m = test::makeModel(problem);
  auto x = Thyra::createMember(m->get_x_space());
  using Extract = Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>;
  auto tx = Extract::getTpetraVector(x);
  // x = e X at every x-DOF (DOF = dim · global node + component), X from this rank's part of the mesh.
  const auto& part = problem.mesh;
  std::map<model::GO, double> X;
  for (std::size_t n = 0; n < part.part.globalNodes.size(); ++n)
    X[static_cast<model::GO>(part.part.globalNodes[n])] = part.local().coordinates[2 * n];
  auto v = tx->getDataNonConst(0);
  for (Teuchos::ArrayRCP<double>::size_type i = 0; i < v.size(); ++i) {
    const auto dof = tx->getMap()->getGlobalElement(static_cast<model::LO>(i));
    v[i] = dof % 2 == 0 ? e * X.at(dof / 2) : 0.0;
  }
  v = Teuchos::null;
  test::evaluate(*m, *x, 0.0, false);
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double sxx = (lambda + 2 * mu) * e, syy = lambda * e, hx = W / nx, hy = H / ny;
  const double expected = std::sqrt(2 * ((ny - 1) * std::pow(sxx * hy, 2) + 2 * std::pow(sxx * hy / 2, 2)) +
                                    2 * ((nx - 1) * std::pow(syy * hx, 2) + 2 * std::pow(syy * hx / 2, 2)));
  EXPECT_NEAR(m->forceScale(), expected, 1e-12 * expected);
  // The out-of-balance force: f_int on the free rows, i.e. the right edge's x and the top edge's y forces,
  // half of F² here.
  EXPECT_NEAR(m->outOfBalanceNorm(), expected / std::sqrt(2.0), 1e-12 * expected);
  // A rigid shift of 1 in y leaves f_int alone and puts 1 (a length) in each bottom node's prescribed row:
  // ||f|| sees it; the out-of-balance force is no measure while a prescribed row does not hold (infinite,
  // so that no force-relative test passes, e.g. at a solve's first iterate from rest under a prescribed
  // displacement, where f_int and f_free are both 0).
  {
    auto shifted = x->clone_v();
    auto ts = Extract::getTpetraVector(shifted);
    auto sv = ts->getDataNonConst(0);
    for (Teuchos::ArrayRCP<double>::size_type i = 0; i < sv.size(); ++i)
      if (ts->getMap()->getGlobalElement(static_cast<model::LO>(i)) % 2 == 1) sv[i] += 1.0;
    sv = Teuchos::null;
    const auto e1 = test::evaluate(*m, *shifted, 0.0, false);
    EXPECT_NEAR(m->forceScale(), expected, 1e-12 * expected);
    EXPECT_TRUE(std::isinf(m->outOfBalanceNorm()));
    EXPECT_NEAR(Thyra::norm_2(*e1.f), std::sqrt(expected * expected / 2 + (nx + 1)), 1e-12 * (nx + 1));
  }
  test::evaluate(*m, *x, 0.0, false);
  // Linear in the state here: twice the strain, twice the scale; and none at rest.
  Thyra::scale(2.0, x.ptr());
  test::evaluate(*m, *x, 0.0, false);
  EXPECT_NEAR(m->forceScale(), 2 * expected, 2e-12 * expected);
  Thyra::assign(x.ptr(), 0.0);
  test::evaluate(*m, *x, 0.0, false);
  EXPECT_EQ(m->forceScale(), 0.0);
}

// The model's rounding level (model/ForceRoundOff.hpp) at the exact solution of a linear problem, where f_free
// is rounding alone: a W × H rectangle of Q4 (linear elastic, plane strain) stretched by a prescribed
// u_x = e W on its right edge, held in x on the left and in y at the bottom; the exact field u = (e X,
// −ν' e Y), ν' = λ/(λ + 2μ), is linear, so every Q4 holds it and the free rows' forces vanish in exact
// arithmetic. At e = 1e-9 what the model computes for them is its own rounding: the estimate must lie above
// it and not far above (measured: ||f_free|| = 3.1e-14 against a level of 2.4e-13, 7.7 times, on 1 and 2
// ranks; the rounding is the same 3.1e-14 at e = 1e-3: it does not scale with the strain), and above
// 1e-10 F, so that the floor decides there; at e = 1e-3 it stays below 1e-10 F (the floor never decides at
// ordinary strains). The level does not depend on the state.
TEST(ForceScale, TheRoundOffLevelBoundsTheRoundingOfAnExactLinearState) {
  using namespace contessa;
  const int nx = 5, ny = 3;
  const double W = 4.1, H = 1.7, E = 210.0, nu = 0.3;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu)), lateral = lambda / (lambda + 2 * mu);
  for (const double e : {1e-9, 1e-3}) {
    auto deck = heldRectangle(nx, ny, W, H, E, nu);
    test::addDirichlet(*deck, "stretch", "right", "x").set("Value", e * W);
    const auto problem = test::buildOn(*deck, test::everyRank());
    auto m = test::makeModel(problem);
    auto x = Thyra::createMember(m->get_x_space());
    using Extract = Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>;
    auto tx = Extract::getTpetraVector(x);
    const auto& part = problem.mesh;
    std::map<model::GO, std::pair<double, double>> X;
    for (std::size_t n = 0; n < part.part.globalNodes.size(); ++n)
      X[static_cast<model::GO>(part.part.globalNodes[n])] = {part.local().coordinates[2 * n], part.local().coordinates[2 * n + 1]};
    auto v = tx->getDataNonConst(0);
    for (Teuchos::ArrayRCP<double>::size_type i = 0; i < v.size(); ++i) {
      const auto dof = tx->getMap()->getGlobalElement(static_cast<model::LO>(i));
      const auto& at = X.at(dof / 2);
      v[i] = dof % 2 == 0 ? e * at.first : -lateral * e * at.second;
    }
    v = Teuchos::null;
    test::evaluate(*m, *x, 1.0, false);
    const double rounding = m->outOfBalanceNorm(), level = m->forceRoundOff(), F = m->forceScale();
    ASSERT_TRUE(std::isfinite(rounding)) << "the prescribed rows hold";
    EXPECT_GT(F, 0.0);
    if (e < 1e-6) {
      EXPECT_GT(rounding, 0.0) << "the state is exact: f_free is rounding only";
      EXPECT_GE(level, rounding);
      EXPECT_LE(level, 100 * rounding);
      EXPECT_GT(level, ResidualTolerance::kDefaultFactor * F) << "1e-10 F is below the rounding here";
      EXPECT_GT(rounding, ResidualTolerance::kDefaultFactor * F);
    } else {
      EXPECT_LT(level, ResidualTolerance::kDefaultFactor * F) << "the floor stays out of ordinary strains";
    }
    // The level is the reference stiffness's: the same at rest.
    const double atStrain = level;
    Thyra::assign(x.ptr(), 0.0);
    test::evaluate(*m, *x, 0.0, false);
    EXPECT_DOUBLE_EQ(m->forceRoundOff(), atStrain);
  }
}

}  // namespace
