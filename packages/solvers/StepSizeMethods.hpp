#pragma once
// Step-size methods by name ("Piro/LOCA/Step Size/Method"): one registry row each (StepSizeMethods.cpp)
// with what it does, the parameters it reads from the Step Size list (docs, defaults, ranges) and, for
// the methods Contessa adds to LOCA, the function that builds its control (StepControl: its LOCA strategy
// and what it adds to the Newton solves, the reports and the stop message); LOCA builds its own methods
// ("Constant", "Adaptive") from the same list. The deck validates Method against the names (an unknown
// one is refused with the known ones listed), the deck reference is generated from the rows, and the
// continuation driver builds the control of the deck's method. Adding a method = its control (and
// strategy) class + one row.
// Light: Teuchos only (the LOCA types are declared, not included), for the deck's validation.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "continuation/ContactEvents.hpp"

namespace contessa::solvers {

class StepControl;
struct StepControlContext;

struct StepSizeMethod {
  std::string name;
  std::string doc;  ///< one phrase, for Method's doc
  /// Adds the parameters only this method reads to the Step Size list (nullptr: none).
  void (*addParameters)(Teuchos::ParameterList& stepSize);
  /// Builds the method's control (StepControl.hpp); empty for LOCA's own methods, which add nothing.
  std::function<std::unique_ptr<StepControl>(const StepControlContext&)> create;
};

/// The registry rows, in the order of the deck reference.
const std::vector<StepSizeMethod>& stepSizeMethodRegistry();

/// The row of a registered name (the deck has validated it; an unknown name is a logic error).
const StepSizeMethod& stepSizeMethod(const std::string& name);

/// The control of the method the Step Size list names (context.stepSize): the row's, or the plain
/// StepControl (no hooks) for LOCA's own methods.
std::unique_ptr<StepControl> createStepControl(const StepControlContext& context);

/// Registered names: "Constant", "Adaptive", "Contact Beta".
std::vector<std::string> stepSizeMethods();

/// The status changes the history's new_events column counts, for every method: Counted Events, declared
/// and read by Contact Beta's parameter table (which limits them to N_c per increment).
continuation::CountedEvents countedEvents(const Teuchos::ParameterList& stepSize);

/// The Step Size list: Method (one of the names), the parameters every method reads, then each method's
/// own, with docs and defaults.
void addStepSizeParameters(Teuchos::ParameterList& stepSize);

}  // namespace contessa::solvers
