// Load steps in the assembled model (ContactMechanicsModel::setLoadStep, BoundaryConditions,
// ExternalLoads, ContactAssembly; continuation::LoadSchedule): a block with every kind of scheduled value
// (a Dirichlet value, a follower pressure, a traction, a body force, a nodal force, a rigid base's
// motion) whose second step changes all of them along a tabulated amplitude. The residual is continuous
// across the step boundary, ∂f/∂λ of the second step (the amplitude's slope included) matches central
// differences of the residual, and the loads' totals are the schedule's values. 1 and 2 ranks.
#include <gtest/gtest.h>

#include <cmath>

#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

#include "../model/ModelHarness.hpp"
#include "TestDeck.hpp"

namespace {

using namespace contessa;
using test::evaluate;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>;

// 4 × 3 block of Neo-Hookean Q4 Enhanced on a frictionless rigid base (y = 0, pushed up into the block by
// its Motion); step "two" changes every value, A(t) = {0, 0.5, 0.9} at t = {0, 0.25, 1}.
deck::ProblemDefinition makeProblem() {
  using test::arrayOf;
  auto p = test::newProblem();
  test::setGrid(p->sublist("Mesh"), "Rectangle", {4, 3}, {4.0, 3.0});
  test::addBlock(*p, "block_1", "Q4 Enhanced", "rubber");
  test::addMaterial(*p, "rubber", "Neo-Hookean", 100.0, 0.3);
  test::addDirichlet(*p, "hold", "left", "x").set("Value", 0.01);
  test::addNodalForce(*p, "pull", "right", "x", 1.0);
  auto& loads = p->sublist("Loads");
  loads.sublist("push").set("Type", std::string("Pressure")).set("Side Set", std::string("right")).set("Pressure", 2.5);
  loads.sublist("drag").set("Type", std::string("Traction")).set("Side Set", std::string("top"))
      .set("Traction", arrayOf({0.3, -1.1}));
  loads.sublist("weight").set("Type", std::string("Body Force")).set("Force Per Volume", arrayOf({-0.2, 0.5}));
  auto& base = p->sublist("Contact").sublist("base");
  base.set("Slave Side Set", std::string("bottom"));
  base.sublist("Rigid Surface").set("Points", arrayOf({5.0, 0.0, -1.0, 0.0})).set("Motion", arrayOf({0.0, 0.02}));
  base.set("Normal Penalty", 1e4);
  auto& steps = p->sublist("Load Steps");
  steps.sublist("one").set("Time Period", 0.5);
  auto& two = steps.sublist("two");
  two.sublist("Dirichlet Conditions").set("hold", -0.02);
  two.sublist("Loads").set("push", 4.0).set("pull", 3.0).set("drag", arrayOf({1.0, 0.5})).set("weight", arrayOf({0.1, 0.0}));
  two.sublist("Contact").sublist("base").set("Motion", arrayOf({0.05, 0.03}));
  two.sublist("Amplitude").set("Times", arrayOf({0.0, 0.25, 1.0})).set("Values", arrayOf({0.0, 0.5, 0.9}));
  return test::buildOn(*p, test::everyRank());
}

// A smooth displacement field (small, the bottom pressed into the base where the base rises).
Teuchos::RCP<Thyra::VectorBase<double>> displacement(const model::ContactMechanicsModel& m,
                                                     const deck::ProblemDefinition& problem, double a) {
  auto x = Thyra::createMember(m.get_x_space());
  auto xt = Extract::getTpetraVector(x);
  const auto& map = *xt->getMap();
  auto v = xt->getDataNonConst(0);
  for (std::size_t k = 0; k < static_cast<std::size_t>(v.size()); ++k) {
    const auto gid = map.getGlobalElement(static_cast<model::LO>(k));
    const double* X = problem.mesh.local().coordinates.data() + problem.mesh.localNode(gid / 2) * 2;
    v[k] = a * (std::sin(0.4 * X[0] + gid % 2) * X[1] + 0.3 * X[0]);
  }
  return x;
}

TEST(LoadStepModel, ResidualIsContinuousAcrossTheStepBoundary) {
  const auto problem = makeProblem();
  auto m = test::makeModel(problem);
  ASSERT_EQ(m->numLoadSteps(), 2);
  auto x = displacement(*m, problem, 0.01);
  const auto end = evaluate(*m, *x, 1.0, false).f;
  m->setLoadStep(1);
  const auto start = evaluate(*m, *x, 0.0, false).f;
  auto diff = end->clone_v();
  Thyra::Vp_StV(diff.ptr(), -1.0, *start);
  EXPECT_LE(Thyra::norm_inf(*diff), 1e-12 * Thyra::norm_inf(*end));
  // …and the second step does move on from there.
  const auto later = evaluate(*m, *x, 0.5, false).f;
  Thyra::V_VmV(diff.ptr(), *later, *start);
  EXPECT_GT(Thyra::norm_inf(*diff), 0.1);
}

TEST(LoadStepModel, DerivativeInTheLoadFactorIsTheCurrentStepsWithTheAmplitudesSlope) {
  const auto problem = makeProblem();
  auto m = test::makeModel(problem);
  auto x = displacement(*m, problem, 0.01);
  for (int step : {0, 1})
    for (double lambda : {0.1, 0.55}) {  // the second step: both segments of its amplitude (slopes 2, 0.533)
      m->setLoadStep(step);
      const double h = 1e-5;
      const auto e = evaluate(*m, *x, lambda, true);
      auto fd = Thyra::createMember(m->get_f_space());
      Thyra::V_StVpStV(fd.ptr(), 0.5 / h, *evaluate(*m, *x, lambda + h, false).f, -0.5 / h,
                       *evaluate(*m, *x, lambda - h, false).f);
      auto diff = fd->clone_v();
      Thyra::Vp_StV(diff.ptr(), -1.0, *e.dfdp->col(0));
      EXPECT_LT(Thyra::norm_inf(*diff), 1e-7 * Thyra::norm_inf(*fd)) << "step " << step << ", lambda " << lambda;
      EXPECT_GT(Thyra::norm_inf(*fd), 0.1);
    }
}

TEST(LoadStepModel, LoadTotalsAreTheScheduledValues) {
  // At u = 0 (no contact force: the base has not risen at the start of step one… but at the end it
  // has: the totals are taken over the free DOFs' x components of the dead loads only, which the base's
  // normal force does not touch) — Σ f_x = −(t_x L_top + b_x A + F_pull) + p·L_right with every value
  // at the second step's λ = 0.6: a = 0.5 + 0.4 (0.35 / 0.75) = 0.68666…, v = v1 + a (v2 − v1).
  const auto problem = makeProblem();
  auto m = test::makeModel(problem);
  auto x = displacement(*m, problem, 0.0);
  m->setLoadStep(1);
  const double a = 0.5 + 0.4 * (0.35 / 0.75);
  const auto value = [a](double v1, double v2) { return v1 + a * (v2 - v1); };
  const double tx = value(0.3, 1.0), bx = value(-0.2, 0.1), pull = value(1.0, 3.0), p = value(2.5, 4.0);
  const auto f = Extract::getConstTpetraVector(evaluate(*m, *x, 0.6, false).f);
  const auto& map = *f->getMap();
  const auto v = f->getData(0);
  // The left edge's x rows are Dirichlet rows (u − ū): leave them out, with their share of the loads.
  double local = 0.0, global = 0.0;
  for (std::size_t k = 0; k < static_cast<std::size_t>(v.size()); ++k) {
    const auto gid = map.getGlobalElement(static_cast<model::LO>(k));
    if (gid % 2 == 0 && problem.mesh.local().coordinates[problem.mesh.localNode(gid / 2) * 2] > 0.0) local += v[k];
  }
  Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_SUM, 1, &local, &global);
  // Shares on the left edge (x = 0): the traction's end node (half of an edge of 1), the body force's
  // (half a column of cells of width 1: 1.5), none of the pull or the pressure (on the right edge).
  const double expected = -(tx * (4.0 - 0.5) + bx * (12.0 - 1.5) + pull) + p * 3.0;
  EXPECT_NEAR(global, expected, 1e-12 * std::abs(expected));
}

}  // namespace
