// LoadFactorDerivativeGroup (solvers/LoadFactorDerivativeGroup.hpp): the ∂f/∂λ it hands LOCA is the
// model's DfDp, agrees with a central difference of f in λ to the difference's own accuracy, costs no
// residual evaluation, and survives LOCA's cloning. The state is a Neo-Hookean block pressed and dragged
// on a rigid base that itself moves with λ, Coulomb friction (μ = 0.3) on the closed nodes, a follower
// pressure and a body force: every λ-dependent term of f but load steps (tests/unit/loadsteps) at once.
// LOCA's own group, for comparison, differences f forward in λ; its error is printed. 1 and 2 ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <LOCA.H>
#include <LOCA_Thyra.H>
#include <NOX_Thyra_MultiVector.H>
#include <NOX_Thyra_Vector.H>
#include <Thyra_VectorStdOps.hpp>
#include <Tpetra_Core.hpp>

#include "../model/ModelHarness.hpp"
#include "BlockOnBase.hpp"
#include "TestDeck.hpp"
#include "solvers/LoadFactorDerivativeGroup.hpp"

namespace {

using namespace contessa;
using solvers::LoadFactorDerivativeGroup;
using test::evaluate;
using Teuchos::RCP;
using Teuchos::rcp;

// The block of the friction model tests (BlockOnBase: its top pressed down 0.05 and dragged 0.03 by
// prescribed displacements), the rigid base moving by (0.01, 0.004) at λ = 1, μ = 0.3, a pressure of 2 on
// the block's right side and a body force.
deck::ProblemDefinition frictionalBlock() {
  test::BlockOnBase block;
  block.elementsX = 6;
  block.elementsY = 3;
  block.shear = 0.03;
  block.tangentialPenalty.reset();
  block.slipTolerance.reset();
  block.friction = 0.3;
  auto deck = block.deck();
  deck->sublist("Contact").sublist("base").sublist("Rigid Surface").set("Motion", test::arrayOf({0.01, 0.004}));
  auto& loads = deck->sublist("Loads");
  loads.sublist("push").set("Type", std::string("Pressure")).set("Side Set", std::string("right")).set("Pressure", 2.0);
  loads.sublist("weight").set("Type", std::string("Body Force")).set("Force Per Volume", test::arrayOf({0.3, -0.5}));
  return test::buildOn(*deck, test::everyRank());
}

// Converged at λ and committed, as LOCA leaves the state before it predicts the next increment.
void convergeAndCommit(model::ContactMechanicsModel& m, Thyra::VectorBase<double>& x, double lambda) {
  const auto norms = test::newtonAt(m, x, lambda, 1e-10, 40);
  ASSERT_LT(norms.back(), 1e-10) << "no convergence at load factor " << lambda;
  evaluate(m, x, lambda, false);
  m.commitState();
}

RCP<LOCA::GlobalData> locaGlobalData() {
  auto top = rcp(new Teuchos::ParameterList("LOCA test"));
  top->sublist("LOCA");
  top->sublist("NOX");
  return LOCA::createGlobalData(top);
}

// ∂f/∂λ as `group` computes it for LOCA (computeDfDpMulti, F not yet valid): column 1 of f, ∂f/∂λ.
RCP<Thyra::VectorBase<double>> dfdpOf(LOCA::MultiContinuation::AbstractGroup& group, Thyra::VectorBase<double>* f) {
  auto fdfdp = group.getX().createMultiVector(2, NOX::ShapeCopy);
  EXPECT_EQ(group.computeDfDpMulti({0}, *fdfdp, false), NOX::Abstract::Group::Ok);
  if (f != nullptr) Thyra::copy(dynamic_cast<const NOX::Thyra::Vector&>((*fdfdp)[0]).getThyraVector(), Teuchos::ptrFromRef(*f));
  return dynamic_cast<const NOX::Thyra::Vector&>((*fdfdp)[1]).getThyraVector().clone_v();
}

double maxDifference(const Thyra::VectorBase<double>& a, const Thyra::VectorBase<double>& b) {
  auto d = a.clone_v();
  Thyra::Vp_StV(d.ptr(), -1.0, b);
  return Thyra::norm_inf(*d);
}

class LoadFactorDerivativeGroupTest : public ::testing::Test {
 protected:
  void SetUp() override {
    m_ = test::makeModel(frictionalBlock());
    x_ = Thyra::createMember(m_->get_x_space());
    Thyra::assign(x_.ptr(), 0.0);
    convergeAndCommit(*m_, *x_, 0.0);
    convergeAndCommit(*m_, *x_, lambda_);
    const auto counts = m_->contactCounts();
    ASSERT_GT(counts.stick + counts.slip, 0) << "the contact is not closed";
    global_ = locaGlobalData();
    p_.addParameter("Load Factor", lambda_);
  }
  void TearDown() override { LOCA::destroyGlobalData(global_); }

  // The central difference of f in λ at x_ with step h.
  RCP<Thyra::VectorBase<double>> centralDifference(double h) {
    auto d = Thyra::createMember(m_->get_f_space());
    const auto fm = evaluate(*m_, *x_, lambda_ - h, false).f;
    const auto fp = evaluate(*m_, *x_, lambda_ + h, false).f;
    Thyra::V_StVpStV(d.ptr(), 0.5 / h, *fp, -0.5 / h, *fm);
    return d;
  }

  const double lambda_ = 0.5;
  RCP<model::ContactMechanicsModel> m_;
  RCP<Thyra::VectorBase<double>> x_;
  RCP<LOCA::GlobalData> global_;
  LOCA::ParameterVector p_;
};

TEST_F(LoadFactorDerivativeGroupTest, HandsLocaTheModelsDfDpAndCentralDifferencesAgree) {
  NOX::Thyra::Vector guess(x_);
  LoadFactorDerivativeGroup group(global_, guess, m_, p_);
  auto f = Thyra::createMember(m_->get_f_space());
  const auto fromGroup = dfdpOf(group, f.get());
  EXPECT_EQ(group.modelDerivativeEvaluations(), 1);

  const auto model = evaluate(*m_, *x_, lambda_, true);
  const double scale = Thyra::norm_inf(*model.dfdp->col(0));
  ASSERT_GT(scale, 1.0);
  // The same evaluation (x, λ) of the same model: equal up to the enhanced elements' warm-started local
  // solve, which the two passes start from different iterates.
  EXPECT_LE(maxDifference(*fromGroup, *model.dfdp->col(0)), 1e-12 * scale);
  EXPECT_LE(maxDifference(*f, *model.f), 1e-12 * std::max(1.0, Thyra::norm_inf(*model.f)));

  // The difference's accuracy: its truncation error, estimated from the steps h and 2h (central: error ∝ h²,
  // so |D(2h) − D(h)| ≈ 3 |D(h) − ∂f/∂λ|), and its round-off, ε |f| / h with |f| the residual forces'
  // size (‖f_int‖∞ ~ the largest force entry of f at λ ± h).
  const double h = 1e-5;
  const auto dh = centralDifference(h), d2h = centralDifference(2 * h);
  const double truncation = maxDifference(*d2h, *dh);
  const double roundOff = 1e-15 * Thyra::norm_inf(*evaluate(*m_, *x_, lambda_ + h, false).f) / h + 1e-13 * scale;
  const double error = maxDifference(*fromGroup, *dh);
  if (Tpetra::getDefaultComm()->getRank() == 0)
    std::printf("max |df/dlambda - D(h)| = %.2e of %.2e; |D(2h) - D(h)| = %.2e, round-off bound %.2e (h = %g)\n", error,
                scale, truncation, roundOff, h);
  EXPECT_LE(error, truncation + roundOff + 1e-9 * scale);
  EXPECT_LE(error, 1e-6 * scale);
}

TEST_F(LoadFactorDerivativeGroupTest, ClonesAreOfTheSameClassAndAskTheModel) {
  NOX::Thyra::Vector guess(x_);
  LoadFactorDerivativeGroup group(global_, guess, m_, p_);
  const auto exact = dfdpOf(group, nullptr);
  for (const auto type : {NOX::DeepCopy, NOX::ShapeCopy}) {
    auto copy = group.clone(type);
    auto* same = dynamic_cast<LoadFactorDerivativeGroup*>(copy.get());
    ASSERT_NE(same, nullptr) << "LOCA clones its groups: a clone must be a LoadFactorDerivativeGroup";
    if (type == NOX::ShapeCopy) continue;  // a shape copy holds no state to differentiate at
    const auto fromClone = dfdpOf(*same, nullptr);
    EXPECT_EQ(same->modelDerivativeEvaluations(), 1);
    EXPECT_LE(maxDifference(*fromClone, *exact), 1e-12 * Thyra::norm_inf(*exact));
  }
}

// What LOCA 13.2's own group gives (built with implement_dfdp = true, as ContinuationDriver did): a forward
// difference with ε = 1e-6 (1e-6 + λ). Printed, not asserted: it documents what the predictor used before.
TEST_F(LoadFactorDerivativeGroupTest, LocasOwnGroupDifferencesInLambda) {
  NOX::Thyra::Vector guess(x_);
  LoadFactorDerivativeGroup group(global_, guess, m_, p_);
  const auto exact = dfdpOf(group, nullptr);
  LOCA::Thyra::Group loca(global_, guess, m_, p_, 0, true);
  const auto differenced = dfdpOf(loca, nullptr);
  const double error = maxDifference(*differenced, *exact), scale = Thyra::norm_inf(*exact);  // collective
  if (Tpetra::getDefaultComm()->getRank() == 0)
    std::printf("LOCA::Thyra::Group's df/dlambda: max error %.2e of %.2e\n", error, scale);
  EXPECT_LE(error, 1e-3 * scale);  // it is a derivative, roughly
}

}  // namespace
