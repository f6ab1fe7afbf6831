// Phase timers (contessa --timers): nothing is recorded while they are off; when on, the accounting is
// exclusive (a nested phase pauses the enclosing one), the phases add up to the wall time since the
// process started, and every entry is counted. The tests run in this order in one process (ctest runs
// each in its own), as switching the timers on cannot be undone.
#include <gtest/gtest.h>

#include <chrono>
#include <numeric>
#include <string>

#include "common/PhaseTimers.hpp"

namespace {

using contessa::timers::Phase;
namespace timers = contessa::timers;
using Clock = std::chrono::steady_clock;

// Busy for at least `seconds` of wall time.
void spin(double seconds) {
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  while (Clock::now() < end) {
  }
}

double sum(const timers::Totals& t) { return std::accumulate(t.seconds.begin(), t.seconds.end(), 0.0); }

TEST(PhaseTimers, OffByDefaultRecordNothing) {
  if (timers::enabled()) GTEST_SKIP() << "switched on by an earlier test in this process";
  {
    timers::Scope scope(Phase::Contact);
    spin(0.002);
  }
  timers::switchTo(Phase::Setup);
  const auto t = timers::localTotals();
  EXPECT_EQ(sum(t), 0.0);
  EXPECT_EQ(t.total, 0.0);
  for (long c : t.counts) EXPECT_EQ(c, 0);
}

TEST(PhaseTimers, NestedPhasesAreExclusiveAndAddUpToTheWallTime) {
  timers::enable();
  ASSERT_TRUE(timers::enabled());
  timers::switchTo(Phase::Setup);
  spin(0.005);
  timers::switchTo(Phase::Other);
  const auto outerStart = Clock::now();
  {
    timers::Scope outer(Phase::Contact);
    spin(0.01);
    {
      timers::Scope inner(Phase::MumpsSolve);
      spin(0.02);
    }
    spin(0.01);
  }
  const double outerWall = std::chrono::duration<double>(Clock::now() - outerStart).count();
  const auto t = timers::localTotals();
  const auto s = [&](Phase p) { return t.seconds[static_cast<int>(p)]; };
  const auto n = [&](Phase p) { return t.counts[static_cast<int>(p)]; };
  EXPECT_GE(s(Phase::Setup), 0.005);
  EXPECT_GE(s(Phase::MumpsSolve), 0.02);
  EXPECT_GE(s(Phase::Contact), 0.02);
  // The inner 20 ms are not the outer phase's: it has at most its own wall time minus the inner.
  EXPECT_LE(s(Phase::Contact), outerWall - s(Phase::MumpsSolve) + 1e-9);
  EXPECT_EQ(n(Phase::Contact), 1);
  EXPECT_EQ(n(Phase::MumpsSolve), 1);
  EXPECT_EQ(n(Phase::Startup), 1);
  EXPECT_GE(s(Phase::Startup), 0.0);
  // Every instant since the process started belongs to exactly one phase.
  EXPECT_NEAR(sum(t), t.total, 1e-9 * t.total);
  EXPECT_GE(t.total, s(Phase::Setup) + 0.04);
}

TEST(PhaseTimers, TableNamesEveryPhaseAndTheRankMaximum) {
  timers::Totals t;
  t.total = 2.0;
  t.seconds[static_cast<int>(Phase::MumpsFactorization)] = 0.5;
  t.counts[static_cast<int>(Phase::MumpsFactorization)] = 183;
  const std::string one = timers::formatTable(t, 1);
  for (int p = 0; p < timers::kNumPhases; ++p)
    EXPECT_NE(one.find(timers::phaseName(static_cast<Phase>(p))), std::string::npos) << one;
  EXPECT_NE(one.find("MUMPS factorisation (JOB=2)                 0.5000   25.0     183"), std::string::npos) << one;
  EXPECT_EQ(one.find("maximum"), std::string::npos);
  EXPECT_NE(timers::formatTable(t, 2).find("the maximum over 2 ranks"), std::string::npos);
}

}  // namespace
