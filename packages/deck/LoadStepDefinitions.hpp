#pragma once
// The deck's load steps (issue 19 §2; docs/user-guide.md, "Load Steps"), Problem/Load Steps/<step>, in
// the order written. Each step names the end values of what changes in it:
//   Dirichlet Conditions/<condition>    double: the condition's Value at the step's end
//   Loads/<load or nodal force>         double for a Pressure or a Nodal Force (its Total Force),
//                                       Array(double) of the dimension for a Traction or a Body Force
//   Contact/<interface>/Motion          Array(double): the rigid surface's displacement at the step's end
//   Contact/<interface>/Friction Coefficient
// and optionally its Time Period, an Amplitude table and its own Step Size list (which replaces
// Piro/LOCA/Step Size for the step; validated by the solvers, apps/contessa). Read and checked against
// the problem's conditions, loads and interfaces; the schedule itself is continuation::LoadSchedule.
#include <map>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "continuation/LoadSchedule.hpp"

namespace contessa::deck {

struct ProblemDefinition;

struct LoadStepDefinition {
  std::string name;
  double timePeriod = 1.0;
  std::map<std::string, double> dirichlet;               ///< end Value by condition name
  std::map<std::string, std::vector<double>> loads;      ///< end value by load (or nodal force) name
  std::map<std::string, std::vector<double>> motion;     ///< end Motion by rigid interface name
  std::map<std::string, double> friction;                ///< end Friction Coefficient by interface name
  std::vector<double> amplitudeTimes, amplitudeValues;   ///< empty: linear ramp
  bool hasStepSize = false;
  Teuchos::ParameterList stepSize;  ///< the step's own Step Size list (unvalidated), when hasStepSize
};

/// Valid parameters of one step (for the deck reference; its open sublists are described there).
Teuchos::RCP<const Teuchos::ParameterList> loadStepValidParameters();

/// Reads Problem/Load Steps against the problem's Dirichlet conditions, loads, nodal forces and contact
/// interfaces (already read into `problem`); InputError naming the step and the parameter otherwise
/// (an unknown name, a value of the wrong shape, a step that changes nothing, a bad amplitude table,
/// Motion of a deformable interface, a negative friction coefficient). No communication.
std::vector<LoadStepDefinition> buildLoadSteps(Teuchos::ParameterList& steps, const ProblemDefinition& problem);

/// Every load step of `problem` changes something (InputError naming the step otherwise).
void requireLoadStepsChange(const ProblemDefinition& problem);

// The schedule's keys: deck paths of the scheduled quantities.
std::string dirichletKey(const std::string& condition);
std::string loadKey(const std::string& load);  ///< a load on sets or a nodal force
std::string motionKey(const std::string& interface);
std::string frictionKey(const std::string& interface);

/// Every Dirichlet value, load magnitude (pressure, traction, body force, nodal force), rigid surface
/// motion and friction coefficient of `problem` (the friction coefficient held from the start, the rest
/// ramped from zero), with its Load Steps.
continuation::LoadSchedule loadScheduleOf(const ProblemDefinition& problem);

}  // namespace contessa::deck
