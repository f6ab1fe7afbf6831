#pragma once
// Step-size methods by name ("Piro/LOCA/Step Size/Method"): one registry row each (StepSizeMethods.cpp)
// with what it does, the parameters it reads from the Step Size list (docs, defaults, ranges) and, for
// the methods Contessa adds to LOCA, the function that builds its strategy; LOCA builds its own methods
// ("Constant", "Adaptive") from the same list. The deck validates Method against the names (an unknown
// one is refused with the known ones listed), the deck reference is generated from the rows, and
// StepSizeFactory builds by name. Adding a method = its strategy class + one row.
// Light: Teuchos only (the LOCA types are declared, not included), for the deck's validation.
#include <functional>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

namespace LOCA::StepSize {
class AbstractStrategy;
}
namespace contessa::continuation {
class ContactEventSource;
class ContactBetaControl;
}  // namespace contessa::continuation

namespace contessa::solvers {

/// What a step-size strategy of the run may use: the slave nodes and the Contact Beta control.
struct StepSizeContext {
  continuation::ContactEventSource& events;
  continuation::ContactBetaControl& contactBeta;
};

struct StepSizeMethod {
  std::string name;
  std::string doc;  ///< one phrase, for Method's doc
  /// Adds the parameters only this method reads to the Step Size list (nullptr: none).
  void (*addParameters)(Teuchos::ParameterList& stepSize);
  /// Builds the strategy; empty for LOCA's own methods (LOCA builds them).
  std::function<Teuchos::RCP<LOCA::StepSize::AbstractStrategy>(const StepSizeContext&)> create;
  /// The strategy regulates contact events through the ContactBetaControl: the Newton solve then takes
  /// its restart test (Restart mode), its veto at convergence and the per-increment bookkeeping.
  bool regulatesContactEvents = false;
};

/// The registry rows, in the order of the deck reference.
const std::vector<StepSizeMethod>& stepSizeMethodRegistry();

/// The row of a registered name (the deck has validated it; an unknown name is a logic error).
const StepSizeMethod& stepSizeMethod(const std::string& name);

/// Registered names: "Constant", "Adaptive", "Contact Beta".
std::vector<std::string> stepSizeMethods();

/// The Step Size list: Method (one of the names), the parameters every method reads, then each method's
/// own, with docs and defaults.
void addStepSizeParameters(Teuchos::ParameterList& stepSize);

}  // namespace contessa::solvers
