#include "solvers/NoxParameters.hpp"

#include <NOX_Observer_Vector.hpp>
#include <NOX_Utils.H>

#include "solvers/KrylovForcing.hpp"

namespace contessa::solvers {
namespace {

template <typename T>
T valueOr(const Teuchos::ParameterList& list, const std::string& name, T fallback) {
  return list.isType<T>(name) ? list.get<T>(name) : fallback;
}

// The forcing term's choice and the Newton target it serves: ResidualTest's max(bound, relative · ‖f₀‖)
// for the continuation, the bound alone for the single solve (StaticSolveDriver). The bound (the deck's
// absolute tolerance or c · F) is set by ResidualTest at each iterate, before the step's linear solve.
void setKrylovForcing(const Teuchos::ParameterList& deckNox, NoxPrinting printing) {
  auto& forcing = krylovForcing();
  const std::string term = valueOr<std::string>(deckNox.sublist("Direction"), "Forcing Term", "Newton Target");
  forcing.term = term == "Constant" ? ForcingTerm::Constant : ForcingTerm::NewtonTarget;
  const auto& tests = deckNox.sublist("Status Tests");
  forcing.absolute = valueOr(tests, "Absolute Residual Tolerance", 0.0);
  forcing.relative = printing == NoxPrinting::Continuation ? valueOr(tests, "Relative Residual Tolerance", 1e-10) : 0.0;
  forcing.inStep = forcing.firstStep = false;
}

}  // namespace

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
  setKrylovForcing(deckNox, printing);
  auto observers = Teuchos::rcp(new NOX::ObserverVector());
  observers->pushBack(krylovForcingObserver());
  if (!observer.is_null()) observers->pushBack(observer);
  nox.sublist("Solver Options").set("Observer", Teuchos::rcp_implicit_cast<NOX::Observer>(observers));
  // An exception in an evaluation fails the solve (and the increment is cut back), not the run.
  nox.set("Catch Throws During Solve", true);
}

}  // namespace contessa::solvers
