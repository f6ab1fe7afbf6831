#include "solvers/SolverParameters.hpp"

#include <cmath>
#include <cstdio>
#include <type_traits>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "common/Error.hpp"
#include "continuation/ContactBetaControl.hpp"
#include "deck/DeckReader.hpp"
#include "deck/ParameterValidation.hpp"

namespace contessa::solvers {

using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;

namespace {

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

// A number given in the deck or by --set (then a string): returns it, or throws InputError naming `where`.
template <typename T>
T requireNumber(Teuchos::ParameterList& list, const std::string& name, const std::string& where) {
  if (list.isType<T>(name)) return list.get<T>(name);
  if (list.isType<std::string>(name)) {
    const std::string text = list.get<std::string>(name);
    try {
      std::size_t used = 0;
      const T value = std::is_integral_v<T> ? static_cast<T>(std::stoll(text, &used)) : static_cast<T>(std::stod(text, &used));
      if (used == text.size()) {
        list.set(name, value);  // Belos reads the typed value
        return value;
      }
    } catch (const std::exception&) {
    }
  }
  throw InputError(where + ": expected " + (std::is_integral_v<T> ? "an integer" : "a number"));
}

// Belos reads its tolerance and iteration limit only at the first solve and takes a negative tolerance
// or a zero limit without complaint (it then fails every solve): checked here, for every solver sublist
// the deck gives.
void validateBelosTolerances(ParameterList& strat) {
  if (!strat.isSublist("Linear Solver Types") || !strat.sublist("Linear Solver Types").isSublist("Belos")) return;
  auto& belos = strat.sublist("Linear Solver Types").sublist("Belos");
  if (!belos.isSublist("Solver Types")) return;
  auto& types = belos.sublist("Solver Types");
  for (auto it = types.begin(); it != types.end(); ++it) {
    if (!types.entry(it).isList()) continue;
    auto& solver = types.sublist(types.name(it));
    const std::string where = "Piro/Stratimikos/Linear Solver Types/Belos/Solver Types/" + types.name(it) + "/";
    if (solver.isParameter("Convergence Tolerance")) {
      const double tol = requireNumber<double>(solver, "Convergence Tolerance", where + "Convergence Tolerance");
      char text[32];
      std::snprintf(text, sizeof text, "%g", tol);
      requireInput(std::isfinite(tol) && tol > 0 && tol < 1,
                   where + "Convergence Tolerance: expected a relative residual reduction in (0, 1), got " + text);
    }
    if (solver.isParameter("Maximum Iterations"))
      requireInput(requireNumber<int>(solver, "Maximum Iterations", where + "Maximum Iterations") > 0,
                   where + "Maximum Iterations: expected a positive integer");
    if (solver.isParameter("Num Blocks"))
      requireInput(requireNumber<int>(solver, "Num Blocks", where + "Num Blocks") > 0,
                   where + "Num Blocks: expected a positive integer (the GMRES restart length)");
  }
}

}  // namespace

std::vector<std::string> stepSizeMethods() { return {"Constant", "Adaptive", "Contact Beta"}; }

std::vector<std::string> linearSolverTypes() { return {"MUMPS", "Amesos2", "Belos"}; }

std::vector<std::string> preconditionerTypes() { return {"None", "Ifpack2", "MueLu"}; }

RCP<const ParameterList> piroValidParameters() {
  auto piro = rcp(new ParameterList("Piro"));
  deck::setChoice(*piro, "Solver Type", "LOCA", {"LOCA", "NOX"},
                  "LOCA: natural continuation in the load factor (the Piro/LOCA list); NOX: one Newton solve at load "
                  "factor 1 through Piro::NOXSolver");
  auto& nox = piro->sublist("NOX", false, "Newton solver (NOX parameter names)");
  deck::setChoice(nox, "Nonlinear Solver", "Line Search Based", {"Line Search Based"}, "NOX solver");
  auto& direction = nox.sublist("Direction", false, "Search direction");
  deck::setChoice(direction, "Method", "Newton", {"Newton"}, "Full Newton with the consistent tangent");
  auto& lineSearch = nox.sublist("Line Search", false, "Globalisation");
  deck::setChoice(lineSearch, "Method", "Full Step", {"Full Step", "Backtrack", "Polynomial"}, "NOX line search");
  auto& tests = nox.sublist("Status Tests", false, "Newton convergence: converged when any of the three tests holds");
  deck::setPositiveInt(tests, "Maximum Iterations", 25, "Newton iterations before the increment counts as failed");
  deck::setNonNegative(tests, "Relative Residual Tolerance", 1e-10,
                       "Converged when ||f|| <= tol * ||f|| at the increment's first iterate");
  deck::setNonNegative(tests, "Absolute Residual Tolerance", 1e-8, "Converged when ||f|| <= tol (2-norm)");
  deck::setNonNegative(tests, "Update Tolerance", 1e-10,
                       "Converged when the Newton update ||dx|| <= tol * ||x|| (round-off floor of penalty contact)");
  auto& printing = nox.sublist("Printing", false, "Solver output");
  printing.set("Newton Details", false, "Print NOX's own per-iteration output besides the increment table");

  auto& loca = piro->sublist("LOCA", false, "Continuation in the load factor (LOCA parameter names)");
  auto& stepper = loca.sublist("Stepper", false, "Natural continuation in the load factor λ");
  stepper.set("Initial Value", 0.0, "λ at the start");
  stepper.set("Max Value", 1.0, "λ at the end: the run succeeds when it gets there");
  stepper.set("Min Value", 0.0, "Lower bound of λ");
  deck::setPositiveInt(stepper, "Max Steps", 1000, "Maximum continuation steps (converged and failed)");
  deck::setPositiveInt(stepper, "Max Nonlinear Iterations", 25, "Newton iterations the step-size strategies aim at");
  auto& predictor = loca.sublist("Predictor", false, "Initial guess of each increment");
  deck::setChoice(predictor, "Method", "Tangent", {"Constant", "Secant", "Tangent"},
                  "Constant: previous solution; Tangent: dx/dλ from the Jacobian");
  auto& step = loca.sublist("Step Size", false, "Increment control");
  deck::setChoice(step, "Method", "Constant", stepSizeMethods(),
                  "Constant: fixed Δλ, cut back on failure; Adaptive: LOCA's iteration-count control; "
                  "Contact Beta: N_c contacts per increment (eq. 10-13)");
  deck::setPositive(step, "Initial Step Size", 0.1, "Δλ of the first increment");
  deck::setPositive(step, "Min Step Size", 1e-6, "Smallest Δλ before the run gives up");
  deck::setPositive(step, "Max Step Size", 1.0, "Largest Δλ");
  deck::setBounded(step, "Failed Step Reduction Factor", 0.5, 1e-3, 0.999, "Δλ multiplier after a failed increment");
  deck::setBounded(step, "Successful Step Increase Factor", 1.26, 1.0, 100.0,
                   "Δλ multiplier after a successful increment (Constant recovers towards the initial step)");
  deck::setBounded(step, "Aggressiveness", 0.5, 0.0, 1.0, "Adaptive only: how fast Δλ grows after easy increments");
  deck::setPositiveInt(step, "Contacts Per Step", 2,
                       "Contact Beta: N_c, the number of slave nodes allowed to come into contact per increment (eq. 13)");
  deck::setChoice(step, "Mode", "Restart", {"Restart", "Predictor"},
                  "Contact Beta: Restart = the paper's Table 1 (β at the first Newton iteration, one restart); "
                  "Predictor = β from the predicted state before the solve (no restart)");
  deck::setBounded(step, "Max Growth Factor", 2.0, 1.0, 1e3, "Contact Beta: largest β (growth of Δλ per increment)");
  deck::setBounded(step, "Max Shrink Factor", 0.05, 1e-6, 1.0, "Contact Beta: smallest β (shrink of Δλ per increment)");
  deck::setBounded(step, "Restart Tolerance", 0.1, 0.0, 1.0, "Contact Beta, Restart: no restart when |β − 1| is below this. Applies with Next Contact Fraction = 0 (the paper), "
                  "when fewer candidates than Contacts Per Step approach, or when a step bound sets β; otherwise the step "
                  "stands when it ends between the predicted N_c-th and next event (docs/theory-load-stepping.md §11)");
  deck::setBounded(step, "Next Contact Fraction", 0.9, 0.0, 0.999,
                   "Contact Beta: β between β^{N_c} (0 = eq. 13 as printed) and β^{N_c+1} (closing N_c nodes, not N_c + 1)");
  deck::setChoice(step, "Counted Events", "Closures", continuation::countedEventsNames(),
                  "Contact Beta: the status changes limited to N_c per increment (history column new_events): "
                  "Closures (the paper) or All Status Changes (closures, openings, stick/slip changes, slip reversals)");
  step.set("Learn Event Rate", true,
           "Contact Beta: correct the β^k of eq. (11) by the ratio of actual to predicted event fractions learned "
           "from the last increments (not with Next Contact Fraction = 0: eq. 13 as printed)");
  deck::setChoice(step, "Growth Without Events", "Max Growth Factor", continuation::quietGrowthNames(),
                  "Contact Beta: how the step grows while at most N_c events lie ahead: to Max Growth Factor, or by "
                  "the Newton iterations of the last increment (towards Target Newton Iterations)");
  step.set("Max Corrections Per Increment", 3,
           "Contact Beta (f > 0): beyond the paper's one restart, how often per increment a restarted step with β "
           "far from 1 is checked again at its first iterate, and how often a converged increment with other than "
           "N_c counted events is solved again with a corrected step; 0 = Table 1 as printed ([0, 10])",
           Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>(0, 10)));
  deck::setPositiveInt(step, "Target Newton Iterations", 6,
                       "Contact Beta with Growth Without Events = Newton Iterations: the iterations an increment aims at");

  piro->sublist("Stratimikos", false, "Linear solver (Stratimikos parameter names; 'MUMPS' added by Contessa; see below)");
  return piro;
}

void validatePiro(ParameterList& piro, int numRanks) {
  deck::validateAndSetDefaults(piro, *piroValidParameters(), "Piro", {"Stratimikos"});
  const auto& step = piro.sublist("LOCA").sublist("Step Size");
  requireInput(step.get<double>("Min Step Size") <= step.get<double>("Initial Step Size") &&
                   step.get<double>("Initial Step Size") <= step.get<double>("Max Step Size"),
               "Piro/LOCA/Step Size: expected Min Step Size <= Initial Step Size <= Max Step Size");
  const auto& stepper = piro.sublist("LOCA").sublist("Stepper");
  requireInput(stepper.get<double>("Max Value") > stepper.get<double>("Initial Value"),
               "Piro/LOCA/Stepper/Max Value: expected a value greater than Initial Value");

  // Stratimikos checks its own names, but it also offers its Epetra solvers (Amesos, AztecOO; the
  // preconditioners ML and Ifpack), which cannot take Contessa's Tpetra matrices and fail only at the
  // first solve: the two choices are checked here. Stratimikos' default preconditioner is Ifpack, so
  // Contessa's default is None. Two solvers of this Trilinos build are refused as well.
  auto& strat = piro.sublist("Stratimikos");
  if (!strat.isParameter("Linear Solver Type")) strat.set("Linear Solver Type", std::string("MUMPS"));
  if (!strat.isParameter("Preconditioner Type")) strat.set("Preconditioner Type", std::string("None"));
  for (const auto& [name, allowed] : {std::make_pair("Linear Solver Type", linearSolverTypes()),
                                      std::make_pair("Preconditioner Type", preconditionerTypes())}) {
    const std::string where = std::string("Piro/Stratimikos/") + name;
    requireInput(strat.isType<std::string>(name), where + ": expected a string, one of " + joinNames(allowed));
    deck::requireOneOf(where, strat.get<std::string>(name), allowed);
  }
  const std::string type = strat.get<std::string>("Linear Solver Type");
  if (type == "Belos") validateBelosTolerances(strat);
  if (type == "Amesos2") {
    std::string solver = "KLU2";
    if (strat.isSublist("Linear Solver Types") && strat.sublist("Linear Solver Types").isSublist("Amesos2"))
      solver = strat.sublist("Linear Solver Types").sublist("Amesos2").get<std::string>("Solver Type", "KLU2");
    requireInput(solver != "Tacho" && solver != "tacho",
                 "Piro/Stratimikos/Linear Solver Types/Amesos2/Solver Type: Tacho crashes in this Trilinos build; use MUMPS");
    deck::requireOneOf("Piro/Stratimikos/Linear Solver Types/Amesos2/Solver Type", solver, {"KLU2"});
    requireInput(numRanks == 1,
                 "Piro/Stratimikos/Linear Solver Type: Amesos2 (" + solver + ") gives wrong solutions on more than one MPI "
                 "rank in this Trilinos build; use MUMPS or Belos");
  }
}

}  // namespace contessa::solvers
