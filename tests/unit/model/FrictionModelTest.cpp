// Coulomb friction with the elastic-slip tolerance (ε_T = μ|t_N|/(s L), docs/theory-contact.md §5) in the
// assembled model: the Jacobian against central differences of the residual, quadratic Newton on a
// frictional increment (residual ratios printed and asserted), and the Coulomb block of
// inputs/verification/coulomb_block.xml sheared one way, reversed and sheared the other way
// (|F_t|/F_n = μ each way, a stick phase after the reversal). Runs on 1 and 2 ranks (friction_model_test_np2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <Teuchos_XMLParameterListHelpers.hpp>
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_VectorStdOps.hpp>
#include <Tpetra_Core.hpp>

#include "deck/DeckReader.hpp"
#include "deck/ProblemDefinition.hpp"
#include "model/ContactMechanicsModel.hpp"
#include "solvers/LinearSolverFactory.hpp"
#include "BlockOnBase.hpp"
#include "ModelHarness.hpp"

namespace {

using namespace contessa;
using test::evaluate;
using test::makeModel;
using test::newtonAt;
using Teuchos::RCP;
using Teuchos::rcp;

std::string trace(const std::vector<double>& norms) {
  std::ostringstream s;
  for (double r : norms) s << r << " ";
  return s.str();
}

/// Converges at λ and commits the increment (as LOCA does after a converged step).
void convergeAndCommit(model::ContactMechanicsModel& m, Thyra::VectorBase<double>& x, double lambda, double tolerance) {
  const auto norms = newtonAt(m, x, lambda, tolerance, 40);
  ASSERT_LT(norms.back(), tolerance) << "no convergence at load factor " << lambda << ": " << trace(norms);
  evaluate(m, x, lambda, false);
  m.commitState();
}

// ---- A Neo-Hookean block pressed and dragged on a base, default slip tolerance ----------------------

// A 2 × 1 block (6 × 3 enhanced quads, Neo-Hookean) 0.001 above a rigid base y = 0, or above a deformable
// base block (the master nodes move: the geometric terms of the element tangent act together with
// ∂ε_T/∂t_N). Its top is pushed down 0.05 × λ and sideways `drag` × λ, with the default slip tolerance
// (0.005 of the facet length 1/3). The nodes close in the first half, with friction from where they touch
// (docs/theory-contact.md §5.2); the second half drags them on.
deck::ProblemDefinition blockOnBase(bool deformableBase, double mu, double drag) {
  test::BlockOnBase deck;
  deck.elementsX = 6;
  deck.elementsY = 3;
  deck.deformableBase = deformableBase;
  deck.blockName = "top";
  deck.shearName = "drag";
  deck.shear = drag;
  deck.tangentialPenalty.reset();
  deck.slipTolerance.reset();
  deck.friction = mu;
  return deck.problem(test::everyRank());
}

// The model of `problem` with its half load reached from rest (λ = 0, then 0.5, each converged and
// committed): where the full-step tests start.
std::pair<RCP<model::ContactMechanicsModel>, RCP<Thyra::VectorBase<double>>> halfLoaded(
    const deck::ProblemDefinition& problem) {
  auto m = makeModel(problem);
  auto x = Thyra::createMember(m->get_x_space());
  Thyra::assign(x.ptr(), 0.0);
  convergeAndCommit(*m, *x, 0.0, 1e-10);
  convergeAndCommit(*m, *x, 0.5, 1e-10);
  return {m, x};
}

class SlipToleranceModelTest : public ::testing::TestWithParam<bool> {};

// After the committed half load, an iterate towards the full load (stick and slip nodes, the pressure-
// dependent ε_T) has the Jacobian of central differences. Nodes exactly at the stick/slip limit would put
// a kink between the two differences; the 2-ranks run sees the same state.
TEST_P(SlipToleranceModelTest, JacobianMatchesCentralDifferences) {
  const auto [m, x] = halfLoaded(blockOnBase(GetParam(), 0.15, 0.05));
  EXPECT_EQ(m->contactForces().size(), 1u);  // one interface
  test::halfNewtonStep(*m, *x, 1.0);
  const auto d = test::differenceJacobian(*m, *x, 1.0, 1e-7);
  if (Tpetra::getDefaultComm()->getRank() == 0)
    std::printf("Friction Jacobian (%s base): max |W - W_FD| / max |W| = %.2e\n", GetParam() ? "deformable" : "rigid",
                d.worst / d.scale);
  EXPECT_LT(d.worst / d.scale, 1e-6);
}

// Newton from the committed half load to the full load (μ = 0.15, drag 0.03: 3 nodes stick, 4 slip; with
// the former drag 0.05 every node slips on the deformable base since friction acts from the first touch).
// Nodes committed in slip start the increment exactly at their Coulomb limit, so round-off decides their
// status at the first iterate and the first step may differ between 1 and 2 ranks (measured: ‖f‖ 0.144
// and 0.170 after it), not the answer nor the quadratic end. Quadratic once the stick/slip set has
// settled: e_k = r_k / max r: e_{k+1} <= 100 e_k² whenever e_k <= 5e-2; steps ending below 1e-11 (the
// rounding of internal forces of order 1e2, about 1e-13 per entry and up to 7e-13 in the norm as
// measured) are not counted, at least one is.
TEST_P(SlipToleranceModelTest, NewtonConvergesQuadraticallyOnAFrictionalIncrement) {
  const auto [m, x] = halfLoaded(blockOnBase(GetParam(), 0.15, 0.03));
  const auto norms = newtonAt(*m, *x, 1.0, 1e-11, 40);
  ASSERT_LT(norms.back(), 1e-11) << trace(norms);
  evaluate(*m, *x, 1.0, false);
  m->commitState();
  const auto counts = m->contactCounts();
  EXPECT_GT(counts.stick, 0);
  EXPECT_GT(counts.slip, 0);
  const double largest = *std::max_element(norms.begin(), norms.end());
  int checked = 0;
  std::ostringstream ratios;
  for (std::size_t k = 1; k + 1 < norms.size(); ++k) {
    const double ek = norms[k] / largest, next = norms[k + 1] / largest;
    if (ek > 5e-2 || norms[k + 1] < 1e-11) continue;
    ratios << next / (ek * ek) << " ";
    EXPECT_LE(next, 100.0 * ek * ek) << "iteration " << k << ": " << trace(norms);
    ++checked;
  }
  EXPECT_GE(checked, 1) << trace(norms);
  if (Tpetra::getDefaultComm()->getRank() == 0)
    std::printf("Friction Newton (%s base, %d stick, %d slip): residuals %s; e_k+1 / e_k^2 = %s\n",
                GetParam() ? "deformable" : "rigid", counts.stick, counts.slip, trace(norms).c_str(),
                ratios.str().c_str());
}

// A two-state cycle, damped. With μ = 0.3 and a drag of 0.03 the nodes near the leading edge end up
// sticking near the edge of their stick range; the full Newton step from the committed half load carries
// them into slip, and the next step (no tangential stiffness along the slip) into slip the other way.
// Without SlipReversalDamping the residual settles at 2.99 and never falls (measured while developing
// it); with it the reversed nodes take the stick stiffness, land in their stick range, and the last
// iterations are quadratic again.
TEST(SlipReversalDamping, EndsTheTwoStateCycleOfAFullStep) {
  const auto [m, x] = halfLoaded(blockOnBase(false, 0.3, 0.03));
  const auto norms = newtonAt(*m, *x, 1.0, 1e-11, 40);
  if (Tpetra::getDefaultComm()->getRank() == 0) std::printf("Damped full step: residuals %s\n", trace(norms).c_str());
  ASSERT_LT(norms.back(), 1e-11) << trace(norms);
  EXPECT_LE(norms.size(), 12u) << trace(norms);
  // The last two reductions: quadratic (the damping is off once the nodes stick).
  const std::size_t n = norms.size();
  const double largest = *std::max_element(norms.begin(), norms.end());
  const double e = norms[n - 3] / largest, next = norms[n - 2] / largest;
  EXPECT_LE(next, 100.0 * e * e) << trace(norms);
}

INSTANTIATE_TEST_SUITE_P(Friction, SlipToleranceModelTest, ::testing::Values(false, true),
                         [](const auto& info) { return info.param ? std::string("DeformableBase") : std::string("RigidBase"); });

// ---- The Coulomb block reversed ------------------------------------------------------------------------

struct Row {
  double lambda, fx, fy;
  contact::ContactCounts counts;
};

// inputs/verification/coulomb_block.xml (exact normal force P, μ = 0.3), its top moved to +0.002 mm
// (λ = 1) in 10 increments, then back to −0.002 mm (λ = −1) in 20: it slides forwards at F_x = −μP,
// sticks after the reversal while the stick springs unload through zero, then slides backwards at
// F_x = +μP. Two laws: the deck's (the paper's constant ε_T = 1e6, a stick range of 6e-7 mm, 1/300 of an
// increment: without SlipReversalDamping every increment after the reversal cycles at ‖f‖ = 0.417), and
// the default slip tolerance. With the constant ε_T the stick phase is linear (equal force steps; the
// block's end node, where the unloading traction concentrates, slips back at once); with the slip
// tolerance ε_T follows the pressure, every node sticks, and the steps only keep their sign.
class CoulombBlockReversal : public ::testing::TestWithParam<double> {};

TEST_P(CoulombBlockReversal, SlidesAtMuPBothWaysWithAStickPhaseAfterTheReversal) {
  const double slipTolerance = GetParam();
  const double mu = 0.3, P = 1.996007984031936;  // g0 / (H/E + 1/ε_N), the deck's exact normal force
  auto deck = deck::readDeck(CONTESSA_INPUTS "/verification/coulomb_block.xml");
  deck::applyOverrides(*deck, {"Problem/Contact/base/Slip Tolerance=" + std::to_string(slipTolerance)});
  const auto problem = deck::buildProblem(deck->sublist("Problem"), CONTESSA_INPUTS "/verification", test::everyRank());
  auto m = makeModel(problem);
  auto x = Thyra::createMember(m->get_x_space());
  Thyra::assign(x.ptr(), 0.0);
  std::vector<Row> rows;
  auto step = [&](double lambda) {
    convergeAndCommit(*m, *x, lambda, 1e-10);
    const auto f = m->contactForces().at(0).second;
    rows.push_back({lambda, f[0], f[1], m->contactCounts()});
    if (Tpetra::getDefaultComm()->getRank() == 0)
      std::printf("[ reversal ] s = %g  lambda %+5.2f  F_x %+.10f  F_y %.10f  stick %d slip %d\n", slipTolerance,
                  lambda, f[0], f[1], rows.back().counts.stick, rows.back().counts.slip);
  };
  step(0.0);
  for (int i = 1; i <= 10; ++i) step(0.1 * i);
  const std::size_t reversal = rows.size();
  for (int i = 9; i >= -10; --i) step(0.1 * i);

  for (const Row& r : rows) {
    EXPECT_NEAR(r.fy, P, 1e-9 * P);                    // ν = 0: the normal force never changes
    EXPECT_LE(std::abs(r.fx), mu * r.fy * (1 + 1e-9));  // Coulomb bound
    EXPECT_EQ(r.counts.active, 9);
  }
  // Forwards: sliding at −μP (the base resists the motion to the right).
  const Row& forward = rows[reversal - 1];
  EXPECT_EQ(forward.counts.slip, 9);
  EXPECT_NEAR(forward.fx / forward.fy, -mu, 1e-9);
  // After the reversal: a stick phase (the same stick/slip set, most nodes sticking) in which the friction
  // force unloads monotonically and changes sign.
  const Row& first = rows[reversal];
  EXPECT_GE(first.counts.stick, 7) << "most nodes stick after the reversal";
  std::size_t phase = 0;
  while (reversal + phase < rows.size() && rows[reversal + phase].counts.stick == first.counts.stick) ++phase;
  EXPECT_GE(phase, 3u) << "increments of the stick phase after the reversal";
  std::vector<double> steps;
  for (std::size_t k = reversal; k < reversal + phase; ++k) {
    const double df = rows[k].fx - rows[k - 1].fx;
    EXPECT_GT(df, 0.0) << "the stick springs unload monotonically, row " << k;
    steps.push_back(df);
  }
  if (slipTolerance == 0.0) {
    // Constant ε_T, linear elastic block, flat base, unchanged stick set: a linear response. Each force is
    // converged to |f| < 1e-10, so a difference of two carries up to 2e-10 (1.2e-9 of a step of 0.163).
    for (double df : steps) EXPECT_NEAR(df, steps.front(), 1e-8 * steps.front());
  }
  EXPECT_LT(rows[reversal].fx, 0.0);
  EXPECT_GT(rows[reversal + phase - 1].fx, 0.0) << "the friction force changes sign within the stick phase";
  // Backwards: sliding at +μP.
  const Row& backward = rows.back();
  EXPECT_EQ(backward.counts.slip, 9);
  EXPECT_NEAR(backward.fx / backward.fy, mu, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Friction, CoulombBlockReversal, ::testing::Values(0.0, 0.005),
                         [](const auto& info) { return info.param == 0.0 ? std::string("ConstantPenalty") : std::string("SlipTolerance"); });

}  // namespace
