#pragma once
// The events Contact Beta counts: status changes of slave nodes over an increment (the paper's closures,
// and optionally openings and the stick/slip changes of Coulomb friction), and the fraction β^k of the
// step at which each one happens: eq. (11) for a closure, and the same linear interpolation of the normal
// gap g_N (openings) or of the Coulomb indicator f of eq. (19) (stick/slip) for the others
// (docs/theory-load-stepping.md §2). Pure C++, no contact or Trilinos types: the model fills the per-node
// data (ContactEventSource).
#include <limits>
#include <string>
#include <vector>

namespace contessa::continuation {

/// Contact status of a slave node; the codes are those of the Exodus variable contact_status.
enum class NodeStatus : int { Open = 0, Stick = 1, Slip = 2 };

/// One slave node over the current increment: its state at the last commit (time t) against a trial
/// state of t + Δt (a Newton iterate, a predicted state, or the converged state of the increment).
struct SlaveNodeIncrement {
  double committedGap = std::numeric_limits<double>::infinity();  ///< ^t g_N (eq. 4); +∞: no master in reach
  double trialGap = std::numeric_limits<double>::infinity();      ///< ^{t+Δt} g_N
  NodeStatus committedStatus = NodeStatus::Open;
  NodeStatus trialStatus = NodeStatus::Open;
  /// The Coulomb indicator f of eq. (19) of the committed tractions, measured along the trial slip
  /// direction n^trial: t_T,t · n^trial − μ|t_N,t|. It is ‖t_T‖ − μ|t_N| (≤ 0; 0 on the cone) when the
  /// trial traction points the way the committed one does, and −‖t_T‖ − μ|t_N| when the node is driven
  /// the other way (a slipping node then has 2μ|t_N| to go before it slips back). NaN unless the node is
  /// in contact in both states with friction (μ > 0).
  double committedIndicator = std::numeric_limits<double>::quiet_NaN();
  /// f^trial = ‖t_T^trial‖ − μ|t_N| of eq. (21) at the trial state (> 0: slip). NaN as above.
  double trialIndicator = std::numeric_limits<double>::quiet_NaN();
  /// Slipping in both states, the trial slip direction opposite to the committed one.
  bool slipReversed = false;
  /// The master facet the trial state was evaluated on (−1: none). A node moving to another facet is
  /// no event, but a kink of the residual (the Jacobian check keeps it out of its differences).
  int trialFacet = -1;
  /// Where on trialFacet the trial state touches: 0 its projection, 1 a vertex, 2 an edge point
  /// (contact::ContactPoint::Kind), 3 its projection past a free edge (the force faded), with the vertex's
  /// or the edge's nodes local in the facet (−1: none). A switch between them (a node exactly under an edge
  /// or a vertex of coplanar facets that a step tilts into a ridge or a valley; a node on a free edge that a
  /// step leaves behind it) is a kink too.
  int trialContactKind = 0;
  int trialContactNodes[2] = {-1, -1};
  /// Its interface has a friction coefficient μ > 0: the answer depends on the path (the slip history),
  /// so automatic N_c keeps the paper's 2 (automaticContactsPerStep).
  bool frictional = false;

  bool inContactAtCommit() const { return committedStatus != NodeStatus::Open; }
};

/// What a node's status change is.
enum class EventKind { None, Closure, Opening, StickToSlip, SlipToStick, SlipReversal };

/// Which status changes Contact Beta limits to N_c per increment (deck `Counted Events`).
enum class CountedEvents {
  Closures,          ///< open → contact, the paper's eq. (11)–(13)
  AllStatusChanges,  ///< closures, openings, stick → slip, slip → stick, slip reversals
};

/// Deck names, in the order of the enum: "Closures", "All Status Changes".
const std::vector<std::string>& countedEventsNames();
/// The rule of a deck name (one of countedEventsNames(); anything else throws std::invalid_argument).
CountedEvents countedEventsByName(const std::string& name);

/// The status change committed → trial (at a converged state: the event that happened).
EventKind statusChange(const SlaveNodeIncrement& node);
bool isCounted(EventKind kind, CountedEvents rule);
/// Events the rule counts among the nodes' status changes.
int countEvents(const std::vector<SlaveNodeIncrement>& nodes, CountedEvents rule);

/// β^k of the event the node is heading for under the rule: the fraction of the step at which its
/// indicator crosses zero, linearly interpolated between t and the trial state (> 1: beyond this step).
/// Negative when the node is not heading for a counted event. By event:
///   closure        open at t: closureFraction (eq. 11) of its gaps
///   opening        in contact at t, g_t ≤ 0, separating (g_trial > g_t): −g_t / (g_trial − g_t)
///   stick → slip   stick at t, f_t < f_trial: f_t / (f_t − f_trial) (0 when f_t ≥ 0)
///   slip reversal  slipping at t, driven the other way (f_t < 0 along the trial direction), approaching
///                  slip the other way: f_t / (f_t − f_trial)
///   slip → stick   slipping at t, sticking in the trial state: 0. With backward-Euler friction (eq. 20–22)
///                  a slipping node is on the cone at t (f_t = 0 along its slip) and sticks as soon as its
///                  relative motion stops, which an increment sees at its start: no step avoids it, as no
///                  step avoids the closure of a touching node.
/// A node in contact at t takes the earliest of its opening and friction fractions. Nodes whose gap at t
/// is within `touchingGap` of zero close (or open) in any step: β^k = 0.
double eventFraction(const SlaveNodeIncrement& node, CountedEvents rule, double touchingGap);

/// The β^k of every node heading for a counted event (unsorted).
std::vector<double> eventFractions(const std::vector<SlaveNodeIncrement>& nodes, CountedEvents rule,
                                   double touchingGap);

}  // namespace contessa::continuation
