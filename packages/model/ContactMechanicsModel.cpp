#include "model/ContactMechanicsModel.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>

#include <Thyra_DefaultSpmdVectorSpace.hpp>
#include <Thyra_DetachedVectorView.hpp>
#include <Thyra_TpetraLinearOp.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include "common/PhaseTimers.hpp"
#include "mesh/MeshDistribution.hpp"
#include "model/BoundaryConditions.hpp"
#include "model/ContactAssembly.hpp"
#include "model/DofLayout.hpp"
#include "model/ForceRoundOff.hpp"
#include "model/FreeMotion.hpp"
#include "model/StiffnessScatter.hpp"

namespace contessa::model {

using Teuchos::RCP;
using Teuchos::rcp;
using MEB = Thyra::ModelEvaluatorBase;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>;

ContactMechanicsModel::ContactMechanicsModel(const RCP<const Comm>& comm,
                                             std::shared_ptr<const deck::ProblemDefinition> problem,
                                             const RCP<Thyra::LinearOpWithSolveFactoryBase<double>>& solverFactory)
    : comm_(comm),
      sharedProblem_(std::move(problem)),
      problem_(*sharedProblem_),
      dim_(problem_.dimension()),
      solverFactory_(solverFactory) {
  if (problem_.mesh.rank != comm->getRank() || problem_.mesh.numRanks != comm->getSize())
    throw std::logic_error("ContactMechanicsModel: the mesh part was made for rank " + std::to_string(problem_.mesh.rank) +
                           " of " + std::to_string(problem_.mesh.numRanks) + ", not for this communicator");
  layout_ = std::make_unique<DofLayout>(comm_, problem_.mesh, ContactAssembly::surfaceNodes(problem_.contacts));
  {
    double local = 0.0;
    for (const double c : problem_.mesh.part.mesh.coordinates) local = std::max(local, std::abs(c));
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, 1, &local, &lengthScale_);
  }
  contact_ = std::make_unique<ContactAssembly>(problem_, *layout_);
  solids_ = std::make_unique<SolidAssembler>(
      problem_, [this](GlobalIndex dof) { return layout_->overlapMap()->getLocalElement(dof); });
  overlapX_ = rcp(new Vector(layout_->overlapMap()));
  overlapForce_ = rcp(new Vector(layout_->overlapMap()));
  overlapDfdLambda_ = rcp(new Vector(layout_->overlapMap()));
  overlapInternal_ = rcp(new Vector(layout_->overlapMap()));
  // The element couplings, once: the assembler runs at u = 0 (before any state matters) to name each
  // element's DOFs; with the stiffness there, the round-off level of the elements' forces (ForceRoundOff.hpp).
  ForceRoundOff roundOff(overlappedReferenceCoordinates(), dim_, problem_.axisymmetric);
  solids_->assemble(std::vector<double>(layout_->numOverlapDofs(), 0.0).data(), true,
                    [&](const int* dofs, int n, const double*, const double* ke) {
                      elementDofBegin_.push_back(elementDofs_.size());
                      elementDofs_.insert(elementDofs_.end(), dofs, dofs + n);
                      roundOff.addElement(dofs, n, ke);
                    });
  elementDofBegin_.push_back(elementDofs_.size());
  buildGraph();
  {
    Vector overlapLevels(layout_->overlapMap());
    auto v = overlapLevels.getDataNonConst(0);
    std::copy(roundOff.squaredLevels().begin(), roundOff.squaredLevels().end(), v.begin());
    v = Teuchos::null;
    squaredRoundOff_ = rcp(new Vector(layout_->ownedMap()));
    squaredRoundOff_->doExport(overlapLevels, layout_->exporter(), Tpetra::ADD);
  }
  passX_ = rcp(new Vector(layout_->ownedMap()));
  passForce_ = rcp(new Vector(layout_->ownedMap()));
  passDfdLambda_ = rcp(new Vector(layout_->ownedMap()));
  internalForce_ = rcp(new Vector(layout_->ownedMap()));
  conditions_ = std::make_unique<BoundaryConditions>(problem_, *layout_);
  results_ = std::make_unique<PostProcessing>(problem_, *layout_, *solids_, *contact_);
  schedule_ = loadScheduleOf(problem_);
  // Without load steps the parts keep the values they were made with (start 0, the deck's values).
  if (!problem_.loadSteps.empty()) setLoadStep(0);

  xSpace_ = Thyra::createVectorSpace<double>(layout_->ownedMap());
  // λ is replicated: a locally replicated map of one entry.
  paramMap_ = rcp(new Map(1, 0, comm_, Tpetra::LocallyReplicated));
  pSpace_ = Thyra::createVectorSpace<double>(paramMap_);

  MEB::InArgsSetup<double> inArgs;
  inArgs.setModelEvalDescription("Contessa contact mechanics model");
  inArgs.setSupports(MEB::IN_ARG_x, true);
  inArgs.set_Np(1);
  nominal_ = inArgs;
  auto x0 = Thyra::createMember(xSpace_);
  Thyra::assign(x0.ptr(), 0.0);
  auto p0 = Thyra::createMember(pSpace_);
  Thyra::assign(p0.ptr(), 0.0);
  nominal_.set_x(x0);
  nominal_.set_p(0, p0);
}

ContactMechanicsModel::~ContactMechanicsModel() = default;

std::vector<double> ContactMechanicsModel::overlappedReferenceCoordinates() const {
  const auto& part = problem_.mesh.part;
  std::vector<double> X(layout_->numOverlapDofs(), 0.0);
  for (std::size_t n = 0; n < part.globalNodes.size(); ++n)
    for (int c = 0; c < dim_; ++c) {
      const LO dof = layout_->overlapMap()->getLocalElement(static_cast<GO>(part.globalNodes[n]) * dim_ + c);
      if (dof != Teuchos::OrdinalTraits<LO>::invalid())
        X[static_cast<std::size_t>(dof)] = part.mesh.coordinates[n * static_cast<std::size_t>(dim_) + static_cast<std::size_t>(c)];
    }
  return X;
}

void ContactMechanicsModel::buildGraph() const {
  // Element couplings and the contact couplings reserved by search, gathered per overlapped row; the
  // owned graph receives them, shared rows from each rank that holds them.
  std::vector<std::vector<LO>> contactRows(layout_->numOverlapDofs());
  contact_->addReservedCouplings(contactRows);
  const auto rows = OverlapCouplings::gather(layout_->numOverlapDofs(), elementDofs_, elementDofBegin_, contactRows);
  layout_->buildGraph(rows);
  const std::size_t numElements = elementDofBegin_.size() - 1;
  // Where each element's stiffness goes in the Jacobian's values, once per graph (the element loop visits
  // the elements in the same order at every pass).
  scatter_ = std::make_unique<StiffnessScatter>(layout_->ownedGraph(), layout_->overlapMap(), rows);
  for (std::size_t e = 0; e < numElements; ++e)
    scatter_->addElement(elementDofs_.data() + elementDofBegin_[e],
                         static_cast<int>(elementDofBegin_[e + 1] - elementDofBegin_[e]));
}

void ContactMechanicsModel::rebuildGraph(const double* u) const {
  timers::Scope scope(timers::Phase::GraphRebuild);
  const auto start = std::chrono::steady_clock::now();
  GraphRebuild rebuild;
  rebuild.reason = contact_->outsideReservation();
  contact_->reserveAround(u);
  buildGraph();
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, 1, &seconds, &rebuild.seconds);
  rebuild.count = ++graphRebuilds_;
  rebuild.entries = static_cast<long long>(layout_->ownedGraph()->getGlobalNumEntries());
  graphRebuildSeconds_ += rebuild.seconds;
  if (rebuildObserver_) rebuildObserver_(rebuild);
}

const RCP<const Map>& ContactMechanicsModel::ownedDofMap() const { return layout_->ownedMap(); }
const RCP<const Map>& ContactMechanicsModel::ownedElementMap() const { return layout_->elementMap(); }
const RCP<const Map>& ContactMechanicsModel::ownedNodeMap() const { return layout_->nodeMap(); }

RCP<const Thyra::VectorSpaceBase<double>> ContactMechanicsModel::get_x_space() const { return xSpace_; }
RCP<const Thyra::VectorSpaceBase<double>> ContactMechanicsModel::get_f_space() const { return xSpace_; }
RCP<const Thyra::VectorSpaceBase<double>> ContactMechanicsModel::get_p_space(int) const { return pSpace_; }

RCP<const Teuchos::Array<std::string>> ContactMechanicsModel::get_p_names(int) const {
  return rcp(new Teuchos::Array<std::string>(1, "Load Factor"));
}

MEB::InArgs<double> ContactMechanicsModel::getNominalValues() const { return nominal_; }
MEB::InArgs<double> ContactMechanicsModel::createInArgs() const {
  MEB::InArgsSetup<double> inArgs;
  inArgs.setModelEvalDescription("Contessa contact mechanics model");
  inArgs.setSupports(MEB::IN_ARG_x, true);
  inArgs.set_Np(1);
  return inArgs;
}

MEB::OutArgs<double> ContactMechanicsModel::createOutArgsImpl() const {
  MEB::OutArgsSetup<double> outArgs;
  outArgs.setModelEvalDescription("Contessa contact mechanics model");
  outArgs.set_Np_Ng(1, 0);
  outArgs.setSupports(MEB::OUT_ARG_f, true);
  outArgs.setSupports(MEB::OUT_ARG_W_op, true);
  outArgs.setSupports(MEB::OUT_ARG_DfDp, 0, MEB::DerivativeSupport(MEB::DERIV_MV_JACOBIAN_FORM));
  outArgs.set_W_properties(MEB::DerivativeProperties(MEB::DERIV_LINEARITY_NONCONST, MEB::DERIV_RANK_FULL, true));
  return outArgs;
}

RCP<Thyra::LinearOpBase<double>> ContactMechanicsModel::create_W_op() const {
  RCP<Operator> op = rcp(new CrsMatrix(layout_->ownedGraph()));
  return Thyra::createLinearOp<double, LO, GO, Node>(op, xSpace_, xSpace_);
}

RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> ContactMechanicsModel::get_W_factory() const {
  return solverFactory_;
}

Teuchos::ArrayRCP<const double> ContactMechanicsModel::overlapped(const Vector& x) const {
  overlapX_->doImport(x, layout_->importer(), Tpetra::INSERT);
  return overlapX_->getData(0);
}

SolidAssembler::Status ContactMechanicsModel::assemble(const Vector& x, double lambda, bool withStiffness,
                                                       bool updateTrial, Vector& force, Vector& dForcedLambda,
                                                       double* internalForceNorm) const {
  using timers::Phase;
  // A pass that leaves the trial state alone is the reactions' own element loop.
  const auto phase = [&](Phase p) { return updateTrial ? p : Phase::Reactions; };
  timers::Scope assemblyScope(phase(Phase::Assembly));
  const auto u = overlapped(x);
  // The step's amplitude a(λ) and its slope: every scheduled value is start + a · change.
  const double a = schedule_.amplitude(loadStep_, lambda), slope = schedule_.amplitudeSlope(loadStep_, lambda);
  overlapForce_->putScalar(0.0);
  overlapDfdLambda_->putScalar(0.0);
  auto fo = overlapForce_->getDataNonConst(0);
  auto dl = overlapDfdLambda_->getDataNonConst(0);
  if (withStiffness) scatter_->beginPass();
  ++elementPasses_;
  if (withStiffness) ++stiffnessPasses_;
  std::optional<timers::Scope> elementScope(std::in_place,
                                            phase(withStiffness ? Phase::ElementJacobian : Phase::ElementResidual));
  const auto status = solids_->assemble(u.getRawPtr(), withStiffness,
                                        [&](const int* dofs, int n, const double* fe, const double* ke) {
                                          for (int i = 0; i < n; ++i) fo[dofs[i]] += fe[i];
                                          if (ke != nullptr) scatter_->addElementStiffness(dofs, n, ke);
                                        });
  elementScope.reset();
  if (internalForceNorm != nullptr) {
    // The elements' forces alone, before contact and loads are added (the force scale, ForceScale.hpp).
    auto fi = overlapInternal_->getDataNonConst(0);
    std::copy(fo.begin(), fo.end(), fi.begin());
  }
  {
    timers::Scope contactScope(phase(Phase::Contact));
    contactFitsGraph_ = contact_->assemble(u.getRawPtr(), a, updateTrial, fo.getRawPtr(), dl.getRawPtr(),
                                           withStiffness ? scatter_.get() : nullptr, slope);
  }
  // Follower loads (the pressures: −f_p(x), its ∂/∂λ and load stiffness) through the same scatter as the
  // elements' (their facets couple only their element's DOFs); the springs' diagonal.
  const ExternalLoads::StiffnessSink facetSink = [this](const int* dofs, int n, const double* k) {
    scatter_->addStiffness(dofs, n, k);
  };
  conditions_->loads().assembleFollowerLoads(u.getRawPtr(), a, slope, fo.getRawPtr(), dl.getRawPtr(),
                                             withStiffness ? &facetSink : nullptr);
  if (withStiffness) conditions_->addSpringStiffness([this](LO dof, double k) { scatter_->addStiffness(&dof, 1, &k); });
  fo = Teuchos::null;
  dl = Teuchos::null;
  force.putScalar(0.0);
  force.doExport(*overlapForce_, layout_->exporter(), Tpetra::ADD);
  dForcedLambda.putScalar(0.0);
  dForcedLambda.doExport(*overlapDfdLambda_, layout_->exporter(), Tpetra::ADD);
  if (internalForceNorm != nullptr) {
    internalForce_->putScalar(0.0);
    internalForce_->doExport(*overlapInternal_, layout_->exporter(), Tpetra::ADD);
    *internalForceNorm = internalForce_->norm2();
  }
  return status;
}

void ContactMechanicsModel::evaluatePass(const Vector& x, double lambda, bool withStiffness) const {
  passStatus_ = assemble(x, lambda, withStiffness, true, *passForce_, *passDfdLambda_, &passForceScale_);
  if (withStiffness && !contactFitsGraph_) {
    // A contact pairing outside the reserved couplings (every rank agrees): reserve around the current
    // configuration, rebuild the graph and assemble the pass again on it. The new reservation holds
    // every pairing the run-time search can make at this x (CouplingReservation.hpp), so the second
    // pass fits; a residual-only pass never rebuilds (the next Jacobian does).
    rebuildGraph(overlapped(x).getRawPtr());
    passStatus_ = assemble(x, lambda, withStiffness, true, *passForce_, *passDfdLambda_, &passForceScale_);
    if (!contactFitsGraph_)
      throw std::logic_error("ContactMechanicsModel: the rebuilt matrix graph does not hold the contact pairing (" +
                             contact_->outsideReservation() + ")");
  }
  passHasStiffness_ = withStiffness;
  passX_->assign(x);
  passLambda_ = lambda;
  passFrozen_ = contact_->newContactsFrozen();
  passServesEvaluations_ = true;
  passServesReactions_ = true;
}

bool ContactMechanicsModel::latestPassIsAt(const Vector& x, double lambda, bool valid) const {
  int same = valid && lambda == passLambda_ && contact_->newContactsFrozen() == passFrozen_ ? 1 : 0;
  if (same) {
    const auto a = x.getData(0);
    const auto b = passX_->getData(0);
    same = std::equal(a.begin(), a.end(), b.begin(), b.end()) ? 1 : 0;
  }
  if (comm_->getSize() > 1) {
    int all = 0;
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, 1, &same, &all);
    same = all;
  }
  return same == 1;
}

void ContactMechanicsModel::evalModelImpl(const MEB::InArgs<double>& inArgs, const MEB::OutArgs<double>& outArgs) const {
  const RCP<const Vector> x = Extract::getConstTpetraVector(inArgs.get_x());
  double lambda = 0.0;
  if (auto p = inArgs.get_p(0); !p.is_null()) lambda = Thyra::get_ele(*p, 0);
  lastLoadFactor_ = lambda;

  const RCP<Thyra::VectorBase<double>> fOut = outArgs.get_f();
  const RCP<Thyra::LinearOpBase<double>> wOut = outArgs.get_W_op();
  const RCP<Thyra::MultiVectorBase<double>> dfdp = outArgs.get_DfDp(0).getMultiVector();

  RCP<Vector> f = fOut.is_null() ? Teuchos::null : Extract::getTpetraVector(fOut);
  RCP<CrsMatrix> W;
  if (!wOut.is_null()) {
    W = Teuchos::rcp_dynamic_cast<CrsMatrix>(Extract::getTpetraOperator(wOut), true);
    ++jacobianEvaluations_;
  }

  RCP<MultiVector> dfdpTpetra = dfdp.is_null() ? Teuchos::null : Extract::getTpetraMultiVector(dfdp);
  SolidAssembler::Status status;
  if (!f.is_null() || !W.is_null() || !dfdp.is_null()) {
    // The tangent only when it is asked for: computing it with every residual (Newton asks for the
    // Jacobian at the point of its last residual) was measured no faster, as the element kernels
    // warm-start their local solve exactly there, and wastes it at every converged iterate.
    const bool needStiffness = !W.is_null();
    if (!latestPassIsAt(*x, lambda, passServesEvaluations_ && (passHasStiffness_ || !needStiffness)))
      evaluatePass(*x, lambda, needStiffness);
    status = passStatus_;
  }
  const bool ok = status.ok();
  if (!f.is_null()) lastElementStatus_ = status;

  if (!f.is_null()) {
    conditions_->residual(*passForce_, *x, schedule_.amplitude(loadStep_, lambda), *f);
    // An inadmissible element (inverted, failed internal solve) poisons the residual: NOX's
    // finite-value test then fails the solve and the continuation cuts the step back.
    if (!ok)
      for (auto& v : f->getDataNonConst(0)) v = std::numeric_limits<double>::quiet_NaN();
    // The out-of-balance force: f without its prescribed rows (x − ū, a displacement). It is only a
    // measure of convergence once those rows hold (to 1e-10 of the largest |x|: round-off after one Newton
    // step, and LOCA 13.2's tangent predictor, whose dx/dλ is a finite difference in λ, lands within 1.3e-10
    // of it on a linear problem); before (e.g. a solve from rest under a prescribed displacement, where f_int
    // and f_free are still 0 and the rows are off by all of ū) it is infinite, so that no force-relative
    // test passes there.
    std::vector<double> free(f->getLocalLength());
    {
      const auto fv = f->getData(0);
      std::copy(fv.begin(), fv.end(), free.begin());
    }
    // Its round-off level (ForceRoundOff.hpp) over the same rows.
    std::vector<double> squaredLevel(free.size());
    {
      const auto rv = squaredRoundOff_->getData(0);
      std::copy(rv.begin(), rv.end(), squaredLevel.begin());
    }
    double local[2] = {0.0, 0.0}, largest[2] = {0.0, 0.0};  // max |x − ū| on prescribed rows, max |x|
    for (const LO r : conditions_->prescribedRows()) {
      local[0] = std::max(local[0], std::abs(free[static_cast<std::size_t>(r)]));
      free[static_cast<std::size_t>(r)] = 0.0;
      squaredLevel[static_cast<std::size_t>(r)] = 0.0;
    }
    for (const double v : x->getData(0)) local[1] = std::max(local[1], std::abs(v));
    double squares[2] = {0.0, 0.0}, sums[2] = {0.0, 0.0};  // ‖f_free‖², ‖r_free‖²
    for (const double v : free) squares[0] += v * v;
    for (const double v : squaredLevel) squares[1] += v;
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, 2, squares, sums);
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, 2, local, largest);
    const bool prescribedHold = largest[0] <= 1e-10 * largest[1];
    lastOutOfBalance_ = prescribedHold ? std::sqrt(sums[0]) : std::numeric_limits<double>::infinity();
    lastRoundOff_ = std::sqrt(sums[1]);
  }
  if (!W.is_null()) {
    // The stiffness of the pass, with the rows of other ranks added; prescribed rows become identity rows.
    timers::Scope scope(timers::Phase::Assembly);
    if (W->getCrsGraph() != layout_->ownedGraph()) {
      // W was made on a graph since rebuilt: the operator the caller holds (NOX's groups share it, and
      // re-initialise their solver from it after every Jacobian evaluation) is pointed at a new matrix on
      // the current graph, over the same maps; the old matrix goes when its last holder lets it go.
      W = rcp(new CrsMatrix(layout_->ownedGraph()));
      Teuchos::rcp_dynamic_cast<Thyra::TpetraLinearOp<double, LO, GO, Node>>(wOut, true)->initialize(xSpace_, xSpace_, W);
    }
    scatter_->copyTo(*W, conditions_->prescribedRows());
  }
  if (!dfdp.is_null()) {
    dfdpTpetra->putScalar(0.0);  // the caller's storage may hold anything, and 0·NaN is NaN
    conditions_->dResidualdLambda(*passDfdLambda_, schedule_.amplitudeSlope(loadStep_, lambda),
                                  *dfdpTpetra->getVectorNonConst(0));
  }
}

void ContactMechanicsModel::setLoadStep(int step) {
  if (step < 0 || step >= schedule_.numSteps())
    throw std::logic_error("ContactMechanicsModel: load step " + std::to_string(step) + " of " +
                           std::to_string(schedule_.numSteps()));
  loadStep_ = step;
  conditions_->setLoadStep(schedule_, step);
  contact_->setLoadStep(schedule_, step);
  // λ now means the new step's load factor: no earlier pass serves an evaluation or the reactions.
  passServesEvaluations_ = false;
  passServesReactions_ = false;
}

void ContactMechanicsModel::commitState() {
  solids_->commit();
  contact_->commit();
  // The history the pass started from has changed: a new request recomputes. The forces of the
  // pass are those of the converged state, which the reactions report.
  passServesEvaluations_ = false;
}

bool ContactMechanicsModel::augmentContact(const AugmentationPoint& at) {
  if (!contact_->augment(lastLoadFactor_, at)) return false;
  // The multipliers changed: the next request evaluates the contact again.
  passServesEvaluations_ = false;
  passServesReactions_ = false;
  return true;
}

bool ContactMechanicsModel::hasAugmentedContact() const {
  for (const auto& spec : problem_.contacts)
    if (spec.law.isAugmented()) return true;
  return false;
}

void ContactMechanicsModel::rollbackState() {
  solids_->rollback();
  contact_->rollback();
  passServesEvaluations_ = false;
  passServesReactions_ = false;
}

namespace {
// The elements' internal variables, one table per state size (each row one element's committed state).
std::string elementTableName(std::size_t values) { return "with_" + std::to_string(values) + "_values"; }
}  // namespace

void ContactMechanicsModel::saveCommittedState(StateRecord& state) const {
  const auto& elements = solids_->elements();
  std::map<std::size_t, std::vector<std::size_t>> bySize;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const std::size_t n = solids_->committedState(i).size();
    if (n > 0) bySize[n].push_back(i);  // elements without internal variables keep nothing
  }
  auto& group = state.child("elements");
  for (const auto& [n, indices] : bySize) {
    StateTableWriter rows(group.child(elementTableName(n)));
    for (const std::size_t i : indices) {
      rows.beginRow(elements[i]);
      rows("state", solids_->committedState(i));
    }
    rows.finish();
  }
  contact_->saveState(state.child("contact"), comm_->getRank() == 0);
}

void ContactMechanicsModel::restoreCommittedState(const StateRecord& state) {
  const auto& group = state.child("elements");
  std::map<std::string, StateTableReader> tables;
  std::vector<double> values;
  for (const auto& [name, table] : group.children()) {
    auto& rows = tables.emplace(name, StateTableReader(table)).first->second;
    for (std::size_t row = 0; row < rows.rows(); ++row) {  // every row checked, on every rank
      rows.seekRow(row);
      rows("state", values);
    }
  }
  const auto& elements = solids_->elements();
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const std::size_t n = solids_->committedState(i).size();
    if (n == 0) continue;
    const std::string what = "element " + std::to_string(elements[i] + 1);
    const auto table = tables.find(elementTableName(n));
    if (table == tables.end()) group.fail(elementTableName(n), "missing (" + what + " has " + std::to_string(n) + " state values)");
    table->second.seek(elements[i], what);
    table->second("state", values);
    solids_->restoreState(i, values);
  }
  contact_->restore(state.child("contact"));
  passServesEvaluations_ = false;
  passServesReactions_ = false;
}

std::string ContactMechanicsModel::inadmissibleElement() const {
  // The lowest failed element id over all ranks, then its status from the rank that holds it.
  const long long none = std::numeric_limits<long long>::max();
  const long long local = lastElementStatus_.ok() ? none : lastElementStatus_.element;
  long long element = none;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, 1, &local, &element);
  if (element == none) return "";
  // Its block from the rank whose part holds it (the part's elements are numbered block by block).
  int localCode = 0, localBlock = -1, code = 0, blockIndex = -1;
  if (local == element) {
    localCode = static_cast<int>(lastElementStatus_.status);
    const auto& globalElements = problem_.mesh.part.globalElements;
    const auto at = static_cast<GlobalIndex>(std::find(globalElements.begin(), globalElements.end(), element) -
                                             globalElements.begin());
    GlobalIndex end = 0;
    for (const auto& b : problem_.mesh.local().blocks) {
      ++localBlock;
      end += b.numElements();
      if (at < end) break;
    }
  }
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, 1, &localCode, &code);
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, 1, &localBlock, &blockIndex);
  const std::string block = problem_.blocks[static_cast<std::size_t>(blockIndex)].block;
  // Element numbers are Exodus ids (1-based), as in the output file.
  const std::string which = "element " + std::to_string(element + 1) + " of block '" + block + "'";
  switch (static_cast<mechanics::ElementStatus>(code)) {
    case mechanics::ElementStatus::InadmissibleDeformation:
      return which + " is inverted or degenerate (det F <= 0)";
    case mechanics::ElementStatus::InternalSolveFailed:
      return "the enhanced-strain solve of " + which + " failed";
    default:
      return which + " could not be evaluated";
  }
}

std::string ContactMechanicsModel::contactTunnelling() const { return contact_->tunnelling(); }

std::string ContactMechanicsModel::describeFreeMotion(const std::vector<std::vector<double>>& nullSpace) const {
  // A diagnostic of a failed run: rank 0 gathers the whole mesh (the null space is over all DOFs on
  // every rank already) and tells every rank the sentence.
  // (On one rank the part is the whole mesh, numbered as the whole.)
  if (comm_->getSize() == 1) return model::describeFreeMotion(problem_.mesh.local(), nullSpace);
  const mesh::Mesh whole = mesh::gatherMeshOnRoot(problem_.mesh);
  std::string text = comm_->getRank() == 0 ? model::describeFreeMotion(whole, nullSpace) : std::string();
  int length = static_cast<int>(text.size());
  Teuchos::broadcast(*comm_, 0, &length);
  text.resize(static_cast<std::size_t>(length));
  if (length > 0) Teuchos::broadcast(*comm_, 0, length, text.data());
  return text;
}

bool ContactMechanicsModel::hasContact() const { return !contact_->empty(); }
RCP<MultiVector> ContactMechanicsModel::contactNodalFields() const { return results_->contactNodalFields(); }
contact::ContactCounts ContactMechanicsModel::contactCounts() const { return results_->contactCounts(); }
std::vector<std::pair<std::string, std::vector<double>>> ContactMechanicsModel::contactForces() const {
  return results_->contactForces();
}

std::vector<std::pair<std::string, contact::RegularisationMeasures>> ContactMechanicsModel::contactRegularisation(
    const Vector& x) const {
  return results_->contactRegularisation(x);
}

std::vector<continuation::SlaveNodeIncrement> ContactMechanicsModel::trialIncrement() const {
  return results_->trialIncrement();
}

std::vector<continuation::SlaveNodeIncrement> ContactMechanicsModel::committedIncrement() const {
  return results_->committedIncrement();
}

std::vector<continuation::SlaveNodeIncrement> ContactMechanicsModel::trialIncrementAt(const Vector& x,
                                                                                      double loadFactor) const {
  const auto u = overlapped(x);
  return results_->incrementAt(u.getRawPtr(), schedule_.amplitude(loadStep_, loadFactor));
}

std::vector<continuation::SlaveNodeIncrement> ContactMechanicsModel::trialIncrementAt(const Thyra::VectorBase<double>& x,
                                                                                      double loadFactor) const {
  return trialIncrementAt(*Extract::getConstTpetraVector(Teuchos::rcpFromRef(x)), loadFactor);
}

void ContactMechanicsModel::freezeNewContacts(bool frozen) { contact_->setNewContactsFrozen(frozen); }
bool ContactMechanicsModel::newContactsFrozen() const { return contact_->newContactsFrozen(); }

RCP<MultiVector> ContactMechanicsModel::elementStresses(const Vector& x) const {
  const auto u = overlapped(x);
  return results_->elementStresses(u.getRawPtr());
}

RCP<Vector> ContactMechanicsModel::loadsOnSets(const Vector& x, double loadFactor) const {
  const double a = schedule_.amplitude(loadStep_, loadFactor);
  const auto u = overlapped(x);
  Vector start(layout_->overlapMap()), change(layout_->overlapMap()), follower(layout_->overlapMap()),
      dFollower(layout_->overlapMap());
  const ExternalLoads& loads = conditions_->loads();
  loads.addDeadLoads(start.getDataNonConst(0).getRawPtr(), false);
  loads.addDeadLoads(change.getDataNonConst(0).getRawPtr(), true);
  // The follower pressures enter the residual as −f_p: their external force is −(that).
  loads.assembleFollowerLoads(u.getRawPtr(), a, 1.0, follower.getDataNonConst(0).getRawPtr(),
                              dFollower.getDataNonConst(0).getRawPtr(), nullptr);
  start.update(a, change, -1.0, follower, 1.0);
  auto owned = rcp(new Vector(layout_->ownedMap()));
  owned->doExport(start, layout_->exporter(), Tpetra::ADD);
  return owned;
}

std::vector<NodeSetReaction> ContactMechanicsModel::reactions(const Vector& x, double loadFactor) const {
  timers::Scope scope(timers::Phase::Reactions);
  // Σ (f_int + contact − f_ext): the converged residual before its Dirichlet rows, which the last
  // Newton pass has just computed. Another state needs a pass of its own (leaving the trial state alone).
  Vector fint(layout_->ownedMap());
  if (latestPassIsAt(x, loadFactor, passServesReactions_)) {
    fint.assign(*passForce_);
  } else {
    Vector dForcedLambda(layout_->ownedMap());
    assemble(x, loadFactor, false, false, fint, dForcedLambda);
    passServesEvaluations_ = false;  // the element pass moved the trial internal variables
    passServesReactions_ = false;
  }
  conditions_->subtractExternalForce(schedule_.amplitude(loadStep_, loadFactor), fint);
  return results_->reactions(fint);
}

}  // namespace contessa::model
