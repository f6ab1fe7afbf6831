#pragma once
// The boundary between physics and solvers (docs/design.md): a Thyra::ModelEvaluator over Tpetra with
// x = nodal displacements and one parameter, the load factor λ. It evaluates the residual
// f(x, λ) = f_int(x) + r_c(x, λ) − λ f_ext on free DOFs and x − λ ū on prescribed DOFs, the Jacobian
// W = ∂f/∂x and ∂f/∂λ. It composes parts with one job each and keeps only the evaluation bookkeeping:
//   DofLayout           maps, Import/Export, the graph (built at set-up; its contact part rebuilt when
//                       the contact leaves the couplings reserved for it)
//   SolidAssembler      continuum elements
//   ContactAssembly     contact interfaces, their reserved couplings and history
//   StiffnessScatter    element and contact blocks into the Jacobian's values, at precomputed positions
//   BoundaryConditions  Dirichlet rows and values, f_ext
//   PostProcessing      stresses, reactions, contact fields and forces, slave-node gathers
// The solvers see it through Thyra, IncrementalState (commit/rollback), continuation::ContactEventSource
// (Contact Beta) and SolveDiagnostics (why a solve failed, counters); this header names no contact type.
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Thyra_LinearOpWithSolveFactoryBase.hpp>
#include <Thyra_StateFuncModelEvaluatorBase.hpp>

#include "contact/ContactCounts.hpp"
#include "contact/RegularisationMeasures.hpp"
#include "continuation/ContactEventSource.hpp"
#include "deck/ProblemDefinition.hpp"
#include "io/RestartFile.hpp"
#include "model/ContactAugmentation.hpp"
#include "model/ForceScale.hpp"
#include "model/IncrementalState.hpp"
#include "model/LoadStepping.hpp"
#include "model/PostProcessing.hpp"
#include "model/SolveDiagnostics.hpp"
#include "model/SolidAssembler.hpp"
#include "model/TpetraTypes.hpp"

namespace contessa::model {

class DofLayout;
class ContactAssembly;
class BoundaryConditions;
class StiffnessScatter;

/// One rebuild of the matrix graph (ContactMechanicsModel::onGraphRebuild).
struct GraphRebuild {
  int count = 0;            ///< rebuilds so far in the run, this one included
  std::string reason;       ///< the pairing outside the old reservation, in words
  double seconds = 0;       ///< reservation, graph, scatter positions (the slowest rank)
  long long entries = 0;    ///< entries of the new graph (global)
};

class ContactMechanicsModel : public Thyra::StateFuncModelEvaluatorBase<double>,
                              public IncrementalState,
                              public LoadStepping,
                              public continuation::ContactEventSource,
                              public SolveDiagnostics,
                              public ContactAugmentation,
                              public ForceScale {
 public:
  /// The model of this rank's part of `problem`'s mesh (problem->mesh, made for `comm`'s rank and size;
  /// std::logic_error otherwise). The model shares the problem: the caller need not keep it alive.
  ContactMechanicsModel(const Teuchos::RCP<const Comm>& comm, std::shared_ptr<const deck::ProblemDefinition> problem,
                        const Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>>& solverFactory);
  ~ContactMechanicsModel() override;

  // Thyra::ModelEvaluator
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_x_space() const override;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_f_space() const override;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> get_p_space(int l) const override;
  Teuchos::RCP<const Teuchos::Array<std::string>> get_p_names(int l) const override;
  Thyra::ModelEvaluatorBase::InArgs<double> getNominalValues() const override;
  Thyra::ModelEvaluatorBase::InArgs<double> createInArgs() const override;
  Teuchos::RCP<Thyra::LinearOpBase<double>> create_W_op() const override;
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<double>> get_W_factory() const override;

  // IncrementalState: enhanced-strain parameters and contact history, committed after a converged
  // increment, rolled back when an increment is abandoned.
  void commitState() override;
  void rollbackState() override;
  // ContactAugmentation: the Uzawa update of the augmented-Lagrangian interfaces at a Newton iterate.
  bool augmentContact(const AugmentationPoint& at) override;
  bool hasAugmentedContact() const override;
  /// This rank's part of the committed state for a restart file: the states of its elements (group
  /// "elements", a table per state size), its contact slave nodes (group "contact"; rank 0 also the master
  /// positions). Rows keyed by global ids: any rank count reads them.
  void saveCommittedState(StateRecord& state) const;
  /// The committed (and trial) state from a restart file's state; InputError naming a field or row that
  /// is missing, of another shape or not finite (every rank checks every row alike).
  void restoreCommittedState(const StateRecord& state);
  /// Load factor of the latest evaluation (the one a failed increment was trying to reach).
  double lastLoadFactor() const override { return lastLoadFactor_; }

  // LoadStepping: λ is the current load step's own load factor (continuation::LoadSchedule).
  int numLoadSteps() const override { return schedule_.numSteps(); }
  void setLoadStep(int step) override;
  int loadStep() const override { return loadStep_; }
  const continuation::LoadSchedule& loadSchedule() const { return schedule_; }

  // Post-processing for output, at a converged state (PostProcessing).
  const Teuchos::RCP<const Map>& ownedDofMap() const;
  const Teuchos::RCP<const Map>& ownedElementMap() const;
  const Teuchos::RCP<const Map>& ownedNodeMap() const;
  /// Columns: σ_xx σ_yy σ_zz σ_xy [σ_yz σ_xz] von Mises, one row per owned element.
  Teuchos::RCP<MultiVector> elementStresses(const Vector& x) const;
  static std::vector<std::string> elementStressNames(int dimension, bool axisymmetric = false) {
    return PostProcessing::elementStressNames(dimension, axisymmetric);
  }
  std::vector<NodeSetReaction> reactions(const Vector& x, double loadFactor) const;
  /// Collective: the loads on sets (Problem/Loads: tractions, body forces, follower pressures on the
  /// deformed faces at `x`; not the nodal forces) at load factor λ of the current load step, as nodal
  /// forces on owned rows (the external force's part that the Applied Force history sums).
  Teuchos::RCP<Vector> loadsOnSets(const Vector& x, double loadFactor) const;

  // Contact results at the last committed state.
  bool hasContact() const override;
  /// Columns contact_pressure, contact_gap, contact_status, contact_slip per owned node (0 off the
  /// slave surfaces; gap NaN where no master segment is in reach).
  Teuchos::RCP<MultiVector> contactNodalFields() const;
  static std::vector<std::string> contactFieldNames() { return PostProcessing::contactFieldNames(); }
  /// Sums over all ranks and interfaces.
  contact::ContactCounts contactCounts() const;
  /// Force the master exerts on the slave body, per interface (both passes of a two-pass interface
  /// are summed under the interface name), summed over ranks: one component per space dimension.
  std::vector<std::pair<std::string, std::vector<double>>> contactForces() const;
  /// Per interface: the largest penetration, elastic slip and slip at the last commit, and the largest
  /// displacement magnitude of its slave nodes in `x` (PostProcessing::contactRegularisation), collective.
  std::vector<std::pair<std::string, contact::RegularisationMeasures>> contactRegularisation(const Vector& x) const;

  // continuation::ContactEventSource: every slave node (all ranks, all interfaces, the same order on
  // every rank) for Contact Beta.
  std::vector<continuation::SlaveNodeIncrement> trialIncrement() const override;
  std::vector<continuation::SlaveNodeIncrement> trialIncrementAt(const Thyra::VectorBase<double>& x,
                                                                 double loadFactor) const override;
  std::vector<continuation::SlaveNodeIncrement> trialIncrementAt(const Vector& x, double loadFactor) const;
  std::vector<continuation::SlaveNodeIncrement> committedIncrement() const override;
  void freezeNewContacts(bool frozen) override;
  bool newContactsFrozen() const override;

  // SolveDiagnostics: why a solve failed or must not be accepted, in words for the one-line stop message.
  // Collective: every rank calls them at the same point and gets the same text.
  std::string nonFiniteResidualCause() const override { return inadmissibleElement(); }
  /// The lowest-numbered element (over all ranks) whose evaluation failed at the latest residual
  /// evaluation — the reason the residual was set to NaN — e.g. "element 17 of block 'tube' is inverted
  /// or degenerate (det F <= 0)"; empty when every element was admissible.
  std::string inadmissibleElement() const;
  /// Slave nodes that passed through their master surface between the last commit and the latest
  /// evaluation and are not in contact now (ContactInterfaceBase::tunnellingNodes, every interface and
  /// rank), e.g. "slave node 41 of interface 'plate' (and 28 more) passed through the master surface";
  /// empty when none did.
  std::string contactTunnelling() const override;
  /// The null space of a singular Jacobian (vectors over all DOFs in global numbering, the same on every
  /// rank) in words: which blocks are free to move, and how (FreeMotion.hpp).
  std::string describeFreeMotion(const std::vector<std::vector<double>>& nullSpace) const override;

  /// Number of rebuilds of the matrix graph so far (a Jacobian evaluation met a contact pairing outside
  /// the reserved couplings) and their total time (the slowest rank's).
  int graphRebuilds() const { return graphRebuilds_; }
  double graphRebuildSeconds() const { return graphRebuildSeconds_; }
  /// Called on every rank after each rebuild (e.g. for a line in the log).
  void onGraphRebuild(std::function<void(const GraphRebuild&)> observer) { rebuildObserver_ = std::move(observer); }

  /// Number of Jacobian evaluations so far (each is followed by one linear solve in Newton).
  int jacobianEvaluations() const override { return jacobianEvaluations_; }
  // ForceScale: ‖f_int‖₂ of the latest evaluation pass (kept with the pass).
  double forceScale() const override { return passForceScale_; }
  double outOfBalanceNorm() const override { return lastOutOfBalance_; }
  double lengthScale() const override { return lengthScale_; }
  double forceRoundOff() const override { return lastRoundOff_; }
  /// Number of element passes (loops over the elements) so far: residual, Jacobian and reaction passes.
  int elementPasses() const { return elementPasses_; }
  int dimension() const { return dim_; }

  // For the finite-difference check of the Jacobian (JacobianCheck; ContactMechanicsModelProbes.cpp).
  /// Everything an evaluation changes: trial element and contact states, the latest pass, counters.
  struct EvaluationState;
  /// Taken before evaluations that must leave no trace, and put back after them.
  std::shared_ptr<const EvaluationState> saveEvaluationState() const;
  void restoreEvaluationState(const EvaluationState& state) const;
  /// The Jacobian W = ∂f/∂x at (x, λ) into `W`, every contact tangent the consistent one: Newton's W gives
  /// a slave node whose slip direction has just reversed a secant slip stiffness (SlipReversalDamping, not
  /// ∂f/∂x; the residual is the same). Collective; returns how many slave nodes (all ranks) Newton's W
  /// would give a secant at this evaluation. Evaluates afresh (no pass is served) and changes the trial
  /// state as an evaluation does.
  int consistentJacobian(const Thyra::VectorBase<double>& x, double lambda, Thyra::LinearOpBase<double>& W) const;
  /// While `held`, every contact slave node is evaluated on the master facet and at the contact point of the
  /// latest evaluation before the hold (ContactInterfaceBase::holdContactPoints): the branch W differentiates.
  /// No pass made before a change of the hold serves an evaluation after it.
  void holdContactPoints(bool held) const;
  /// Who couples two DOFs (global ids), in words: "element 12 of block 'tube'", "contact 'plate' slave
  /// node 41" (Exodus numbering), or both.
  std::string describeCoupling(GO rowDof, GO columnDof) const;

 private:
  Thyra::ModelEvaluatorBase::OutArgs<double> createOutArgsImpl() const override;
  void evalModelImpl(const Thyra::ModelEvaluatorBase::InArgs<double>& inArgs,
                     const Thyra::ModelEvaluatorBase::OutArgs<double>& outArgs) const override;

  /// The graph from the element couplings and the contact reservations, and the scatter positions.
  void buildGraph() const;
  /// The contact couplings reserved again around the overlapped displacement `u` (after a stiffness pass
  /// met a pairing outside them), the graph and the scatter built again; collective. A Jacobian on the old
  /// graph is re-pointed at a new matrix when it is next evaluated (evalModelImpl).
  void rebuildGraph(const double* u) const;
  /// One assembly pass at owned x and load factor λ: internal and contact forces and their ∂/∂λ,
  /// exported to owned rows, before boundary conditions; with `withStiffness`, the stiffness into
  /// scatter_. `updateTrial` stores the trial state. `internalForceNorm` (may be null): ‖f_int‖₂, the
  /// elements' forces alone, global. Returns the first element that failed, if any.
  SolidAssembler::Status assemble(const Vector& x, double lambda, bool withStiffness, bool updateTrial,
                                  Vector& force, Vector& dForcedLambda, double* internalForceNorm = nullptr) const;
  /// The pass every evaluation request is served from: residual, Jacobian and ∂f/∂λ at (x, λ).
  void evaluatePass(const Vector& x, double lambda, bool withStiffness) const;
  /// Whether the latest pass was made at exactly this x, λ and contact freeze, and `valid` still holds
  /// (agreed by every rank).
  bool latestPassIsAt(const Vector& x, double lambda, bool valid) const;
  /// x imported into the overlapped vector; its values.
  Teuchos::ArrayRCP<const double> overlapped(const Vector& x) const;

  Teuchos::RCP<const Comm> comm_;
  std::shared_ptr<const deck::ProblemDefinition> sharedProblem_;
  const deck::ProblemDefinition& problem_;  ///< *sharedProblem_
  // Each owned element's DOFs (overlapped local numbering, in the element loop's order), flattened: the
  // element part of the graph, kept for rebuilds (the element loop itself would move the trial state).
  std::vector<int> elementDofs_;
  std::vector<std::size_t> elementDofBegin_;
  int dim_;
  std::unique_ptr<DofLayout> layout_;  ///< its graph is replaced by a rebuild
  // The parts an evaluation changes (trial states, the scatter's values): Thyra evaluates through a
  // const method, so they are held by pointer and changed from it.
  std::unique_ptr<SolidAssembler> solids_;
  std::unique_ptr<ContactAssembly> contact_;
  mutable std::unique_ptr<StiffnessScatter> scatter_;  ///< made again by a rebuild
  std::unique_ptr<BoundaryConditions> conditions_;
  std::unique_ptr<PostProcessing> results_;
  Teuchos::RCP<const Map> paramMap_;
  Teuchos::RCP<Vector> overlapX_, overlapForce_, overlapDfdLambda_;
  Teuchos::RCP<Vector> overlapInternal_, internalForce_;  ///< f_int alone (overlapped, owned): the force scale
  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<double>> solverFactory_;
  Teuchos::RCP<const Thyra::VectorSpaceBase<double>> xSpace_, pSpace_;
  Thyra::ModelEvaluatorBase::InArgs<double> nominal_;
  // The latest evaluation pass: residual forces, ∂f/∂λ and (when asked for) the stiffness at one
  // (x, λ). A later request at the same point is served from it; at a converged increment it gives
  // the reactions (no second element loop for the output).
  Teuchos::RCP<Vector> passX_, passForce_, passDfdLambda_;  ///< owned; force = f_int + contact
  mutable double passLambda_ = 0;
  mutable double passForceScale_ = 0;  ///< ‖f_int‖₂ of the pass (ForceScale)
  mutable bool passFrozen_ = false, passHasStiffness_ = false;
  mutable SolidAssembler::Status passStatus_;
  mutable bool passServesEvaluations_ = false;  ///< until the state is committed or rolled back
  mutable bool passServesReactions_ = false;    ///< until the state is rolled back
  mutable int jacobianEvaluations_ = 0, elementPasses_ = 0, stiffnessPasses_ = 0;
  mutable bool contactFitsGraph_ = true;  ///< the latest stiffness pass found every contact pairing in the graph
  mutable int graphRebuilds_ = 0;
  mutable double graphRebuildSeconds_ = 0;
  std::function<void(const GraphRebuild&)> rebuildObserver_;
  mutable double lastLoadFactor_ = 0;
  mutable double lastOutOfBalance_ = 0;  ///< ‖f‖₂ over the free rows of the latest residual (ForceScale)
  double lengthScale_ = 0;  ///< max |X| of the reference coordinates over every rank (ForceScale)
  Teuchos::RCP<Vector> squaredRoundOff_;  ///< r² of every owned DOF, at the reference state (ForceRoundOff.hpp)
  mutable double lastRoundOff_ = 0;       ///< ‖r‖₂ over the free rows of the latest residual (ForceScale)
  /// X of each overlapped DOF (its node's reference coordinate in its component; 0 for DOFs of no node of
  /// this rank's part).
  std::vector<double> overlappedReferenceCoordinates() const;
  continuation::LoadSchedule schedule_;
  int loadStep_ = 0;
  mutable SolidAssembler::Status lastElementStatus_;  ///< of the latest residual evaluation, this rank
};

}  // namespace contessa::model
