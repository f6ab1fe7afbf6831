// The Newton residual test's absolute bound (solvers/ResidualTolerance.hpp, ResidualTest.hpp): the deck's
// absolute tolerance or c · F; the decision on either side of the bound; the loose acceptance said once; a
// NOX Newton whose iterations do not depend on the unit of force under the force-scaled bound (and stops at
// its predictor under a small absolute one, the audit's soft inflation); and F = ||f_int|| of the model at a
// homogeneous state whose nodal forces are known in closed form, on 1 and 2 ranks.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
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
};

// A NOX full-step Newton from x = 1.05 (a predictor near the root 1) with ResidualTest alone (no relative or
// update test) under `bound`.
Solve newton(double unit, const ResidualTolerance& bound) {
  ScaledCubic problem(unit, 1.05);
  auto group = Teuchos::rcp(new NOX::LAPACK::Group(problem));
  auto residual = Teuchos::rcp(new ResidualTest(bound, &problem, 0.0, 0.0, nullptr));
  auto combo = Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
  combo->addStatusTest(residual);
  combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::MaxIters(30)));
  auto params = Teuchos::rcp(new Teuchos::ParameterList);
  params->set("Nonlinear Solver", "Line Search Based");
  params->sublist("Printing").set("Output Information", 0);
  auto solver = NOX::Solver::buildSolver(group, combo, params);
  EXPECT_EQ(solver->solve(), NOX::StatusTest::Converged);
  const auto& x = dynamic_cast<const NOX::LAPACK::Vector&>(solver->getSolutionGroup().getX());
  return {solver->getNumIterations(), x(0)};
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

// F of the model at a homogeneous state: x = (e X, 0) on a W × H rectangle of nx × ny Q4 of linear elastic
// material (plane strain), σxx = (λ + 2μ) e, σyy = λ e, σxy = 0: the internal force is σ·n over the
// boundary, lumped to the nodes (σxx hy on a right or left edge node, half at a corner; σyy hx on a top or
// bottom node, half at a corner), zero inside; so F² = 2[(ny − 1)(σxx hy)² + 2(σxx hy / 2)²] +
// 2[(nx − 1)(σyy hx)² + 2(σyy hx / 2)²], whatever the partition.
TEST(ForceScale, IsTheNormOfTheInternalForcesAtAKnownState) {
  using namespace contessa;
  const int nx = 4, ny = 3;
  const double W = 4.0, H = 1.5, E = 200.0, nu = 0.3, e = 1e-3;
  auto deck = test::newProblem();
  test::setGrid(deck->sublist("Mesh"), "Rectangle", {nx, ny}, {W, H});
  test::addBlock(*deck, "block_1", "Q4", "steel");
  test::addMaterial(*deck, "steel", "Linear Elastic", E, nu);
  test::addDirichlet(*deck, "hold x", "left", "x");
  test::addDirichlet(*deck, "hold y", "bottom", "y");
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

}  // namespace
