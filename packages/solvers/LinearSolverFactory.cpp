#include "solvers/LinearSolverFactory.hpp"

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Teuchos_AbstractFactoryStd.hpp>
#include <Thyra_Ifpack2PreconditionerFactory.hpp>

#include "common/Error.hpp"
#include "common/ErrorText.hpp"
#include "model/TpetraTypes.hpp"
#include "solvers/MumpsSolver.hpp"

namespace contessa::solvers {
namespace {

void registerSolvers(Stratimikos::DefaultLinearSolverBuilder& builder) {
  builder.setLinearSolveStrategyFactory(
      Teuchos::abstractFactoryStd<Thyra::LinearOpWithSolveFactoryBase<double>, MumpsLinearOpWithSolveFactory>(),
      "MUMPS");
  builder.setPreconditioningStrategyFactory(
      Teuchos::abstractFactoryStd<Thyra::PreconditionerFactoryBase<double>,
                                  Thyra::Ifpack2PreconditionerFactory<model::CrsMatrix>>(),
      "Ifpack2");
}

std::string joinNames(const Teuchos::ParameterList& list) {
  std::string out;
  for (auto it = list.begin(); it != list.end(); ++it) out += (out.empty() ? "" : ", ") + list.name(it);
  return out;
}

// Stratimikos reports a refused list with pages of Teuchos text. After it refuses, this finds the
// first entry of the deck that its valid list does not take and says why in one line naming the deck
// path; empty when it finds none.
std::string firstRefusedEntry(const Teuchos::ParameterList& given, const Teuchos::ParameterList& valid,
                              const std::string& path) {
  for (auto it = given.begin(); it != given.end(); ++it) {
    const std::string& name = given.name(it);
    const std::string where = path + "/" + name;
    const Teuchos::ParameterEntry& entry = given.entry(it);
    const Teuchos::ParameterEntry* expected = valid.getEntryPtr(name);
    if (expected == nullptr) return where + ": unknown parameter (expected one of: " + joinNames(valid) + ")";
    if (entry.isList() != expected->isList())
      return where + (expected->isList() ? ": expected a sublist" : ": expected a parameter, not a sublist");
    if (entry.isList()) {
      const std::string inner = firstRefusedEntry(given.sublist(name), valid.sublist(name), where);
      if (!inner.empty()) return inner;
      continue;
    }
    const auto validator = expected->validator();
    if (validator.is_null()) {
      if (entry.getAny(false).type() != expected->getAny(false).type())
        return where + ": expected type " + expected->getAny(false).typeName() + ", got " + entry.getAny(false).typeName();
      continue;
    }
    const auto strings = validator->validStringValues();
    if (!strings.is_null() && entry.isType<std::string>()) {
      const std::string value = Teuchos::getValue<std::string>(entry);
      std::string allowed;
      bool found = false;
      for (const auto& s : *strings) {
        allowed += (allowed.empty() ? "" : ", ") + s;
        found = found || s == value;
      }
      if (!found) return where + ": expected one of " + allowed + "; got '" + value + "'";
    }
    try {
      validator->validate(entry, name, path);
    } catch (const std::exception& e) {
      return where + ": " + plainMessage(e);
    }
  }
  return "";
}

}  // namespace

Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> createLinearSolverFactory(Teuchos::ParameterList& stratimikos) {
  Stratimikos::DefaultLinearSolverBuilder builder;
  registerSolvers(builder);
  try {
    // The solvers keep pointers into the list: give them their own copy.
    builder.setParameterList(Teuchos::rcp(new Teuchos::ParameterList(stratimikos)));
    // Stratimikos hands a solver its sublist only at the first solve: check MUMPS' now, before the run.
    if (stratimikos.isSublist("Linear Solver Types") && stratimikos.sublist("Linear Solver Types").isSublist("MUMPS")) {
      Teuchos::ParameterList mumps(stratimikos.sublist("Linear Solver Types").sublist("MUMPS"));
      const auto valid = MumpsLinearOpWithSolveFactory().getValidParameters();
      // Twice: the first pass turns a number given as text (--set) into a number, the second checks its range.
      mumps.validateParametersAndSetDefaults(*valid);
      mumps.validateParametersAndSetDefaults(*valid);
    }
    return Thyra::createLinearSolveStrategy(builder);
  } catch (const std::exception& e) {
    const std::string refused = firstRefusedEntry(stratimikos, *builder.getValidParameters(), "Piro/Stratimikos");
    throw InputError(refused.empty() ? "Piro/Stratimikos: " + plainMessage(e) : refused);
  }
}

Teuchos::RCP<const Teuchos::ParameterList> stratimikosValidParameters() {
  Stratimikos::DefaultLinearSolverBuilder builder;
  registerSolvers(builder);
  return builder.getValidParameters();
}

}  // namespace contessa::solvers
