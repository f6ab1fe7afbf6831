// The model evaluator over Tpetra: the assembled Jacobian and ∂f/∂λ against finite differences of the
// residual, quadratic Newton convergence with the MUMPS solver, and the same answer on 1 and 2 ranks.
#include <gtest/gtest.h>

#include <cmath>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>
#include <Tpetra_Core.hpp>

#include "deck/ProblemDefinition.hpp"
#include "mesh/Partition.hpp"
#include "model/ContactMechanicsModel.hpp"
#include "solvers/LinearSolverFactory.hpp"

namespace {

using namespace contessa;
using Teuchos::RCP;
using Teuchos::rcp;
using MEB = Thyra::ModelEvaluatorBase;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>;

// A 4 × 3 block of Neo-Hookean enhanced quads: left edge clamped, right edge stretched by 30 % and
// sheared, a nodal force on the top: large deformation, every kind of boundary condition.
deck::ProblemDefinition makeProblem(const std::string& element) {
  auto p = Teuchos::getParametersFromXmlString(R"XML(
<ParameterList name="Problem">
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="Rectangle"/>
    <Parameter name="Length X" type="double" value="4.0"/>
    <Parameter name="Length Y" type="double" value="2.0"/>
    <Parameter name="Elements X" type="int" value="4"/>
    <Parameter name="Elements Y" type="int" value="3"/>
  </ParameterList>
  <ParameterList name="Blocks">
    <ParameterList name="block_1">
      <Parameter name="Element" type="string" value="Q4 Enhanced"/>
      <Parameter name="Material" type="string" value="rubber"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="rubber">
      <Parameter name="Model" type="string" value="Neo-Hookean"/>
      <Parameter name="Young's Modulus" type="double" value="100.0"/>
      <Parameter name="Poisson's Ratio" type="double" value="0.3"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Dirichlet Conditions">
    <ParameterList name="clamp x"><Parameter name="Node Set" type="string" value="left"/>
      <Parameter name="Component" type="string" value="x"/></ParameterList>
    <ParameterList name="clamp y"><Parameter name="Node Set" type="string" value="left"/>
      <Parameter name="Component" type="string" value="y"/></ParameterList>
    <ParameterList name="stretch"><Parameter name="Node Set" type="string" value="right"/>
      <Parameter name="Component" type="string" value="x"/><Parameter name="Value" type="double" value="1.2"/></ParameterList>
  </ParameterList>
  <ParameterList name="Nodal Forces">
    <ParameterList name="lift"><Parameter name="Node Set" type="string" value="top"/>
      <Parameter name="Component" type="string" value="y"/><Parameter name="Total Force" type="double" value="15.0"/></ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Reaction Node Sets" type="Array(string)" value="{left, right}"/>
  </ParameterList>
</ParameterList>)XML");
  p->sublist("Blocks").sublist("block_1").set("Element", element);
  return deck::buildProblem(*p, "");
}

RCP<model::ContactMechanicsModel> makeModel(const RCP<const Teuchos::Comm<int>>& comm, const deck::ProblemDefinition& problem) {
  Teuchos::ParameterList strat("Stratimikos");
  strat.set("Linear Solver Type", std::string("MUMPS"));
  auto lows = solvers::createLinearSolverFactory(strat);
  return rcp(new model::ContactMechanicsModel(comm, problem, mesh::partitionMesh(problem.mesh, comm->getSize()), lows));
}

struct Evaluation {
  RCP<Thyra::VectorBase<double>> f;
  RCP<Thyra::LinearOpBase<double>> W;
  RCP<Thyra::MultiVectorBase<double>> dfdp;
};

Evaluation evaluate(model::ContactMechanicsModel& m, const Thyra::VectorBase<double>& x, double lambda, bool withW) {
  auto in = m.createInArgs();
  auto p = Thyra::createMember(m.get_p_space(0));
  Thyra::set_ele(0, lambda, p.ptr());
  in.set_x(Teuchos::rcpFromRef(x));
  in.set_p(0, p);
  Evaluation e;
  e.f = Thyra::createMember(m.get_f_space());
  auto out = m.createOutArgs();
  out.set_f(e.f);
  if (withW) {
    e.W = m.create_W_op();
    e.dfdp = Thyra::createMembers(m.get_f_space(), 1);
    out.set_W_op(e.W);
    out.set_DfDp(0, MEB::Derivative<double>(e.dfdp, MEB::DERIV_MV_JACOBIAN_FORM));
  }
  m.evalModel(in, out);
  return e;
}

// A deformed state that inverts nothing: a smooth field, the same on every partition.
RCP<Thyra::VectorBase<double>> deformedState(const model::ContactMechanicsModel& m, double scale) {
  auto x = Thyra::createMember(m.get_x_space());
  auto tx = Extract::getTpetraVector(x);
  auto v = tx->getDataNonConst(0);
  for (Teuchos::ArrayRCP<double>::size_type i = 0; i < v.size(); ++i) {
    const auto gid = tx->getMap()->getGlobalElement(i);
    v[i] = scale * std::sin(0.7 * gid + 0.3) * (gid % 2 == 0 ? 1.0 : 0.6);
  }
  return x;
}

class ModelTest : public ::testing::TestWithParam<std::string> {};

TEST_P(ModelTest, JacobianAndDfDpMatchCentralDifferences) {
  auto comm = Tpetra::getDefaultComm();
  const auto problem = makeProblem(GetParam());
  auto m = makeModel(comm, problem);
  auto x = deformedState(*m, 0.15);
  const double lambda = 0.7;
  const auto e = evaluate(*m, *x, lambda, true);
  const double h = 1e-6;
  const auto n = m->get_x_space()->dim();
  double worst = 0, scale = 0;
  auto unit = Thyra::createMember(m->get_x_space());
  auto Wcol = Thyra::createMember(m->get_f_space());
  auto fd = Thyra::createMember(m->get_f_space());
  for (Thyra::Ordinal j = 0; j < n; ++j) {
    Thyra::assign(unit.ptr(), 0.0);
    Thyra::set_ele(j, 1.0, unit.ptr());
    Thyra::apply(*e.W, Thyra::NOTRANS, *unit, Wcol.ptr());
    auto xp = x->clone_v(), xm = x->clone_v();
    Thyra::Vp_StV(xp.ptr(), h, *unit);
    Thyra::Vp_StV(xm.ptr(), -h, *unit);
    const auto fp = evaluate(*m, *xp, lambda, false).f;
    const auto fm = evaluate(*m, *xm, lambda, false).f;
    Thyra::V_StVpStV(fd.ptr(), 0.5 / h, *fp, -0.5 / h, *fm);
    scale = std::max(scale, Thyra::norm_inf(*Wcol));
    Thyra::Vp_StV(fd.ptr(), -1.0, *Wcol);
    worst = std::max(worst, Thyra::norm_inf(*fd));
  }
  EXPECT_LT(worst / scale, 1e-6) << "max |W - FD| / max |W| over " << n << " columns";

  // ∂f/∂λ: f is affine in λ, so a central difference is exact up to round-off.
  const auto fp = evaluate(*m, *x, lambda + 1e-3, false).f;
  const auto fm = evaluate(*m, *x, lambda - 1e-3, false).f;
  Thyra::V_StVpStV(fd.ptr(), 0.5 / 1e-3, *fp, -0.5 / 1e-3, *fm);
  Thyra::Vp_StV(fd.ptr(), -1.0, *e.dfdp->col(0));
  EXPECT_LT(Thyra::norm_inf(*fd), 1e-8 * std::max(1.0, Thyra::norm_inf(*e.dfdp->col(0))));
}

// Full Newton from the undeformed state straight to λ = 1 (no continuation): the residual norms.
std::vector<double> newtonResiduals(model::ContactMechanicsModel& m, RCP<Thyra::VectorBase<double>>& x) {
  x = Thyra::createMember(m.get_x_space());
  Thyra::assign(x.ptr(), 0.0);
  auto lowsFactory = m.get_W_factory();
  std::vector<double> norms;
  for (int it = 0; it < 20; ++it) {
    auto e = evaluate(m, *x, 1.0, true);
    norms.push_back(Thyra::norm_2(*e.f));
    if (norms.back() < 1e-11 || !std::isfinite(norms.back())) break;
    auto lows = Thyra::linearOpWithSolve<double>(*lowsFactory, e.W.getConst());
    auto dx = Thyra::createMember(m.get_x_space());
    Thyra::assign(dx.ptr(), 0.0);
    const auto status = Thyra::solve<double>(*lows, Thyra::NOTRANS, *e.f, dx.ptr());
    EXPECT_EQ(status.solveStatus, Thyra::SOLVE_STATUS_CONVERGED);
    Thyra::Vp_StV(x.ptr(), -1.0, *dx);
  }
  return norms;
}

TEST_P(ModelTest, NewtonConvergesQuadratically) {
  auto comm = Tpetra::getDefaultComm();
  const auto problem = makeProblem(GetParam());
  auto m = makeModel(comm, problem);
  RCP<Thyra::VectorBase<double>> x;
  const auto norms = newtonResiduals(*m, x);
  std::ostringstream trace;
  for (double r : norms) trace << r << " ";
  ASSERT_LT(norms.back(), 1e-11) << trace.str();
  ASSERT_LE(norms.size(), 10u) << trace.str();
  // Quadratic: once in the basin, r_{k+1} / r_k^2 stays bounded while r_k falls by orders of magnitude.
  // Checked on the last steps before round-off, where r_k < 1e-2 r_0.
  int checked = 0;
  for (std::size_t k = 1; k + 1 < norms.size(); ++k) {
    if (norms[k] > 1e-2 * norms[0] || norms[k + 1] < 1e-12) continue;
    const double order = std::log(norms[k + 1] / norms[0]) / std::log(norms[k] / norms[0]);
    EXPECT_GT(order, 1.8) << "convergence order at iteration " << k << ": " << trace.str();
    ++checked;
  }
  EXPECT_GE(checked, 1) << trace.str();
  if (comm->getRank() == 0) std::printf("Newton residuals (%s): %s\n", GetParam().c_str(), trace.str().c_str());
}

// On several ranks: the same problem on rank 0 alone must give the same solution and reactions.
TEST_P(ModelTest, SameAnswerOnOneRankAndAllRanks) {
  auto comm = Tpetra::getDefaultComm();
  const auto problem = makeProblem(GetParam());
  auto m = makeModel(comm, problem);
  RCP<Thyra::VectorBase<double>> x;
  const auto norms = newtonResiduals(*m, x);
  const double normAll = Thyra::norm_2(*x);
  const auto reactionsAll = m->reactions(*Extract::getConstTpetraVector(x), 1.0);

  auto self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  if (comm->getRank() == 0) {
    auto serial = makeModel(self, problem);
    RCP<Thyra::VectorBase<double>> xs;
    newtonResiduals(*serial, xs);
    EXPECT_NEAR(Thyra::norm_2(*xs), normAll, 1e-10 * normAll);
    const auto reactionsSerial = serial->reactions(*Extract::getConstTpetraVector(xs), 1.0);
    for (std::size_t s = 0; s < reactionsAll.size(); ++s)
      for (int c = 0; c < 2; ++c)
        EXPECT_NEAR(reactionsSerial[s].force[c], reactionsAll[s].force[c], 1e-9 * std::max(1.0, std::abs(reactionsAll[s].force[c])));
  }
  // Equilibrium: the reactions balance the applied nodal force (15 upwards at λ = 1).
  EXPECT_NEAR(reactionsAll[0].force[1] + reactionsAll[1].force[1], -15.0, 1e-8);
  EXPECT_NEAR(reactionsAll[0].force[0] + reactionsAll[1].force[0], 0.0, 1e-8);
}

INSTANTIATE_TEST_SUITE_P(Elements, ModelTest, ::testing::Values("Q4", "Q4 Enhanced"),
                         [](const auto& info) { return info.param == "Q4" ? std::string("Q4") : std::string("Q4Enhanced"); });

}  // namespace

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  // Only rank 0 reports, so a 2-rank run prints one result.
  if (Tpetra::getDefaultComm()->getRank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
