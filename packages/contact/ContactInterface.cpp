#include "contact/ContactInterface.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/Error.hpp"
#include "contact/BoundingBoxTree.hpp"
#include "contact/FacetSelector.hpp"
#include "contact/HistoryTransfer.hpp"
#include "contact/MasterSurface.hpp"
#include "contact/NodeToFacetContact.hpp"
#include "contact/NormalToggleDamping.hpp"
#include <cstdlib>
#include "contact/SlipReversalDamping.hpp"
#include "contact/SweptCrossing.hpp"
#include "contact/SmoothedMaster.hpp"
#include "contact/ValleyBlend.hpp"

namespace contessa::contact {

namespace {
constexpr double kTouchingGap = 1e-10;  // as continuation::BetaOptions::touchingGap
/// The most a secant step of a sticking node's multiplier may stretch Uzawa's (stickSecantFactor).
constexpr double kMaxStickSecantFactor = 1000.0;

/// ‖t_T‖/ε_T of an element result (RegularisationMeasures), ‖t_T‖ = √(t_α ā^αβ t_β) of eq. (19). With the
/// augmented Lagrangian the stick spring is stretched by t_T − λ_T only (eq. 15.2), and only while sticking.
template <class Facet>
double elasticSlipOf(const NodeToFacetResult<Facet>& r, const ContactHistory<Facet::kSurfaceDim>& committed,
                     bool augmented) {
  if (r.status == ContactStatus::Open) return 0.0;
  if (augmented && r.status != ContactStatus::Stick) return 0.0;
  const auto t = augmented ? subtract(r.trial.tangentialTraction, committed.tangentialMultiplier) : r.tangentialTraction;
  return contact::elasticSlipOf(std::sqrt(dot(t, multiply(r.projection.inverseMetric, t))), r.friction.tangentialPenalty);
}

/// The largest distance between two nodes of a facet: the segment's length, the face's longer diagonal
/// (or edge): the size the global search enlarges boxes by.
template <class Facet>
double facetSize(const MasterFacetNodes<Facet>& m) {
  double size = 0;
  for (int a = 0; a < Facet::kNodes; ++a)
    for (int b = a + 1; b < Facet::kNodes; ++b) size = std::max(size, norm(subtract(m.x[b], m.x[a])));
  return size;
}
}  // namespace

ContactInterfaceBase::ContactInterfaceBase(ContactInterfaceSpec spec, std::vector<char> evaluatesSlave)
    : spec_(std::move(spec)),
      evaluatesSlave_(std::move(evaluatesSlave)),
      trialOutput_(spec_.slaveNodes.size()),
      committedOutput_(spec_.slaveNodes.size()),
      trialChanges_(spec_.slaveNodes.size()),
      committedIncrement_(spec_.slaveNodes.size()),
      trialForce_(spec_.dimension, 0.0),
      committedForce_(spec_.dimension, 0.0),
      deckNormalPenalty_(spec_.law.normalPenalty) {
  spec_.law.validate();
  if (spec_.slaveFacetLengths.size() != spec_.slaveNodes.size() || spec_.slaveAreas.size() != spec_.slaveNodes.size())
    throw std::logic_error("ContactInterface '" + spec_.label() + "': one area and facet length per slave node expected");
  for (auto& s : trialOutput_) s.gap = std::numeric_limits<double>::infinity();
  committedOutput_ = trialOutput_;
}

RegularisationMeasures ContactInterfaceBase::committedRegularisation() const {
  RegularisationMeasures m;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k]) continue;
    const SlaveNodeState& s = committedOutput_[k];
    if (s.status != ContactStatus::Open && std::isfinite(s.gap)) m.penetration = std::max(m.penetration, -s.gap);
    m.elasticSlip = std::max(m.elasticSlip, s.elasticSlip);
    m.slip = std::max(m.slip, s.slip);
    if (s.status == ContactStatus::Slip && !spec_.law.isFrictionless()) {
      m.slippingNodes += 1.0;
      m.slipSum += s.slip;
    }
  }
  return m;
}

void ContactInterfaceBase::readSlaveRows(const StateRecord& table, StateTableReader& rows,
                                         const std::function<void(std::size_t)>& read) const {
  const std::size_t n = spec_.slaveNodes.size();
  for (std::size_t row = 0; row < rows.rows(); ++row) {
    const std::int64_t id = rows.idAt(row);
    if (id < 0 || static_cast<std::size_t>(id) >= n)
      table.fail("id", "slave node " + std::to_string(id) + ", the interface has " + std::to_string(n));
    rows.seekRow(row);
    read(static_cast<std::size_t>(id));
  }
  for (std::size_t k = 0; k < n; ++k)
    if (evaluatesSlave()[k] && !rows.hasRow(static_cast<std::int64_t>(k)))
      table.fail("id", "no row for slave node " + std::to_string(k) + " of interface '" + spec_.label() + "'");
}

void ContactInterfaceBase::setPenaltyGrowth(double growth) {
  if (growth == growth_) return;
  growth_ = growth;
  spec_.law.normalPenalty = deckNormalPenalty_ * growth;
  lawChanged();
}

AugmentationViolation ContactInterfaceBase::trialViolation() const {
  AugmentationViolation v;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    const SlaveNodeState& s = trialOutput_[k];
    if (!evaluatesSlave_[k] || s.status == ContactStatus::Open) continue;
    const double length = spec_.slaveFacetLengths[k];
    // A node in contact at g_N > 0 (held there by λ_N) violates g_N t_N = 0 as a penetration does.
    if (std::isfinite(s.gap)) v.penetration = std::max(v.penetration, std::abs(s.gap) / length);
    v.elasticSlip = std::max(v.elasticSlip, s.elasticSlip / length);
  }
  return v;
}

std::vector<SlaveNodeChange> ContactInterfaceBase::owned(const std::vector<SlaveNodeChange>& all) const {
  std::vector<SlaveNodeChange> out;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k)
    if (evaluatesSlave_[k]) out.push_back(all[k]);
  return out;
}

/// One interface over master facets of type Facet: search → select → history transfer → element → scale
/// by the tributary area → scatter with DOF ids and ∂r/∂λ.
template <class Facet>
class ContactInterface final : public ContactInterfaceBase {
 public:
  static constexpr int kDim = Facet::kSpaceDim;
  static constexpr int kXi = Facet::kSurfaceDim;
  static constexpr int kDofs = NodeToFacetContact<Facet>::kDofs;
  using Point = typename Facet::Point;
  using Facets = std::vector<MasterFacetNodes<Facet>>;

  ContactInterface(ContactInterfaceSpec spec, std::vector<char> evaluatesSlave)
      : ContactInterfaceBase(std::move(spec), std::move(evaluatesSlave)),
        master_(spec_),
        element_(spec_.law),
        history_(spec_.slaveNodes.size()),
        damping_(spec_.slaveNodes.size()),
        toggleDamping_(spec_.slaveNodes.size()),
        lastSlave_(spec_.slaveNodes.size()) {}

  std::unique_ptr<ContactInterfaceBase> clone() const override { return std::make_unique<ContactInterface>(*this); }
  void setRigidMotion(const std::vector<double>& offset, const std::vector<double>& motion) override {
    master_.setMotion(offset, motion);
  }
  void setFrictionCoefficient(double mu) override {
    spec_.law.frictionCoefficient = mu;
    spec_.law.validate();
    element_ = NodeToFacetContact<Facet>(spec_.law);
  }
  void lawChanged() override { element_ = NodeToFacetContact<Facet>(spec_.law); }
  void evaluate(const NodePosition& position, double loadFactor, bool updateTrial, const Sink& sink) override;
  std::vector<SlaveNodeChange> changesAt(const NodePosition& position, double loadFactor) const override;
  std::vector<TunnellingNode> tunnellingNodes() const override;
  void commit() override;
  void rollback() override;
  void augment(bool atEquilibrium) override {
    // The secant reads the update's iterate as an equilibrium (t_T = F − K m): at an early update it would
    // pass the iterate's Newton error on with the gain K + ε_T (theory §15, "The secant reads equilibria").
    if (!spec_.law.isFrictionless() && atEquilibrium) accelerateStickMultipliers();
    history_.augment();
  }
  void measureTractionRates(double loadChange) override;
  void predictMultipliers(double loadChange) override;
  void setConsistentTangents(bool consistent) override { consistentTangents_ = consistent; }
  int secantTangentNodes() const override { return secantTangentNodes_; }
  void saveCommittedSlaves(StateRecord& table) const override;
  void restoreSlaves(const StateRecord& table) override;
  void saveCommittedMaster(StateRecord& table) const override;
  void restoreMaster(const StateRecord& table) override;

 private:
  Point slavePosition(const NodePosition& position, std::size_t k) const {
    Point x{};
    position(spec_.slaveNodes[k], x.data());
    return x;
  }
  /// The element of slave node k at `xs` on master facet `facet` against the committed history on it, at
  /// the point the selection chose (its projection, or a vertex or edge of the facet).
  NodeToFacetResult<Facet> evaluateElement(std::size_t k, const Point& xs, const MasterFacetNodes<Facet>& facet,
                                           const FacetSelection<Facet>& selection,
                                           const ContactHistory<kXi>& committed,
                                           SlipTangent tangent = SlipTangent::consistent()) const {
    NodeToFacetGeometry<Facet> geometry;
    geometry.slave = xs;
    geometry.master = facet.x;
    const double freeEdgeReach = selector_.options().freeEdgeTolerance * spec_.slaveFacetLengths[k];
    return element_.evaluate(geometry, facet.id, committed, spec_.slaveFacetLengths[k], tangent,
                             contactPointOf(selection, facet, freeEdgeReach), approachOf(k, facet.id, committed));
  }
  /// Where slave node k, open at the commit, was relative to master `facet` then: its gap at the commit and
  /// its committed position projected on the facet's committed position (CommittedApproach: the element
  /// puts its stick reference where it touched). Unknown before the first commit, for a node that had no
  /// master in reach, and for a node in contact at the commit (its history is the reference).
  CommittedApproach<kXi> approachOf(std::size_t k, int facet, const ContactHistory<kXi>& committed) const {
    const double gap = committedOutput_[k].gap;
    if (committed.isInContact() || !std::isfinite(gap) || committedSlave_.size() != spec_.slaveNodes.size() ||
        facet < 0 || facet >= static_cast<int>(committedMaster_.size()))
      return {};
    const auto p = Projection<Facet>().project(committedSlave_[k], committedMaster_[facet].x);
    if (!p.converged) return {};
    return CommittedApproach<kXi>::at(gap, p.xi);
  }
  /// The global search's tree: master facet boxes enlarged by the largest facet, so a slave node finds every
  /// facet it could project on, and its neighbours (edges, corners).
  static BoundingBoxTree<kDim> searchTree(const Facets& facets) {
    double reach = 0;
    for (const auto& m : facets) reach = std::max(reach, facetSize(m));
    std::vector<BoundingBox<kDim>> boxes(facets.size());
    for (std::size_t s = 0; s < facets.size(); ++s) {
      for (const auto& x : facets[s].x) boxes[s].include(x);
      boxes[s].enlarge(reach);
    }
    return BoundingBoxTree<kDim>(std::move(boxes));
  }
  /// Slave node k at `xs` among the facets whose boxes hold it (`hits`, `candidates`: reused storage).
  FacetSelection<Facet> select(std::size_t k, const Point& xs, const Facets& facets, const BoundingBoxTree<kDim>& tree,
                               std::vector<int>& hits, Facets& candidates) const {
    hits.clear();
    tree.query(xs, hits);
    candidates.clear();
    for (int h : hits) candidates.push_back(facets[h]);
    return selector_.select(xs, candidates, spec_.slaveFacetLengths[k], heldGap(k));
  }
  /// The gap below which the contact law holds slave node k in contact (the selector's free-edge rule): 0
  /// for the penalty law (eq. 6); with the augmented Lagrangian −λ_N/ε_N ≥ 0, where λ_N + ε_N g_N < 0
  /// (eq. 15.1): a node that a multiplier update has lifted out of penetration is still in contact.
  double heldGap(std::size_t k) const {
    if (!spec_.law.isAugmented()) return 0.0;
    return -history_.committed(k).normalMultiplier / spec_.law.normalPenalty;
  }
  /// The selection's contact point in the facet's local node numbers; on the facet, the force fades over
  /// `freeEdgeReach` past a free boundary (ContactPoint).
  static ContactPoint contactPointOf(const FacetSelection<Facet>& selection, const MasterFacetNodes<Facet>& facet,
                                     double freeEdgeReach) {
    const auto local = [&](int node) {
      for (int a = 0; a < Facet::kNodes; ++a)
        if (facet.nodes[a] == node) return a;
      throw std::logic_error("ContactInterface: the selected vertex or edge is not on the selected facet");
    };
    const double side = selection.gap < 0.0 ? -1.0 : 1.0;
    switch (selection.kind) {
      case SelectionKind::AtVertex: return ContactPoint::vertex(local(selection.vertexNode), side);
      case SelectionKind::AtEdge: return ContactPoint::edge(local(selection.edgeNodes[0]), local(selection.edgeNodes[1]), side);
      default: return ContactPoint::projection(freeEdgeReach);
    }
  }
  /// Scales the element by the tributary area of slave node k and hands it to the sink; returns the
  /// scaled residual (its first kDim entries are minus the force on the slave node).
  Vector<kDofs> scatter(std::size_t k, int facet, const NodeToFacetResult<Facet>& r, const Sink& sink) const;
  /// A slave node within the band around a valley edge: the element blended over the two facets sharing it
  /// (ValleyBlend.hpp), which replaces the selection's contact; nullopt elsewhere. With friction (penalty
  /// enforcement) its tangential part lives in the chart of facet a, the selected one, against `committed`,
  /// the node's committed history on it.
  struct Blend {
    ValleyEdge edge;
    ValleyBlendResult<Facet> result;
  };
  std::optional<Blend> valleyBlend(std::size_t k, const Point& xs, const FacetSelection<Facet>& selection,
                                   const Facets& candidates, const ContactHistory<kXi>& committed) const {
    if constexpr (!kValleyBlendable<Facet>) {
      return std::nullopt;
    } else {
      if (!blendable_ || selection.kind == SelectionKind::None) return std::nullopt;
      const bool frictional = !spec_.law.isFrictionless();
      if (frictional && spec_.law.isAugmented()) return std::nullopt;  // the blend's friction: penalty only
      for (std::size_t c = 0; c < candidates.size(); ++c) {
        if (candidates[c].id != selection.facet) continue;
        const auto edge = findValleyEdge<Facet>(xs, c, candidates, committedMaster_, spec_.slaveFacetLengths[k]);
        if (!edge) return std::nullopt;
        ValleyFriction<Facet> friction;
        if (frictional) {
          friction.law = &spec_.law;
          friction.committed = committed;
          friction.facetLength = spec_.slaveFacetLengths[k];
          friction.approach = chartApproachOf(k, candidates[edge->a].id, candidates[edge->b].id, *edge, committed);
        }
        Blend blend{*edge, evaluateValleyBlend<Facet>(PenaltyNormalLaw(spec_.law.normalPenalty), xs,
                                                      candidates[edge->a], candidates[edge->b], *edge, friction)};
        if (blend.result.numBlocks == 0) return std::nullopt;
        // The facets' positions in the surface, for their DOF ids.
        blend.edge.a = static_cast<std::size_t>(candidates[edge->a].id);
        blend.edge.b = static_cast<std::size_t>(candidates[edge->b].id);
        return blend;
      }
      return std::nullopt;
    }
  }
  /// approachOf for a blended node: its committed position over the committed facets a and b, in a's chart.
  CommittedApproach<kXi> chartApproachOf(std::size_t k, int a, int b, const ValleyEdge& edge,
                                         const ContactHistory<kXi>& committed) const {
    const double gap = committedOutput_[k].gap;
    if (committed.isInContact() || !std::isfinite(gap) || committedSlave_.size() != spec_.slaveNodes.size() ||
        a < 0 || b < 0 || a >= static_cast<int>(committedMaster_.size()) || b >= static_cast<int>(committedMaster_.size()))
      return {};
    if constexpr (kValleyBlendable<Facet>) {
      const auto xi = valleyChartPoint<Facet>(committedSlave_[k], committedMaster_[a], committedMaster_[b], edge);
      if (xi) return CommittedApproach<kXi>::at(gap, *xi);
    }
    return {};
  }
  /// The node's state from the blend: its gap, status and normal traction; with friction its tangential
  /// state and trial history in facet a's chart (ValleyFriction).
  static void applyBlend(const Blend& blend, double& gap, NodeToFacetResult<Facet>& r,
                         const ContactHistory<kXi>& committed) {
    const auto& b = blend.result;
    gap = b.gap;
    r.gap = b.gap;
    r.status = b.isActive() ? b.status : ContactStatus::Open;
    r.normalTraction = b.isActive() ? b.normalTraction : 0.0;
    if (b.isActive() && b.frictional) {
      r.projection.xi = b.chartXi;
      r.projection.metric = b.chartMetric;
      r.projection.inverseMetric = inverse(b.chartMetric);
      r.friction = b.friction;
      r.tangentialTraction = b.traction;
      r.trial = b.trial;
    }
    if (r.status == ContactStatus::Open) {  // as the element leaves an open node: no traction, no new slip
      r.tangentialTraction = {};
      r.trial.tangentialTraction = {};
      r.trial.accumulatedSlip = committed.accumulatedSlip;
    }
    r.trial.status = r.status;
  }
  /// scatter for a blended element (its DOFs: the slave node's, then the two facets' distinct nodes').
  std::vector<double> scatterBlend(std::size_t k, const Blend& blend, const Sink& sink) const;
  /// Slave node k against its commit: `result` is its contact evaluation with `committed` (its committed
  /// history on the evaluated facet), or null when it was not evaluated (no master, or frozen).
  SlaveNodeChange changeOf(std::size_t k, double gap, const NodeToFacetResult<Facet>* result,
                           const ContactHistory<kXi>& committed) const;
  /// The committed history of slave node k, re-expressed on master `facet` when it was kept on another
  /// (committed coordinates, so it stays constant within the increment).
  ContactHistory<kXi> committedHistoryOn(std::size_t k, int facet) const;
  /// Slave node k with nothing changed since the commit.
  SlaveNodeChange unchanged(std::size_t k) const;
  /// Augmented Lagrangian with friction, at a commit: the trial history of each node that sticks and was in
  /// contact at the last commit gets that commit's stick reference ξ_n (with g_T there) and multiplier λ_T
  /// back, on the facet it now touches (eq. 15.4 of docs/theory-contact.md).
  void keepStickReferences();
  /// Augmented Lagrangian with friction, at an update: the trial multiplier λ_T of each node that sticks on the
  /// facet of its last update in the increment goes the secant's step (stickSecantFactor) instead of Uzawa's.
  void accelerateStickMultipliers();
  /// Forgets the increment's updates (a commit, a cut-back, a restart).
  void forgetStickUpdates() { stickUpdates_.clear(); }

  MasterSurface<Facet> master_;
  NodeToFacetContact<Facet> element_;
  FacetSelector<Facet> selector_;
  ContactHistoryStore<kXi> history_;
  SlipReversalDamping damping_;  ///< tangent of nodes whose slip direction flips between iterates
  NormalToggleDamping toggleDamping_;  ///< tangent of augmented nodes that cycle between open and closed
  bool consistentTangents_ = false;  ///< the damping's secants left out of the tangent (setConsistentTangents)
  int secantTangentNodes_ = 0;       ///< nodes the latest trial evaluation gave (or would give) a secant
  Facets committedMaster_;       ///< master positions of the committed configuration
  Facets lastFacets_;            ///< master positions of the latest trial evaluation
  std::vector<Point> committedSlave_;  ///< slave positions of the committed configuration
  std::vector<Point> lastSlave_;       ///< slave positions of the latest trial evaluation
  /// Per slave node, the augmented Lagrangian's updates in the increment: the last one of a node that stuck
  /// on facet `stickFacets_[k]` (−1: none), and ā^αβ of its latest trial evaluation.
  std::vector<StickUpdate<kXi>> stickUpdates_;
  std::vector<int> stickFacets_;
  std::vector<Matrix<kXi, kXi>> trialInverseMetric_;
  std::vector<double> trialStickPenalty_;  ///< ε_T of a sticking node's latest trial evaluation (0: not sticking)
  /// Per slave node, the multiplier predictor's rates over the last converged increment (eq. 15.8): state of
  /// the committed configuration, in the restart file.
  std::vector<TractionRate<kXi>> rates_ = std::vector<TractionRate<kXi>>(spec_.slaveNodes.size());
  /// Frictionless or penalty enforced at set-up: the matrix graph then holds the couplings across master
  /// edges that a valley blend needs (model::ContactAssembly), so only such an interface blends.
  const bool blendable_ = spec_.law.isFrictionless() || !spec_.law.isAugmented();
};

template <class Facet>
void ContactInterface<Facet>::evaluate(const NodePosition& position, double loadFactor, bool updateTrial,
                                       const Sink& sink) {
  const Facets facets = master_.facets(position, loadFactor);
  if (committedMaster_.empty()) committedMaster_ = facets;
  const BoundingBoxTree<kDim> tree = searchTree(facets);

  std::vector<double> force(kDim, 0.0);
  std::vector<int> hits;
  Facets candidates;
  if (updateTrial) secantTangentNodes_ = 0;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k]) continue;
    const Point xs = slavePosition(position, k);
    if (updateTrial) lastSlave_[k] = xs;
    const FacetSelection<Facet> selection = select(k, xs, facets, tree, hits, candidates);

    SlaveNodeState out;
    out.gap = selection.kind == SelectionKind::None ? std::numeric_limits<double>::infinity() : selection.gap;
    ContactHistory<kXi> trial = history_.committed(k);
    SlaveNodeChange change = changeOf(k, out.gap, nullptr, trial);
    // Frozen: nodes open at the commit carry no force — except nodes already touching (zero gap),
    // which close at once in any step and shape how their neighbours approach.
    const bool frozenOpen =
        frozen_ && !history_.committed(k).isInContact() && !(committedOutput_[k].gap <= kTouchingGap);
    if (selection.kind != SelectionKind::None && !frozenOpen) {
      // The history is kept on the facet the node projected on at the last commit; near a valley edge the
      // blend replaces the element. Newton iterates (updateTrial): a node whose slip direction has just
      // reversed gets a secant tangential stiffness (SlipReversalDamping; not in the blend, nor with
      // consistent tangents), an augmented node that cycles between open and closed a secant normal stiffness
      // while open (NormalToggleDamping); the residual is the same either way.
      const auto& facet = facets[selection.facet];
      const ContactHistory<kXi> committed = committedHistoryOn(k, selection.facet);
      NodeToFacetResult<Facet> r = evaluateElement(k, xs, facet, selection, committed);
      const std::optional<Blend> blend = valleyBlend(k, xs, selection, candidates, committed);
      if (blend) applyBlend(*blend, out.gap, r, committed);
      bool openSecant = false;  // an open node whose tangent holds the normal secant (NormalToggleDamping)
      if (updateTrial) {
        damping_.observe(k, history_.trial(k), r.trial);
        SlipTangent tangent = damping_.tangent(k);
        if (spec_.law.isAugmented()) {
          const ContactHistory<kXi>& previous = history_.trial(k);
          const bool open = r.status == ContactStatus::Open;
          toggleDamping_.observe(k, previous.status == ContactStatus::Open, open, out.gap, r.normalTraction,
                                 previous == r.trial, committed.normalMultiplier);
          if (open) tangent.normalStiffness = toggleDamping_.stiffness(k);
        }
        if (tangent.damped() && !blend) {
          ++secantTangentNodes_;
          if (!consistentTangents_) r = evaluateElement(k, xs, facet, selection, committed, tangent);
          openSecant = !consistentTangents_ && r.status == ContactStatus::Open && tangent.normalStiffness > 0.0;
        }
      }
      trial = r.trial;
      change = changeOf(k, out.gap, &r, committed);
      out.status = r.status;
      out.pressure = r.status == ContactStatus::Open ? 0.0 : -r.normalTraction;
      out.elasticSlip = elasticSlipOf(r, committed, spec_.law.isAugmented());
      if (updateTrial && spec_.law.isAugmented()) {
        trialInverseMetric_.resize(spec_.slaveNodes.size());
        trialStickPenalty_.resize(spec_.slaveNodes.size());
        trialInverseMetric_[k] = r.projection.inverseMetric;
        trialStickPenalty_[k] = r.status == ContactStatus::Stick ? r.friction.tangentialPenalty : 0.0;
      }
      // An open node with a normal secant (NormalToggleDamping) adds its tangent only (its residual is 0).
      if (r.status != ContactStatus::Open || openSecant) {
        if (blend) {
          const std::vector<double> residual = scatterBlend(k, *blend, sink);
          for (int c = 0; c < kDim; ++c) force[c] -= residual[c];
        } else {
          const Vector<kDofs> residual = scatter(k, selection.facet, r, sink);
          for (int c = 0; c < kDim; ++c) force[c] -= residual[c];
        }
      }
    } else {
      trial.status = ContactStatus::Open;
      trial.normalMultiplier = 0.0;  // no master or frozen: no traction for the next multiplier update
      trial.tangentialMultiplier = {};
    }
    out.slip = trial.accumulatedSlip;
    if (updateTrial) {
      history_.setTrial(k, trial);
      trialOutput_[k] = out;
      trialChanges_[k] = change;
    }
  }
  if (updateTrial) {
    trialForce_ = force;
    lastFacets_ = facets;
    if (committedSlave_.empty()) committedSlave_ = lastSlave_;
  }
}

template <class Facet>
auto ContactInterface<Facet>::scatter(std::size_t k, int facet,
                                                                          const NodeToFacetResult<Facet>& r,
                                                                          const Sink& sink) const -> Vector<kDofs> {
  // t_N and t_T are tractions (eq. 14–16): the nodal force is the traction times the slave node's
  // tributary area (length in 2D), so ε_N does not depend on the mesh size.
  const double area = spec_.slaveAreas[k];
  Vector<kDofs> residual{};
  std::array<double, kDofs * kDofs> tangent{};
  Vector<kDofs> dLambda{};
  for (int i = 0; i < kDofs; ++i) residual[i] = area * r.residual[i];
  for (int i = 0; i < kDofs; ++i)
    for (int j = 0; j < kDofs; ++j) tangent[i * kDofs + j] = area * r.tangent(i, j);
  std::array<GlobalIndex, kDofs> dofs{};
  const GlobalIndex node = spec_.slaveNodes[k];
  for (int c = 0; c < kDim; ++c) dofs[c] = kDim * node + c;
  const auto masterDofs = master_.dofs(facet);
  for (int j = 0; j < MasterSurface<Facet>::kFacetDofs; ++j) dofs[kDim + j] = masterDofs[j];
  // x_master = X + λ · motion for a rigid master: ∂r_c/∂λ = Σ_master K[:, master] · ∂x_master/∂λ.
  const auto dx = master_.dPositiondLambda(facet);
  for (int i = 0; i < kDofs; ++i)
    for (int j = 0; j < MasterSurface<Facet>::kFacetDofs; ++j) dLambda[i] += tangent[i * kDofs + kDim + j] * dx[j];
  sink(dofs.data(), kDofs, residual.data(), tangent.data(), dLambda.data());
  return residual;
}

template <class Facet>
std::vector<double> ContactInterface<Facet>::scatterBlend(std::size_t k, const Blend& blend, const Sink& sink) const {
  const auto& r = blend.result;
  const int n = r.numDofs();
  const double area = spec_.slaveAreas[k];
  std::vector<double> residual(n), tangent(static_cast<std::size_t>(n) * n), dLambda(n, 0.0), dx(n, 0.0);
  std::vector<GlobalIndex> dofs(n);
  const GlobalIndex node = spec_.slaveNodes[k];
  for (int c = 0; c < kDim; ++c) dofs[c] = kDim * node + c;
  const int facets[2] = {static_cast<int>(blend.edge.a), static_cast<int>(blend.edge.b)};
  for (int u = 1; u < r.numBlocks; ++u) {
    const auto [f, i] = r.source[u];
    const auto masterDofs = master_.dofs(facets[f]);
    const auto motion = master_.dPositiondLambda(facets[f]);
    for (int c = 0; c < kDim; ++c) {
      dofs[u * kDim + c] = masterDofs[i * kDim + c];
      dx[u * kDim + c] = motion[i * kDim + c];
    }
  }
  for (int i = 0; i < n; ++i) residual[i] = area * r.residual[i];
  for (std::size_t i = 0; i < tangent.size(); ++i) tangent[i] = area * r.tangent[i];
  // x_master = X + λ · motion for a rigid master: ∂r_c/∂λ = Σ_master K[:, master] · ∂x_master/∂λ.
  for (int i = 0; i < n; ++i)
    for (int j = kDim; j < n; ++j) dLambda[i] += tangent[static_cast<std::size_t>(i) * n + j] * dx[j];
  sink(dofs.data(), n, residual.data(), tangent.data(), dLambda.data());
  return residual;
}

template <class Facet>
std::vector<TunnellingNode> ContactInterface<Facet>::tunnellingNodes() const {
  std::vector<TunnellingNode> out;
  if (lastFacets_.empty() || committedSlave_.empty() || committedMaster_.size() != lastFacets_.size()) return out;
  // Swept boxes: each facet's box over both states, a hair larger so touching counts.
  double largest = 0;
  for (const auto& m : lastFacets_) largest = std::max(largest, facetSize(m));
  const double margin = 1e-9 * largest;
  std::vector<BoundingBox<kDim>> boxes(lastFacets_.size());
  for (std::size_t s = 0; s < lastFacets_.size(); ++s) {
    for (int a = 0; a < Facet::kNodes; ++a) {
      boxes[s].include(committedMaster_[s].x[a]);
      boxes[s].include(lastFacets_[s].x[a]);
    }
    boxes[s].enlarge(margin);
  }
  const BoundingBoxTree<kDim> tree(std::move(boxes));
  std::vector<int> hits;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    // In contact now (g_N ≤ 0 on the selected facet): penalty penetration, not tunnelling.
    if (!evaluatesSlave_[k] || !(trialOutput_[k].gap > 0.0)) continue;
    // A node in contact at the commit starts from its contact point on the master: its penalty
    // penetration there is not a crossing.
    Point start = committedSlave_[k];
    const auto& committed = history_.committed(k);
    if (committed.isInContact() && committed.segment >= 0 &&
        committed.segment < static_cast<int>(committedMaster_.size()))
      start = Projection<Facet>::evaluateAt(start, committedMaster_[committed.segment].x, committed.xi).position;
    const Point& end = lastSlave_[k];
    BoundingBox<kDim> path;
    path.include(start);
    path.include(end);
    hits.clear();
    tree.queryBox(path, hits);
    for (int s : hits) {
      const SweptCrossing crossing = sweptCrossing<Facet>(start, end, committedMaster_[s].x, lastFacets_[s].x);
      if (!crossing.crossed) continue;
      out.push_back({k, spec_.slaveNodes[k], s, crossing.time});
      break;
    }
  }
  return out;
}

template <class Facet>
SlaveNodeChange ContactInterface<Facet>::changeOf(std::size_t k, double gap, const NodeToFacetResult<Facet>* result,
                                                  const ContactHistory<kXi>& committed) const {
  SlaveNodeChange c = unchanged(k);
  c.trialGap = gap;
  c.trialStatus = result != nullptr ? result->status : ContactStatus::Open;
  c.trialFacet = result != nullptr ? result->trial.segment : -1;
  if (result != nullptr) {
    c.trialContactKind = result->pastFreeEdge ? 3 : static_cast<int>(result->point.kind);
    c.trialContactNodes[0] = result->point.nodes[0];
    c.trialContactNodes[1] = result->point.nodes[1];
  }
  const double mu = spec_.law.frictionCoefficient;
  if (result == nullptr || mu == 0.0 || !committed.isInContact() || result->status == ContactStatus::Open) return c;
  // Coulomb indicators (eq. 19, 21) in the facet's metric: ‖t‖² = t_α ā^αβ t_β; the committed traction is
  // "driven the other way" when its scalar product with the trial traction, t_α ā^αβ t^trial_β, is < 0.
  const auto& friction = result->friction;
  const auto& inverseMetric = result->projection.inverseMetric;
  double committedSquare = 0.0, along = 0.0;
  for (int a = 0; a < kXi; ++a)
    for (int b = 0; b < kXi; ++b) {
      committedSquare += committed.tangentialTraction[a] * inverseMetric(a, b) * committed.tangentialTraction[b];
      along += committed.tangentialTraction[a] * inverseMetric(a, b) * friction.trialTraction[b];
    }
  const double committedNorm = std::sqrt(committedSquare);
  const bool opposite = along < 0.0;
  c.committedIndicator = (opposite ? -committedNorm : committedNorm) - mu * committedOutput_[k].pressure;
  c.trialIndicator = friction.trialIndicator;
  c.slipReversed = opposite && committed.status == ContactStatus::Slip && result->status == ContactStatus::Slip;
  return c;
}

template <class Facet>
auto ContactInterface<Facet>::committedHistoryOn(std::size_t k, int facet) const -> ContactHistory<kXi> {
  const ContactHistory<kXi>& committed = history_.committed(k);
  if (!committed.isInContact() || committed.segment == facet || committed.segment < 0) return committed;
  ContactHistory<kXi> moved = transferHistory<Facet>(committed, committedMaster_[committed.segment], committedMaster_[facet]);
  if (spec_.law.isAugmented()) {
    // λ_T is a covariant traction on the committed facet like t_T,n: carried over the same way.
    ContactHistory<kXi> multiplier = committed;
    multiplier.tangentialTraction = committed.tangentialMultiplier;
    moved.tangentialMultiplier =
        transferHistory<Facet>(multiplier, committedMaster_[committed.segment], committedMaster_[facet]).tangentialTraction;
    moved.normalMultiplier = committed.normalMultiplier;
  }
  return moved;
}

template <class Facet>
SlaveNodeChange ContactInterface<Facet>::unchanged(std::size_t k) const {
  SlaveNodeChange c;
  c.committedGap = c.trialGap = committedOutput_[k].gap;
  c.committedStatus = c.trialStatus = history_.committed(k).status;
  c.frictional = !spec_.law.isFrictionless();
  return c;
}

template <class Facet>
std::vector<SlaveNodeChange> ContactInterface<Facet>::changesAt(const NodePosition& position, double loadFactor) const {
  // The run-time search (evaluate): the candidates of the tree, not every facet, O((n + m) log m).
  const Facets facets = master_.facets(position, loadFactor);
  const BoundingBoxTree<kDim> tree = searchTree(facets);
  std::vector<int> hits;
  Facets candidates;
  std::vector<SlaveNodeChange> out;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k]) continue;
    const Point xs = slavePosition(position, k);
    const FacetSelection<Facet> selection = select(k, xs, facets, tree, hits, candidates);
    if (selection.kind == SelectionKind::None) {
      out.push_back(changeOf(k, std::numeric_limits<double>::infinity(), nullptr, history_.committed(k)));
      continue;
    }
    const ContactHistory<kXi> committed = committedHistoryOn(k, selection.facet);
    NodeToFacetResult<Facet> r = evaluateElement(k, xs, facets[selection.facet], selection, committed);
    double gap = selection.gap;
    if (const auto blend = valleyBlend(k, xs, selection, candidates, committed)) applyBlend(*blend, gap, r, committed);
    out.push_back(changeOf(k, gap, &r, committed));
  }
  return out;
}

template <class Facet>
void ContactInterface<Facet>::commit() {
  ContactCounts counts;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k]) continue;
    const auto status = history_.trial(k).status;
    if (status == ContactStatus::Open) continue;
    ++counts.active;
    if (!history_.committed(k).isInContact()) ++counts.newlyActive;
    // Without friction a closed node is neither sticking nor slipping (the element marks it Slip only
    // because t_T ≡ 0): it counts as active alone, stick = slip = 0 (issue 25, point 4).
    if (spec_.law.isFrictionless()) continue;
    if (status == ContactStatus::Stick) ++counts.stick;
    if (status == ContactStatus::Slip) ++counts.slip;
  }
  if (spec_.law.isAugmented() && !spec_.law.isFrictionless()) keepStickReferences();
  history_.commit();
  forgetStickUpdates();
  commitPenaltyGrowth();
  damping_.reset();
  toggleDamping_.reset();
  committedIncrement_ = trialChanges_;
  committedOutput_ = trialOutput_;
  committedForce_ = trialForce_;
  committedCounts_ = counts;
  if (!lastFacets_.empty()) {
    committedMaster_ = lastFacets_;
    committedSlave_ = lastSlave_;
  }
  for (std::size_t k = 0; k < trialChanges_.size(); ++k) trialChanges_[k] = unchanged(k);
}

template <class Facet>
void ContactInterface<Facet>::accelerateStickMultipliers() {
  const std::size_t n = spec_.slaveNodes.size();
  if (stickUpdates_.size() != n) {
    stickUpdates_.assign(n, {});
    stickFacets_.assign(n, -1);
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (!evaluatesSlave_[k]) continue;
    ContactHistory<kXi> trial = history_.trial(k);
    const ContactHistory<kXi>& committed = history_.committed(k);
    // λ_T and t_T on one facet: the node sticks where its multiplier lives.
    if (trial.status != ContactStatus::Stick || trial.segment != committed.segment || trial.segment < 0) {
      stickFacets_[k] = -1;
      continue;
    }
    const double penalty = trialStickPenalty_[k];
    if (!(penalty > 0.0)) {
      stickFacets_[k] = -1;
      continue;
    }
    const Vector<kXi> stretch = subtract(trial.tangentialMultiplier, committed.tangentialMultiplier);
    const StickUpdate<kXi> now{trial.tangentialMultiplier, scaled(1.0 / penalty, stretch)};
    // The secant's regularisation length n of eq. (15.7): the motion the updates are to resolve, Elastic Slip
    // Tolerance x L_k. A tenth of it (the Newton error an early update may read) left the Tet10 press-slide
    // audit 7.6e-7 apart between mm and m (its bound 1e-8); tol x L: within it, but half or twice that not
    // (the audit's sensitivity to the update path, which today's main misses on this machine too: theory §15).
    const double noise = spec_.law.elasticSlipTolerance * spec_.slaveFacetLengths[k];
    const double factor =
        stickFacets_[k] == trial.segment
            ? stickSecantFactor(stickUpdates_[k], now, committed.tangentialMultiplier, penalty, trialInverseMetric_[k],
                                spec_.law.frictionCoefficient * std::abs(trial.normalMultiplier), noise,
                                kMaxStickSecantFactor)
            : 1.0;
    stickUpdates_[k] = now;
    stickFacets_[k] = trial.segment;
    if (factor == 1.0) continue;
    trial.tangentialMultiplier = add(committed.tangentialMultiplier, scaled(factor, stretch));
    history_.setTrial(k, trial);
  }
}

template <class Facet>
void ContactInterface<Facet>::measureTractionRates(double loadChange) {
  if (!spec_.law.isAugmented() || spec_.law.isFrictionless()) return;
  const bool step = std::isfinite(loadChange) && loadChange != 0.0;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k]) continue;
    const ContactHistory<kXi>& trial = history_.trial(k);
    const ContactHistory<kXi>& start = history_.committed(k);  // status and facet of the increment's start
    TractionRate<kXi>& rate = rates_[k];
    // Sticking at both commits on one facet: the tractions are on one chart and follow the structure. A node
    // that slips at either keeps the commit's multipliers: predicted, the contact edge's slipping nodes
    // changed which nodes close and lost Contact Beta's N_c (theory §15).
    rate.known = step && trial.status == ContactStatus::Stick && start.status == ContactStatus::Stick &&
                 trial.segment == start.segment;
    if (!rate.known) {
      rate = {};
      continue;
    }
    // The trial copy holds the converged tractions (t_N in normalMultiplier); the start's are its commit's.
    rate.normal = (trial.normalMultiplier + committedOutput_[k].pressure) / loadChange;
    rate.tangential = scaled(1.0 / loadChange, subtract(trial.tangentialTraction, start.tangentialTraction));
  }
}

template <class Facet>
void ContactInterface<Facet>::predictMultipliers(double loadChange) {
  if (!spec_.law.isAugmented() || !std::isfinite(loadChange)) return;
  const double mu = spec_.law.frictionCoefficient;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k] || !rates_[k].known) continue;
    const ContactHistory<kXi>& c = history_.committed(k);
    if (c.status != ContactStatus::Stick || c.segment < 0 || c.segment >= static_cast<int>(committedMaster_.size()))
      continue;
    // eq. (15.8): the tractions of the last commit extrapolated over the new load step, λ_N ≤ 0 and λ_T inside
    // the Coulomb cone μ|λ_N| (in the facet's metric at the node's stick reference).
    const bool fromTractions = std::getenv("I21T_PRED_TRACTIONS") != nullptr;
    const double normal = std::min(0.0, (fromTractions ? -committedOutput_[k].pressure : c.normalMultiplier) +
                                            loadChange * rates_[k].normal);
    Vector<kXi> tangential = add(fromTractions ? c.tangentialTraction : c.tangentialMultiplier,
                                 scaled(loadChange, rates_[k].tangential));
    const auto p = Projection<Facet>::evaluateAt(committedSlave_.empty() ? Point{} : committedSlave_[k],
                                                 committedMaster_[c.segment].x, c.xi);
    const double length = std::sqrt(dot(tangential, multiply(p.inverseMetric, tangential)));
    const double radius = mu * std::abs(normal);
    if (length > radius) tangential = scaled(length > 0.0 ? radius / length : 0.0, tangential);
    history_.predict(k, normal, tangential);
  }
}

template <class Facet>
void ContactInterface<Facet>::keepStickReferences() {
  // eq. (15.4): a sticking node's trial λ_T + ε_T ā_αβ (ξ̄ − ξ_n)^β has the same value at the converged state
  // whether the commit moves ξ_n to ξ̄ and λ_T to t_T (as for a slipping node) or keeps both. Kept, the
  // relative motion the Uzawa updates drive below Elastic Slip Tolerance is the node's whole motion since it
  // stuck, not the latest increment's, which added up over the increments (6.3e-4 mm = 2.5e-3 L after the
  // frictional patch test's 39 increments, its pressure 0.99721 … 1.00089 instead of uniform).
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k]) continue;
    const ContactHistory<kXi>& trial = history_.trial(k);
    if (trial.status != ContactStatus::Stick || !history_.committed(k).isInContact()) continue;
    // The commit's history as the element used it: on the facet the node now touches (committedHistoryOn).
    const ContactHistory<kXi> reference = committedHistoryOn(k, trial.segment);
    ContactHistory<kXi> kept = trial;
    kept.xi = reference.xi;
    kept.accumulatedSlip = reference.accumulatedSlip;
    kept.tangentialMultiplier = reference.tangentialMultiplier;
    history_.setTrial(k, kept);
  }
}

template <class Facet>
void ContactInterface<Facet>::rollback() {
  history_.rollback();
  forgetStickUpdates();
  rollbackPenaltyGrowth();
  damping_.reset();
  toggleDamping_.reset();
  trialOutput_ = committedOutput_;
  trialForce_ = committedForce_;
  for (std::size_t k = 0; k < trialChanges_.size(); ++k) trialChanges_[k] = unchanged(k);
}

// A slave node's fields in the restart file: its history, its change over the last increment, its output
// and its committed position (const parts when saving, copies to put back when loading).
template <class History, class Rate, class Change, class Output, class Position, class Fields>
void slaveNodeFields(History& h, Rate& rate, Change& c, Output& o, Position& x, Fields& field) {
  field("facet", h.segment);
  field("xi", h.xi);
  field("tangential_traction", h.tangentialTraction);
  field("status", h.status);
  field("slip", h.accumulatedSlip);
  field("normal_multiplier", h.normalMultiplier);  // augmented Lagrangian (0 with the penalty law)
  field("tangential_multiplier", h.tangentialMultiplier);
  field("traction_rate_known", rate.known);  // the multiplier predictor's (eq. 15.8)
  field("normal_traction_rate", rate.normal);
  field("tangential_traction_rate", rate.tangential);
  slaveChangeFields(c, field);
  field("trial_facet", c.trialFacet);
  slaveOutputFields(o, field);
  field("position", x);
}

template <class Facet, class Fields>
void masterFacetFields(Facet& m, Fields& field) {
  field("facet", m.id);
  field("nodes", m.nodes);
  field("x", m.x);
}

template <class Facet>
void ContactInterface<Facet>::saveCommittedSlaves(StateRecord& table) const {
  StateTableWriter rows(table);
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave()[k]) continue;
    rows.beginRow(static_cast<std::int64_t>(k));
    const Point x = committedSlave_.empty() ? Point{} : committedSlave_[k];
    slaveNodeFields(history_.committed(k), rates_[k], committedIncrement_[k], committedOutput_[k], x, rows);
  }
  rows.finish();
}

template <class Facet>
void ContactInterface<Facet>::restoreSlaves(const StateRecord& table) {
  StateTableReader rows(table);
  const std::size_t n = spec_.slaveNodes.size();
  forgetStickUpdates();
  readSlaveRows(table, rows, [&](std::size_t k) {
    ContactHistory<kXi> h;
    TractionRate<kXi> rate;
    SlaveNodeChange c;
    SlaveNodeState o;
    Point x{};
    slaveNodeFields(h, rate, c, o, x, rows);
    if (!evaluatesSlave()[k]) return;
    history_.restore(k, h);
    rates_[k] = rate;
    committedIncrement_[k] = c;
    committedOutput_[k] = o;
    if (committedSlave_.size() != n) committedSlave_.assign(n, Point{});
    committedSlave_[k] = x;
    lastSlave_[k] = x;
    trialOutput_[k] = o;
    trialChanges_[k] = unchanged(k);
  });
}

template <class Facet>
void ContactInterface<Facet>::saveCommittedMaster(StateRecord& table) const {
  StateTableWriter rows(table);
  for (std::size_t i = 0; i < committedMaster_.size(); ++i) {
    rows.beginRow(static_cast<std::int64_t>(i));
    masterFacetFields(committedMaster_[i], rows);
  }
  rows.finish();
}

template <class Facet>
void ContactInterface<Facet>::restoreMaster(const StateRecord& table) {
  StateTableReader rows(table);
  Facets facets(rows.rows());
  for (std::size_t i = 0; i < facets.size(); ++i) {
    rows.seek(static_cast<std::int64_t>(i), "master facet " + std::to_string(i));
    masterFacetFields(facets[i], rows);
  }
  committedMaster_ = facets;
  lastFacets_ = std::move(facets);
}

#define CONTESSA_INSTANTIATE_CONTACT_INTERFACE(F) template class ContactInterface<F>;
CONTESSA_FOR_EACH_FACET(CONTESSA_INSTANTIATE_CONTACT_INTERFACE)
#undef CONTESSA_INSTANTIATE_CONTACT_INTERFACE

std::unique_ptr<ContactInterfaceBase> makeContactInterface(ContactInterfaceSpec spec, std::vector<char> evaluatesSlave) {
  // The master facets' type (MasterFacet.hpp), from the space dimension and their node count.
  switch (spec.dimension * 100 + spec.nodesPerFacet()) {
    case 202: return std::make_unique<ContactInterface<Line2Facet>>(std::move(spec), std::move(evaluatesSlave));
    case 203: return std::make_unique<ContactInterface<Line3Facet>>(std::move(spec), std::move(evaluatesSlave));
    case 204: return std::make_unique<ContactInterface<HermiteLine4Facet>>(std::move(spec), std::move(evaluatesSlave));
    case 303: return std::make_unique<ContactInterface<Tri3Facet>>(std::move(spec), std::move(evaluatesSlave));
    case 304: return std::make_unique<ContactInterface<Quad4Facet>>(std::move(spec), std::move(evaluatesSlave));
    case 306: return std::make_unique<ContactInterface<Tri6Facet>>(std::move(spec), std::move(evaluatesSlave));
    case 308: return std::make_unique<ContactInterface<Quad8Facet>>(std::move(spec), std::move(evaluatesSlave));
    case 309: return std::make_unique<ContactInterface<Quad9Facet>>(std::move(spec), std::move(evaluatesSlave));
    default: break;
  }
  throw std::logic_error("makeContactInterface: interface '" + spec.label() + "' has no facet type of " +
                         std::to_string(spec.nodesPerFacet()) + " nodes in " + std::to_string(spec.dimension) + "D");
}

}  // namespace contessa::contact
