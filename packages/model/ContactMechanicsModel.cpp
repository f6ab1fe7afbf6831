#include "model/ContactMechanicsModel.hpp"

#include <algorithm>
#include <stdexcept>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

#include <Thyra_DefaultSpmdVectorSpace.hpp>
#include <Thyra_DetachedVectorView.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include "common/Error.hpp"
#include "common/PhaseTimers.hpp"
#include "model/FreeMotion.hpp"

namespace contessa::model {

using Teuchos::RCP;
using Teuchos::rcp;
using MEB = Thyra::ModelEvaluatorBase;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, LO, GO, Node>;


ContactMechanicsModel::ContactMechanicsModel(const RCP<const Comm>& comm, const deck::ProblemDefinition& problem,
                                             const mesh::Partition& partition,
                                             const RCP<Thyra::LinearOpWithSolveFactoryBase<double>>& solverFactory)
    : comm_(comm), problem_(problem), dim_(problem.mesh.dimension), solverFactory_(solverFactory) {
  buildMaps(partition);
  for (const auto& spec : problem_.contacts) {
    std::vector<char> evaluates(spec.slaveNodes.size());
    for (std::size_t k = 0; k < spec.slaveNodes.size(); ++k)
      evaluates[k] = partition.nodeOwner[spec.slaveNodes[k]] == comm_->getRank();
    contacts_.push_back(contact::makeContactInterface(spec, evaluates));
  }
  solids_ = std::make_unique<SolidAssembler>(problem_, partition.ownedElements(comm_->getRank()),
                                             [this](GlobalIndex dof) { return overlapMap_->getLocalElement(dof); });
  buildGraph();
  buildBoundaryConditions();

  xSpace_ = Thyra::createVectorSpace<double>(ownedMap_);
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

void ContactMechanicsModel::buildMaps(const mesh::Partition& partition) {
  const int rank = comm_->getRank();
  const auto owned = partition.ownedNodes(rank);
  auto overlap = partition.overlapNodes(problem_.mesh, rank);
  // Contact surfaces are replicated on every rank (DESIGN.md): their nodes join the overlap, so the
  // owner of a slave node sees its master segment wherever it slides.
  for (const auto& spec : problem_.contacts) {
    overlap.insert(overlap.end(), spec.slaveNodes.begin(), spec.slaveNodes.end());
    overlap.insert(overlap.end(), spec.masterFacets.begin(), spec.masterFacets.end());
  }
  std::sort(overlap.begin(), overlap.end());
  overlap.erase(std::unique(overlap.begin(), overlap.end()), overlap.end());
  std::vector<GO> ownedDofs, overlapDofs;
  for (GO n : owned)
    for (int c = 0; c < dim_; ++c) ownedDofs.push_back(n * dim_ + c);
  for (GO n : overlap)
    for (int c = 0; c < dim_; ++c) overlapDofs.push_back(n * dim_ + c);
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  ownedMap_ = rcp(new Map(invalid, Teuchos::ArrayView<const GO>(ownedDofs), 0, comm_));
  overlapMap_ = rcp(new Map(invalid, Teuchos::ArrayView<const GO>(overlapDofs), 0, comm_));
  const auto elements = partition.ownedElements(rank);
  std::vector<GO> elementIds(elements.begin(), elements.end());
  elementMap_ = rcp(new Map(invalid, Teuchos::ArrayView<const GO>(elementIds), 0, comm_));
  nodeMap_ = rcp(new Map(invalid, Teuchos::ArrayView<const GO>(std::vector<GO>(owned.begin(), owned.end())), 0, comm_));
  exporter_ = rcp(new Export(overlapMap_, ownedMap_));
  importer_ = rcp(new Import(ownedMap_, overlapMap_));
  overlapX_ = rcp(new Vector(overlapMap_));
  overlapForce_ = rcp(new Vector(overlapMap_));
  overlapDfdLambda_ = rcp(new Vector(overlapMap_));
}

void ContactMechanicsModel::buildGraph() {
  // Element couplings, gathered per overlapped row, inserted once; the owned graph receives them
  // through the exporter and is never rebuilt while the pairing stays the same.
  const LO numOverlap = static_cast<LO>(overlapMap_->getNodeNumElements());
  std::vector<std::vector<LO>> rows(numOverlap);
  std::vector<std::vector<int>> elementDofs;
  solids_->assemble(std::vector<double>(numOverlap, 0.0).data(), false,
                    [&](const int* dofs, int n, const double*, const double*) {
                      elementDofs.emplace_back(dofs, dofs + n);
                      for (int i = 0; i < n; ++i)
                        for (int j = 0; j < n; ++j) rows[dofs[i]].push_back(dofs[j]);
                    });
  // Contact couplings are reserved once, by the reach rule of contact::CouplingReservation: the whole
  // master surface for a small interface, else the master facets within reach of the slave node found by
  // a box search in the reference configuration, so the graph grows with the surface, not its square.
  // A rigid master has no unknowns: its slave nodes need only their own DOFs, which their elements hold.
  reservations_.clear();
  for (std::size_t i = 0; i < contacts_.size(); ++i) {
    const auto& spec = contacts_[i]->spec();
    const auto& evaluates = contacts_[i]->evaluatesSlave();
    reservations_.push_back(contact::reserveCouplings(spec, problem_.mesh.coordinates, evaluates));
    const auto& reservation = reservations_.back();
    if (spec.rigidMaster) continue;
    const auto dofsOf = [&](GO node, LO* out) {
      for (int c = 0; c < dim_; ++c) out[c] = overlapMap_->getLocalElement(node * dim_ + c);
    };
    // A master facet's own couplings exist in the global graph (its element), but this rank's
    // overlap rows of a master node owned elsewhere must hold them too, to receive contact terms.
    const std::size_t perFacet = spec.nodesPerFacet();
    LO a[3], b[3];
    for (std::size_t f = 0; f + perFacet <= spec.masterFacets.size(); f += perFacet)
      for (std::size_t ia = f; ia < f + perFacet; ++ia)
        for (std::size_t ib = f; ib < f + perFacet; ++ib) {
          dofsOf(spec.masterFacets[ia], a);
          dofsOf(spec.masterFacets[ib], b);
          for (int c = 0; c < dim_; ++c)
            for (int d = 0; d < dim_; ++d) rows[a[c]].push_back(b[d]);
        }
    for (std::size_t k = 0; k < spec.slaveNodes.size(); ++k) {
      if (!evaluates[k]) continue;
      dofsOf(spec.slaveNodes[k], a);
      for (const contact::GlobalIndex* m = reservation.begin(k); m != reservation.end(k); ++m) {
        dofsOf(*m, b);
        for (int c = 0; c < dim_; ++c)
          for (int d = 0; d < dim_; ++d) {
            rows[a[c]].push_back(b[d]);
            rows[b[d]].push_back(a[c]);
          }
      }
    }
  }
  std::size_t maxPerRow = 1;
  for (auto& r : rows) {
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
    maxPerRow = std::max(maxPerRow, r.size());
  }
  auto overlapGraph = rcp(new CrsGraph(overlapMap_, overlapMap_, maxPerRow));
  for (LO i = 0; i < numOverlap; ++i)
    if (!rows[i].empty()) overlapGraph->insertLocalIndices(i, Teuchos::ArrayView<const LO>(rows[i]));
  overlapGraph->fillComplete(ownedMap_, ownedMap_);
  // Rows shared between ranks receive entries from each: the sum of the contributions bounds a row.
  Vector overlapCounts(overlapMap_), ownedCounts(ownedMap_);
  {
    auto c = overlapCounts.getDataNonConst(0);
    for (LO i = 0; i < numOverlap; ++i) c[i] = static_cast<double>(rows[i].size());
  }
  ownedCounts.doExport(overlapCounts, *exporter_, Tpetra::ADD);
  std::vector<std::size_t> perRow;
  for (double c : ownedCounts.getData(0)) perRow.push_back(std::max<std::size_t>(1, static_cast<std::size_t>(c)));
  auto ownedGraph = rcp(new CrsGraph(ownedMap_, Teuchos::ArrayView<const std::size_t>(perRow)));
  ownedGraph->doExport(*overlapGraph, *exporter_, Tpetra::INSERT);
  ownedGraph->fillComplete(ownedMap_, ownedMap_);
  ownedGraph_ = ownedGraph;
  // Where each element's stiffness goes in the Jacobian's values, once (the element loop visits the
  // elements in the same order at every pass).
  scatter_ = std::make_unique<StiffnessScatter>(ownedGraph_, overlapMap_, rows);
  for (const auto& dofs : elementDofs) scatter_->addElement(dofs.data(), static_cast<int>(dofs.size()));
  passX_ = rcp(new Vector(ownedMap_));
  passForce_ = rcp(new Vector(ownedMap_));
  passDfdLambda_ = rcp(new Vector(ownedMap_));
}

void ContactMechanicsModel::buildBoundaryConditions() {
  const mesh::Mesh& mesh = problem_.mesh;
  // Dirichlet: one value per DOF; the same DOF prescribed twice with different values is an input error.
  std::map<GO, std::pair<double, std::string>> prescribed;
  for (const auto& bc : problem_.dirichlet) {
    for (GO node : mesh.nodeSet(bc.nodeSet).nodes) {
      const GO dof = node * dim_ + bc.component;
      auto [it, inserted] = prescribed.emplace(dof, std::make_pair(bc.value, bc.name));
      requireInput(inserted || it->second.first == bc.value,
                   "Problem/Dirichlet Conditions/" + bc.name + ": prescribes node " + std::to_string(node) +
                       " differently from '" + it->second.second + "'");
    }
  }
  isPrescribedOverlap_.assign(overlapMap_->getNodeNumElements(), 0);
  for (const auto& [dof, value] : prescribed) {
    const LO lo = ownedMap_->getLocalElement(dof);
    if (lo != Teuchos::OrdinalTraits<LO>::invalid()) {
      prescribedRows_.push_back(lo);
      prescribedValues_.push_back(value.first);
    }
    const LO lov = overlapMap_->getLocalElement(dof);
    if (lov != Teuchos::OrdinalTraits<LO>::invalid()) isPrescribedOverlap_[lov] = 1;
  }
  // Nodal forces: shared equally by the set's nodes; only the owner adds a node's share.
  externalForce_ = rcp(new Vector(ownedMap_));
  auto f = externalForce_->getDataNonConst(0);
  for (const auto& force : problem_.nodalForces) {
    const auto& nodes = mesh.nodeSet(force.nodeSet).nodes;
    for (GO node : nodes) {
      const LO lo = ownedMap_->getLocalElement(node * dim_ + force.component);
      if (lo != Teuchos::OrdinalTraits<LO>::invalid()) f[lo] += force.totalForce / static_cast<double>(nodes.size());
    }
  }
}

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
  RCP<Operator> op = rcp(new CrsMatrix(ownedGraph_));
  return Thyra::createLinearOp<double, LO, GO, Node>(op, xSpace_, xSpace_);
}

RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> ContactMechanicsModel::get_W_factory() const {
  return solverFactory_;
}

SolidAssembler::Status ContactMechanicsModel::assemble(const Vector& x, double lambda, bool withStiffness,
                                                       bool updateTrial, Vector& force, Vector& dForcedLambda) const {
  using timers::Phase;
  // A pass that leaves the trial state alone is the reactions' own element loop.
  const auto phase = [&](Phase p) { return updateTrial ? p : Phase::Reactions; };
  timers::Scope assemblyScope(phase(Phase::Assembly));
  overlapX_->doImport(x, *importer_, Tpetra::INSERT);
  auto u = overlapX_->getData(0);
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

  // Contact: each slave node's owner adds its node-to-segment element; rigid masters have no DOFs.
  std::optional<timers::Scope> contactScope(std::in_place, phase(Phase::Contact));
  const auto& X = problem_.mesh.coordinates;
  const auto position = [&](GlobalIndex node, double* p) {
    for (int c = 0; c < dim_; ++c) p[c] = X[node * dim_ + c] + u[overlapMap_->getLocalElement(node * dim_ + c)];
  };
  std::vector<LO> local;
  std::vector<int> entry;
  std::vector<double> block;
  // The first contact pairing (this rank) outside the couplings the graph reserved: (interface, slave node).
  const long long none = std::numeric_limits<long long>::max();
  const long long numNodes = problem_.mesh.numNodes();
  long long outsideReach = none;
  std::string missingCoupling;
  for (std::size_t i = 0; i < contacts_.size(); ++i) {
    const auto& reservation = reservations_[i];
    contacts_[i]->evaluate(position, lambda, updateTrial,
                       [&](const GlobalIndex* dofs, int n, const double* r, const double* k, const double* drdl) {
                         // The DOFs that are unknowns (not those of a rigid master), in local numbering.
                         local.clear();
                         entry.clear();
                         for (int j = 0; j < n; ++j)
                           if (dofs[j] >= 0) {
                             local.push_back(overlapMap_->getLocalElement(dofs[j]));
                             entry.push_back(j);
                           }
                         const int m = static_cast<int>(local.size());
                         for (int a = 0; a < m; ++a) {
                           fo[local[a]] += r[entry[a]];
                           dl[local[a]] += drdl[entry[a]];
                         }
                         if (!withStiffness) return;
                         // dofs: the slave node's, then the master facet's nodes'. A master node beyond the
                         // reserved reach has no place in the graph; it is agreed on below so that no rank
                         // leaves the pass while the others wait in its exports.
                         const GlobalIndex slave = dofs[0] / dim_;
                         const auto& slaves = contacts_[i]->spec().slaveNodes;
                         const std::size_t slaveIndex = static_cast<std::size_t>(
                             std::lower_bound(slaves.begin(), slaves.end(), slave) - slaves.begin());
                         for (int a = dim_; a < n; a += dim_)
                           if (dofs[a] >= 0 && !contact::isReserved(reservation, slaveIndex, dofs[a] / dim_)) {
                             outsideReach = std::min(outsideReach, static_cast<long long>(i) * numNodes + slave);
                             return;
                           }
                         block.resize(static_cast<std::size_t>(m) * m);
                         for (int a = 0; a < m; ++a)
                           for (int b = 0; b < m; ++b) block[a * m + b] = k[entry[a] * n + entry[b]];
                         try {  // inside the reservation the graph holds it; anything else is a defect
                           scatter_->addStiffness(local.data(), m, block.data());
                         } catch (const std::logic_error& e) {
                           if (missingCoupling.empty()) missingCoupling = e.what();
                         }
                       });
  }
  contactScope.reset();
  if (withStiffness) {
    int mine = missingCoupling.empty() ? 0 : 1, any = mine;
    if (comm_->getSize() > 1) Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, 1, &mine, &any);
    if (any != 0)
      throw std::logic_error(missingCoupling.empty()
                                 ? "StiffnessScatter: a contact coupling on another rank is not in the matrix graph"
                                 : missingCoupling);
    long long first = outsideReach;
    if (comm_->getSize() > 1) Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, 1, &outsideReach, &first);
    if (first != none) {
      // The graph is built once and the solver holds the Jacobian made on it: the evaluation fails on every
      // rank with the same words. The continuation cuts the step back (each attempt fails at its first
      // Jacobian, at once) and stops with this reason (exit 1); the user raises Search Reach.
      const std::size_t i = static_cast<std::size_t>(first / numNodes);
      const auto& spec = contacts_[i]->spec();
      std::ostringstream message;
      message << "contact interface '" << spec.name << "': slave node " << first % numNodes + 1
              << " met a master facet beyond the matrix graph's reach " << reservations_[i].reach
              << " (2 x largest master facet + Search Reach); raise Problem/Contact/" << spec.name
              << "/Search Reach to how far slave nodes slide on the master";
      throw std::runtime_error(message.str());
    }
  }
  fo = Teuchos::null;
  dl = Teuchos::null;
  force.putScalar(0.0);
  force.doExport(*overlapForce_, *exporter_, Tpetra::ADD);
  dForcedLambda.putScalar(0.0);
  dForcedLambda.doExport(*overlapDfdLambda_, *exporter_, Tpetra::ADD);
  return status;
}

void ContactMechanicsModel::evaluatePass(const Vector& x, double lambda, bool withStiffness) const {
  passStatus_ = assemble(x, lambda, withStiffness, true, *passForce_, *passDfdLambda_);
  passHasStiffness_ = withStiffness;
  passX_->assign(x);
  passLambda_ = lambda;
  passFrozen_ = newContactsFrozen_;
  passServesEvaluations_ = true;
  passServesReactions_ = true;
}

bool ContactMechanicsModel::latestPassIsAt(const Vector& x, double lambda, bool valid) const {
  int same = valid && lambda == passLambda_ && newContactsFrozen_ == passFrozen_ ? 1 : 0;
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
    // Free rows: f_int − λ f_ext (eq. of equilibrium); prescribed rows: u − λ ū.
    f->update(1.0, *passForce_, -lambda, *externalForce_, 0.0);
    auto fv = f->getDataNonConst(0);
    auto xv = x->getData(0);
    for (std::size_t k = 0; k < prescribedRows_.size(); ++k) {
      const LO r = prescribedRows_[k];
      fv[r] = xv[r] - lambda * prescribedValues_[k];
    }
    // An inadmissible element (inverted, failed internal solve) poisons the residual: NOX's
    // finite-value test then fails the solve and the continuation cuts the step back.
    if (!ok)
      for (auto& v : fv) v = std::numeric_limits<double>::quiet_NaN();
  }
  if (!W.is_null()) {
    // The stiffness of the pass, with the rows of other ranks added; prescribed rows become identity rows.
    timers::Scope scope(timers::Phase::Assembly);
    scatter_->copyTo(*W, prescribedRows_);
  }
  if (!dfdp.is_null()) {
    // ∂f/∂λ = ∂r_c/∂λ − f_ext on free rows (a rigid master moves with λ), −ū on prescribed rows.
    auto d = dfdpTpetra;
    d->putScalar(0.0);  // the caller's storage may hold anything, and 0·NaN is NaN
    d->getVectorNonConst(0)->update(-1.0, *externalForce_, 1.0, *passDfdLambda_, 1.0);
    auto dv = d->getDataNonConst(0);
    for (std::size_t k = 0; k < prescribedRows_.size(); ++k) dv[prescribedRows_[k]] = -prescribedValues_[k];
  }
}

void ContactMechanicsModel::commitState() {
  solids_->commit();
  for (auto& c : contacts_) c->commit();
  // The history the pass started from has changed: a new request recomputes. The forces of the
  // pass are those of the converged state, which the reactions report.
  passServesEvaluations_ = false;
}

void ContactMechanicsModel::rollbackState() {
  solids_->rollback();
  for (auto& c : contacts_) c->rollback();
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
  int localCode = local == element ? static_cast<int>(lastElementStatus_.status) : 0, code = 0;
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, 1, &localCode, &code);
  const std::string block = problem_.blocks[problem_.mesh.locate(element).block].block;
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

std::string ContactMechanicsModel::contactTunnelling() const {
  // The lowest (interface, node) over all ranks names the case; the count says how many there are.
  const long long none = std::numeric_limits<long long>::max();
  const long long numNodes = problem_.mesh.numNodes();
  long long local = none, first = none;
  int localCount = 0, count = 0;
  for (std::size_t i = 0; i < contacts_.size(); ++i) {
    const auto nodes = contacts_[i]->tunnellingNodes();
    localCount += static_cast<int>(nodes.size());
    for (const auto& t : nodes) local = std::min(local, static_cast<long long>(i) * numNodes + t.node);
  }
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, 1, &localCount, &count);
  if (count == 0) return "";
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MIN, 1, &local, &first);
  const auto& interface = contacts_[first / numNodes]->spec();
  // Node numbers are Exodus ids (1-based), as in the output file.
  return "slave node " + std::to_string(first % numNodes + 1) + " of interface '" + interface.label() + "'" +
         (count > 1 ? " (and " + std::to_string(count - 1) + " more)" : "") + " passed through the master surface";
}

std::string ContactMechanicsModel::describeFreeMotion(const std::vector<std::vector<double>>& nullSpace) const {
  return model::describeFreeMotion(problem_.mesh, nullSpace);
}

std::vector<std::string> ContactMechanicsModel::contactFieldNames() {
  return {"contact_pressure", "contact_gap", "contact_status", "contact_slip"};
}

RCP<MultiVector> ContactMechanicsModel::contactNodalFields() const {
  auto out = rcp(new MultiVector(nodeMap_, 4));
  for (const auto& interface : contacts_) {
    const auto& spec = interface->spec();
    const auto& states = interface->committedStates();
    for (std::size_t k = 0; k < spec.slaveNodes.size(); ++k) {
      if (!interface->evaluatesSlave()[k]) continue;
      const LO lo = nodeMap_->getLocalElement(spec.slaveNodes[k]);
      const auto& st = states[k];
      // A node on several slave surfaces shows its largest pressure.
      if (st.pressure < out->getData(0)[lo]) continue;
      out->replaceLocalValue(lo, 0, st.pressure);
      out->replaceLocalValue(lo, 1, std::isfinite(st.gap) ? st.gap : std::numeric_limits<double>::quiet_NaN());
      out->replaceLocalValue(lo, 2, static_cast<double>(static_cast<int>(st.status)));
      out->replaceLocalValue(lo, 3, st.slip);
    }
  }
  return out;
}

namespace {
// Every rank needs every slave node's change to sort the β^k of eq. (12): gather them all, as
// continuation::SlaveNodeIncrement (7 numbers each), in rank order.
std::vector<continuation::SlaveNodeIncrement> gatherAll(const Comm& comm, const std::vector<contact::SlaveNodeChange>& local) {
  constexpr int kFields = 8;
  std::vector<double> packed;
  for (const auto& c : local) {
    packed.insert(packed.end(), {c.committedGap, c.trialGap, static_cast<double>(static_cast<int>(c.committedStatus)),
                                 static_cast<double>(static_cast<int>(c.trialStatus)), c.committedIndicator,
                                 c.trialIndicator, c.slipReversed ? 1.0 : 0.0, static_cast<double>(c.trialFacet)});
  }
  const int size = comm.getSize();
  std::vector<int> counts(size), offsets(size + 1, 0);
  const int mine = static_cast<int>(packed.size());
  Teuchos::gatherAll(comm, 1, &mine, size, counts.data());
  for (int r = 0; r < size; ++r) offsets[r + 1] = offsets[r] + counts[r];
  std::vector<double> all(offsets[size]);
  // Teuchos has no gatherv: every rank contributes a zero-padded slice, summed.
  std::vector<double> slice(offsets[size], 0.0);
  std::copy(packed.begin(), packed.end(), slice.begin() + offsets[comm.getRank()]);
  if (!all.empty()) Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(all.size()), slice.data(), all.data());
  std::vector<continuation::SlaveNodeIncrement> out;
  for (std::size_t i = 0; i + kFields <= all.size(); i += kFields) {
    continuation::SlaveNodeIncrement n;
    n.committedGap = all[i];
    n.trialGap = all[i + 1];
    n.committedStatus = static_cast<continuation::NodeStatus>(static_cast<int>(all[i + 2]));
    n.trialStatus = static_cast<continuation::NodeStatus>(static_cast<int>(all[i + 3]));
    n.committedIndicator = all[i + 4];
    n.trialIndicator = all[i + 5];
    n.slipReversed = all[i + 6] != 0.0;
    n.trialFacet = static_cast<int>(all[i + 7]);
    out.push_back(n);
  }
  return out;
}
}  // namespace

std::vector<continuation::SlaveNodeIncrement> ContactMechanicsModel::trialIncrement() const {
  std::vector<contact::SlaveNodeChange> local;
  for (const auto& interface : contacts_) {
    const auto c = interface->trialChanges();
    local.insert(local.end(), c.begin(), c.end());
  }
  return gatherAll(*comm_, local);
}

std::vector<continuation::SlaveNodeIncrement> ContactMechanicsModel::committedIncrement() const {
  std::vector<contact::SlaveNodeChange> local;
  for (const auto& interface : contacts_) {
    const auto c = interface->committedIncrement();
    local.insert(local.end(), c.begin(), c.end());
  }
  return gatherAll(*comm_, local);
}

std::vector<continuation::SlaveNodeIncrement> ContactMechanicsModel::trialIncrementAt(const Vector& x, double loadFactor) const {
  overlapX_->doImport(x, *importer_, Tpetra::INSERT);
  auto u = overlapX_->getData(0);
  const auto& X = problem_.mesh.coordinates;
  const auto position = [&](GlobalIndex node, double* p) {
    for (int c = 0; c < dim_; ++c) p[c] = X[node * dim_ + c] + u[overlapMap_->getLocalElement(node * dim_ + c)];
  };
  std::vector<contact::SlaveNodeChange> local;
  for (const auto& interface : contacts_) {
    const auto c = interface->changesAt(position, loadFactor);
    local.insert(local.end(), c.begin(), c.end());
  }
  return gatherAll(*comm_, local);
}

contact::ContactCounts ContactMechanicsModel::contactCounts() const {
  int local[4] = {0, 0, 0, 0}, global[4] = {0, 0, 0, 0};
  for (const auto& interface : contacts_) {
    const auto c = interface->committedCounts();
    local[0] += c.active;
    local[1] += c.newlyActive;
    local[2] += c.stick;
    local[3] += c.slip;
  }
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, 4, local, global);
  return {global[0], global[1], global[2], global[3]};
}

std::vector<std::pair<std::string, std::vector<double>>> ContactMechanicsModel::contactForces() const {
  std::vector<std::pair<std::string, std::vector<double>>> out;
  for (const auto& spec : problem_.contacts) {
    if (out.empty() || out.back().first != spec.name) out.push_back({spec.name, std::vector<double>(dim_, 0.0)});
  }
  for (const auto& interface : contacts_) {
    const std::string& name = interface->spec().name;
    const auto& f = interface->committedSlaveForce();
    for (auto& [n, total] : out)
      if (n == name) {
        // The second pass pushes the other body: the force on the first slave body is its opposite.
        const double sign = interface->spec().secondPass ? -1.0 : 1.0;
        for (int c = 0; c < dim_; ++c) total[c] += sign * f[c];
      }
  }
  for (auto& [n, total] : out) {
    std::vector<double> g(dim_);
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, dim_, total.data(), g.data());
    total = g;
  }
  return out;
}

std::vector<std::string> ContactMechanicsModel::elementStressNames(int dimension) {
  if (dimension == 2) return {"stress_xx", "stress_yy", "stress_zz", "stress_xy", "von_mises"};
  return {"stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_xz", "von_mises"};
}

RCP<MultiVector> ContactMechanicsModel::elementStresses(const Vector& x) const {
  overlapX_->doImport(x, *importer_, Tpetra::INSERT);
  auto u = overlapX_->getData(0);
  const auto sigmas = solids_->elementStresses(u.getRawPtr());
  const auto names = elementStressNames(dim_);
  auto out = rcp(new MultiVector(elementMap_, names.size()));
  const std::vector<std::pair<int, int>> comps = dim_ == 2
      ? std::vector<std::pair<int, int>>{{0, 0}, {1, 1}, {2, 2}, {0, 1}}
      : std::vector<std::pair<int, int>>{{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {0, 2}};
  for (std::size_t c = 0; c < comps.size(); ++c) {
    auto col = out->getDataNonConst(c);
    for (std::size_t e = 0; e < sigmas.size(); ++e) col[e] = sigmas[e][mechanics::idx2(comps[c].first, comps[c].second)];
  }
  auto vm = out->getDataNonConst(comps.size());
  for (std::size_t e = 0; e < sigmas.size(); ++e) vm[e] = mechanics::vonMises(sigmas[e]);
  return out;
}

std::vector<NodeSetReaction> ContactMechanicsModel::reactions(const Vector& x, double loadFactor) const {
  timers::Scope scope(timers::Phase::Reactions);
  // Σ (f_int + contact − λ f_ext): the converged residual before its Dirichlet rows, which the last
  // Newton pass has just computed. Another state needs a pass of its own (leaving the trial state alone).
  Vector fint(ownedMap_);
  if (latestPassIsAt(x, loadFactor, passServesReactions_)) {
    fint.assign(*passForce_);
  } else {
    Vector dForcedLambda(ownedMap_);
    assemble(x, loadFactor, false, false, fint, dForcedLambda);
    passServesEvaluations_ = false;  // the element pass moved the trial internal variables
    passServesReactions_ = false;
  }
  fint.update(-loadFactor, *externalForce_, 1.0);
  auto fv = fint.getData(0);
  std::vector<NodeSetReaction> out;
  for (const auto& name : problem_.reactionNodeSets) {
    std::vector<double> local(dim_, 0.0), global(dim_, 0.0);
    for (GO node : problem_.mesh.nodeSet(name).nodes)
      for (int c = 0; c < dim_; ++c) {
        const LO lo = ownedMap_->getLocalElement(node * dim_ + c);
        if (lo != Teuchos::OrdinalTraits<LO>::invalid()) local[c] += fv[lo];
      }
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, dim_, local.data(), global.data());
    out.push_back({name, global});
  }
  return out;
}

}  // namespace contessa::model
