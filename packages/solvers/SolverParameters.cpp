#include "solvers/SolverParameters.hpp"

#include <cmath>
#include <cstdio>
#include <type_traits>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "common/Error.hpp"
#include "deck/DeckReader.hpp"
#include "deck/ParameterValidation.hpp"
#include "deck/ProblemDefinition.hpp"
#include "solvers/ResidualTolerance.hpp"
#include "solvers/StepSizeMethods.hpp"

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

std::vector<std::string> linearSolverTypes() { return {"Automatic", "MUMPS", "Amesos2", "Belos"}; }

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
  deck::setChoice(direction, "Forcing Term", "Newton Target", {"Newton Target", "Constant"},
                  "Krylov tolerance of each Newton step (iterative solvers): Newton Target tightens a step whose "
                  "linear residual at the Belos Convergence Tolerance could exceed a tenth of the Newton target "
                  "(at most 100 times tighter); Constant: the Convergence Tolerance for every solve");
  auto& lineSearch = nox.sublist("Line Search", false, "Globalisation");
  deck::setChoice(lineSearch, "Method", "Full Step", {"Full Step", "Backtrack", "Polynomial"}, "NOX line search");
  auto& tests = nox.sublist("Status Tests", false, "Newton convergence: converged when any of the three tests holds");
  deck::setPositiveInt(tests, "Maximum Iterations", 25, "Newton iterations before the increment counts as failed");
  deck::setNonNegative(tests, "Relative Residual Tolerance", 1e-10,
                       "Converged when ||f|| <= tol * ||f|| at the increment's first iterate");
  deck::setNonNegative(tests, "Absolute Residual Tolerance", 0.0,
                       "Not set (the default): the force-scaled test below. Set: converged when ||f|| <= tol (2-norm) "
                       "in the deck's force unit, instead of the force-scaled test (0: no absolute test)");
  deck::setNonNegative(tests, "Force-Scaled Residual Tolerance", ResidualTolerance::kDefaultFactor,
                       "Without Absolute Residual Tolerance: converged when ||f|| <= tol * F, F = ||f_int|| (2-norm of "
                       "the internal forces at the state: external loads, contact forces and reactions), the same in "
                       "any unit of force");
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
  addStepSizeParameters(step);

  piro->sublist("Stratimikos", false, "Linear solver (Stratimikos parameter names; 'MUMPS' and 'Automatic', the default, added by Contessa; see below)");
  return piro;
}

LinearSolverChoice chooseLinearSolver(ParameterList& stratimikos, const ProblemSize& size) {
  const std::string key = "Linear Solver Type";
  const bool automatic = !stratimikos.isParameter(key) ||
                         (stratimikos.isType<std::string>(key) && stratimikos.get<std::string>(key) == "Automatic");
  LinearSolverChoice choice;
  choice.automatic = automatic;
  if (automatic) {
    const long long limit = size.dimension == 3 ? kDirectSolverLimit3D : kDirectSolverLimit2D;
    const bool direct = size.unknowns <= limit;
    stratimikos.set(key, std::string(direct ? "MUMPS" : "Belos"));
    if (!direct && !stratimikos.isParameter("Preconditioner Type")) stratimikos.set("Preconditioner Type", std::string("MueLu"));
    choice.reason = "automatic: " + std::to_string(size.dimension) + "D, " + std::to_string(size.unknowns) +
                    " unknowns " + (direct ? "<= " : "> ") + std::to_string(limit) +
                    "; Piro/Stratimikos/Linear Solver Type = MUMPS or Belos forces one";
  } else {
    choice.reason = "given by Piro/Stratimikos/Linear Solver Type";
  }
  if (!stratimikos.isType<std::string>(key)) return choice;  // validatePiro reports it
  choice.solver = stratimikos.get<std::string>(key);
  if (choice.solver == "Belos") {
    const std::string prec = stratimikos.isType<std::string>("Preconditioner Type")
                                 ? stratimikos.get<std::string>("Preconditioner Type") : std::string("None");
    choice.solver += prec == "None" ? " without preconditioner" : " with " + prec;
  }
  return choice;
}

LinearSolverChoice validatePiro(ParameterList& piro, int numRanks, const ProblemSize& size) {
  const auto gives = [&piro](const std::string& name) {
    return piro.isSublist("NOX") && piro.sublist("NOX").isSublist("Status Tests") &&
           piro.sublist("NOX").sublist("Status Tests").isParameter(name);
  };
  const bool absoluteGiven = gives("Absolute Residual Tolerance");
  requireInput(!absoluteGiven || !gives("Force-Scaled Residual Tolerance"),
               "Piro/NOX/Status Tests: expected one of Absolute Residual Tolerance (in the deck's force unit) and "
               "Force-Scaled Residual Tolerance (relative to the force scale), not both");
  deck::validateAndSetDefaults(piro, *piroValidParameters(), "Piro", {"Stratimikos"});
  // The absolute tolerance stays only where the deck gives it: its absence selects the force-scaled test
  // (ResidualTolerance::fromDeck).
  if (!absoluteGiven) piro.sublist("NOX").sublist("Status Tests").remove("Absolute Residual Tolerance");
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
  const LinearSolverChoice choice = chooseLinearSolver(strat, size);
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
  return choice;
}

std::vector<ParameterList> loadStepSizes(const deck::ProblemDefinition& problem, const ParameterList& piro) {
  std::vector<ParameterList> out;
  if (problem.loadSteps.empty()) return out;
  requireInput(piro.get<std::string>("Solver Type") == "LOCA",
               "Problem/Load Steps: each step is a continuation; expected Piro/Solver Type = LOCA");
  const auto& stepper = piro.sublist("LOCA").sublist("Stepper");
  requireInput(stepper.get<double>("Initial Value") == 0.0 && stepper.get<double>("Max Value") == 1.0,
               "Problem/Load Steps: each step runs its own load factor from 0 to 1; expected Piro/LOCA/Stepper/"
               "Initial Value = 0 and Max Value = 1");
  const auto valid = piroValidParameters();
  const auto& validStepSize = valid->sublist("LOCA").sublist("Step Size");
  for (const auto& step : problem.loadSteps) {
    if (!step.hasStepSize) {
      out.push_back(piro.sublist("LOCA").sublist("Step Size"));
      continue;
    }
    const std::string where = "Problem/Load Steps/" + step.name + "/Step Size";
    ParameterList list = step.stepSize;
    deck::validateAndSetDefaults(list, validStepSize, where);
    requireInput(list.get<double>("Min Step Size") <= list.get<double>("Initial Step Size") &&
                     list.get<double>("Initial Step Size") <= list.get<double>("Max Step Size"),
                 where + ": expected Min Step Size <= Initial Step Size <= Max Step Size");
    out.push_back(list);
  }
  return out;
}

}  // namespace contessa::solvers
