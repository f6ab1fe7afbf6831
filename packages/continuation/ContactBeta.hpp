#pragma once
// The load-step correction of the reference paper (section 2.1, Table 1, after Chamoret et al. 2002):
// choose the increment so that only N_c slave nodes come into contact in it. Pure arithmetic on the
// gaps of the slave nodes: the continuation strategy (solvers/ContactBetaStepSize) supplies them.
#include <cstddef>
#include <limits>
#include <vector>

namespace contessa::continuation {

/// The normal gap of one slave node at the start of the increment (time t, converged) and at the
/// first iterate of t + Δt (after the first Newton iteration, or at the predicted state).
struct GapChange {
  double gapStart = 0;         ///< ^t g_N (eq. 4); +∞ when no master segment is in reach
  double gapEnd = 0;           ///< ^{t+Δt} g_N
  bool inContactAtStart = false;
};

/// Contacts Per Step = 0: N_c is chosen from the number of slave nodes (automaticContactsPerStep).
constexpr int kAutomaticContactsPerStep = 0;

/// The share of the slave nodes that automatic N_c lets close per increment without friction
/// (docs/theory-load-stepping.md §11.7; bench/README.md, "A default Contact Beta that takes the cheapest
/// path"): on the frictionless tube (102 slave nodes) every N_c from 34 on takes the fewest Newton
/// iterations, 36, with Max Step Size bounding the steps (N_c = 32: 47, 24: 73, 2: 145); half the slave
/// nodes keeps a margin above that edge.
constexpr double kAutomaticContactsShare = 0.5;
/// Automatic N_c never falls below the paper's N_c = 2, and is 2 with friction: the frictional answer
/// depends on the path (the slip history), and on the frictional tube every N_c above 2 moves the final
/// plate force by more than the user's fixed step does (N_c = 4: 1.9e-3, 32: 6.8e-3 against 8.9e-4).
constexpr int kAutomaticContactsMinimum = 2;

/// N_c for `slaveNodes` frictionless slave nodes (every interface, every rank) when the deck does not
/// give it: max(2, ⌈kAutomaticContactsShare × slaveNodes⌉).
int automaticContactsPerStep(std::size_t slaveNodes);

/// The defaults here (and in ContactBetaSettings) are the deck's: solvers/ContactBetaStepControl declares
/// the Step Size parameters with them.
struct BetaOptions {
  /// N_c, ≥ 1 when β is computed (computeBeta, betaFromFractions); kAutomaticContactsPerStep (the
  /// deck's default) only in the settings, which ContactBetaControl resolves for the nodes it is given.
  int contactsPerStep = kAutomaticContactsPerStep;
  double maxGrowth = 2.0;      ///< β ≤ maxGrowth (the step may grow at most this much per increment)
  double maxShrink = 0.05;     ///< β ≥ maxShrink
  /// Where β falls between β^{N_c} (0: the paper's eq. 13) and β^{N_c+1} (1): see computeBeta.
  double nextContactFraction = 0.9;
  /// Nodes open by less than this at the start count as touching: β^k = 0 (they take one of the N_c
  /// places, since they close in any step).
  double touchingGap = 1e-10;
  /// c: the learned ratio of the actual to the predicted β^k (EventRateCorrection); every β^k is read as
  /// c β^k before the choice. 1 = eq. (11) as it stands.
  double eventRateScale = 1.0;
};

struct BetaResult {
  double beta = 1;                 ///< the correction factor of eq. (10), within [maxShrink, maxGrowth]
  std::vector<double> candidates;  ///< β^k of eq. (11), sorted as in eq. (12), times eventRateScale
  int predictedContacts = 0;       ///< candidates with β^k ≤ β: nodes expected to close (events) in βΔt
  bool fewCandidates = false;      ///< at most N_c candidates: β is the growth cap, not an event's
  bool fromEvents = false;         ///< β was set by the events' β^k, not by a bound
  /// Where the planned step (β = 1) lies between β^{N_c} (0) and β^{N_c+1} (1): in [0, 1) it takes
  /// exactly N_c events; < 0 fewer, ≥ 1 more. NaN with few candidates.
  double placement = std::numeric_limits<double>::quiet_NaN();
};

/// β^k = ^t g / (^t g − ^{t+Δt} g), eq. (11), for every node likely to come into contact: open at the
/// start and approaching (g_t − g_{t+Δt} > 0); 0 for a touching node (g_t ≤ touchingGap). Others
/// return a negative value (not a candidate).
double closureFraction(const GapChange& change, double touchingGap);

/// Sorts the β^k (eq. 12) and returns the correction. Eq. (13) takes β = β^{N_c}, at which node N_c
/// is predicted to touch with zero gap, so whether it counts as in contact is left to round-off, and
/// nothing else closes. Contessa goes further by default, to β^{N_c} + f (β^{N_c+1} − β^{N_c}) with
/// f = nextContactFraction = 0.9: the largest step (with a margin) in which N_c nodes close and node
/// N_c + 1 does not; f = 0 is eq. (13) as printed. With exactly N_c candidates, or fewer, the step
/// grows to the cap (the paper: "β > 1 grows the step when the user's step is too small").
BetaResult computeBeta(const std::vector<GapChange>& changes, const BetaOptions& options);

/// The same choice over given β^k (of any event kind, ContactEvents.hpp), each first multiplied by
/// options.eventRateScale. Unavoidable events (β^k = 0) take places among the N_c; when there are more
/// of them than N_c (and f > 0) the step is the one that adds no avoidable event to them:
/// β = f β^{m+1} for m unavoidable events (f = 0 keeps eq. 13: β = 0, clamped to the shrink bound).
BetaResult betaFromFractions(std::vector<double> fractions, const BetaOptions& options);

}  // namespace contessa::continuation
