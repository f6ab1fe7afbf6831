// JacobianCheck (--check-jacobian): it finds the model's own Jacobian right, catches a wrong one (a
// matrix 0.1 % off, one entry changed) and names where, and leaves the model's evaluation state (trial
// histories, the latest pass) exactly as it was; on 1 and 2 ranks.
#include <gtest/gtest.h>

#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>
#include <Tpetra_Core.hpp>

#include "deck/ProblemDefinition.hpp"
#include "mesh/Partition.hpp"
#include "model/JacobianCheck.hpp"
#include "solvers/LinearSolverFactory.hpp"

namespace {

using namespace contessa;
using Teuchos::RCP;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>;

// A 3 × 2 Neo-Hookean enhanced block pressed onto a rigid base and sheared (friction, stick).
deck::ProblemDefinition blockOnBase() {
  auto p = Teuchos::getParametersFromXmlString(R"XML(
<ParameterList name="Problem">
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="Rectangle"/>
    <Parameter name="Length X" type="double" value="2.0"/>
    <Parameter name="Elements X" type="int" value="3"/>
    <Parameter name="Elements Y" type="int" value="2"/>
    <Parameter name="Y Origin" type="double" value="0.001"/>
  </ParameterList>
  <ParameterList name="Blocks">
    <ParameterList name="block_1"><Parameter name="Element" type="string" value="Q4 Enhanced"/>
      <Parameter name="Material" type="string" value="rubber"/></ParameterList>
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="rubber"><Parameter name="Model" type="string" value="Neo-Hookean"/>
      <Parameter name="Young's Modulus" type="double" value="100.0"/>
      <Parameter name="Poisson's Ratio" type="double" value="0.3"/></ParameterList>
  </ParameterList>
  <ParameterList name="Dirichlet Conditions">
    <ParameterList name="press"><Parameter name="Node Set" type="string" value="top"/>
      <Parameter name="Component" type="string" value="y"/><Parameter name="Value" type="double" value="-0.05"/></ParameterList>
    <ParameterList name="shear"><Parameter name="Node Set" type="string" value="top"/>
      <Parameter name="Component" type="string" value="x"/><Parameter name="Value" type="double" value="0.02"/></ParameterList>
  </ParameterList>
  <ParameterList name="Contact">
    <ParameterList name="base"><Parameter name="Slave Side Set" type="string" value="bottom"/>
      <Parameter name="Normal Penalty" type="double" value="1e4"/>
      <Parameter name="Tangential Penalty" type="double" value="1e4"/>
      <Parameter name="Friction Coefficient" type="double" value="1.0"/>
      <ParameterList name="Rigid Surface">
        <Parameter name="Points" type="Array(double)" value="{3.0, 0.0, -1.0, 0.0}"/>
        <Parameter name="Motion" type="Array(double)" value="{0.0, 0.0}"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>)XML");
  return deck::buildProblem(*p, "");
}

struct Fixture {
  deck::ProblemDefinition problem = blockOnBase();
  RCP<model::ContactMechanicsModel> model;
  RCP<Thyra::VectorBase<double>> x;
  Fixture() {
    auto comm = Tpetra::getDefaultComm();
    Teuchos::ParameterList strat("Stratimikos");
    strat.set("Linear Solver Type", std::string("MUMPS"));
    model = Teuchos::rcp(new model::ContactMechanicsModel(comm, problem, mesh::partitionMesh(problem.mesh, comm->getSize()),
                                                          solvers::createLinearSolverFactory(strat)));
    // Every DOF moved by a smooth field, the bottom pushed into the base (the same on every partition).
    x = Thyra::createMember(model->get_x_space());
    auto tx = Extract::getTpetraVector(x);
    auto v = tx->getDataNonConst(0);
    for (Teuchos::ArrayRCP<double>::size_type i = 0; i < v.size(); ++i) {
      const auto gid = tx->getMap()->getGlobalElement(i);
      v[i] = gid % 2 == 1 ? -0.004 - 0.001 * std::sin(0.7 * gid) : 0.002 * std::cos(0.3 * gid);
    }
  }
  RCP<Thyra::VectorBase<double>> residual(double lambda) const {
    auto in = model->createInArgs();
    auto p = Thyra::createMember(model->get_p_space(0));
    Thyra::set_ele(0, lambda, p.ptr());
    in.set_x(x);
    in.set_p(0, p);
    auto out = model->createOutArgs();
    auto f = Thyra::createMember(model->get_f_space());
    out.set_f(f);
    model->evalModel(in, out);
    return f;
  }
  RCP<Thyra::LinearOpBase<double>> jacobian(double lambda) const {
    auto in = model->createInArgs();
    auto p = Thyra::createMember(model->get_p_space(0));
    Thyra::set_ele(0, lambda, p.ptr());
    in.set_x(x);
    in.set_p(0, p);
    auto out = model->createOutArgs();
    auto W = model->create_W_op();
    out.set_W_op(W);
    model->evalModel(in, out);
    return W;
  }
};

TEST(JacobianCheck, FindsTheModelsJacobianRightAndLeavesNoTrace) {
  Fixture fx;
  const auto before = fx.residual(0.8);
  ASSERT_GT(fx.model->trialIncrement().size(), 0u);
  const auto gaps = fx.model->trialIncrement();
  const int passes = fx.model->elementPasses();
  const auto r = model::JacobianCheck().check(*fx.model, *fx.x, 0.8);
  EXPECT_LT(r.worstRelativeError, 1e-5) << model::JacobianCheck::describe(r, *fx.model);
  EXPECT_LT(r.normwiseError, 1e-6);
  EXPECT_EQ(r.residualEvaluations, 1 + 2 * fx.model->get_x_space()->dim());
  // No trace: the same latest pass (the residual is served from it, no new element pass), the same
  // contact trial state, the same residual to the bit.
  EXPECT_EQ(fx.model->elementPasses(), passes);
  const auto after = fx.residual(0.8);
  EXPECT_EQ(fx.model->elementPasses(), passes);
  auto difference = before->clone_v();
  Thyra::Vp_StV(difference.ptr(), -1.0, *after);
  EXPECT_EQ(Thyra::norm_inf(*difference), 0.0);
  const auto gapsAfter = fx.model->trialIncrement();
  ASSERT_EQ(gaps.size(), gapsAfter.size());
  for (std::size_t k = 0; k < gaps.size(); ++k) {
    EXPECT_EQ(gaps[k].trialGap, gapsAfter[k].trialGap) << k;
    EXPECT_EQ(gaps[k].trialStatus, gapsAfter[k].trialStatus) << k;
  }
}

// The must-fail side: a matrix 0.1 % off everywhere, and one with a single entry changed.
TEST(JacobianCheck, CatchesAWrongJacobianAndSaysWhere) {
  Fixture fx;
  auto W = fx.jacobian(0.8);
  auto matrix = Teuchos::rcp_dynamic_cast<model::CrsMatrix>(Extract::getTpetraOperator(W), true);
  matrix->resumeFill();
  matrix->scale(1.001);
  matrix->fillComplete();
  const auto scaled = model::JacobianCheck().compare(*fx.model, *fx.x, 0.8, *W);
  EXPECT_GT(scaled.worstRelativeError, 0.9e-3);
  EXPECT_GT(scaled.normwiseError, 0.9e-3);

  // One entry: row and column of the first slave node's y DOF (its contact stiffness) halved.
  W = fx.jacobian(0.8);
  matrix = Teuchos::rcp_dynamic_cast<model::CrsMatrix>(Extract::getTpetraOperator(W), true);
  const model::GO target = fx.problem.contacts[0].slaveNodes[1] * 2 + 1;
  matrix->resumeFill();
  const model::LO row = matrix->getRowMap()->getLocalElement(target);
  if (row != Teuchos::OrdinalTraits<model::LO>::invalid()) {
    const double value = [&] {
      model::CrsMatrix::local_inds_host_view_type indices;
      model::CrsMatrix::values_host_view_type values;
      matrix->getLocalRowView(row, indices, values);
      for (std::size_t k = 0; k < indices.extent(0); ++k)
        if (matrix->getColMap()->getGlobalElement(indices(k)) == target) return values(k);
      return 0.0;
    }();
    const model::GO col = target;
    const double half = 0.5 * value;
    matrix->replaceGlobalValues(target, Teuchos::ArrayView<const model::GO>(&col, 1), Teuchos::ArrayView<const double>(&half, 1));
  }
  matrix->fillComplete();
  const auto one = model::JacobianCheck().compare(*fx.model, *fx.x, 0.8, *W);
  EXPECT_NEAR(one.worstRelativeError, 1.0, 0.01) << model::JacobianCheck::describe(one, *fx.model);
  EXPECT_EQ(one.row, target);
  EXPECT_EQ(one.column, target);
  const std::string line = model::JacobianCheck::describe(one, *fx.model);
  EXPECT_NE(line.find("contact 'base' slave node " + std::to_string(target / 2 + 1)), std::string::npos) << line;
}

}  // namespace

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  if (Tpetra::getDefaultComm()->getRank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  return RUN_ALL_TESTS();
}
