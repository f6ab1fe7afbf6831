#include "continuation/LoadSchedule.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace contessa::continuation {

Amplitude::Amplitude(std::vector<double> times, std::vector<double> values)
    : times_(std::move(times)), values_(std::move(values)) {
  if (times_.size() != values_.size() || times_.size() < 2)
    throw std::invalid_argument("Amplitude: Times and Values need the same length, at least 2");
  if (times_.front() != 0.0 || times_.back() != 1.0)
    throw std::invalid_argument("Amplitude: Times must run from 0 to 1");
  for (std::size_t i = 1; i < times_.size(); ++i)
    if (!(times_[i] > times_[i - 1])) throw std::invalid_argument("Amplitude: Times must increase strictly");
}

std::size_t Amplitude::segment(double t) const {
  // The segment [t_i, t_{i+1}) holding t; t ≥ 1 (and beyond, a step's last Newton iterate may overshoot
  // by round-off) in the last one, t < 0 in the first.
  const auto upper = std::upper_bound(times_.begin(), times_.end(), t);
  const auto i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(upper - times_.begin(), 1)) - 1;
  return std::min(i, times_.size() - 2);
}

double Amplitude::value(double t) const {
  if (isRamp()) return t;  // exactly λ: a run without a table is the single proportional load factor
  const std::size_t i = segment(t);
  const double w = (t - times_[i]) / (times_[i + 1] - times_[i]);
  return values_[i] + w * (values_[i + 1] - values_[i]);
}

double Amplitude::slope(double t) const {
  if (isRamp()) return 1.0;
  const std::size_t i = segment(t);
  return (values_[i + 1] - values_[i]) / (times_[i + 1] - times_[i]);
}

void LoadSchedule::addQuantity(const std::string& key, std::vector<double> deckValue, bool rampedFromZero) {
  Quantity& q = quantities_[key];
  q.deckValue = std::move(deckValue);
  q.rampedFromZero = rampedFromZero;
  rebuild();
}

void LoadSchedule::addStep(ScheduledStep step) {
  for (const auto& [key, value] : step.endValues) {
    const auto it = quantities_.find(key);
    if (it == quantities_.end()) throw std::invalid_argument("LoadSchedule: step '" + step.name + "' names unknown '" + key + "'");
    if (value.size() != it->second.deckValue.size())
      throw std::invalid_argument("LoadSchedule: step '" + step.name + "': '" + key + "' has " +
                                  std::to_string(value.size()) + " values, expected " +
                                  std::to_string(it->second.deckValue.size()));
  }
  steps_.push_back(std::move(step));
  rebuild();
}

void LoadSchedule::rebuild() {
  const int n = numSteps();
  for (auto& [key, q] : quantities_) {
    q.starts.assign(static_cast<std::size_t>(n), {});
    q.ends.assign(static_cast<std::size_t>(n), {});
    for (int s = 0; s < n; ++s) {
      const auto i = static_cast<std::size_t>(s);
      q.starts[i] = s > 0 ? q.ends[i - 1]
                          : q.rampedFromZero ? std::vector<double>(q.deckValue.size(), 0.0) : q.deckValue;
      const auto& named = step(s).endValues;
      const auto it = named.find(key);
      q.ends[i] = it != named.end() ? it->second : s > 0 ? q.ends[i - 1] : q.deckValue;
    }
  }
}

const ScheduledStep& LoadSchedule::step(int s) const {
  if (steps_.empty()) {
    if (s != 0) throw std::out_of_range("LoadSchedule: step " + std::to_string(s) + " of a run without steps");
    return single_;
  }
  return steps_.at(static_cast<std::size_t>(s));
}

const LoadSchedule::Quantity& LoadSchedule::quantity(const std::string& key) const {
  const auto it = quantities_.find(key);
  if (it == quantities_.end()) throw std::out_of_range("LoadSchedule: unknown quantity '" + key + "'");
  return it->second;
}

const std::string& LoadSchedule::stepName(int s) const { return step(s).name; }
double LoadSchedule::timePeriod(int s) const { return step(s).timePeriod; }

double LoadSchedule::startTime(int s) const {
  double t = 0.0;
  for (int k = 0; k < s; ++k) t += timePeriod(k);
  return t;
}

double LoadSchedule::amplitude(int s, double lambda) const { return step(s).amplitude.value(lambda); }
double LoadSchedule::amplitudeSlope(int s, double lambda) const { return step(s).amplitude.slope(lambda); }

const std::vector<double>& LoadSchedule::start(int s, const std::string& key) const {
  step(s);  // the step's range check
  return quantity(key).starts[static_cast<std::size_t>(s)];
}

const std::vector<double>& LoadSchedule::end(int s, const std::string& key) const {
  step(s);
  return quantity(key).ends[static_cast<std::size_t>(s)];
}

std::vector<double> LoadSchedule::change(int s, const std::string& key) const {
  const auto& a = start(s, key);
  std::vector<double> d = end(s, key);
  for (std::size_t i = 0; i < d.size(); ++i) d[i] -= a[i];
  return d;
}

bool LoadSchedule::changes(int s, const std::string& key) const { return start(s, key) != end(s, key); }

bool LoadSchedule::changesAnything(int s) const {
  for (const auto& [key, q] : quantities_)
    if (changes(s, key)) return true;
  return false;
}

std::vector<double> LoadSchedule::value(int s, const std::string& key, double lambda) const {
  const double a = amplitude(s, lambda);
  std::vector<double> v = start(s, key);
  const auto d = change(s, key);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] += a * d[i];
  return v;
}

std::vector<double> LoadSchedule::derivative(int s, const std::string& key, double lambda) const {
  std::vector<double> d = change(s, key);
  const double slope = amplitudeSlope(s, lambda);
  for (double& v : d) v *= slope;
  return d;
}

}  // namespace contessa::continuation
