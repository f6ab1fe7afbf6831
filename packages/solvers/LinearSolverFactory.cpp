#include "solvers/LinearSolverFactory.hpp"

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Teuchos_AbstractFactoryStd.hpp>
#include <Thyra_Ifpack2PreconditionerFactory.hpp>

#include "common/Error.hpp"
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

std::string oneLine(std::string msg) {
  for (auto& c : msg)
    if (c == '\n') c = ' ';
  if (msg.size() > 400) msg = msg.substr(0, 400) + "...";
  return msg;
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
    throw InputError("Piro/Stratimikos: " + oneLine(e.what()));
  }
}

Teuchos::RCP<const Teuchos::ParameterList> stratimikosValidParameters() {
  Stratimikos::DefaultLinearSolverBuilder builder;
  registerSolvers(builder);
  return builder.getValidParameters();
}

}  // namespace contessa::solvers
