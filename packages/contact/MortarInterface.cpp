#include "contact/MortarInterface.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "contact/BoundingBoxTree.hpp"
#include "contact/MasterSurface.hpp"
#include "contact/MortarSegment.hpp"

namespace contessa::contact {

namespace {
constexpr double kTouchingGap = 1e-10;  // as continuation::BetaOptions::touchingGap
constexpr int kDim = 2;
using Facets = std::vector<MasterFacetNodes<Line2Facet>>;

double segmentLength(const Vector<2>& a, const Vector<2>& b) { return norm(subtract(b, a)); }

/// The weighted gap of one slave node, g̃_k = Σ over its slave segments and the master segments they meet
/// (eq. M5), with, when asked, its gradient and Hessian over its support: the nodes it depends on.
struct NodeWeightedGap {
  bool overlaps = false;  ///< some master segment meets one of the node's slave segments
  double value = 0;       ///< g̃_k
  std::vector<GlobalIndex> nodes;  ///< the support: slave node k first, then the others (rigid points < 0)
  std::vector<GlobalIndex> dofs;   ///< kDim per support node; −1 for a rigid point's
  std::vector<double> dPositiondLambda;  ///< kDim per support node: a rigid point's motion, else 0
  std::vector<double> gradient;          ///< ∂g̃_k/∂x over the support's coordinates
  std::vector<double> hessian;           ///< ∂²g̃_k/∂x², row-major

  /// The support index of `node`, added (with its DOF ids and ∂x/∂λ) when new.
  int indexOf(GlobalIndex node, const GlobalIndex* nodeDofs, const double* motion) {
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (nodes[i] == node) return static_cast<int>(i);
    nodes.push_back(node);
    for (int c = 0; c < kDim; ++c) {
      dofs.push_back(nodeDofs[c]);
      dPositiondLambda.push_back(motion[c]);
    }
    return static_cast<int>(nodes.size()) - 1;
  }
  int size() const { return kDim * static_cast<int>(nodes.size()); }
};

}  // namespace

/// The mortar interface (2D segments): see MortarInterface.hpp.
class MortarInterface final : public ContactInterfaceBase {
 public:
  MortarInterface(ContactInterfaceSpec spec, std::vector<char> evaluatesSlave)
      : ContactInterfaceBase(std::move(spec), std::move(evaluatesSlave)), master_(spec_) {
    if (spec_.dimension != 2 || spec_.slaveFacets.size() != 2 * spec_.slaveSegmentLengths.size())
      throw std::logic_error("MortarInterface '" + spec_.label() + "': 2D slave segments with their lengths expected");
    segmentsAt_.resize(spec_.slaveNodes.size());
    for (std::size_t s = 0; s < spec_.slaveFacets.size() / 2; ++s)
      for (int a = 0; a < 2; ++a) segmentsAt_[slaveIndex(spec_.slaveFacets[2 * s + a])].push_back({s, a});
  }

  std::unique_ptr<ContactInterfaceBase> clone() const override { return std::make_unique<MortarInterface>(*this); }
  void setRigidMotion(const std::vector<double>& offset, const std::vector<double>& motion) override {
    master_.setMotion(offset, motion);
  }
  /// Frictionless for now: the deck refuses a load step's μ > 0 on a mortar interface (LoadStepDefinitions).
  void setFrictionCoefficient(double mu) override {
    if (mu != 0.0) throw std::logic_error("MortarInterface '" + spec_.label() + "': friction is not implemented");
  }
  void evaluate(const NodePosition& position, double loadFactor, bool updateTrial, const Sink& sink) override;
  std::vector<SlaveNodeChange> changesAt(const NodePosition& position, double loadFactor) const override;
  /// None: a mortar node's penetration is measured by its weighted gap, which sees a master segment
  /// wherever the slave segments meet it; the swept node-through-facet test is node-to-segment's
  /// (theory-contact §12).
  std::vector<TunnellingNode> tunnellingNodes() const override { return {}; }
  void commit() override;
  void rollback() override;
  void saveCommittedSlaves(StateRecord& table) const override;
  void restoreSlaves(const StateRecord& table) override;
  void saveCommittedMaster(StateRecord& table) const override { StateTableWriter(table).finish(); }
  void restoreMaster(const StateRecord& /*table*/) override {}

 private:
  struct SegmentEnd {
    std::size_t segment;
    int end;  ///< 0 or 1: which node of the segment the slave node is
  };
  std::size_t slaveIndex(GlobalIndex node) const {
    const auto& s = spec_.slaveNodes;
    const auto it = std::lower_bound(s.begin(), s.end(), node);
    if (it == s.end() || *it != node) throw std::logic_error("MortarInterface: a slave facet's node is not a slave node");
    return static_cast<std::size_t>(it - s.begin());
  }
  BoundingBoxTree<kDim> searchTree(const Facets& facets) const;
  NodeWeightedGap weightedGap(std::size_t k, const NodePosition& position, const Facets& facets,
                              const BoundingBoxTree<kDim>& tree, bool derivatives) const;
  /// The nodes of a slave segment's pairs: its two slave nodes, two master nodes (set per master facet),
  /// and the slave nodes beyond its ends (which enter the averaged nodal normals).
  struct PairNodes {
    std::array<GlobalIndex, kMortarPairCoordinates / kDim> nodes{};
    MortarSlaveNeighbours neighbours;
    double referenceLength = 0;
  };
  PairNodes pairNodes(std::size_t segment) const;
  void addPair(NodeWeightedGap& w, int end, const SegmentPairCoordinates<double>& x, const PairNodes& pair,
               int facet, bool derivatives) const;
  /// Node k's term: residual −p ∇g̃, tangent (ε/A) ∇g̃ ⊗ ∇g̃ − p ∇²g̃ (eq. M7–M8); adds the force on the
  /// slave nodes to `force`.
  void assemble(std::size_t k, const NodeWeightedGap& w, double pressure, const Sink& sink,
                std::vector<double>& force) const;
  SlaveNodeState stateOf(std::size_t k, const NodeWeightedGap& w, bool frozenOpen) const;
  SlaveNodeChange changeOf(std::size_t k, const SlaveNodeState& trial) const;
  SlaveNodeChange unchanged(std::size_t k) const {
    SlaveNodeChange c;
    c.committedGap = c.trialGap = committedOutput_[k].gap;
    c.committedStatus = c.trialStatus = committedOutput_[k].status;
    return c;
  }

  MasterSurface<Line2Facet> master_;
  std::vector<std::vector<SegmentEnd>> segmentsAt_;  ///< per slave node: its slave segments
};

MortarInterface::PairNodes MortarInterface::pairNodes(std::size_t segment) const {
  PairNodes pair;
  pair.referenceLength = spec_.slaveSegmentLengths[segment];
  for (int a = 0; a < 2; ++a) pair.nodes[a] = spec_.slaveFacets[2 * segment + a];
  // The neighbour segment at end a (a 2D slave surface has at most one): its other node, and whether it
  // runs into the pair's segment (σ = +1 at end 0: stored y → s_0; at end 1: s_1 → y) or against it.
  for (int a = 0; a < 2; ++a)
    for (const SegmentEnd& other : segmentsAt_[slaveIndex(pair.nodes[a])]) {
      if (other.segment == segment) continue;
      pair.nodes[4 + a] = spec_.slaveFacets[2 * other.segment + 1 - other.end];
      pair.neighbours.orientation[a] = (other.end == 1 - a) ? 1 : -1;
      break;
    }
  return pair;
}

BoundingBoxTree<kDim> MortarInterface::searchTree(const Facets& facets) const {
  // Master boxes enlarged by the largest master and slave segments: a slave segment's box then meets every
  // master segment the mortar integral can pair it with.
  double reach = 0;
  for (const auto& m : facets) reach = std::max(reach, segmentLength(m.x[0], m.x[1]));
  for (double h : spec_.slaveFacetLengths) reach = std::max(reach, h);
  std::vector<BoundingBox<kDim>> boxes(facets.size());
  for (std::size_t s = 0; s < facets.size(); ++s) {
    for (const auto& x : facets[s].x) boxes[s].include(x);
    boxes[s].enlarge(reach);
  }
  return BoundingBoxTree<kDim>(std::move(boxes));
}

void MortarInterface::addPair(NodeWeightedGap& w, int end, const SegmentPairCoordinates<double>& x,
                              const PairNodes& pair, int facet, bool derivatives) const {
  if (!derivatives) {
    const MortarPairGaps<double> g = segmentPairGaps(x, pair.referenceLength, pair.neighbours);
    w.overlaps = w.overlaps || g.overlaps;
    if (g.overlaps) w.value += g.weightedGap[end];
    return;
  }
  const MortarPairDerivatives g = segmentPairDerivatives(x, pair.referenceLength, pair.neighbours);
  if (!g.overlaps) return;
  w.overlaps = true;
  w.value += g.weightedGap[end];
  const auto masterDofs = master_.dofs(facet);
  const auto masterMotion = master_.dPositiondLambda(facet);
  constexpr int kPairNodes = kMortarPairCoordinates / kDim;
  std::array<int, kPairNodes> at{};
  for (int a = 0; a < kPairNodes; ++a) {
    const bool master = a == 2 || a == 3;
    if (!master && a >= 4 && pair.neighbours.orientation[a - 4] == 0) {
      at[a] = -1;  // no slave node beyond this end: its coordinates are unused
      continue;
    }
    const GlobalIndex slaveDofs[kDim] = {kDim * pair.nodes[a], kDim * pair.nodes[a] + 1};
    const double still[kDim] = {0.0, 0.0};
    at[a] = master ? w.indexOf(pair.nodes[a], &masterDofs[kDim * (a - 2)], &masterMotion[kDim * (a - 2)])
                   : w.indexOf(pair.nodes[a], slaveDofs, still);
  }
  const int n = w.size();
  w.gradient.resize(static_cast<std::size_t>(n), 0.0);
  // Grow the Hessian to the support's size, keeping the entries summed so far.
  std::vector<double> grown(static_cast<std::size_t>(n) * n, 0.0);
  const int old = static_cast<int>(std::lround(std::sqrt(static_cast<double>(w.hessian.size()))));
  for (int i = 0; i < old; ++i)
    for (int j = 0; j < old; ++j) grown[i * n + j] = w.hessian[i * old + j];
  w.hessian.swap(grown);
  constexpr int m = kMortarPairCoordinates;
  for (int i = 0; i < m; ++i) {
    if (at[i / kDim] < 0) continue;
    const int gi = kDim * at[i / kDim] + i % kDim;
    w.gradient[gi] += g.gradient[end][i];
    for (int j = 0; j < m; ++j)
      if (at[j / kDim] >= 0) w.hessian[gi * n + kDim * at[j / kDim] + j % kDim] += g.hessian[end][i * m + j];
  }
}

NodeWeightedGap MortarInterface::weightedGap(std::size_t k, const NodePosition& position, const Facets& facets,
                                             const BoundingBoxTree<kDim>& tree, bool derivatives) const {
  NodeWeightedGap w;
  if (derivatives) {  // slave node k first: the assembly reads the slave node from the first DOFs
    const GlobalIndex node = spec_.slaveNodes[k];
    const GlobalIndex dofs[kDim] = {kDim * node, kDim * node + 1};
    const double still[kDim] = {0.0, 0.0};
    w.indexOf(node, dofs, still);
    w.gradient.assign(kDim, 0.0);
    w.hessian.assign(kDim * kDim, 0.0);
  }
  std::vector<int> hits;
  for (const SegmentEnd& se : segmentsAt_[k]) {
    PairNodes pair = pairNodes(se.segment);
    SegmentPairCoordinates<double> x{};
    position(pair.nodes[0], &x[0]);
    position(pair.nodes[1], &x[2]);
    for (int a = 0; a < 2; ++a)
      if (pair.neighbours.orientation[a] != 0) position(pair.nodes[4 + a], &x[8 + 2 * a]);
    BoundingBox<kDim> box;
    box.include({x[0], x[1]});
    box.include({x[2], x[3]});
    hits.clear();
    tree.queryBox(box, hits);
    std::sort(hits.begin(), hits.end());  // the same summation order on every rank and every call
    for (int f : hits) {
      for (int a = 0; a < 2; ++a) {
        pair.nodes[2 + a] = facets[f].nodes[a];
        x[4 + 2 * a] = facets[f].x[a][0];
        x[5 + 2 * a] = facets[f].x[a][1];
      }
      addPair(w, se.end, x, pair, f, derivatives);
    }
  }
  return w;
}

SlaveNodeState MortarInterface::stateOf(std::size_t k, const NodeWeightedGap& w, bool frozenOpen) const {
  SlaveNodeState out;
  // The gap shown and counted: g̃_k / A_k, so that the pressure is −ε_N times it, as t_N = ε_N g_N (eq. 16).
  out.gap = w.overlaps ? w.value / spec_.slaveAreas[k] : std::numeric_limits<double>::infinity();
  if (w.overlaps && w.value < 0.0 && !frozenOpen) {
    out.status = ContactStatus::Slip;  // frictionless: free sliding, as node-to-segment reports it
    out.pressure = -spec_.law.normalPenalty * out.gap;
  }
  return out;
}

SlaveNodeChange MortarInterface::changeOf(std::size_t k, const SlaveNodeState& trial) const {
  SlaveNodeChange c = unchanged(k);
  c.trialGap = trial.gap;
  c.trialStatus = trial.status;
  return c;
}

void MortarInterface::assemble(std::size_t k, const NodeWeightedGap& w, double pressure, const Sink& sink,
                               std::vector<double>& force) const {
  const int n = w.size();
  const double stiffness = spec_.law.normalPenalty / spec_.slaveAreas[k];
  std::vector<double> residual(static_cast<std::size_t>(n)), tangent(static_cast<std::size_t>(n) * n),
      dLambda(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n; ++i) {
    residual[i] = -pressure * w.gradient[i];
    for (int j = 0; j < n; ++j)
      tangent[i * n + j] = stiffness * w.gradient[i] * w.gradient[j] - pressure * w.hessian[i * n + j];
  }
  // A rigid master moves as X + λ · motion: ∂r/∂λ = K[:, rigid] · motion.
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) dLambda[i] += tangent[i * n + j] * w.dPositiondLambda[j];
  sink(w.dofs.data(), n, residual.data(), tangent.data(), dLambda.data());
  const auto& slaves = spec_.slaveNodes;
  for (std::size_t a = 0; a < w.nodes.size(); ++a)
    if (std::binary_search(slaves.begin(), slaves.end(), w.nodes[a]))
      for (int c = 0; c < kDim; ++c) force[c] -= residual[kDim * a + c];
}

void MortarInterface::evaluate(const NodePosition& position, double loadFactor, bool updateTrial, const Sink& sink) {
  const Facets facets = master_.facets(position, loadFactor);
  const BoundingBoxTree<kDim> tree = searchTree(facets);
  std::vector<double> force(kDim, 0.0);
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k]) continue;
    // Frozen: nodes open at the commit carry no force, except those already touching (zero gap).
    const bool frozenOpen = frozen_ && committedOutput_[k].status == ContactStatus::Open &&
                            !(committedOutput_[k].gap <= kTouchingGap);
    NodeWeightedGap w = weightedGap(k, position, facets, tree, false);
    const SlaveNodeState out = stateOf(k, w, frozenOpen);
    if (out.status != ContactStatus::Open) {
      w = weightedGap(k, position, facets, tree, true);
      assemble(k, w, out.pressure, sink, force);
    }
    if (updateTrial) {
      trialOutput_[k] = out;
      trialChanges_[k] = changeOf(k, out);
    }
  }
  if (updateTrial) trialForce_ = force;
}

std::vector<SlaveNodeChange> MortarInterface::changesAt(const NodePosition& position, double loadFactor) const {
  const Facets facets = master_.facets(position, loadFactor);
  const BoundingBoxTree<kDim> tree = searchTree(facets);
  std::vector<SlaveNodeChange> out;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k)
    if (evaluatesSlave_[k]) out.push_back(changeOf(k, stateOf(k, weightedGap(k, position, facets, tree, false), false)));
  return out;
}

void MortarInterface::commit() {
  ContactCounts counts;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k] || trialOutput_[k].status == ContactStatus::Open) continue;
    ++counts.active;
    if (committedOutput_[k].status == ContactStatus::Open) ++counts.newlyActive;
    if (trialOutput_[k].status == ContactStatus::Stick) ++counts.stick;
    if (trialOutput_[k].status == ContactStatus::Slip) ++counts.slip;
  }
  committedIncrement_ = trialChanges_;
  committedOutput_ = trialOutput_;
  committedForce_ = trialForce_;
  committedCounts_ = counts;
  for (std::size_t k = 0; k < trialChanges_.size(); ++k) trialChanges_[k] = unchanged(k);
}

void MortarInterface::rollback() {
  trialOutput_ = committedOutput_;
  trialForce_ = committedForce_;
  for (std::size_t k = 0; k < trialChanges_.size(); ++k) trialChanges_[k] = unchanged(k);
}

namespace {
// A mortar slave node's fields in the restart file: its change over the last increment and its output
// (the frictionless mortar keeps no other history).
template <class Change, class Output, class Fields>
void mortarSlaveFields(Change& c, Output& o, Fields& field) {
  field("committed_gap", c.committedGap, StateValues::AnyDouble);  // +inf: no master segment met
  field("trial_gap", c.trialGap, StateValues::AnyDouble);
  field("committed_status", c.committedStatus);
  field("trial_status", c.trialStatus);
  field("pressure", o.pressure);
  field("gap", o.gap, StateValues::AnyDouble);
  field("output_status", o.status);
}
}  // namespace

void MortarInterface::saveCommittedSlaves(StateRecord& table) const {
  StateTableWriter rows(table);
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave()[k]) continue;
    rows.beginRow(static_cast<std::int64_t>(k));
    mortarSlaveFields(committedIncrement_[k], committedOutput_[k], rows);
  }
  rows.finish();
}

void MortarInterface::restoreSlaves(const StateRecord& table) {
  StateTableReader rows(table);
  readSlaveRows(table, rows, [&](std::size_t k) {
    SlaveNodeChange c;
    SlaveNodeState o;
    mortarSlaveFields(c, o, rows);
    if (!evaluatesSlave()[k]) return;
    committedIncrement_[k] = c;
    committedOutput_[k] = trialOutput_[k] = o;
    trialChanges_[k] = unchanged(k);
  });
}

std::unique_ptr<ContactInterfaceBase> makeMortarInterface(ContactInterfaceSpec spec, std::vector<char> evaluatesSlave) {
  return std::make_unique<MortarInterface>(std::move(spec), std::move(evaluatesSlave));
}

ContactInterfaceSpec mortarReservationSpec(const ContactInterfaceSpec& spec) {
  ContactInterfaceSpec out = spec;
  double slaveSize = 0;
  for (double h : spec.slaveFacetLengths) slaveSize = std::max(slaveSize, h);
  // The run-time search pairs a slave segment with master segments up to a master and a slave segment
  // length away (searchTree); the node is one slave segment from the far end of its segments.
  out.searchReach = std::max(0.0, spec.searchReach) + 2.0 * slaveSize;
  return out;
}

std::vector<std::size_t> mortarSlaveNeighbours(const ContactInterfaceSpec& spec, std::size_t k) {
  const auto& s = spec.slaveNodes;
  const auto index = [&](GlobalIndex node) { return static_cast<std::size_t>(std::lower_bound(s.begin(), s.end(), node) - s.begin()); };
  const auto adjacent = [&](std::size_t j, std::vector<std::size_t>& out) {
    for (std::size_t f = 0; f + 1 < spec.slaveFacets.size(); f += 2)
      for (int a = 0; a < 2; ++a)
        if (spec.slaveFacets[f + a] == s[j]) out.push_back(index(spec.slaveFacets[f + 1 - a]));
  };
  // Two segments away: the nodal normals at node k's neighbours depend on their own neighbours.
  std::vector<std::size_t> near{k};
  adjacent(k, near);
  std::vector<std::size_t> out = near;
  for (std::size_t i = 1; i < near.size(); ++i) adjacent(near[i], out);
  std::sort(out.begin() + 1, out.end());
  out.erase(std::unique(out.begin() + 1, out.end()), out.end());
  out.erase(std::remove(out.begin() + 1, out.end(), k), out.end());
  return out;
}

}  // namespace contessa::contact
