// What the finite-difference check of the Jacobian (JacobianCheck) needs of the model beyond the
// Thyra::ModelEvaluator: to put its evaluation state back after the perturbed residuals, its Jacobian
// with the consistent contact tangents, and to name who couples two DOFs.
#include <algorithm>

#include <Teuchos_CommHelpers.hpp>
#include <Thyra_VectorStdOps.hpp>

#include "model/ContactMechanicsModel.hpp"
#include "model/ContactAssembly.hpp"

namespace contessa::model {

struct ContactMechanicsModel::EvaluationState {
  std::vector<double> solidTrial;
  ContactAssembly::Interfaces contacts;  ///< trial histories, last positions, slip damping
  Teuchos::RCP<Vector> passX, passForce, passDfdLambda;
  double passLambda = 0, passForceScale = 0, lastOutOfBalance = 0, lastRoundOff = 0;
  bool passFrozen = false, passHasStiffness = false, passServesEvaluations = false, passServesReactions = false;
  SolidAssembler::Status passStatus, lastElementStatus;
  int jacobianEvaluations = 0, elementPasses = 0, stiffnessPasses = 0;
  double lastLoadFactor = 0;
};

std::shared_ptr<const ContactMechanicsModel::EvaluationState> ContactMechanicsModel::saveEvaluationState() const {
  auto s = std::make_shared<EvaluationState>();
  s->solidTrial = solids_->trialState();
  s->contacts = contact_->saveState();
  s->passX = Teuchos::rcp(new Vector(*passX_, Teuchos::Copy));
  s->passForce = Teuchos::rcp(new Vector(*passForce_, Teuchos::Copy));
  s->passDfdLambda = Teuchos::rcp(new Vector(*passDfdLambda_, Teuchos::Copy));
  s->passLambda = passLambda_;
  s->passForceScale = passForceScale_;
  s->lastOutOfBalance = lastOutOfBalance_;
  s->lastRoundOff = lastRoundOff_;
  s->passFrozen = passFrozen_;
  s->passHasStiffness = passHasStiffness_;
  s->passServesEvaluations = passServesEvaluations_;
  s->passServesReactions = passServesReactions_;
  s->passStatus = passStatus_;
  s->lastElementStatus = lastElementStatus_;
  s->jacobianEvaluations = jacobianEvaluations_;
  s->elementPasses = elementPasses_;
  s->stiffnessPasses = stiffnessPasses_;
  s->lastLoadFactor = lastLoadFactor_;
  return s;
}

void ContactMechanicsModel::restoreEvaluationState(const EvaluationState& s) const {
  solids_->restoreTrialState(s.solidTrial);
  contact_->restoreState(s.contacts);
  passX_->assign(*s.passX);
  passForce_->assign(*s.passForce);
  passDfdLambda_->assign(*s.passDfdLambda);
  passLambda_ = s.passLambda;
  passForceScale_ = s.passForceScale;
  lastOutOfBalance_ = s.lastOutOfBalance;
  lastRoundOff_ = s.lastRoundOff;
  passFrozen_ = s.passFrozen;
  // The stiffness of the saved pass is not kept: when a stiffness pass has overwritten it since, a
  // Jacobian asked for at the saved point is computed again (the residual is still served).
  passHasStiffness_ = s.passHasStiffness && stiffnessPasses_ == s.stiffnessPasses;
  passServesEvaluations_ = s.passServesEvaluations;
  passServesReactions_ = s.passServesReactions;
  passStatus_ = s.passStatus;
  lastElementStatus_ = s.lastElementStatus;
  jacobianEvaluations_ = s.jacobianEvaluations;
  elementPasses_ = s.elementPasses;
  lastLoadFactor_ = s.lastLoadFactor;
  // (stiffnessPasses_ keeps counting: it says whether the scatter holds the saved pass's stiffness.)
}

int ContactMechanicsModel::consistentJacobian(const Thyra::VectorBase<double>& x, double lambda,
                                             Thyra::LinearOpBase<double>& W) const {
  auto in = createInArgs();
  auto p = Thyra::createMember(get_p_space(0));
  Thyra::set_ele(0, lambda, p.ptr());
  in.set_x(Teuchos::rcpFromRef(x));
  in.set_p(0, p);
  auto out = createOutArgs();
  out.set_W_op(Teuchos::rcpFromRef(W));
  // A pass at x with stiffness may hold Newton's tangent (with its secants): evaluate afresh.
  passServesEvaluations_ = false;
  contact_->setConsistentTangents(true);
  try {
    evalModel(in, out);
  } catch (...) {
    contact_->setConsistentTangents(false);
    throw;
  }
  contact_->setConsistentTangents(false);
  // The pass holds the consistent tangent: not Newton's, so no later evaluation is served from it.
  passServesEvaluations_ = false;
  int local = contact_->secantTangentNodes(), all = 0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, 1, &local, &all);
  return all;
}

void ContactMechanicsModel::holdContactPoints(bool held) const {
  contact_->holdContactPoints(held);
  passServesEvaluations_ = false;
}

std::string ContactMechanicsModel::describeCoupling(GO rowDof, GO columnDof) const {
  const GlobalIndex a = rowDof / dim_, b = columnDof / dim_;
  std::vector<std::string> who;
  // The first solid element of this rank's part holding both nodes (Exodus numbering, 1-based).
  const mesh::DistributedMesh& part = problem_.mesh;
  const GlobalIndex localA = part.localNode(a), localB = part.localNode(b);
  for (std::size_t k = 0; k < part.local().blocks.size() && who.empty() && localA >= 0 && localB >= 0; ++k) {
    const auto& block = part.local().blocks[k];
    const int n = mesh::nodesPerCell(block.cellType);
    for (GlobalIndex e = 0; e < block.numElements(); ++e) {
      const auto first = block.connectivity.begin() + e * n, last = first + n;
      if (std::find(first, last, localA) != last && std::find(first, last, localB) != last) {
        who.push_back("element " + std::to_string(part.part.globalElements[block.elements[e]] + 1) + " of block '" +
                      problem_.blocks[k].block + "'");
        break;
      }
    }
  }
  // A contact element couples its slave node with the nodes of its master segment.
  for (const auto& spec : problem_.contacts) {
    for (GlobalIndex node : {a, b})
      if (std::binary_search(spec.slaveNodes.begin(), spec.slaveNodes.end(), node)) {
        who.push_back("contact '" + spec.label() + "' slave node " + std::to_string(node + 1));
        break;
      }
  }
  if (who.empty()) return "no element or contact slave node holds both nodes";
  std::string out;
  for (const auto& w : who) out += (out.empty() ? "" : ", ") + w;
  return out;
}

}  // namespace contessa::model
