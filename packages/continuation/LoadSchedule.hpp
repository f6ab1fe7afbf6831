#pragma once
// The load steps of a run (issue 19 §2; docs/user-guide.md, "Load Steps"): which value every scheduled
// quantity (a Dirichlet value, a load's magnitude, a rigid surface's motion, a friction coefficient) has
// at each step's own load factor λ_s ∈ [0, 1], and its ∂/∂λ_s. Each quantity is keyed by its deck path
// (e.g. "Dirichlet Conditions/shear", "Contact/die/Motion"). In step s
//     v(λ_s) = v_{s−1} + A_s(λ_s) (v_s − v_{s−1}),     ∂v/∂λ_s = A_s'(λ_s) (v_s − v_{s−1}),
// with v_{s−1} the previous step's end value (step 0 starts at zero, or at the deck value for a quantity
// that is not ramped, the friction coefficient), v_s the step's end value (held when the step does not
// name the quantity) and A_s the step's amplitude (the identity unless tabulated). A run without steps is
// one step ending at the deck values: v = λ v_deck, exactly as a single proportional load factor.
// Pure C++: the model asks it for (start, change) at a step change and for A, A' at every evaluation.
#include <map>
#include <string>
#include <vector>

namespace contessa::continuation {

/// A_s: the fraction of a step's change reached at normalised step time t ∈ [0, 1]. Linear ramp A(t) = t
/// by default; a table (strictly increasing times from 0 to 1) is interpolated piecewise linearly.
class Amplitude {
 public:
  Amplitude() = default;
  /// std::invalid_argument when the table is not valid (tests; the deck checks it with its own words).
  Amplitude(std::vector<double> times, std::vector<double> values);
  double value(double t) const;
  /// dA/dt; at a breakpoint the slope of the segment that starts there (the direction of continuation),
  /// at t = 1 that of the last segment.
  double slope(double t) const;
  bool isRamp() const { return times_.empty(); }

 private:
  std::size_t segment(double t) const;
  std::vector<double> times_, values_;
};

/// One step as the schedule takes it: the end values it names (any subset of the quantities).
struct ScheduledStep {
  std::string name;
  double timePeriod = 1.0;
  Amplitude amplitude;
  std::map<std::string, std::vector<double>> endValues;
};

class LoadSchedule {
 public:
  /// A quantity with its deck value; `rampedFromZero`: the first step starts from zero (false: it holds
  /// the deck value from the start until a step names it).
  void addQuantity(const std::string& key, std::vector<double> deckValue, bool rampedFromZero = true);
  /// Steps in order. Before the first: the deck values are the first step's end values; a step's
  /// endValues must name known quantities of the same size (std::invalid_argument otherwise).
  void addStep(ScheduledStep step);

  /// At least 1: a run without steps has one (unnamed, period 1, linear ramp).
  int numSteps() const { return steps_.empty() ? 1 : static_cast<int>(steps_.size()); }
  const std::string& stepName(int step) const;
  double timePeriod(int step) const;
  /// Time at the start of `step` (the sum of the earlier periods); time(s, λ) = start + λ·period.
  double startTime(int step) const;
  double time(int step, double lambda) const { return startTime(step) + lambda * timePeriod(step); }

  double amplitude(int step, double lambda) const;
  double amplitudeSlope(int step, double lambda) const;
  /// The quantity's value at the start and the end of `step`.
  const std::vector<double>& start(int step, const std::string& key) const;
  const std::vector<double>& end(int step, const std::string& key) const;
  /// end − start (0 for what the step holds).
  std::vector<double> change(int step, const std::string& key) const;
  bool changes(int step, const std::string& key) const;
  std::vector<double> value(int step, const std::string& key, double lambda) const;
  std::vector<double> derivative(int step, const std::string& key, double lambda) const;
  bool has(const std::string& key) const { return quantities_.count(key) != 0; }
  /// Whether `step` changes any quantity.
  bool changesAnything(int step) const;

 private:
  struct Quantity {
    std::vector<double> deckValue;
    bool rampedFromZero = true;
    std::vector<std::vector<double>> starts, ends;  ///< per step
  };
  const ScheduledStep& step(int s) const;
  /// Every quantity's start and end values of every step, from the deck values and the steps.
  void rebuild();
  const Quantity& quantity(const std::string& key) const;

  std::map<std::string, Quantity> quantities_;
  std::vector<ScheduledStep> steps_;
  ScheduledStep single_;  ///< the one step of a run without steps
};

}  // namespace contessa::continuation
