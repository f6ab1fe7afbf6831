#pragma once
// A parallel direct solver for Thyra/Stratimikos: MUMPS (distributed assembled matrix, centralised
// right-hand side). Amesos2 in this Trilinos build has only KLU2 (wrong answers on more than one
// rank) and Tacho (crashes), so this is the solver that gives the same answer on 1 and N ranks.
// Registered with Stratimikos under "Linear Solver Type" = "MUMPS".
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

namespace contessa::solvers {

class MumpsLinearOpWithSolveFactory : public Thyra::LinearOpWithSolveFactoryBase<double> {
 public:
  MumpsLinearOpWithSolveFactory();

  bool isCompatible(const Thyra::LinearOpSourceBase<double>& fwdOpSrc) const override;
  Teuchos::RCP<Thyra::LinearOpWithSolveBase<double>> createOp() const override;
  void initializeOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>& fwdOpSrc,
                    Thyra::LinearOpWithSolveBase<double>* op,
                    const Thyra::ESupportSolveUse supportSolveUse) const override;
  void uninitializeOp(Thyra::LinearOpWithSolveBase<double>* op,
                      Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* fwdOpSrc,
                      Teuchos::RCP<const Thyra::PreconditionerBase<double>>* prec,
                      Teuchos::RCP<const Thyra::LinearOpSourceBase<double>>* approxFwdOpSrc,
                      Thyra::ESupportSolveUse* supportSolveUse) const override;

  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& params) override;
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override;
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override;
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override;
  std::string description() const override { return "MUMPS direct solver"; }

 private:
  Teuchos::RCP<Teuchos::ParameterList> params_;
};

/// Number of MUMPS factorizations and solves so far on this process (for the run statistics).
struct MumpsCounters {
  long factorizations = 0;
  long solves = 0;
};
MumpsCounters& mumpsCounters();

}  // namespace contessa::solvers
