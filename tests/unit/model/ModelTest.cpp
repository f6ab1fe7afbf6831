// The model evaluator over Tpetra: the assembled Jacobian and ∂f/∂λ against finite differences of the
// residual, quadratic Newton convergence with the MUMPS solver, and the same answer on 1 and 2 ranks.
#include <gtest/gtest.h>

#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>
#include <Tpetra_Core.hpp>

#include "deck/ProblemDefinition.hpp"
#include "model/ContactMechanicsModel.hpp"
#include "solvers/LinearSolverFactory.hpp"
#include "BlockOnBase.hpp"
#include "ModelHarness.hpp"
#include "TestDeck.hpp"

namespace {

using namespace contessa;
using test::evaluate;
using test::Evaluation;
using test::newtonAt;
using Teuchos::RCP;
using Teuchos::rcp;
using MEB = Thyra::ModelEvaluatorBase;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>;

// A 4 × 3 block of Neo-Hookean enhanced quads: left edge clamped, right edge stretched by 30 % and
// sheared, a nodal force on the top: large deformation, every kind of boundary condition. Spread over
// the ranks of `comm`.
deck::ProblemDefinition makeProblem(const std::string& element, MPI_Comm comm = test::everyRank()) {
  auto p = test::newProblem();
  test::setGrid(p->sublist("Mesh"), "Rectangle", {4, 3}, {4.0, 2.0});
  test::addBlock(*p, "block_1", element, "rubber");
  test::addMaterial(*p, "rubber", "Neo-Hookean", 100.0, 0.3);
  test::addDirichlet(*p, "clamp x", "left", "x");
  test::addDirichlet(*p, "clamp y", "left", "y");
  test::addDirichlet(*p, "stretch", "right", "x").set("Value", 1.2);
  test::addNodalForce(*p, "lift", "top", "y", 15.0);
  test::setReactionSets(*p, {"left", "right"});
  return test::buildOn(*p, comm);
}

// The model with the given communicator (the 1-vs-all-ranks tests build one on a single rank too).
RCP<model::ContactMechanicsModel> makeModel(const RCP<const Teuchos::Comm<int>>& comm, const deck::ProblemDefinition& problem) {
  return test::makeModel(problem, comm);
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

// Each reaction's components equal the reference's to `relative` of their size (at least 1).
template <class Reactions>
void expectSameReactions(const Reactions& reactions, const Reactions& reference, double relative) {
  ASSERT_EQ(reactions.size(), reference.size());
  for (std::size_t s = 0; s < reference.size(); ++s)
    for (int c = 0; c < 2; ++c)
      EXPECT_NEAR(reactions[s].force[c], reference[s].force[c], relative * std::max(1.0, std::abs(reference[s].force[c])));
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
  return newtonAt(m, *x, 1.0, 1e-11);
}

// The problem's model on `comm` solved from rest (newtonResiduals): the model, its solution, the
// residual norms, and the reactions there.
struct SolvedFromRest {
  RCP<model::ContactMechanicsModel> m;
  RCP<Thyra::VectorBase<double>> x;
  std::vector<double> norms;
  SolvedFromRest(const RCP<const Teuchos::Comm<int>>& comm, const deck::ProblemDefinition& problem)
      : m(makeModel(comm, problem)), norms(newtonResiduals(*m, x)) {}
  auto reactions() const { return m->reactions(*Extract::getConstTpetraVector(x), 1.0); }
};

TEST_P(ModelTest, NewtonConvergesQuadratically) {
  auto comm = Tpetra::getDefaultComm();
  const auto norms = SolvedFromRest(comm, makeProblem(GetParam())).norms;
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
  const SolvedFromRest all(comm, problem);
  const double normAll = Thyra::norm_2(*all.x);
  const auto reactionsAll = all.reactions();

  auto self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  const auto wholeProblem = test::onOneRank(problem);
  if (comm->getRank() == 0) {
    const SolvedFromRest serial(self, wholeProblem);
    EXPECT_NEAR(Thyra::norm_2(*serial.x), normAll, 1e-10 * normAll);
    expectSameReactions(serial.reactions(), reactionsAll, 1e-9);
  }
  // Equilibrium: the reactions balance the applied nodal force (15 upwards at λ = 1).
  EXPECT_NEAR(reactionsAll[0].force[1] + reactionsAll[1].force[1], -15.0, 1e-8);
  EXPECT_NEAR(reactionsAll[0].force[0] + reactionsAll[1].force[0], 0.0, 1e-8);
}

// Problems on communicators of their own: the ranks split into groups of one rank (MPI_Comm_split by
// rank), and each group builds the deck's problem (its mesh made on the group alone) and its model on
// its communicator and solves it, while the other groups solve theirs: each gets the answer of the run
// on all ranks. A problem built on MPI_COMM_WORLD under a model on the group would hold another part
// of the mesh than its model's ranks assemble, and the collective steps would wait for the other group.
TEST_P(ModelTest, ProblemsOnSplitCommunicatorsEachSolveAlone) {
  auto comm = Tpetra::getDefaultComm();
  const SolvedFromRest all(comm, makeProblem(GetParam()));
  const double normAll = Thyra::norm_2(*all.x);
  const auto reactionsAll = all.reactions();

  MPI_Comm group = MPI_COMM_NULL;
  MPI_Comm_split(test::everyRank(), comm->getRank(), 0, &group);
  double normAlone = 0;
  {
    const auto alone = makeProblem(GetParam(), group);
    EXPECT_EQ(alone.mesh.numRanks, 1);
    EXPECT_EQ(alone.mesh.local().numElements(), 12) << "the group's problem holds the whole mesh";
    const SolvedFromRest solved(rcp(new Teuchos::MpiComm<int>(group)), alone);
    EXPECT_LT(solved.norms.back(), 1e-11);
    normAlone = Thyra::norm_2(*solved.x);
    EXPECT_NEAR(normAlone, normAll, 1e-10 * normAll);
    expectSameReactions(solved.reactions(), reactionsAll, 1e-9);
  }
  MPI_Comm_free(&group);
  // Every group solved its own problem: the answers agree across the groups too.
  double lowest = normAlone, highest = normAlone;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, 1, &normAlone, &lowest);
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, 1, &normAlone, &highest);
  EXPECT_NEAR(lowest, highest, 1e-10 * normAll);
}

// Reactions at a converged state come from the residual pass Newton has just made (no element loop of
// their own), and equal those of a pass made for them.
TEST_P(ModelTest, ReactionsComeFromTheLastResidualPass) {
  auto comm = Tpetra::getDefaultComm();
  const auto problem = makeProblem(GetParam());
  auto m = makeModel(comm, problem);
  RCP<Thyra::VectorBase<double>> x;
  newtonResiduals(*m, x);
  const auto tx = Extract::getConstTpetraVector(x);
  evaluate(*m, *x, 1.0, false);  // the residual at the converged state, as Newton's last test
  m->commitState();
  const int passes = m->elementPasses();
  const auto fromPass = m->reactions(*tx, 1.0);
  EXPECT_EQ(m->elementPasses(), passes) << "the reactions made an element pass of their own";

  // Another state in between: the reactions need (and make) a pass of their own, with the same answer.
  evaluate(*m, *deformedState(*m, 0.01), 1.0, false);
  const int before = m->elementPasses();
  const auto ownPass = m->reactions(*tx, 1.0);
  EXPECT_EQ(m->elementPasses(), before + 1);
  expectSameReactions(ownPass, fromPass, 1e-10);

  // After a rollback the pass no longer describes the state: a new one.
  evaluate(*m, *x, 1.0, false);
  m->rollbackState();
  const int afterRollback = m->elementPasses();
  m->reactions(*tx, 1.0);
  EXPECT_EQ(m->elementPasses(), afterRollback + 1);
}

// A Jacobian asked for at the point of the last residual is the same as one asked for alone.
TEST_P(ModelTest, JacobianAfterResidualEqualsJacobianAlone) {
  auto comm = Tpetra::getDefaultComm();
  const auto problem = makeProblem(GetParam());
  auto m = makeModel(comm, problem);
  auto x = deformedState(*m, 0.15);
  evaluate(*m, *x, 0.7, false);
  const auto afterResidual = evaluate(*m, *x, 0.7, true);
  auto fresh = makeModel(comm, problem);
  const auto alone = evaluate(*fresh, *x, 0.7, true);
  auto a = Teuchos::rcp_dynamic_cast<const model::CrsMatrix>(Extract::getConstTpetraOperator(afterResidual.W), true);
  auto b = Teuchos::rcp_dynamic_cast<const model::CrsMatrix>(Extract::getConstTpetraOperator(alone.W), true);
  const auto va = a->getLocalMatrixHost().values;
  const auto vb = b->getLocalMatrixHost().values;
  ASSERT_EQ(va.extent(0), vb.extent(0));
  double worst = 0, scale = 0;
  for (std::size_t k = 0; k < va.extent(0); ++k) {
    worst = std::max(worst, std::abs(va(k) - vb(k)));
    scale = std::max(scale, std::abs(vb(k)));
  }
  EXPECT_LT(worst, 1e-12 * scale);
  EXPECT_LT(Thyra::norm_inf(*afterResidual.f) - Thyra::norm_inf(*alone.f), 1e-12 * Thyra::norm_inf(*alone.f));
}

// ---- Contact in the model: the assembled tangent includes the contact element exactly. -------------

// A 2 × 1 Neo-Hookean block on a rigid base (y = 0), its top pushed down and sideways: stick or slip
// by μ. With `deformableBase`, the base is a second (meshed) block instead, so the master nodes move.
deck::ProblemDefinition makeContactProblem(double mu, bool deformableBase, bool twoPass,
                                           MPI_Comm comm = test::everyRank()) {
  test::BlockOnBase deck;
  deck.friction = mu;
  deck.deformableBase = deformableBase;
  if (deformableBase) deck.twoPass = twoPass;
  // Two-pass: upper nodes (x = 0, 2/3, 4/3, 2) interleave with the base's (0.1, 0.7, 1.3, 1.9), so
  // base nodes penetrate the upper block's segments and the second pass carries force too.
  if (deformableBase && twoPass) deck.elementsX = 3;
  return deck.problem(comm);
}

struct ContactCase {
  std::string name;
  double mu;
  bool deformable, twoPass;
};

class ContactModelTest : public ::testing::TestWithParam<ContactCase> {};

// After a converged, committed half load (contact established), the tangent at an iterate of the full
// load (stick or slip, large sliding for the small μ) matches central differences of the residual.
// The friction coefficients keep every node clear of the stick/slip limit, where the residual has a
// kink and central differences would straddle it.
TEST_P(ContactModelTest, JacobianMatchesCentralDifferences) {
  auto comm = Tpetra::getDefaultComm();
  const auto problem = makeContactProblem(GetParam().mu, GetParam().deformable, GetParam().twoPass);
  auto m = makeModel(comm, problem);
  auto x = Thyra::createMember(m->get_x_space());
  Thyra::assign(x.ptr(), 0.0);
  const auto first = newtonAt(*m, *x, 0.5);
  ASSERT_LT(first.back(), 1e-10);
  evaluate(*m, *x, 0.5, false);
  m->commitState();
  ASSERT_GT(m->contactCounts().active, 0);
  // The second pass is active: base nodes as slaves too (the upper block has 3 bottom nodes).
  if (GetParam().twoPass) { EXPECT_GT(m->contactCounts().active, 3) << m->contactCounts().active; }
  // Half a Newton step towards λ = 1: a state away from equilibrium, contact still active.
  test::halfNewtonStep(*m, *x, 1.0);
  const auto [worst, scale, worstColumn] = test::differenceJacobian(*m, *x, 1.0, 1e-7);
  EXPECT_LT(worst / scale, 1e-6) << GetParam().name << ": worst column " << worstColumn;
}

// Quadratic convergence on a contact increment once the active set has settled.
TEST_P(ContactModelTest, NewtonConvergesQuadraticallyOnAContactIncrement) {
  auto comm = Tpetra::getDefaultComm();
  const auto problem = makeContactProblem(GetParam().mu, GetParam().deformable, GetParam().twoPass);
  auto m = makeModel(comm, problem);
  auto x = Thyra::createMember(m->get_x_space());
  Thyra::assign(x.ptr(), 0.0);
  ASSERT_LT(newtonAt(*m, *x, 0.5).back(), 1e-10);
  evaluate(*m, *x, 0.5, false);
  m->commitState();
  const auto norms = newtonAt(*m, *x, 1.0);
  std::ostringstream trace;
  for (double r : norms) trace << r << " ";
  ASSERT_LT(norms.back(), 1e-10) << trace.str();
  // Quadratic: with e_k = r_k / max_j r_j, e_{k+1} <= C e_k^2 once e_k is small (C = 100 here).
  // Linear convergence at any rate fails this within two steps. Steps ending below 1e-14 (round-off)
  // are not counted, but at least one must be. (A node exactly at the stick/slip limit would make
  // the residual non-smooth there; the cases are chosen away from it.)
  const double largest = *std::max_element(norms.begin(), norms.end());
  int checked = 0;
  for (std::size_t k = 1; k + 1 < norms.size(); ++k) {
    const double ek = norms[k] / largest, next = norms[k + 1] / largest;
    if (ek > 5e-2) continue;
    EXPECT_LE(next, 100.0 * ek * ek) << "iteration " << k << ": " << trace.str();
    if (norms[k + 1] >= 1e-14) ++checked;
  }
  EXPECT_GE(checked, 1) << trace.str();
  if (comm->getRank() == 0) std::printf("Contact Newton residuals (%s): %s\n", GetParam().name.c_str(), trace.str().c_str());
}

// The residual at the smooth state of scale 0.01 (in contact) and the Jacobian there applied to the
// smooth field of scale 1.
std::pair<RCP<Thyra::VectorBase<double>>, RCP<Thyra::VectorBase<double>>> residualAndProduct(model::ContactMechanicsModel& m) {
  const auto e = evaluate(m, *deformedState(m, 0.01), 1.0, true);
  auto Wv = Thyra::createMember(m.get_f_space());
  Thyra::apply(*e.W, Thyra::NOTRANS, *deformedState(m, 1.0), Wv.ptr());
  return {e.f, Wv};
}

// The residual and the Jacobian of a contact problem are the same on all ranks as on rank 0 alone.
TEST_P(ContactModelTest, SameResidualAndJacobianOnOneRankAndAllRanks) {
  auto comm = Tpetra::getDefaultComm();
  const auto problem = makeContactProblem(GetParam().mu, GetParam().deformable, GetParam().twoPass);
  auto m = makeModel(comm, problem);
  // A state in contact: every DOF moved by a smooth field, the top pushed into the base.
  const auto [f, Wv] = residualAndProduct(*m);
  // Gather to rank 0 by global DOF id (Thyra's own ordering follows the ranks, not the ids).
  const auto n = m->get_x_space()->dim();
  std::vector<model::GO> ids;
  if (comm->getRank() == 0)
    for (model::GO i = 0; i < n; ++i) ids.push_back(i);
  auto rootMap = rcp(new model::Map(n, Teuchos::ArrayView<const model::GO>(ids), 0, comm));
  model::Import toRoot(m->ownedDofMap(), rootMap);
  model::Vector fRoot(rootMap), WvRoot(rootMap);
  fRoot.doImport(*Extract::getConstTpetraVector(f), toRoot, Tpetra::INSERT);
  WvRoot.doImport(*Extract::getConstTpetraVector(Wv), toRoot, Tpetra::INSERT);
  const auto fAll = fRoot.getData(0), WvAll = WvRoot.getData(0);
  const auto wholeProblem = test::onOneRank(problem);
  if (comm->getRank() == 0) {
    auto self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
    auto serial = makeModel(self, wholeProblem);
    const auto [fs, Wvs] = residualAndProduct(*serial);
    const double fScale = Thyra::norm_inf(*fs), WvScale = Thyra::norm_inf(*Wvs);
    for (Thyra::Ordinal i = 0; i < n; ++i) {
      EXPECT_NEAR(fAll[i], Thyra::get_ele(*fs, i), 1e-10 * fScale) << "residual row " << i;
      EXPECT_NEAR(WvAll[i], Thyra::get_ele(*Wvs, i), 1e-10 * WvScale) << "Jacobian row " << i;
    }
  }
}

// The deformable contact pair (a Parts mesh: read whole on the group's rank 0 and sent out, its contact
// surfaces gathered over the group) on groups of one rank: each group's Newton at half load reaches
// the all-ranks solution with the same contacts.
TEST(SplitCommunicator, AContactPairOfPartsSolvesOnEachGroupAlone) {
  auto comm = Tpetra::getDefaultComm();
  const auto solveHalfLoad = [](const RCP<const Teuchos::Comm<int>>& on, const deck::ProblemDefinition& problem) {
    auto m = makeModel(on, problem);
    auto x = Thyra::createMember(m->get_x_space());
    Thyra::assign(x.ptr(), 0.0);
    EXPECT_LT(newtonAt(*m, *x, 0.5).back(), 1e-10);
    evaluate(*m, *x, 0.5, false);
    m->commitState();
    return std::make_pair(Thyra::norm_2(*x), m->contactCounts().active);
  };
  const auto [normAll, activeAll] = solveHalfLoad(comm, makeContactProblem(1.0, true, false));
  ASSERT_GT(activeAll, 0);
  MPI_Comm group = MPI_COMM_NULL;
  MPI_Comm_split(test::everyRank(), comm->getRank(), 0, &group);
  {
    const auto [norm, active] =
        solveHalfLoad(rcp(new Teuchos::MpiComm<int>(group)), makeContactProblem(1.0, true, false, group));
    EXPECT_NEAR(norm, normAll, 1e-10 * normAll);
    EXPECT_EQ(active, activeAll);
  }
  MPI_Comm_free(&group);
}

// The top block of makeContactProblem's deformable pair moved rigidly by (dx, dy): its nodes (y > 0) only.
RCP<Thyra::VectorBase<double>> translatedTop(const model::ContactMechanicsModel& m, const deck::ProblemDefinition& problem,
                                             double dx, double dy) {
  auto x = Thyra::createMember(m.get_x_space());
  auto tx = Extract::getTpetraVector(x);
  auto v = tx->getDataNonConst(0);
  for (Teuchos::ArrayRCP<double>::size_type i = 0; i < v.size(); ++i) {
    const auto gid = tx->getMap()->getGlobalElement(i);
    const auto node = static_cast<std::size_t>(problem.mesh.localNode(gid / 2));  // owned: in the part
    const bool top = problem.mesh.local().coordinates[node * 2 + 1] > 0.0;
    v[i] = top ? (gid % 2 == 0 ? dx : dy) : 0.0;
  }
  return x;
}

// The matrix graph follows the contact: with Search Reach = 0 (reach 2 h = 1.2 around the reference
// positions) the top block slid 1.5 along the base (segments 0.6 long) pairs its slave nodes with base segments the graph
// never reserved. A residual alone does not rebuild; the first Jacobian re-reserves around the current
// configuration, rebuilds the graph and re-points the W operator the caller made on the old graph, and
// gives the same residual and Jacobian as the whole-surface reservation (Search Reach = -1, small
// interface: nothing to rebuild); any other W made before the rebuild is re-pointed when evaluated. On
// any number of ranks.
TEST(GraphRebuild, TheJacobianFollowsTheContactBeyondTheReservedReach) {
  auto comm = Tpetra::getDefaultComm();
  auto reach0 = makeContactProblem(0.0, true, false);
  reach0.contacts.at(0).searchReach = 0.0;
  auto whole = makeContactProblem(0.0, true, false);
  ASSERT_LT(whole.contacts.at(0).searchReach, 0.0);
  auto m = makeModel(comm, reach0);
  auto reference = makeModel(comm, whole);
  auto Wbefore = m->create_W_op();
  auto Wother = m->create_W_op();
  const auto x = translatedTop(*m, reach0, 1.5, -0.01);
  const auto xr = translatedTop(*reference, whole, 1.5, -0.01);

  const auto residualOnly = evaluate(*m, *x, 1.0, false);
  EXPECT_EQ(m->graphRebuilds(), 0);
  int rebuildsSeen = 0;
  m->onGraphRebuild([&](const model::GraphRebuild& r) {
    ++rebuildsSeen;
    EXPECT_EQ(r.count, 1);
    EXPECT_NE(r.reason.find("contact interface 'base': slave node"), std::string::npos) << r.reason;
    EXPECT_GT(r.entries, 0);
  });
  auto in = m->createInArgs();
  auto p = Thyra::createMember(m->get_p_space(0));
  Thyra::set_ele(0, 1.0, p.ptr());
  in.set_x(x);
  in.set_p(0, p);
  auto f = Thyra::createMember(m->get_f_space());
  auto out = m->createOutArgs();
  out.set_f(f);
  out.set_W_op(Wbefore);
  m->evalModel(in, out);
  EXPECT_EQ(m->graphRebuilds(), 1);
  EXPECT_EQ(rebuildsSeen, 1);

  const auto e = evaluate(*reference, *xr, 1.0, true);
  EXPECT_EQ(reference->graphRebuilds(), 0);
  const auto v = deformedState(*m, 1.0);
  const auto vr = deformedState(*reference, 1.0);
  auto Wv = Thyra::createMember(m->get_f_space());
  auto Wvr = Thyra::createMember(reference->get_f_space());
  Thyra::apply(*Wbefore, Thyra::NOTRANS, *v, Wv.ptr());
  Thyra::apply(*e.W, Thyra::NOTRANS, *vr, Wvr.ptr());
  // Every contact coupling is in the rebuilt W (a dropped one would change W v).
  const double fScale = Thyra::norm_inf(*e.f), WScale = Thyra::norm_inf(*Wvr);
  ASSERT_GT(fScale, 0.0);
  // Same maps (one partition of the same mesh): compare entry by entry.
  const auto fa = Extract::getConstTpetraVector(f)->getData(0), fb = Extract::getConstTpetraVector(e.f)->getData(0);
  const auto wa = Extract::getConstTpetraVector(Wv)->getData(0), wb = Extract::getConstTpetraVector(Wvr)->getData(0);
  const auto ra = Extract::getConstTpetraVector(residualOnly.f)->getData(0);
  for (Teuchos::ArrayRCP<double>::size_type i = 0; i < fa.size(); ++i) {
    EXPECT_NEAR(fa[i], fb[i], 1e-10 * fScale) << "residual row " << i;
    EXPECT_NEAR(ra[i], fb[i], 1e-10 * fScale) << "residual-only row " << i;
    EXPECT_NEAR(wa[i], wb[i], 1e-10 * WScale) << "Jacobian row " << i;
  }

  // A W op made before the rebuild and evaluated after it: re-pointed, no second rebuild.
  auto out2 = m->createOutArgs();
  out2.set_W_op(Wother);
  m->evalModel(in, out2);
  EXPECT_EQ(m->graphRebuilds(), 1);
  auto Wv2 = Thyra::createMember(m->get_f_space());
  Thyra::apply(*Wother, Thyra::NOTRANS, *v, Wv2.ptr());
  const auto w2 = Extract::getConstTpetraVector(Wv2)->getData(0);
  for (Teuchos::ArrayRCP<double>::size_type i = 0; i < w2.size(); ++i) EXPECT_EQ(w2[i], wa[i]) << "row " << i;
}

INSTANTIATE_TEST_SUITE_P(Contact, ContactModelTest,
                         ::testing::Values(ContactCase{"RigidStick", 1.0, false, false},
                                           ContactCase{"RigidSlip", 0.05, false, false},
                                           ContactCase{"RigidFrictionless", 0.0, false, false},
                                           ContactCase{"DeformableSlip", 0.05, true, false},
                                           ContactCase{"DeformableStick", 1.0, true, false},
                                           ContactCase{"DeformableFrictionless", 0.0, true, false},
                                           ContactCase{"DeformableTwoPassStick", 1.0, true, true}),
                         [](const auto& info) { return info.param.name; });

INSTANTIATE_TEST_SUITE_P(Elements, ModelTest, ::testing::Values("Q4", "Q4 Enhanced"),
                         [](const auto& info) { return info.param == "Q4" ? std::string("Q4") : std::string("Q4Enhanced"); });

}  // namespace
