#include "deck/LoadStepDefinitions.hpp"

#include <cmath>
#include <set>
#include <sstream>

#include <Teuchos_Array.hpp>

#include "common/Error.hpp"
#include "deck/ParameterValidation.hpp"
#include "deck/ProblemDefinition.hpp"
#include "deck/ValueText.hpp"

namespace contessa::deck {
namespace {

using Teuchos::ParameterList;

std::string listOf(const std::set<std::string>& names) {
  std::string text;
  for (const auto& n : names) text += (text.empty() ? "" : ", ") + n;
  return text.empty() ? "none" : text;
}

// A value as the deck gives it: a double (an int is taken as one) or an Array(double); a new name given
// on the command line (--set) arrives as text and is read as either.
struct DeckValue {
  std::vector<double> values;
  bool array = false;
};

DeckValue readValue(const ParameterList& list, const std::string& name, const std::string& where) {
  if (list.isType<double>(name)) return {{list.get<double>(name)}, false};
  if (list.isType<int>(name)) return {{static_cast<double>(list.get<int>(name))}, false};
  if (list.isType<Teuchos::Array<double>>(name)) {
    const auto& a = list.get<Teuchos::Array<double>>(name);
    return {{a.begin(), a.end()}, true};
  }
  if (list.isType<std::string>(name)) {
    const std::string& text = list.get<std::string>(name);
    const ParsedValue scalar = parseValue("double", text);
    if (scalar.problem == ValueProblem::None) return {{Teuchos::getValue<double>(scalar.entry)}, false};
    const ParsedValue array = parseValue("Array(double)", text, true);
    if (array.problem == ValueProblem::None) {
      const auto& a = Teuchos::getValue<Teuchos::Array<double>>(array.entry);
      return {{a.begin(), a.end()}, true};
    }
    throw InputError(where + ": expected a double or an Array(double), got '" + text + "'");
  }
  throw InputError(where + ": expected a double or an Array(double)");
}

void requireFinite(const std::vector<double>& values, const std::string& where) {
  for (double v : values) requireInput(std::isfinite(v), where + ": expected finite values");
}

// A number as the deck would write it: 0.5, -0.1, 1e-06.
std::string numberText(double x) {
  std::ostringstream text;
  text << x;
  return text.str();
}

// "a double" or "an Array(double) of 3 values".
std::string shapeText(std::size_t n, bool scalar) {
  return scalar ? "a double" : "an Array(double) of " + std::to_string(n) + (n == 1 ? " value" : " values");
}

void readDirichlet(const ParameterList& list, const ProblemDefinition& problem, const std::string& where,
                   LoadStepDefinition& step) {
  std::set<std::string> known;
  for (const auto& bc : problem.dirichlet) known.insert(bc.name);
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    const std::string at = where + "/" + name;
    requireInput(known.count(name) != 0, at + ": no Dirichlet condition of that name (known: " + listOf(known) + ")");
    const std::string expected = at + ": expected a double (the condition's Value at the end of the step)";
    requireInput(!list.isSublist(name), expected);
    const DeckValue v = readValue(list, name, at);
    requireInput(!v.array, expected + ", got " + shapeText(v.values.size(), false));
    requireFinite(v.values, at);
    step.dirichlet[name] = v.values[0];
  }
}

void readLoads(const ParameterList& list, const ProblemDefinition& problem, const std::string& where,
               LoadStepDefinition& step) {
  // Each load's shape: a Pressure's or a nodal force's one value, a traction's or a body force's vector.
  std::map<std::string, bool> scalar;
  std::set<std::string> known;
  for (const auto& load : problem.loads) {
    if (load.type == LoadType::Spring) continue;  // a support, not a load
    scalar[load.name] = load.type == LoadType::Pressure;
    known.insert(load.name);
  }
  for (const auto& force : problem.nodalForces) {
    scalar[force.name] = true;
    known.insert(force.name);
  }
  const auto n = static_cast<std::size_t>(problem.dimension());
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    const std::string at = where + "/" + name;
    requireInput(known.count(name) != 0,
                 at + ": no load or nodal force of that name (known: " + listOf(known) + "; springs are supports)");
    const bool isScalar = scalar.at(name);
    const std::string expected = at + ": expected " + shapeText(n, isScalar) + " (the load's end value)";
    requireInput(!list.isSublist(name), expected);
    const DeckValue v = readValue(list, name, at);
    requireInput(isScalar ? !v.array : v.array && v.values.size() == n,
                 expected + ", got " + shapeText(v.values.size(), !v.array));
    requireFinite(v.values, at);
    step.loads[name] = v.values;
  }
}

void readContact(const ParameterList& list, const ProblemDefinition& problem, const std::string& where,
                 LoadStepDefinition& step) {
  std::map<std::string, const contact::ContactInterfaceSpec*> interfaces;
  std::set<std::string> known;
  for (const auto& spec : problem.contacts) {
    if (spec.secondPass) continue;
    interfaces[spec.name] = &spec;
    known.insert(spec.name);
  }
  const auto n = static_cast<std::size_t>(problem.dimension());
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& name = list.name(it);
    const std::string at = where + "/" + name;
    requireInput(known.count(name) != 0, at + ": no contact interface of that name (known: " + listOf(known) + ")");
    requireInput(list.isSublist(name), at + ": expected a sublist (Motion, Friction Coefficient)");
    const auto& entry = list.sublist(name);
    const contact::ContactInterfaceSpec& spec = *interfaces.at(name);
    for (auto e = entry.begin(); e != entry.end(); ++e) {
      const std::string& p = entry.name(e);
      requireInput(p == "Motion" || p == "Friction Coefficient",
                   at + "/" + p + ": unknown parameter (expected Motion, Friction Coefficient)");
    }
    if (entry.isParameter("Motion")) {
      const std::string m = at + "/Motion";
      requireInput(spec.rigidMaster, m + ": interface '" + name + "' has a deformable master (Motion moves a rigid surface)");
      const DeckValue v = readValue(entry, "Motion", m);
      requireInput(v.array && v.values.size() == n,
                   m + ": expected " + shapeText(n, false) + ", got " + shapeText(v.values.size(), !v.array));
      requireFinite(v.values, m);
      step.motion[name] = v.values;
    }
    if (entry.isParameter("Friction Coefficient")) {
      const std::string f = at + "/Friction Coefficient";
      const DeckValue v = readValue(entry, "Friction Coefficient", f);
      requireInput(!v.array, f + ": expected a double, got " + shapeText(v.values.size(), false));
      const double mu = v.values[0];
      requireInput(std::isfinite(mu) && mu >= 0.0, f + ": expected a value >= 0, got " + numberText(mu));
      // The interface's law must take μ > 0 (a tangential penalty or a slip tolerance).
      contact::ContactLawParameters law = spec.law;
      law.frictionCoefficient = mu;
      try {
        law.validate();
      } catch (const InputError& e) {
        throw InputError(f + ": " + e.what());
      }
      step.friction[name] = mu;
    }
  }
}

void readAmplitude(const ParameterList& list, const std::string& where, LoadStepDefinition& step) {
  for (auto it = list.begin(); it != list.end(); ++it)
    requireInput(list.name(it) == "Times" || list.name(it) == "Values",
                 where + "/" + list.name(it) + ": unknown parameter (expected Times, Values)");
  std::vector<double> tv[2];
  for (int k = 0; k < 2; ++k) {
    const std::string name = k == 0 ? "Times" : "Values";
    requireInput(list.isParameter(name), where + "/" + name + ": required (an Array(double))");
    const DeckValue value = readValue(list, name, where + "/" + name);
    requireInput(value.array, where + "/" + name + ": expected an Array(double), got a double");
    tv[k] = value.values;
  }
  const std::vector<double>& t = tv[0];
  const std::vector<double>& v = tv[1];
  requireInput(t.size() == v.size(), where + ": Times has " + std::to_string(t.size()) + " values, Values " +
                                         std::to_string(v.size()) + " (one value per time)");
  requireInput(t.size() >= 2, where + "/Times: expected at least 2 times, from 0 to 1");
  requireInput(t.front() == 0.0 && t.back() == 1.0,
               where + "/Times: expected normalised step times from 0 to 1 (the first 0, the last 1)");
  for (std::size_t i = 1; i < t.size(); ++i)
    requireInput(t[i] > t[i - 1], where + "/Times: expected strictly increasing times, got " + numberText(t[i]) +
                                      " after " + numberText(t[i - 1]));
  for (double x : v) requireInput(std::isfinite(x), where + "/Values: expected finite values");
  step.amplitudeTimes.assign(t.begin(), t.end());
  step.amplitudeValues.assign(v.begin(), v.end());
}

LoadStepDefinition readStep(ParameterList& list, const std::string& name, const ProblemDefinition& problem) {
  const std::string where = "Problem/Load Steps/" + name;
  validateAndSetDefaults(list, *loadStepValidParameters(), where,
                         {"Dirichlet Conditions", "Loads", "Contact", "Amplitude", "Step Size"});
  LoadStepDefinition step;
  step.name = name;
  step.timePeriod = list.get<double>("Time Period");
  readDirichlet(list.sublist("Dirichlet Conditions"), problem, where + "/Dirichlet Conditions", step);
  readLoads(list.sublist("Loads"), problem, where + "/Loads", step);
  readContact(list.sublist("Contact"), problem, where + "/Contact", step);
  if (list.isSublist("Amplitude") && list.sublist("Amplitude").numParams() > 0)
    readAmplitude(list.sublist("Amplitude"), where + "/Amplitude", step);
  if (list.isSublist("Step Size") && list.sublist("Step Size").numParams() > 0) {
    step.hasStepSize = true;
    step.stepSize = list.sublist("Step Size");
  }
  return step;
}

}  // namespace

std::string dirichletKey(const std::string& condition) { return "Dirichlet Conditions/" + condition; }
std::string loadKey(const std::string& load) { return "Loads/" + load; }
std::string motionKey(const std::string& interface) { return "Contact/" + interface + "/Motion"; }
std::string frictionKey(const std::string& interface) { return "Contact/" + interface + "/Friction Coefficient"; }

continuation::LoadSchedule loadScheduleOf(const deck::ProblemDefinition& problem) {
  continuation::LoadSchedule schedule;
  for (const auto& bc : problem.dirichlet) schedule.addQuantity(dirichletKey(bc.name), {bc.value});
  for (const auto& force : problem.nodalForces) schedule.addQuantity(loadKey(force.name), {force.totalForce});
  for (const auto& load : problem.loads) {
    if (load.type == LoadType::Spring) continue;  // a support: not scaled
    schedule.addQuantity(loadKey(load.name),
                         load.type == LoadType::Pressure ? std::vector<double>{load.pressure} : load.vector);
  }
  for (const auto& spec : problem.contacts) {
    if (spec.secondPass) continue;  // the same interface's name and law
    if (spec.rigidMaster) schedule.addQuantity(motionKey(spec.name), spec.rigidSurface.motion);
    // Friction acts from the first increment (issue 19 §4): its coefficient is not ramped from zero.
    schedule.addQuantity(frictionKey(spec.name), {spec.law.frictionCoefficient}, false);
  }
  for (const auto& step : problem.loadSteps) {
    continuation::ScheduledStep s;
    s.name = step.name;
    s.timePeriod = step.timePeriod;
    if (!step.amplitudeTimes.empty()) s.amplitude = continuation::Amplitude(step.amplitudeTimes, step.amplitudeValues);
    for (const auto& [name, value] : step.dirichlet) s.endValues[dirichletKey(name)] = {value};
    for (const auto& [name, value] : step.loads) s.endValues[loadKey(name)] = value;
    for (const auto& [name, value] : step.motion) s.endValues[motionKey(name)] = value;
    for (const auto& [name, value] : step.friction) s.endValues[frictionKey(name)] = {value};
    schedule.addStep(std::move(s));
  }
  return schedule;
}

void requireLoadStepsChange(const ProblemDefinition& problem) {
  if (problem.loadSteps.empty()) return;
  // A step names a load by its name: a load on sets and a nodal force may not share one.
  for (const auto& force : problem.nodalForces)
    for (const auto& load : problem.loads)
      requireInput(force.name != load.name, "Problem/Load Steps: '" + force.name +
                                                "' names both a nodal force and a load (Problem/Loads); rename one");
  const auto schedule = loadScheduleOf(problem);
  for (int s = 0; s < schedule.numSteps(); ++s)
    requireInput(schedule.changesAnything(s),
                 "Problem/Load Steps/" + schedule.stepName(s) +
                     ": the step changes nothing (name an end value that differs from the previous step's in its "
                     "Dirichlet Conditions, Loads or Contact)");
}

Teuchos::RCP<const Teuchos::ParameterList> loadStepValidParameters() {
  auto p = Teuchos::rcp(new ParameterList("Load Step"));
  setPositive(*p, "Time Period", 1.0, "Time the step takes; the history's time runs on continuously across steps");
  p->sublist("Dirichlet Conditions", false, "End Value (double) of a named Dirichlet condition");
  p->sublist("Loads", false,
             "End value of a named load: a double for a Pressure or a Nodal Force (its Total Force), an "
             "Array(double) of the dimension for a Traction or a Body Force");
  p->sublist("Contact", false, "Per interface name: the rigid surface's end Motion, the end Friction Coefficient");
  p->sublist("Amplitude", false,
             "Times (normalised step time, strictly increasing from 0 to 1) and Values (the fraction of the step's "
             "change reached); without it a linear ramp");
  p->sublist("Step Size", false, "Replaces Piro/LOCA/Step Size for this step (the same parameters)");
  return p;
}

std::vector<LoadStepDefinition> buildLoadSteps(ParameterList& steps, const ProblemDefinition& problem) {
  std::vector<LoadStepDefinition> out;
  std::vector<std::string> names;
  for (auto it = steps.begin(); it != steps.end(); ++it) {
    const std::string& name = steps.name(it);
    requireInput(steps.isSublist(name), "Problem/Load Steps/" + name + ": expected a sublist (one per load step)");
    names.push_back(name);
  }
  for (const auto& name : names) out.push_back(readStep(steps.sublist(name), name, problem));
  return out;
}

}  // namespace contessa::deck
