// The augmented Lagrangian's multiplier predictor (docs/theory-contact.md §15, eq. 15.8): at an increment's
// start each node that stuck on one facet at both ends of the last increment gets the multipliers its
// converged tractions extrapolate to over the new load step, λ_N = min(0, t_N + Δλ ṫ_N) and
// λ_T = t_T + Δλ ṫ_T inside the cone μ|λ_N|; a cut-back forgets them with the rest of the attempt, and a node
// without such a rate keeps the commit's multipliers.
#include "InterfaceTestTools.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>

namespace {

namespace cc = contessa::contact;
namespace ct = contessa::contact::testing;
using Law = cc::ContactLawParameters;

// Three slave nodes on y = 0 (areas 0.5, 1, 0.5: 2 in all) under a rigid line at y = 0.5 that moves by λ
// (0.5, −1): it touches them at λ = 0.5, penetrates them by λ − 0.5 and drags them along x by (λ − 0.5)/2.
// ε_N = 1e6 and a constant ε_T = 1e4: t_N = −1e4, −2e4 and t_T = 0, 50 (first touch: no stick motion yet)
// at the commits λ = 0.51, 0.52, all nodes sticking, so the rates are ṫ_N = −1e6 and ṫ_T = 5e3 per unit λ.
std::unique_ptr<cc::ContactInterfaceBase> draggedPlate(double mu) {
  auto spec = ct::threeNodesUnderRigidLine({{-10.0, 0.5}, {10.0, 0.5}}, {0.5, -1.0});
  spec.law.frictionCoefficient = mu;
  spec.law.tangentialPenalty = 1e4;
  spec.law.slipTolerance = 0.0;
  spec.law.enforcement = Law::Enforcement::AugmentedLagrangian;
  spec.law.penetrationTolerance = 1e-3;
  spec.law.elasticSlipTolerance = 1e-4;
  spec.law.maxAugmentations = 10;
  return cc::makeContactInterface(spec, {1, 1, 1});
}

struct Force {
  double x = 0, y = 0;
};

// The total force on the slave nodes at load factor λ (a trial evaluation, as a Newton iterate's).
Force forceAt(cc::ContactInterfaceBase& plate, double lambda) {
  Force f;
  plate.evaluate(ct::threeNodesOnXAxis, lambda, true,
                 [&](const cc::GlobalIndex*, int, const double* r, const double*, const double*) {
                   f.x -= r[0];
                   f.y -= r[1];
                 });
  return f;
}

// Commits at λ = 0.51 and 0.52 with the load steps ContactAssembly hands over (none known before the first).
void twoCommits(cc::ContactInterfaceBase& plate) {
  forceAt(plate, 0.51);
  plate.measureTractionRates(std::numeric_limits<double>::quiet_NaN());
  plate.commit();
  forceAt(plate, 0.52);
  plate.measureTractionRates(0.01);
  plate.commit();
}

}  // namespace

TEST(AugmentedPredictor, ExtrapolatesTheConvergedTractionsOverTheNewLoadStep) {
  const auto plain = draggedPlate(0.3), predicted = draggedPlate(0.3);
  twoCommits(*plain);
  twoCommits(*predicted);
  predicted->predictMultipliers(0.01);
  const Force a = forceAt(*plain, 0.53), b = forceAt(*predicted, 0.53);
  // The commit's multipliers are λ_N = 0 (no update) and λ_T = 0 (the stick reference's, eq. 15.4); the
  // predicted ones λ_N = −2e4 + 0.01·(−1e6) = −3e4 and λ_T = 50 + 0.01·5e3 = 100, on the area 2.
  EXPECT_NEAR(std::abs(b.y) - std::abs(a.y), 2.0 * 3e4, 1e-9 * std::abs(b.y));
  EXPECT_NEAR(std::abs(b.x) - std::abs(a.x), 2.0 * 100.0, 1e-9 * std::abs(b.y));
  // A cut-back forgets the prediction with the attempt.
  predicted->rollback();
  const Force c = forceAt(*predicted, 0.53);
  EXPECT_EQ(c.x, a.x);
  EXPECT_EQ(c.y, a.y);
}

TEST(AugmentedPredictor, ANodeThatDidNotStickAtBothCommitsKeepsTheCommitsMultipliers) {
  // After the first commit the nodes' last increment went from open to stick: no rate, nothing predicted.
  const auto plain = draggedPlate(0.3), predicted = draggedPlate(0.3);
  for (auto* plate : {plain.get(), predicted.get()}) {
    forceAt(*plate, 0.51);
    plate->measureTractionRates(0.51);
    plate->commit();
  }
  predicted->predictMultipliers(0.01);
  const Force a = forceAt(*plain, 0.52), b = forceAt(*predicted, 0.52);
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
}

TEST(AugmentedPredictor, ThePredictedStickMultiplierStaysInsideTheCoulombCone) {
  // μ = 0.0031: the commits stick (50 ≤ 0.0031·2e4 = 62), the extrapolated λ_T = 100 lies outside the cone of
  // the predicted λ_N, 0.0031·3e4 = 93, and is drawn back onto it. Evaluated at λ = 0.52 (t_N = −3e4 − 2e4,
  // cone 155) the nodes stick with t_T = 93 + 50 = 143 (unclamped: 150).
  const auto plate = draggedPlate(0.0031);
  twoCommits(*plate);
  plate->predictMultipliers(0.01);
  const Force f = forceAt(*plate, 0.52);
  EXPECT_NEAR(std::abs(f.y), 2.0 * 5e4, 1e-9 * 1e5);
  EXPECT_NEAR(std::abs(f.x), 2.0 * 143.0, 1e-9 * 1e5);
  // Predicted past unloading (λ_N extrapolates to a tension): λ_N = 0, and with it λ_T = 0.
  const auto unloaded = draggedPlate(0.3), reference = draggedPlate(0.3);
  twoCommits(*unloaded);
  twoCommits(*reference);
  unloaded->predictMultipliers(-0.03);
  const Force u = forceAt(*unloaded, 0.52), r = forceAt(*reference, 0.52);
  EXPECT_EQ(u.x, r.x);
  EXPECT_EQ(u.y, r.y);
}
