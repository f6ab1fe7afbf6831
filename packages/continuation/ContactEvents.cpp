#include "continuation/ContactEvents.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "continuation/ContactBeta.hpp"

namespace contessa::continuation {

namespace {

/// Fraction at which a quantity going linearly from `start` (< 0) to `end` crosses zero, or −1 when it
/// does not move towards zero.
double zeroCrossing(double start, double end) {
  const double rise = end - start;
  if (!(rise > 0)) return -1;
  return -start / rise;
}

double openingFraction(const SlaveNodeIncrement& n) {
  if (!std::isfinite(n.committedGap) || !std::isfinite(n.trialGap)) return -1;
  if (!(n.trialGap > n.committedGap)) return -1;  // pressed harder, or unchanged
  // No pressure left (g_t ≥ 0): opens in any step. A node pressed by a tiny penetration still carries
  // ε_N |g_t| (touchingGap is a length for closures, not a pressure): it opens where the line crosses.
  if (n.committedGap >= 0) return 0;
  return zeroCrossing(n.committedGap, n.trialGap);
}

double frictionFraction(const SlaveNodeIncrement& n) {
  if (std::isnan(n.committedIndicator) || std::isnan(n.trialIndicator)) return -1;
  if (n.committedStatus == NodeStatus::Stick) {
    if (!(n.trialIndicator > n.committedIndicator)) return -1;  // moving away from the cone
    if (n.committedIndicator >= 0) return 0;                    // on the cone already
    return zeroCrossing(n.committedIndicator, n.trialIndicator);
  }
  // Slipping at t.
  if (n.trialStatus == NodeStatus::Stick) return 0;  // slip → stick: at the start of any step
  if (!(n.committedIndicator < 0)) return -1;         // still slipping the same way: no event ahead
  return zeroCrossing(n.committedIndicator, n.trialIndicator);  // driven the other way: reversal
}

}  // namespace

const std::vector<std::string>& countedEventsNames() {
  static const std::vector<std::string> names = {"Closures", "All Status Changes"};
  return names;
}

CountedEvents countedEventsByName(const std::string& name) {
  const auto& names = countedEventsNames();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) throw std::invalid_argument("unknown counted events '" + name + "'");
  return static_cast<CountedEvents>(it - names.begin());
}

EventKind statusChange(const SlaveNodeIncrement& n) {
  const bool before = n.committedStatus != NodeStatus::Open, after = n.trialStatus != NodeStatus::Open;
  if (!before && after) return EventKind::Closure;
  if (before && !after) return EventKind::Opening;
  if (!before) return EventKind::None;
  if (n.committedStatus == NodeStatus::Stick && n.trialStatus == NodeStatus::Slip) return EventKind::StickToSlip;
  if (n.committedStatus == NodeStatus::Slip && n.trialStatus == NodeStatus::Stick) return EventKind::SlipToStick;
  if (n.committedStatus == NodeStatus::Slip && n.slipReversed) return EventKind::SlipReversal;
  return EventKind::None;
}

bool isCounted(EventKind kind, CountedEvents rule) {
  if (kind == EventKind::None) return false;
  return rule == CountedEvents::AllStatusChanges || kind == EventKind::Closure;
}

int countEvents(const std::vector<SlaveNodeIncrement>& nodes, CountedEvents rule) {
  return static_cast<int>(
      std::count_if(nodes.begin(), nodes.end(), [rule](const auto& n) { return isCounted(statusChange(n), rule); }));
}

double eventFraction(const SlaveNodeIncrement& n, CountedEvents rule, double touchingGap) {
  if (!n.inContactAtCommit()) return closureFraction({n.committedGap, n.trialGap, false}, touchingGap);  // eq. (11)
  if (rule == CountedEvents::Closures) return -1;
  const double opening = openingFraction(n);
  const double friction = frictionFraction(n);
  if (opening < 0) return friction;
  if (friction < 0) return opening;
  return std::min(opening, friction);
}

std::vector<double> eventFractions(const std::vector<SlaveNodeIncrement>& nodes, CountedEvents rule,
                                   double touchingGap) {
  std::vector<double> out;
  for (const auto& n : nodes) {
    const double b = eventFraction(n, rule, touchingGap);
    if (b >= 0) out.push_back(b);
  }
  return out;
}

}  // namespace contessa::continuation
