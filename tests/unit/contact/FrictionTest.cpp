// Coulomb return mapping (eq. 17–23), the penalty normal law (eq. 16) and the committed/trial history.
#include "contact/ContactHistory.hpp"
#include "contact/ContactLawParameters.hpp"
#include "contact/CoulombReturnMapping.hpp"
#include "contact/HistoryTransfer.hpp"
#include "contact/NormalToggleDamping.hpp"
#include "contact/FacetSelector.hpp"
#include "contact/PenaltyNormalLaw.hpp"
#include "contact/SlipReversalDamping.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace cc = contessa::contact;
using cc::ContactStatus;
using cc::Vector;

namespace {

cc::ReturnMappingInput<1> input1(double committed, double slip, double a11, double tN) {
  cc::ReturnMappingInput<1> in;
  in.committedTraction = {committed};
  in.slipIncrement = {slip};
  in.metric(0, 0) = a11;
  in.normalTraction = tN;
  return in;
}

/// ‖t‖ = √(t_α ā^αβ t_β), eq. (19)
template <int NXi>
double tractionNorm(const Vector<NXi>& t, const cc::Matrix<NXi, NXi>& metric) {
  return std::sqrt(cc::dot(t, cc::multiply(cc::inverse(metric), t)));
}

}  // namespace

TEST(PenaltyNormalLaw, ActiveOnlyWhenPenetrating) {
  const cc::PenaltyNormalLaw law(1e3);
  EXPECT_DOUBLE_EQ(law.traction(-0.01), -10.0);  // eq. (16), compressive
  EXPECT_DOUBLE_EQ(law.tractionDerivative(-0.01), 1e3);
  EXPECT_DOUBLE_EQ(law.traction(0.01), 0.0);
  EXPECT_DOUBLE_EQ(law.tractionDerivative(0.01), 0.0);
  EXPECT_FALSE(law.isActive(0.0));
  EXPECT_THROW(cc::PenaltyNormalLaw(0.0), contessa::InputError);
}

TEST(ContactLawParameters, ValidationNamesTheParameter) {
  EXPECT_NO_THROW((cc::ContactLawParameters{1e3, 0.0, 0.0}.validate()));
  EXPECT_THROW((cc::ContactLawParameters{-1.0, 1.0, 0.1}.validate()), contessa::InputError);
  EXPECT_THROW((cc::ContactLawParameters{1e3, 1.0, -0.1}.validate()), contessa::InputError);
  try {
    cc::ContactLawParameters{1e3, 0.0, 0.3}.validate();
    FAIL() << "mu > 0 with epsilon_T = 0 and no slip tolerance must be rejected";
  } catch (const contessa::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("epsilon_T"), std::string::npos);
  }
  // With a slip tolerance ε_T comes from the pressure; the Tangential Penalty is an optional bound.
  EXPECT_NO_THROW((cc::ContactLawParameters{1e3, 0.0, 0.3, 0.005}.validate()));
  EXPECT_THROW((cc::ContactLawParameters{1e3, 0.0, 0.3, -0.005}.validate()), contessa::InputError);
  EXPECT_THROW((cc::ContactLawParameters{1e3, -1.0, 0.3, 0.005}.validate()), contessa::InputError);
  EXPECT_THROW(cc::CoulombReturnMapping<1>(0.0, 0.3, 0.0), contessa::InputError);
}

TEST(CoulombReturnMapping, SticksBelowTheCoulombLimit) {
  const cc::CoulombReturnMapping<1> map(100.0, 0.3);
  // ā_11 = 4 (segment of length 4): t^trial = 0 + 100·4·0.01 = 4, ‖t^trial‖ = 4/2 = 2 < 0.3·100.
  const auto r = map.map(input1(0.0, 0.01, 4.0, -100.0));
  EXPECT_EQ(r.status, ContactStatus::Stick);
  EXPECT_DOUBLE_EQ(r.trialTraction[0], 4.0);  // eq. (20)
  EXPECT_DOUBLE_EQ(r.trialNorm, 2.0);          // eq. (19)
  EXPECT_DOUBLE_EQ(r.trialIndicator, -28.0);   // eq. (21)
  EXPECT_DOUBLE_EQ(r.traction[0], 4.0);        // eq. (22a)
  EXPECT_DOUBLE_EQ(r.dTraction_dSlipIncrement(0, 0), 400.0);
}

TEST(CoulombReturnMapping, SlipsAboveTheLimitWithTheCoulombTractionInTheTrialDirection) {
  const cc::CoulombReturnMapping<1> map(100.0, 0.3);
  for (double slip : {0.5, -0.5}) {
    const auto r = map.map(input1(0.0, slip, 4.0, -100.0));
    EXPECT_EQ(r.status, ContactStatus::Slip);
    EXPECT_GT(r.trialIndicator, 0.0);
    EXPECT_NEAR(std::abs(r.traction[0]) / 2.0, 30.0, 1e-12);           // ‖t_T‖ = μ|t_N|, eq. (22b)
    EXPECT_EQ(std::signbit(r.traction[0]), std::signbit(r.trialTraction[0]));  // n^trial, eq. (23)
    EXPECT_DOUBLE_EQ(r.dTraction_dTrial(0, 0), 0.0);  // eq. (27): δ − n_1 n^1 = 0 with one ξ
  }
}

TEST(CoulombReturnMapping, SlipWithTwoSurfaceCoordinatesKeepsTheNormAndDirection) {
  const cc::CoulombReturnMapping<2> map(50.0, 0.4);
  cc::ReturnMappingInput<2> in;
  in.committedTraction = {0.7, -0.2};
  in.slipIncrement = {0.3, 0.1};
  in.metric(0, 0) = 2.0;
  in.metric(0, 1) = in.metric(1, 0) = 0.6;
  in.metric(1, 1) = 1.5;
  in.normalTraction = -20.0;
  const auto r = map.map(in);
  ASSERT_EQ(r.status, ContactStatus::Slip);
  EXPECT_NEAR(tractionNorm<2>(r.traction, in.metric), 0.4 * 20.0, 1e-12);
  // parallel to the trial traction, same sense
  EXPECT_NEAR(r.traction[0] * r.trialTraction[1] - r.traction[1] * r.trialTraction[0], 0.0, 1e-12);
  EXPECT_GT(cc::dot(r.traction, r.trialTraction), 0.0);
  EXPECT_NEAR(tractionNorm<2>(r.trialDirection, in.metric), 1.0, 1e-12);
}

TEST(CoulombReturnMapping, ReversalSticksFirstThenSlipsTheOtherWay) {
  // ā_11 = 1, ε_T = 1000, μ|t_N| = 30. History committed per increment.
  const cc::CoulombReturnMapping<1> map(1000.0, 0.3);
  cc::ContactHistoryStore<1> store(1);
  auto increment = [&](double slip) {
    const auto r = map.map(input1(store.committed(0).tangentialTraction[0], slip, 1.0, -100.0));
    cc::ContactHistory<1> h = store.committed(0);
    h.tangentialTraction = r.traction;
    h.status = r.status;
    store.setTrial(0, h);
    store.commit();
    return r;
  };
  const auto forward = increment(0.1);  // trial 100 > 30
  EXPECT_EQ(forward.status, ContactStatus::Slip);
  EXPECT_DOUBLE_EQ(forward.traction[0], 30.0);
  const auto back = increment(-0.02);  // trial 30 − 20 = 10: elastic unloading, stick
  EXPECT_EQ(back.status, ContactStatus::Stick);
  EXPECT_DOUBLE_EQ(back.traction[0], 10.0);
  const auto reverse = increment(-0.1);  // trial 10 − 100 = −90: slip the other way
  EXPECT_EQ(reverse.status, ContactStatus::Slip);
  EXPECT_DOUBLE_EQ(reverse.traction[0], -30.0);
  EXPECT_EQ(store.committed(0).status, ContactStatus::Slip);
}

TEST(CoulombReturnMapping, FrictionlessHasNoTangentialTraction) {
  const cc::CoulombReturnMapping<1> map(0.0, 0.0);
  const auto r = map.map(input1(5.0, 0.7, 3.0, -100.0));
  EXPECT_EQ(r.status, ContactStatus::Slip);
  EXPECT_EQ(r.traction[0], 0.0);
  EXPECT_EQ(r.dTraction_dSlipIncrement(0, 0), 0.0);
  EXPECT_EQ(r.dTraction_dNormalTraction[0], 0.0);
  EXPECT_EQ(r.dTraction_dMetric[0](0, 0), 0.0);
}

// The partial derivatives the element tangent is built from, against central differences. `scale` is
// the size of the derivatives (the tolerance is 1e-6 (|value| + scale)); the t_N step is 1e-6 of |t_N|
// at small pressures, so it never crosses t_N = 0.
template <int NXi>
void checkDerivatives(const cc::CoulombReturnMapping<NXi>& map, const cc::ReturnMappingInput<NXi>& in,
                      ContactStatus expected, double scale = 1.0) {
  const auto r = map.map(in);
  ASSERT_EQ(r.status, expected);
  const double h = 1e-6;
  const double hN = 1e-6 * std::min(1.0, std::abs(in.normalTraction));
  for (int beta = 0; beta < NXi; ++beta) {
    auto plus = in;
    auto minus = in;
    plus.slipIncrement[beta] += h;
    minus.slipIncrement[beta] -= h;
    const auto tp = map.map(plus).traction;
    const auto tm = map.map(minus).traction;
    for (int alpha = 0; alpha < NXi; ++alpha)
      EXPECT_NEAR(r.dTraction_dSlipIncrement(alpha, beta), (tp[alpha] - tm[alpha]) / (2 * h), 1e-6 * (scale + std::abs(r.dTraction_dSlipIncrement(alpha, beta))));
    for (int gamma = 0; gamma < NXi; ++gamma) {
      auto mp = in;
      auto mm = in;
      mp.metric(beta, gamma) += h;
      mm.metric(beta, gamma) -= h;
      const auto sp = map.map(mp).traction;
      const auto sm = map.map(mm).traction;
      for (int alpha = 0; alpha < NXi; ++alpha)
        EXPECT_NEAR(r.dTraction_dMetric[alpha](beta, gamma), (sp[alpha] - sm[alpha]) / (2 * h), 1e-6 * (scale + std::abs(r.dTraction_dMetric[alpha](beta, gamma))));
    }
  }
  auto np = in;
  auto nm = in;
  np.normalTraction += hN;
  nm.normalTraction -= hN;
  const auto up = map.map(np).traction;
  const auto um = map.map(nm).traction;
  for (int alpha = 0; alpha < NXi; ++alpha)
    EXPECT_NEAR(r.dTraction_dNormalTraction[alpha], (up[alpha] - um[alpha]) / (2 * hN),
                1e-6 * (1.0 + std::abs(r.dTraction_dNormalTraction[alpha])));
}

TEST(CoulombReturnMapping, LinearisationMatchesFiniteDifferences) {
  const cc::CoulombReturnMapping<1> map1(80.0, 0.3);
  checkDerivatives<1>(map1, input1(1.0, 0.01, 2.5, -50.0), ContactStatus::Stick);
  checkDerivatives<1>(map1, input1(1.0, 0.4, 2.5, -50.0), ContactStatus::Slip);
  checkDerivatives<1>(map1, input1(-3.0, -0.4, 0.7, -50.0), ContactStatus::Slip);

  const cc::CoulombReturnMapping<2> map2(80.0, 0.3);
  cc::ReturnMappingInput<2> in;
  in.committedTraction = {1.0, -0.5};
  in.metric(0, 0) = 2.0;
  in.metric(0, 1) = in.metric(1, 0) = 0.4;
  in.metric(1, 1) = 1.2;
  in.normalTraction = -50.0;
  in.slipIncrement = {0.01, -0.02};
  checkDerivatives<2>(map2, in, ContactStatus::Stick);
  in.slipIncrement = {0.3, -0.2};
  checkDerivatives<2>(map2, in, ContactStatus::Slip);
}

// ---- Slip tolerance: ε_T = μ|t_N|/(s L), capped by the Tangential Penalty ----------------------------

namespace {

cc::ReturnMappingInput<1> input1L(double committed, double slip, double a11, double tN, double facetLength) {
  auto in = input1(committed, slip, a11, tN);
  in.facetLength = facetLength;
  return in;
}

}  // namespace

TEST(CoulombReturnMapping, SlipToleranceKeepsTheStickRangeWhateverThePressure) {
  // s = 0.005, L = 2: a node sticks while its elastic slip is below s L = 0.01, at any pressure.
  // ā_11 = 4 (‖ā_1‖ = 2): a physical slip d is Δξ = d/2, and ‖t^trial‖ = ε_T d from t_n = 0.
  const cc::CoulombReturnMapping<1> map(0.0, 0.3, 0.005);
  for (double tN : {-100.0, -1.0, -1e-6, -1e-11}) {
    SCOPED_TRACE(tN);
    const auto inside = map.map(input1L(0.0, 0.99 * 0.01 / 2.0, 4.0, tN, 2.0));
    EXPECT_EQ(inside.status, ContactStatus::Stick);
    EXPECT_NEAR(inside.tangentialPenalty, 0.3 * std::abs(tN) / 0.01, 1e-12 * 0.3 * std::abs(tN) / 0.01);
    EXPECT_NEAR(inside.trialNorm, 0.99 * 0.3 * std::abs(tN), 1e-12 * std::abs(tN));  // 99 % of the cone
    const auto outside = map.map(input1L(0.0, -1.01 * 0.01 / 2.0, 4.0, tN, 2.0));
    EXPECT_EQ(outside.status, ContactStatus::Slip);
    EXPECT_NEAR(outside.traction[0] / 2.0, -0.3 * std::abs(tN), 1e-12 * std::abs(tN));  // eq. (22b), backwards
  }
  // The paper's constant ε_T (s = 0): the stick range μ|t_N|/ε_T vanishes with the pressure.
  const cc::CoulombReturnMapping<1> constant(1e9, 0.3);
  EXPECT_EQ(constant.map(input1L(0.0, 1e-9, 4.0, -0.1, 2.0)).status, ContactStatus::Slip);
  EXPECT_EQ(map.map(input1L(0.0, 1e-9, 4.0, -0.1, 2.0)).status, ContactStatus::Stick);
}

TEST(CoulombReturnMapping, TangentialPenaltyCapsThePressurePenalty) {
  // μ|t_N|/(s L) = 0.3·100/0.01 = 3000 above the cap 1000: ε_T = 1000, independent of t_N.
  const cc::CoulombReturnMapping<1> capped(1000.0, 0.3, 0.005);
  const auto high = capped.map(input1L(0.0, 1e-4, 4.0, -100.0, 2.0));
  EXPECT_EQ(high.tangentialPenalty, 1000.0);
  EXPECT_EQ(high.dTangentialPenalty_dNormalTraction, 0.0);
  EXPECT_DOUBLE_EQ(high.traction[0], 1000.0 * 4.0 * 1e-4);  // eq. (20)
  // 0.3·1/0.01 = 30 below the cap: tied to the pressure, ∂ε_T/∂t_N = −μ/(s L).
  const auto low = capped.map(input1L(0.0, 1e-4, 4.0, -1.0, 2.0));
  EXPECT_DOUBLE_EQ(low.tangentialPenalty, 30.0);
  EXPECT_DOUBLE_EQ(low.dTangentialPenalty_dNormalTraction, -0.3 / 0.01);
  // A slip tolerance needs the facet length.
  EXPECT_THROW(capped.map(input1(0.0, 1e-4, 4.0, -1.0)), std::logic_error);
}

TEST(CoulombReturnMapping, SlipToleranceLinearisationMatchesFiniteDifferences) {
  // ∂t/∂t_N now has the stick term ā Δξ ∂ε_T/∂t_N; checked in stick and slip, at a normal and at a very
  // small pressure (where the paper's constant ε_T leaves no stick range), with and without the cap.
  for (double pressure : {50.0, 1e-6}) {
    SCOPED_TRACE(pressure);
    const double limit = 0.3 * pressure;  // μ|t_N|
    const double sL = 0.005 * 2.0;
    for (double cap : {0.0, 0.5 * limit / sL}) {
      SCOPED_TRACE(cap);
      const cc::CoulombReturnMapping<1> map1(cap, 0.3, 0.005);
      // ‖ā_1‖ = 1.58: stick with a committed traction at 20 % of the cone and 30 % of s L more slip
      // (50 % with the cap halving ε_T), slip with 3 s L.
      const double a11 = 2.5, length = std::sqrt(a11);
      auto stick = input1L(0.2 * limit * length, 0.3 * sL / length, a11, -pressure, 2.0);
      checkDerivatives<1>(map1, stick, ContactStatus::Stick, limit);
      auto slip = input1L(0.2 * limit * length, -3.0 * sL / length, a11, -pressure, 2.0);
      checkDerivatives<1>(map1, slip, ContactStatus::Slip, limit);
      // The normal derivative is of size μ ā Δξ/(s L) ~ 1: compare it relatively as well.
      const auto r = map1.map(stick);
      auto plus = stick, minus = stick;
      const double h = 1e-3 * pressure;
      plus.normalTraction += h;
      minus.normalTraction -= h;
      const double fd = (map1.map(plus).traction[0] - map1.map(minus).traction[0]) / (2 * h);
      EXPECT_NEAR(r.dTraction_dNormalTraction[0], fd, 1e-7 * std::max(1.0, std::abs(fd)));
      if (cap == 0.0) {
        EXPECT_NE(r.dTraction_dNormalTraction[0], 0.0);
      }
    }
    // Two surface coordinates (3D faces): slip has ∂t/∂t_N through ε_T in t^trial and eq. (27) too.
    const cc::CoulombReturnMapping<2> map2(0.0, 0.3, 0.005);
    cc::ReturnMappingInput<2> in;
    in.metric(0, 0) = 2.0;
    in.metric(0, 1) = in.metric(1, 0) = 0.4;
    in.metric(1, 1) = 1.2;
    in.normalTraction = -pressure;
    in.facetLength = 2.0;
    in.committedTraction = {0.1 * limit, -0.05 * limit};
    in.slipIncrement = {0.1 * sL, -0.2 * sL};
    checkDerivatives<2>(map2, in, ContactStatus::Stick, limit);
    in.slipIncrement = {3.0 * sL, -2.0 * sL};
    checkDerivatives<2>(map2, in, ContactStatus::Slip, limit);
  }
}

// ---- The augmented Lagrangian's stick penalty: ε_T = μ|λ_N|/(s L), frozen between updates ----------------

TEST(CoulombReturnMapping, AugmentedStickPenaltyFollowsTheNormalMultiplierNotThePressure) {
  // s = 0.005, L = 2 (s L = 0.01), μ = 0.3, λ_N = −50: ε_T = 0.3·50/0.01 = 1500 at any t_N, ∂ε_T/∂t_N = 0.
  const cc::CoulombReturnMapping<1> map(0.0, 0.3, 0.005);
  for (double tN : {-100.0, -50.0, -1.0}) {
    auto in = input1L(0.0, 1e-4, 4.0, tN, 2.0);
    in.frozenNormalTraction = -50.0;
    const auto r = map.map(in);
    EXPECT_DOUBLE_EQ(r.tangentialPenalty, 1500.0);
    EXPECT_EQ(r.dTangentialPenalty_dNormalTraction, 0.0);
  }
  // The first update of the frictional patch test (docs/theory-contact.md §15): a penalty solve converged
  // with t_N = −p and a stick traction τ = ε_T(p) ā Δξ = 0.7 μ p; the update sets λ_N = −p, λ_T = τ, and at
  // the unchanged iterate t_N = λ_N + ε_N g_N = −2p. The trial λ_T + ε_T ā Δξ is 2τ = 1.4 μ p, inside
  // μ 2p: the node sticks. ε_T following t_N doubled with it: 3τ = 2.1 μ p, slip.
  // ā_11 = 4: the covariant component of a traction of norm τ is 2τ.
  const double p = 50.0, tau = 0.7 * 0.3 * p, a11 = 4.0, length = 2.0;
  const double slip = tau * length / (0.3 * p / 0.01 * a11);
  auto afterUpdate = input1L(tau * length, slip, a11, -2.0 * p, 2.0);
  afterUpdate.frozenNormalTraction = -p;
  const auto frozen = map.map(afterUpdate);
  EXPECT_EQ(frozen.status, ContactStatus::Stick);
  EXPECT_NEAR(frozen.trialNorm, 2.0 * tau, 1e-12 * tau);
  afterUpdate.frozenNormalTraction = 0.0;  // ε_T from t_N, as before
  EXPECT_EQ(map.map(afterUpdate).status, ContactStatus::Slip);
}

TEST(CoulombReturnMapping, AugmentedStickPenaltyLinearisationMatchesFiniteDifferences) {
  // ∂t/∂t_N without the ε_T(t_N) term: through μ|t_N| only (slip), nothing in stick. One and two surface
  // coordinates, stick and slip, with the multiplier's pressure above and below the current one.
  const double sL = 0.005 * 2.0;
  for (double multiplier : {-80.0, -20.0}) {
    SCOPED_TRACE(multiplier);
    const double epsT = 0.3 * std::abs(multiplier) / sL, limit = 0.3 * 50.0;
    const cc::CoulombReturnMapping<1> map1(0.0, 0.3, 0.005);
    auto stick = input1L(0.2 * limit, 0.3 * limit / epsT / 2.5, 2.5, -50.0, 2.0);
    stick.frozenNormalTraction = multiplier;
    checkDerivatives<1>(map1, stick, ContactStatus::Stick, limit);
    EXPECT_EQ(map1.map(stick).dTraction_dNormalTraction[0], 0.0);
    auto slip = input1L(0.2 * limit, -3.0 * limit / epsT, 2.5, -50.0, 2.0);
    slip.frozenNormalTraction = multiplier;
    checkDerivatives<1>(map1, slip, ContactStatus::Slip, limit);

    const cc::CoulombReturnMapping<2> map2(0.0, 0.3, 0.005);
    cc::ReturnMappingInput<2> in;
    in.metric(0, 0) = 2.0;
    in.metric(0, 1) = in.metric(1, 0) = 0.4;
    in.metric(1, 1) = 1.2;
    in.normalTraction = -50.0;
    in.frozenNormalTraction = multiplier;
    in.facetLength = 2.0;
    in.committedTraction = {0.1 * limit, -0.05 * limit};
    in.slipIncrement = {0.1 * limit / epsT, -0.2 * limit / epsT};
    checkDerivatives<2>(map2, in, ContactStatus::Stick, limit);
    in.slipIncrement = {3.0 * limit / epsT, -2.0 * limit / epsT};
    checkDerivatives<2>(map2, in, ContactStatus::Slip, limit);
  }
}

TEST(ContactHistoryStore, RollbackRestoresTheCommittedStateExactly) {
  cc::ContactHistoryStore<1> store(3);
  cc::ContactHistory<1> h;
  h.segment = 4;
  h.xi = {0.123456789};
  h.tangentialTraction = {-7.25};
  h.status = ContactStatus::Slip;
  h.accumulatedSlip = 0.31;
  store.setTrial(1, h);
  store.commit();
  const cc::ContactHistory<1> committed = store.committed(1);
  EXPECT_EQ(committed, h);

  cc::ContactHistory<1> iterate = h;  // a Newton iterate of the next increment
  iterate.segment = 5;
  iterate.xi = {-0.9};
  iterate.tangentialTraction = {3.0};
  iterate.status = ContactStatus::Stick;
  iterate.accumulatedSlip = 0.5;
  store.setTrial(1, iterate);
  store.setTrial(2, iterate);
  EXPECT_NE(store.trial(1), store.committed(1));
  EXPECT_EQ(store.committed(1), committed);  // trial updates never touch the committed copy

  store.rollback();
  for (std::size_t node = 0; node < store.size(); ++node) EXPECT_EQ(store.trial(node), store.committed(node));
  EXPECT_EQ(store.trial(1), h);
  EXPECT_EQ(store.trial(2), cc::ContactHistory<1>{});
  EXPECT_EQ(store.trial(1).xi[0], 0.123456789);  // bit for bit
}

TEST(HistoryTransfer, UnrollsTheContactPointAcrossTheSharedVertex) {
  // Counter-clockwise top of a block: segment 0 from (4,0) to (2,0) (‖ā_1‖ = 1), then segment 1 from
  // (2,0) to (−2,0) (‖ā_1‖ = 2).
  const cc::MasterFacetNodes<cc::Line2Facet> first{0, {0, 1}, {{{4.0, 0.0}, {2.0, 0.0}}}};
  const cc::MasterFacetNodes<cc::Line2Facet> second{1, {1, 2}, {{{2.0, 0.0}, {-2.0, 0.0}}}};
  cc::ContactHistory<1> h;
  h.segment = 0;
  h.xi = {0.5};                   // x = 2.5, 0.5 before the vertex
  h.tangentialTraction = {3.0};   // physical 3.0/1
  h.status = ContactStatus::Stick;
  h.accumulatedSlip = 0.2;
  const auto moved = cc::transferHistory(h, first, second);
  EXPECT_EQ(moved.segment, 1);
  EXPECT_NEAR(moved.xi[0], -1.25, 1e-14);  // x = 2.5 on the line of segment 1: ξ = −1 − 0.5/2
  EXPECT_NEAR(moved.tangentialTraction[0], 6.0, 1e-14);  // same physical traction, ‖ā_1‖ = 2
  EXPECT_EQ(moved.status, ContactStatus::Stick);
  EXPECT_EQ(moved.accumulatedSlip, 0.2);
  // And back.
  const auto back = cc::transferHistory(moved, second, first);
  EXPECT_NEAR(back.xi[0], 0.5, 1e-14);
  EXPECT_NEAR(back.tangentialTraction[0], 3.0, 1e-14);
}

// 3D: a node sliding from face A over the shared edge x = 2 onto face B. Coplanar, and folded down by 90°
// (a convex edge): unfolding about the edge gives B the same ξ_n and covariant traction in both cases, i.e.
// the arc length slid and the traction along the path are carried over the edge.
TEST(HistoryTransfer, UnfoldsTheContactPointAndTractionAboutTheSharedEdge) {
  using Face = cc::MasterFacetNodes<cc::Quad4Facet>;
  const Face a{0, {0, 1, 2, 3}, {{{0.0, 0.0, 0.0}, {2.0, 0.0, 0.0}, {2.0, 2.0, 0.0}, {0.0, 2.0, 0.0}}}};
  const Face flat{1, {1, 4, 5, 2}, {{{2.0, 0.0, 0.0}, {5.0, 0.0, 0.0}, {5.0, 2.0, 0.0}, {2.0, 2.0, 0.0}}}};
  const Face folded{2, {1, 4, 5, 2}, {{{2.0, 0.0, 0.0}, {2.0, 0.0, -3.0}, {2.0, 2.0, -3.0}, {2.0, 2.0, 0.0}}}};
  cc::ContactHistory<2> h;
  h.segment = 0;
  h.xi = {0.5, 0.2};                   // x = (1.5, 1.2, 0), 0.5 before the edge
  h.tangentialTraction = {3.0, 1.0};   // ā_α = e_x, e_y on A: physical traction (3, 1, 0)
  h.status = ContactStatus::Slip;
  h.accumulatedSlip = 0.7;
  for (const Face* b : {&flat, &folded}) {
    SCOPED_TRACE(b->id);
    const auto moved = cc::transferHistory(h, a, *b);
    EXPECT_EQ(moved.segment, b->id);
    EXPECT_EQ(moved.status, ContactStatus::Slip);
    EXPECT_EQ(moved.accumulatedSlip, 0.7);
    EXPECT_NEAR(moved.xi[0], -1.0 - 0.5 / 1.5, 1e-12);  // 0.5 before the edge, ‖ā_1‖ = 1.5 on B
    EXPECT_NEAR(moved.xi[1], 0.2, 1e-12);
    EXPECT_NEAR(moved.tangentialTraction[0], 3.0 * 1.5, 1e-12);  // t·ā_1: across the edge, along the path
    EXPECT_NEAR(moved.tangentialTraction[1], 1.0, 1e-12);        // t·ā_2: along the edge
    const auto back = cc::transferHistory(moved, *b, a);
    EXPECT_NEAR(back.xi[0], 0.5, 1e-12);
    EXPECT_NEAR(back.xi[1], 0.2, 1e-12);
    EXPECT_NEAR(back.tangentialTraction[0], 3.0, 1e-12);
    EXPECT_NEAR(back.tangentialTraction[1], 1.0, 1e-12);
  }
  // Faces sharing only a corner: the old point is projected onto the new face, the traction onto its
  // tangent plane with its magnitude kept.
  const Face tilted{3, {2, 6, 7, 8}, {{{2.0, 2.0, 0.0}, {4.0, 2.0, 0.5}, {4.0, 4.0, 0.5}, {2.0, 4.0, 0.0}}}};
  const auto moved = cc::transferHistory(h, a, tilted);
  const auto p = cc::FaceProjection3D().project({1.5, 1.2, 0.0}, tilted.x);
  EXPECT_NEAR(moved.xi[0], p.xi[0], 1e-12);
  EXPECT_NEAR(moved.xi[1], p.xi[1], 1e-12);
  Vector<3> t{};
  for (int al = 0; al < 2; ++al) cc::addScaled(t, moved.tangentialTraction[al], p.contravariantBasis[al]);
  EXPECT_NEAR(cc::norm(t), std::sqrt(10.0), 1e-12);
  EXPECT_NEAR(cc::dot(t, p.normal), 0.0, 1e-12);
}

// ---- Slip reversal damping (tangent only) ------------------------------------------------------------

TEST(SlipReversalDamping, GivesANodeWhoseSlipDirectionReversesTheSecantStiffness) {
  auto state = [](ContactStatus status, double xi, double traction) {
    cc::ContactHistory<1> h;
    h.segment = 2;
    h.status = status;
    h.xi = {xi};
    h.tangentialTraction = {traction};
    return h;
  };
  cc::SlipReversalDamping damping(3);
  EXPECT_FALSE(damping.tangent(1).secant);
  const auto forward = state(ContactStatus::Slip, 0.10, 0.3), backward = state(ContactStatus::Slip, 0.04, -0.3);
  // Slip forwards, then forwards again: no reversal, consistent tangent.
  EXPECT_FALSE(damping.observe(1, forward, state(ContactStatus::Slip, 0.12, 0.31)));
  EXPECT_FALSE(damping.tangent(1).secant);
  // Forwards, then backwards: the secant Δt/Δξ = (−0.3 − 0.3)/(0.04 − 0.10) = 10 between the two states.
  EXPECT_TRUE(damping.observe(1, forward, backward));
  ASSERT_TRUE(damping.tangent(1).secant);
  EXPECT_NEAR(damping.tangent(1).stiffness, 10.0, 1e-12);
  EXPECT_FALSE(damping.tangent(0).secant);  // other nodes untouched
  // The same iterate evaluated again (residual and Jacobian in two calls) changes nothing.
  EXPECT_FALSE(damping.observe(1, backward, backward));
  EXPECT_TRUE(damping.tangent(1).secant);
  // Slipping the same way for kReleaseIterates iterates: it really slips, consistent tangent again.
  const auto further = state(ContactStatus::Slip, 0.03, -0.3), furthest = state(ContactStatus::Slip, 0.02, -0.3);
  EXPECT_FALSE(damping.observe(1, backward, further));
  EXPECT_TRUE(damping.tangent(1).secant);
  EXPECT_FALSE(damping.observe(1, further, furthest));
  EXPECT_FALSE(damping.tangent(1).secant);
  // A node that sticks after its reversal takes its consistent (stick) tangent at once.
  EXPECT_TRUE(damping.observe(0, forward, backward));
  EXPECT_FALSE(damping.observe(0, backward, state(ContactStatus::Stick, 0.07, 0.1)));
  EXPECT_FALSE(damping.tangent(0).secant);
  // A reversal counts only on the same segment (another segment has its own orientation).
  auto elsewhere = backward;
  elsewhere.segment = 3;
  EXPECT_FALSE(damping.observe(2, forward, elsewhere));
  EXPECT_TRUE(damping.observe(2, backward, forward));
  EXPECT_EQ(damping.reversals(), 3);
  damping.reset();  // commit or rollback of the increment
  EXPECT_FALSE(damping.tangent(2).secant);
  EXPECT_EQ(damping.reversals(), 0);
}

TEST(SlipReversalDamping, FromTwoReversalsInARowWhenAskedTo) {
  // reversalsToDamp = 2 (mortar): a reversal followed by an iterate that slips on the same way keeps the
  // consistent tangent (an overshoot corrected), two reversals at consecutive iterates (the two-state cycle)
  // take the secant of the second; a reset (commit, rollback) starts anew.
  auto state = [](double xi, double traction) {
    cc::ContactHistory<1> h;
    h.segment = 0;
    h.status = ContactStatus::Slip;
    h.xi = {xi};
    h.tangentialTraction = {traction};
    return h;
  };
  cc::SlipReversalDamping damping(1, 2);
  const auto forward = state(0.10, 0.3), backward = state(0.04, -0.3), further = state(0.03, -0.3),
             again = state(0.07, 0.3), back = state(0.05, -0.3);
  EXPECT_TRUE(damping.observe(0, forward, backward));
  EXPECT_FALSE(damping.tangent(0).secant);
  EXPECT_FALSE(damping.observe(0, backward, further));  // the same way: the overshoot corrected
  EXPECT_TRUE(damping.observe(0, further, again));       // a reversal again, but not in a row
  EXPECT_FALSE(damping.tangent(0).secant);
  EXPECT_TRUE(damping.observe(0, again, back));           // in a row: the cycle
  ASSERT_TRUE(damping.tangent(0).secant);
  EXPECT_NEAR(damping.tangent(0).stiffness, 0.6 / 0.02, 1e-12);  // (0.3 − (−0.3)) / (0.07 − 0.05)
  EXPECT_EQ(damping.reversals(), 3);
  damping.reset();
  EXPECT_TRUE(damping.observe(0, forward, backward));
  EXPECT_FALSE(damping.tangent(0).secant);
}

TEST(NormalToggleDamping, GivesANodeThatCyclesBetweenOpenAndClosedTheNormalSecant) {
  // The tube's node at ε_N = 1e9 (docs/theory-contact.md §15): open at g_N = 1.27e-11, closed at −3.14e-6 with
  // t_N = −3141, and back. States: (open, g_N, t_N).
  cc::NormalToggleDamping damping(2);
  const double gOpen = 1.27e-11, gClosed = -3.14e-6, tClosed = -3141.0;
  // An ordinary closure and an opening (the predictor's overshoot corrected): the consistent tangent.
  EXPECT_FALSE(damping.observe(0, true, false, gClosed, tClosed, false));
  EXPECT_FALSE(damping.observe(0, false, true, gOpen, 0.0, false));
  EXPECT_EQ(damping.stiffness(0), 0.0);
  // The same iterate evaluated again changes nothing.
  EXPECT_FALSE(damping.observe(0, false, true, gOpen, 0.0, true));
  // Closed again at the next iterate, open at the one after: four changes in a row, the cycle repeated.
  EXPECT_FALSE(damping.observe(0, true, false, 2.0 * gClosed, 2.0 * tClosed, false));
  EXPECT_EQ(damping.stiffness(0), 0.0);
  EXPECT_TRUE(damping.observe(0, false, true, gOpen, 0.0, false));
  EXPECT_NEAR(damping.stiffness(0), 2.0 * tClosed / (2.0 * gClosed - gOpen), 1e-12 * 1e9);
  EXPECT_EQ(damping.stiffness(1), 0.0);  // other nodes untouched
  // Open for kReleaseIterates iterates: it really opens, the consistent tangent (none) again.
  EXPECT_FALSE(damping.observe(0, true, true, 2.0 * gOpen, 0.0, false));
  EXPECT_GT(damping.stiffness(0), 0.0);
  EXPECT_FALSE(damping.observe(0, true, true, 3.0 * gOpen, 0.0, false));
  EXPECT_EQ(damping.stiffness(0), 0.0);
  // A node that closes takes its consistent tangent at once.
  for (bool open : {false, true, false}) damping.observe(1, !open, open, open ? gOpen : gClosed, open ? 0.0 : tClosed, false);
  EXPECT_TRUE(damping.observe(1, false, true, gOpen, 0.0, false));
  EXPECT_FALSE(damping.observe(1, true, false, gClosed, tClosed, false));
  EXPECT_EQ(damping.stiffness(1), 0.0);
  EXPECT_EQ(damping.toggles(), 2);
  damping.reset();  // commit or rollback of the increment
  EXPECT_EQ(damping.toggles(), 0);
  EXPECT_FALSE(damping.observe(1, false, true, gOpen, 0.0, false));
  EXPECT_EQ(damping.stiffness(1), 0.0);
  // A change of state at a multiplier update (another λ_N: the same iterate, another problem) does not count.
  EXPECT_FALSE(damping.observe(0, true, false, gClosed, tClosed, false));
  EXPECT_FALSE(damping.observe(0, false, true, gOpen, 0.0, false));
  EXPECT_FALSE(damping.observe(0, true, false, gClosed, tClosed, false));
  EXPECT_FALSE(damping.observe(0, false, true, gOpen, 0.0, false, -0.01));  // the update opened it
  EXPECT_FALSE(damping.observe(0, true, false, gClosed, tClosed, false, -0.01));
  EXPECT_FALSE(damping.observe(0, false, true, gOpen, 0.0, false, -0.01));
  EXPECT_FALSE(damping.observe(0, true, false, gClosed, tClosed, false, -0.01));
  EXPECT_TRUE(damping.observe(0, false, true, gOpen, 0.0, false, -0.01));
}
