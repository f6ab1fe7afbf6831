#include "solvers/LoadFactorDerivativeGroup.hpp"

#include <stdexcept>
#include <string>

#include <NOX_Thyra_Vector.H>
#include <Thyra_MultiVectorStdOps.hpp>
#include <Thyra_VectorStdOps.hpp>

namespace contessa::solvers {

using MEB = Thyra::ModelEvaluatorBase;

LoadFactorDerivativeGroup::LoadFactorDerivativeGroup(const Teuchos::RCP<LOCA::GlobalData>& globalData,
                                                     const NOX::Thyra::Vector& initialGuess,
                                                     const Teuchos::RCP<::Thyra::ModelEvaluator<double>>& model,
                                                     const LOCA::ParameterVector& p, int pIndex)
    // LOCA::Thyra::Group derives virtually from both groups: the most derived class constructs them.
    : NOX::Thyra::Group(initialGuess, model),
      LOCA::Abstract::Group(globalData),
      LOCA::Thyra::Group(globalData, initialGuess, model, p, pIndex),
      modelIndex_(pIndex) {
  if (!model->createOutArgs().supports(MEB::OUT_ARG_DfDp, pIndex).supports(MEB::DERIV_MV_BY_COL))
    throw std::logic_error("LoadFactorDerivativeGroup: the model gives no DfDp of parameter vector " +
                           std::to_string(pIndex) + " by columns");
  if (model->get_p_space(pIndex)->dim() != p.length())
    throw std::logic_error("LoadFactorDerivativeGroup: the model's parameter vector " + std::to_string(pIndex) + " has " +
                           std::to_string(model->get_p_space(pIndex)->dim()) + " entries, LOCA's " +
                           std::to_string(p.length()));
}

LoadFactorDerivativeGroup::LoadFactorDerivativeGroup(const LoadFactorDerivativeGroup& source, NOX::CopyType type)
    : NOX::Thyra::Group(source, type),
      LOCA::Abstract::Group(source, type),
      LOCA::Thyra::Group(source, type),
      modelIndex_(source.modelIndex_) {}

Teuchos::RCP<NOX::Abstract::Group> LoadFactorDerivativeGroup::clone(NOX::CopyType type) const {
  return Teuchos::rcp(new LoadFactorDerivativeGroup(*this, type));
}

NOX::Abstract::Group::ReturnType LoadFactorDerivativeGroup::computeDfDpMulti(const std::vector<int>& paramIDs,
                                                                             NOX::Abstract::MultiVector& fdfdp,
                                                                             bool isValidF) {
  if (!isValidF) {
    const auto status = computeF();
    fdfdp[0] = getF();
    if (status != NOX::Abstract::Group::Ok) return status;
  }
  // The model's parameter vector, from LOCA's values (the group's own view of them is private to LOCA).
  auto p = ::Thyra::createMember(model_->get_p_space(modelIndex_));
  for (int i = 0; i < params.length(); ++i) ::Thyra::set_ele(i, params.getValue(i), p.ptr());
  auto in = model_->createInArgs();
  in.set_x(x_vec_->getThyraRCPVector().assert_not_null());
  in.set_p(modelIndex_, p);
  // Every parameter's column (the model gives them all at once); LOCA's are copied out.
  auto all = ::Thyra::createMembers(model_->get_f_space(), params.length());
  auto out = model_->createOutArgs();
  out.set_DfDp(modelIndex_, MEB::Derivative<double>(all, MEB::DERIV_MV_BY_COL));
  model_->evalModel(in, out);
  ++modelDerivativeEvaluations_;
  for (std::size_t i = 0; i < paramIDs.size(); ++i)
    fdfdp[static_cast<int>(i) + 1] = NOX::Thyra::Vector(*all->col(paramIDs[i]));
  return out.isFailed() ? NOX::Abstract::Group::Failed : NOX::Abstract::Group::Ok;
}

}  // namespace contessa::solvers
