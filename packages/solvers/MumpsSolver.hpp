#pragma once
// A parallel direct solver for Thyra/Stratimikos: MUMPS (distributed assembled matrix, centralised
// right-hand side). Amesos2 in this Trilinos build has only KLU2 (wrong answers on more than one
// rank) and Tacho (crashes), so this is the solver that gives the same answer on 1 and N ranks.
// Registered with Stratimikos under "Linear Solver Type" = "MUMPS". With "Reproducible" the matrix is
// gathered on rank 0 and MUMPS runs there alone: N-rank runs then repeat bit for bit (MumpsHostInput).
#include <memory>
#include <vector>

#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

namespace contessa::solvers {

/// What the failed factorizations of one factory found, the same on every rank (for the stop message).
struct MumpsFailures {
  long count = 0;        ///< failed factorizations so far
  int info = 0;          ///< INFOG(1) of the last one (e.g. −10: numerically singular; 0 with null pivots)
  int nullPivots = 0;    ///< INFOG(28) of the last one: the rank deficiency MUMPS detected
  /// The last one's null space basis (its first INFOG(28) vectors, at most 12, over all DOFs in global
  /// numbering): the directions in which the structure can move without resistance.
  std::vector<std::vector<double>> nullSpace;
};

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

  /// Failed factorizations of the operators this factory initialised (shared by all of them).
  const MumpsFailures& failures() const { return *failures_; }

 private:
  Teuchos::RCP<Teuchos::ParameterList> params_;
  std::shared_ptr<MumpsFailures> failures_ = std::make_shared<MumpsFailures>();
};

/// Number of MUMPS factorizations and solves so far on this process (for the run statistics).
struct MumpsCounters {
  long factorizations = 0;
  long symmetricFactorizations = 0;  ///< of them, LDLᵀ (a symmetric Jacobian on one rank)
  long solves = 0;
  long reusedFactorizations = 0;  ///< matrices equal to the last factorised one: its factors served
};
MumpsCounters& mumpsCounters();

}  // namespace contessa::solvers
