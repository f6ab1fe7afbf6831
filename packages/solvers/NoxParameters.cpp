#include "solvers/NoxParameters.hpp"

#include <NOX_Utils.H>

namespace contessa::solvers {

void setNoxParameters(Teuchos::ParameterList& nox, const Teuchos::ParameterList& deckNox,
                      const Teuchos::RCP<NOX::Observer>& observer, const Teuchos::RCP<std::ostream>& messages,
                      NoxPrinting printing) {
  nox.set("Nonlinear Solver", deckNox.get<std::string>("Nonlinear Solver"));
  nox.sublist("Direction").set("Method", deckNox.sublist("Direction").get<std::string>("Method"));
  nox.sublist("Line Search").set("Method", deckNox.sublist("Line Search").get<std::string>("Method"));
  const bool details = deckNox.sublist("Printing").get<bool>("Newton Details");
  int information = NOX::Utils::Error;
  if (details) information |= NOX::Utils::Warning | NOX::Utils::OuterIteration;
  if (details && printing == NoxPrinting::Continuation) information |= NOX::Utils::StepperIteration;
  nox.sublist("Printing").set("Output Information", information);
  // NOX/LOCA errors, and the exceptions NOX catches during a solve, are collected for Contessa's
  // one-line message, not spread on stderr and stdout.
  nox.sublist("Printing").set("Error Stream", messages);
  if (!details) nox.sublist("Printing").set("Output Stream", messages);
  nox.sublist("Solver Options").set("Observer", observer);
  // An exception in an evaluation fails the solve (and the increment is cut back), not the run.
  nox.set("Catch Throws During Solve", true);
}

}  // namespace contessa::solvers
