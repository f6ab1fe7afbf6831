// JacobianCheck (--check-jacobian): it finds the model's own Jacobian right, catches a wrong one (a
// matrix 0.1 % off, one entry changed) and names where, checks the consistent tangent where Newton's W
// carries slip-reversal secants (and says so), and leaves the model's evaluation state (trial histories,
// the latest pass) exactly as it was; on 1 and 2 ranks.
#include <gtest/gtest.h>

#include <cmath>

#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>
#include <Tpetra_Core.hpp>

#include "deck/ProblemDefinition.hpp"
#include "model/JacobianCheck.hpp"
#include "solvers/LinearSolverFactory.hpp"
#include "BlockOnBase.hpp"
#include "ModelHarness.hpp"
#include "TestDeck.hpp"

namespace {

using namespace contessa;
using Teuchos::RCP;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>;

// A 3 × 2 Neo-Hookean enhanced block pressed onto a rigid base and sheared (friction, stick).
deck::ProblemDefinition blockOnBase() {
  test::BlockOnBase deck;
  deck.elementsX = 3;
  deck.slipTolerance.reset();
  deck.friction = 1.0;
  return deck.problem(test::everyRank());
}

// A 1 x 1 x 1 mm linear elastic block (2 x 1 x 1 Hex8) pressed lightly onto a rigid base (t_N = -2 MPa at zero displacement)
// with Coulomb friction (mu = 0.3, eps_T = 1e6 MPa/mm, constant): the stick radius mu|t_N|/eps_T is
// 6e-7 mm, below the check's step h = 1e-6 mm, as at the first iterates of the 3D Coulomb block
// (inputs/verification/coulomb_block_3d.xml). `twoFaces`: the base is two coplanar faces meeting at x = 0.5,
// under the block's middle row of bottom nodes.
deck::ProblemDefinition blockOnBase3d(bool twoFaces = false) {
  auto p = test::newProblem();
  test::setGrid(p->sublist("Mesh"), "Box", {2, 1, 1});
  test::addBlock(*p, "block_1", "Hex8", "elastic");
  test::addMaterial(*p, "elastic", "Linear Elastic", 1000.0, 0.0);
  test::addDirichlet(*p, "top", "top", "y").set("Value", 0.0);
  auto& base = p->sublist("Contact").sublist("base");
  base.set("Slave Side Set", std::string("bottom"));
  base.set("Normal Penalty", 1e6);
  base.set("Tangential Penalty", 1e6);
  base.set("Friction Coefficient", 0.3);
  base.set("Slip Tolerance", 0.0);
  auto& rigid = base.sublist("Rigid Surface");
  if (twoFaces) {
    rigid.set("Points", test::arrayOf<double>({-1.0, 2e-6, -1.0, -1.0, 2e-6, 2.0, 0.5, 2e-6, 2.0, 0.5, 2e-6, -1.0,
                                               2.0, 2e-6, 2.0, 2.0, 2e-6, -1.0}));
    rigid.set("Facets", test::arrayOf<int>({0, 1, 2, 3, 3, 2, 4, 5}));
  } else {
    rigid.set("Points", test::arrayOf<double>({-1.0, 2e-6, -1.0, -1.0, 2e-6, 2.0, 2.0, 2e-6, 2.0, 2.0, 2e-6, -1.0}));
    rigid.set("Facets", test::arrayOf<int>({0, 1, 2, 3}));
  }
  rigid.set("Motion", test::arrayOf<double>({0.0, 0.0, 0.0}));
  return test::buildOn(*p, test::everyRank());
}

struct Fixture {
  explicit Fixture(deck::ProblemDefinition definition = blockOnBase()) : problem(std::move(definition)) { setUp(); }
  deck::ProblemDefinition problem;
  RCP<model::ContactMechanicsModel> model;
  RCP<Thyra::VectorBase<double>> x;
  void setUp() {
    model = test::makeModel(problem);
    // Every DOF moved by a smooth field, the bottom pushed into the base (the same on every partition).
    x = Thyra::createMember(model->get_x_space());
    auto tx = Extract::getTpetraVector(x);
    auto v = tx->getDataNonConst(0);
    for (Teuchos::ArrayRCP<double>::size_type i = 0; i < v.size(); ++i) {
      const auto gid = tx->getMap()->getGlobalElement(i);
      v[i] = gid % 2 == 1 ? -0.004 - 0.001 * std::sin(0.7 * gid) : 0.002 * std::cos(0.3 * gid);
    }
  }
  // The model's inputs at x and λ.
  Thyra::ModelEvaluatorBase::InArgs<double> at(double lambda) const {
    auto in = model->createInArgs();
    auto p = Thyra::createMember(model->get_p_space(0));
    Thyra::set_ele(0, lambda, p.ptr());
    in.set_x(x);
    in.set_p(0, p);
    return in;
  }
  RCP<Thyra::VectorBase<double>> residual(double lambda) const {
    auto out = model->createOutArgs();
    auto f = Thyra::createMember(model->get_f_space());
    out.set_f(f);
    model->evalModel(at(lambda), out);
    return f;
  }
  RCP<Thyra::LinearOpBase<double>> jacobian(double lambda) const {
    auto out = model->createOutArgs();
    auto W = model->create_W_op();
    out.set_W_op(W);
    model->evalModel(at(lambda), out);
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
  // No kink; where the residual bends within h (entries with a small slope and a real curvature), the
  // column is differenced again at a shorter step and both agree: the longer step's differences stand.
  EXPECT_EQ(r.nonSmoothColumns, 0);
  EXPECT_EQ(r.bentColumns, 0);
  // (f(x) twice: before the contact points are held and on the held branch)
  EXPECT_EQ(r.residualEvaluations, 2 + 2 * fx.model->get_x_space()->dim() + 2 * r.retriedColumns);
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

// The 3D slipping node of the Coulomb block: its slip direction n = t^trial/|t^trial| turns by about
// eps_T h / |t^trial| = 0.5 rad within the step, so central differences at h = 1e-6 mm were 50 % off W
// (which is right: the error fell as h², to 1e-6 at h = 1e-9 mm). The check sees the bend and
// differences those columns again at a shorter step.
TEST(JacobianCheck, DifferencesA3DSlippingNodeWithAShortEnoughStep) {
  Fixture fx(blockOnBase3d());
  auto tx = Extract::getTpetraVector(fx.x);
  tx->putScalar(0.0);
  fx.residual(0.0);  // every bottom node in contact (first contact: stick, no tangential traction)
  fx.model->commitState();
  // The bottom slides by 2e-6 mm in differing directions in the x-z plane: |t^trial| = eps_T |slip| ≈ 2,
  // more than mu |t_N| = 0.6, so every bottom node slips.
  {
    auto v = tx->getDataNonConst(0);
    for (Teuchos::ArrayRCP<double>::size_type i = 0; i < v.size(); ++i) {
      const auto gid = tx->getMap()->getGlobalElement(i);
      const long node = static_cast<long>(gid / 3);
      const double angle = 0.9 + 0.6 * node;
      if (gid % 3 == 0) v[i] = 2e-6 * std::cos(angle);
      if (gid % 3 == 2) v[i] = 2e-6 * std::sin(angle);
    }
  }
  fx.residual(0.0);
  int slipping = 0;  // (the model lists every slave node on every rank)
  for (const auto& n : fx.model->trialIncrement()) slipping += n.trialStatus == continuation::NodeStatus::Slip ? 1 : 0;
  ASSERT_EQ(slipping, 6);
  const auto r = model::JacobianCheck().check(*fx.model, *fx.x, 0.0);
  EXPECT_LT(r.worstRelativeError, 1e-5) << model::JacobianCheck::describe(r, *fx.model);
  EXPECT_LT(r.normwiseError, 1e-6);
  EXPECT_GT(r.bentColumns, 0);
  EXPECT_EQ(r.nonSmoothColumns, 0);

  // Still catches a wrong entry in those columns: a slave node's tangential stiffness halved.
  auto W = fx.jacobian(0.0);
  auto matrix = Teuchos::rcp_dynamic_cast<model::CrsMatrix>(Extract::getTpetraOperator(W), true);
  const model::GO target = fx.problem.contacts[0].slaveNodes[0] * 3 + 2;
  matrix->resumeFill();
  const model::LO row = matrix->getRowMap()->getLocalElement(target);
  if (row != Teuchos::OrdinalTraits<model::LO>::invalid()) {
    model::CrsMatrix::local_inds_host_view_type indices;
    model::CrsMatrix::values_host_view_type values;
    matrix->getLocalRowView(row, indices, values);
    double value = 0;
    for (std::size_t k = 0; k < indices.extent(0); ++k)
      if (matrix->getColMap()->getGlobalElement(indices(k)) == target) value = values(k);
    const double half = 0.5 * value;
    matrix->replaceGlobalValues(target, Teuchos::ArrayView<const model::GO>(&target, 1),
                                Teuchos::ArrayView<const double>(&half, 1));
  }
  matrix->fillComplete();
  const auto wrong = model::JacobianCheck().compare(*fx.model, *fx.x, 0.0, *W);
  // (|W - D| = |W|, measured against the floor of the shortened step, τ max_k |W_ik| / shrink ≈ 2 |W|)
  EXPECT_GT(wrong.worstRelativeError, 0.3) << model::JacobianCheck::describe(wrong, *fx.model);
  EXPECT_EQ(wrong.row, target);
  EXPECT_EQ(wrong.column, target);
}

// A slave node whose slip has just reversed: Newton's W gives it SlipReversalDamping's secant stiffness
// along its slip, which is the derivative of no residual (the residual is the same with or without it).
// The Tet10 Coulomb block's node 20 at the first iterate of increment 2 was such a node: W = 36.1 against
// FD = -119.4, differences that held from h = 1e-6 down to 1e-10 mm. check() compares the consistent
// tangent and counts the nodes; Newton's W itself (what check() compared before) is far off there.
TEST(JacobianCheck, ChecksTheConsistentTangentOfANodeWhoseSlipReversed) {
  Fixture fx(blockOnBase3d());
  auto tx = Extract::getTpetraVector(fx.x);
  // The bottom moved by `amount` along (0.6, 0, 0.8) (the top too: a rigid slide; y held).
  const auto slide = [&](double amount) {
    auto v = tx->getDataNonConst(0);
    for (Teuchos::ArrayRCP<double>::size_type i = 0; i < v.size(); ++i) {
      const auto gid = tx->getMap()->getGlobalElement(i);
      v[i] = gid % 3 == 0 ? 0.6 * amount : gid % 3 == 2 ? 0.8 * amount : 0.0;
    }
  };
  slide(0.0);
  fx.residual(0.0);  // every bottom node in contact, sticking without traction
  fx.model->commitState();
  slide(2e-6);  // |t^trial| = eps_T 2e-6 = 2 > mu |t_N| = 0.6: every bottom node slips
  fx.residual(0.0);
  fx.model->commitState();
  slide(-2e-6);  // back by 4e-6: t^trial = (0.6 - 4) along the slide, slipping the other way
  fx.residual(0.0);
  int reversed = 0;
  for (const auto& n : fx.model->trialIncrement()) reversed += n.slipReversed ? 1 : 0;
  ASSERT_EQ(reversed, 6);

  const auto r = model::JacobianCheck().check(*fx.model, *fx.x, 0.0);
  const std::string line = model::JacobianCheck::describe(r, *fx.model);
  EXPECT_LT(r.worstRelativeError, 1e-5) << line;
  EXPECT_LT(r.normwiseError, 1e-6) << line;
  EXPECT_EQ(r.nonSmoothColumns, 0) << line;
  EXPECT_EQ(r.secantTangentNodes, 6) << line;
  EXPECT_NE(line.find("; 6 slave node(s) with a secant slip tangent in Newton's W (slip reversed; checked: the "
                      "consistent one)"),
            std::string::npos)
      << line;

  // Newton's W at this iterate, the secants in: each node's stiffness along its slip is the secant of its
  // traction between the two slip states (a change of 2 mu |t_N| over the slide back) against a consistent 0.
  const auto newton = model::JacobianCheck().compare(*fx.model, *fx.x, 0.0, *fx.jacobian(0.0));
  EXPECT_GT(newton.worstRelativeError, 0.1) << model::JacobianCheck::describe(newton, *fx.model);
  EXPECT_GT(newton.normwiseError, 1e-3) << model::JacobianCheck::describe(newton, *fx.model);
  EXPECT_EQ(newton.secantTangentNodes, 0);  // compare() takes W as given
}

// A knife edge: the block's middle row of bottom nodes lies on the line x = 0.5 where the base's two coplanar
// faces meet, so a step of ±h along x puts such a node inside one face or the other (a facet change on one
// side; on a deformable master a step of a master node tilts the faces into a ridge or a valley instead, as
// under the ring of edges_ring_jacobian_3d). W is the derivative on the facet the node is on; the check holds
// each node's facet and contact point (ContactMechanicsModel::holdContactPoints), so every column is
// differenced on both sides on that facet, none on one side only, none left out.
TEST(JacobianCheck, HoldsEachNodesFacetOnAKnifeEdge) {
  Fixture fx(blockOnBase3d(true));
  auto tx = Extract::getTpetraVector(fx.x);
  tx->putScalar(0.0);
  fx.residual(0.0);  // every bottom node in contact, sticking (t_N = -2 MPa)
  // The knife edge is there: some slave node's x moved by ±1e-6 mm (the check's step) changes its facet.
  const auto facetsAt = [&](model::GO dof, double step) {
    const model::LO local = tx->getMap()->getLocalElement(dof);
    const bool mine = local != Teuchos::OrdinalTraits<model::LO>::invalid();
    if (mine) tx->getDataNonConst(0)[local] = step;
    fx.residual(0.0);
    if (mine) tx->getDataNonConst(0)[local] = 0.0;
    std::vector<int> facets;
    for (const auto& n : fx.model->trialIncrement()) facets.push_back(n.trialFacet);
    return facets;
  };
  int knifeEdges = 0;
  for (const auto node : fx.problem.contacts[0].slaveNodes)
    knifeEdges += facetsAt(3 * node, 1e-6) != facetsAt(3 * node, -1e-6) ? 1 : 0;
  ASSERT_EQ(knifeEdges, 2);  // the two bottom nodes at x = 0.5 (z = 0 and 1)
  fx.residual(0.0);

  const auto r = model::JacobianCheck().check(*fx.model, *fx.x, 0.0);
  const std::string line = model::JacobianCheck::describe(r, *fx.model);
  EXPECT_LT(r.worstRelativeError, 1e-5) << line;
  EXPECT_LT(r.normwiseError, 1e-6) << line;
  EXPECT_EQ(r.nonSmoothColumns, 0) << line;
  EXPECT_EQ(r.oneSidedColumns, 0) << line;
}

}  // namespace
