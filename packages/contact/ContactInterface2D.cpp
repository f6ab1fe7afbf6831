#include "contact/ContactInterface2D.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "contact/BoundingBoxTree.hpp"
#include "contact/HistoryTransfer.hpp"
#include "contact/SweptCrossing.hpp"

namespace contessa::contact {

namespace {
constexpr double kTouchingGap = 1e-10;  // as continuation::BetaOptions::touchingGap
}  // namespace

ContactInterface2D::ContactInterface2D(ContactInterfaceSpec2D spec, std::vector<char> evaluatesSlave)
    : spec_(std::move(spec)),
      evaluatesSlave_(std::move(evaluatesSlave)),
      element_(spec_.law),
      history_(spec_.slaveNodes.size()),
      damping_(spec_.slaveNodes.size()),
      lastSlave_(spec_.slaveNodes.size()),
      trialOutput_(spec_.slaveNodes.size()),
      committedOutput_(spec_.slaveNodes.size()),
      trialChanges_(spec_.slaveNodes.size()),
      committedIncrement_(spec_.slaveNodes.size()) {
  spec_.law.validate();
  if (spec_.slaveFacetLengths.size() != spec_.slaveNodes.size())
    throw std::logic_error("ContactInterface2D '" + spec_.name + "': one facet length per slave node expected");
  for (auto& s : trialOutput_) s.gap = std::numeric_limits<double>::infinity();
  committedOutput_ = trialOutput_;
}

std::vector<MasterSegment2D> ContactInterface2D::masterSegments(const NodePosition& position, double loadFactor) const {
  std::vector<MasterSegment2D> segments;
  if (spec_.rigidMaster) {
    const auto& pts = spec_.rigidSurface.points;
    // Rigid points are not mesh nodes: number them −1, −2, ... so shared vertices are still recognised.
    for (std::size_t s = 0; s + 1 < pts.size(); ++s) {
      MasterSegment2D m;
      m.id = static_cast<int>(s);
      m.nodes = {-1 - static_cast<int>(s), -2 - static_cast<int>(s)};
      for (int a = 0; a < 2; ++a)
        for (int c = 0; c < 2; ++c) m.x[a][c] = pts[s + a][c] + loadFactor * spec_.rigidSurface.motion[c];
      segments.push_back(m);
    }
  } else {
    for (std::size_t s = 0; s < spec_.masterSegments.size(); ++s) {
      MasterSegment2D m;
      m.id = static_cast<int>(s);
      for (int a = 0; a < 2; ++a) {
        m.nodes[a] = static_cast<int>(spec_.masterSegments[s][a]);
        m.x[a] = position(spec_.masterSegments[s][a]);
      }
      segments.push_back(m);
    }
  }
  return segments;
}

void ContactInterface2D::evaluate(const NodePosition& position, double loadFactor, bool updateTrial, const Sink& sink) {
  const auto segments = masterSegments(position, loadFactor);
  if (committedMaster_.empty()) committedMaster_ = segments;

  // Global search: master segment boxes enlarged by the longest segment, so a slave node finds every
  // segment it could project on, and its neighbours (corners).
  double reach = 0;
  for (const auto& m : segments)
    reach = std::max(reach, std::hypot(m.x[1][0] - m.x[0][0], m.x[1][1] - m.x[0][1]));
  std::vector<BoundingBox<2>> boxes(segments.size());
  for (std::size_t s = 0; s < segments.size(); ++s) {
    boxes[s].include(segments[s].x[0]);
    boxes[s].include(segments[s].x[1]);
    boxes[s].enlarge(reach);
  }
  const BoundingBoxTree<2> tree(boxes);

  Vector<2> force{};
  std::vector<int> hits;
  std::vector<MasterSegment2D> candidates;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k]) continue;
    const GlobalIndex node = spec_.slaveNodes[k];
    const Vector<2> xs = position(node);
    if (updateTrial) lastSlave_[k] = xs;
    hits.clear();
    tree.query(xs, hits);
    candidates.clear();
    for (int h : hits) candidates.push_back(segments[h]);
    const SegmentSelection selection = selector_.select(xs, candidates);

    SlaveNodeState out;
    out.gap = selection.kind == SelectionKind::None ? std::numeric_limits<double>::infinity() : selection.gap;
    ContactHistory<1> trial = history_.committed(k);
    SlaveNodeChange change = changeOf(k, out.gap, nullptr, trial);
    // Frozen: nodes open at the commit carry no force — except nodes already touching (zero gap),
    // which close at once in any step and shape how their neighbours approach.
    const bool frozenOpen =
        frozen_ && !history_.committed(k).isInContact() && !(committedOutput_[k].gap <= kTouchingGap);
    if (selection.kind != SelectionKind::None && !frozenOpen) {
      // The history is kept on the segment the node projected on at the last commit; re-express it on
      // the segment chosen now (committed coordinates, so it stays constant within the increment).
      ContactHistory<1> committed = history_.committed(k);
      if (committed.isInContact() && committed.segment != selection.segment && committed.segment >= 0)
        committed = transferHistory(committed, committedMaster_[committed.segment], committedMaster_[selection.segment]);
      NodeToFacetGeometry<Line2Facet> geometry;
      geometry.slave = xs;
      geometry.master = segments[selection.segment].x;
      // Newton iterates (updateTrial): a node whose slip direction has just reversed gets a secant
      // tangential stiffness (SlipReversalDamping); the residual is the same either way.
      const double facetLength = spec_.slaveFacetLengths[k];
      NodeToFacetResult<Line2Facet> r = element_.evaluate(geometry, selection.segment, committed, facetLength);
      if (updateTrial) {
        damping_.observe(k, history_.trial(k), r.trial);
        const SlipTangent tangent = damping_.tangent(k);
        if (tangent.secant) r = element_.evaluate(geometry, selection.segment, committed, facetLength, tangent);
      }
      trial = r.trial;
      change = changeOf(k, out.gap, &r, committed);
      out.status = r.status;
      out.pressure = r.status == ContactStatus::Open ? 0.0 : -r.normalTraction;
      if (r.status != ContactStatus::Open) {
        // t_N and t_T are tractions (eq. 14–16): the nodal force is the traction times the slave
        // node's tributary area, so ε_N does not depend on the mesh size.
        const double area = spec_.slaveAreas[k];
        std::array<double, 6> residual{};
        std::array<double, 36> tangent{};
        std::array<double, 6> dLambda{};
        for (int i = 0; i < 6; ++i) residual[i] = area * r.residual[i];
        for (int i = 0; i < 6; ++i)
          for (int j = 0; j < 6; ++j) tangent[i * 6 + j] = area * r.tangent(i, j);
        std::array<GlobalIndex, 6> dofs{};
        dofs[0] = 2 * node;
        dofs[1] = 2 * node + 1;
        for (int a = 0; a < 2; ++a)
          for (int c = 0; c < 2; ++c)
            dofs[2 + 2 * a + c] = spec_.rigidMaster ? -1 : 2 * spec_.masterSegments[selection.segment][a] + c;
        if (spec_.rigidMaster) {
          // x_master = X + λ · motion: ∂r_c/∂λ = Σ_master K[:, master] · motion.
          for (int i = 0; i < 6; ++i)
            for (int a = 0; a < 2; ++a)
              for (int c = 0; c < 2; ++c) dLambda[i] += tangent[i * 6 + 2 + 2 * a + c] * spec_.rigidSurface.motion[c];
        }
        sink(dofs.data(), 6, residual.data(), tangent.data(), dLambda.data());
        force[0] -= residual[0];
        force[1] -= residual[1];
      }
    } else {
      trial.status = ContactStatus::Open;
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
    lastSegments_ = segments;
    if (committedSlave_.empty()) committedSlave_ = lastSlave_;
  }
}

std::vector<TunnellingNode> ContactInterface2D::tunnellingNodes() const {
  std::vector<TunnellingNode> out;
  if (lastSegments_.empty() || committedSlave_.empty() || committedMaster_.size() != lastSegments_.size()) return out;
  // Swept boxes: each segment's box over both states, a hair larger so touching counts.
  double longest = 0;
  for (const auto& m : lastSegments_) longest = std::max(longest, norm(subtract(m.x[1], m.x[0])));
  const double margin = 1e-9 * longest;
  std::vector<BoundingBox<2>> boxes(lastSegments_.size());
  for (std::size_t s = 0; s < lastSegments_.size(); ++s) {
    for (int a = 0; a < 2; ++a) {
      boxes[s].include(committedMaster_[s].x[a]);
      boxes[s].include(lastSegments_[s].x[a]);
    }
    boxes[s].enlarge(margin);
  }
  const BoundingBoxTree<2> tree(boxes);
  std::vector<int> hits;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    // In contact now (g_N ≤ 0 on the selected segment): penalty penetration, not tunnelling.
    if (!evaluatesSlave_[k] || !(trialOutput_[k].gap > 0.0)) continue;
    // A node in contact at the commit starts from its contact point on the master: its penalty
    // penetration there is not a crossing.
    Vector<2> start = committedSlave_[k];
    const auto& committed = history_.committed(k);
    if (committed.isInContact() && committed.segment >= 0 &&
        committed.segment < static_cast<int>(committedMaster_.size())) {
      const auto h = Line2Facet::shapeFunctions(committed.xi);
      const auto& m = committedMaster_[committed.segment].x;
      for (int c = 0; c < 2; ++c) start[c] = h[0] * m[0][c] + h[1] * m[1][c];
    }
    const Vector<2>& end = lastSlave_[k];
    BoundingBox<2> path;
    path.include(start);
    path.include(end);
    hits.clear();
    tree.queryBox(path, hits);
    for (int s : hits) {
      const SweptCrossing crossing =
          sweptCrossing<Line2Facet>(start, end, committedMaster_[s].x, lastSegments_[s].x);
      if (!crossing.crossed) continue;
      out.push_back({k, spec_.slaveNodes[k], s, crossing.time});
      break;
    }
  }
  return out;
}

SlaveNodeChange ContactInterface2D::changeOf(std::size_t k, double gap, const NodeToFacetResult<Line2Facet>* result,
                                             const ContactHistory<1>& committed) const {
  SlaveNodeChange c = unchanged(k);
  c.trialGap = gap;
  c.trialStatus = result != nullptr ? result->status : ContactStatus::Open;
  const double mu = spec_.law.frictionCoefficient;
  if (result == nullptr || mu == 0.0 || !committed.isInContact() || result->status == ContactStatus::Open) return c;
  // Coulomb indicators (eq. 19, 21) in 2D: one covariant component t_T1, ‖t‖ = |t_T1| √ā^11.
  const auto& friction = result->friction;
  const double committedTraction = committed.tangentialTraction[0];
  const double trialTraction = friction.trialTraction[0];
  const double committedNorm = std::abs(committedTraction) * std::sqrt(result->projection.inverseMetric(0, 0));
  const bool opposite = committedTraction * trialTraction < 0.0;  // driven the other way
  c.committedIndicator = (opposite ? -committedNorm : committedNorm) - mu * committedOutput_[k].pressure;
  c.trialIndicator = friction.trialIndicator;
  c.slipReversed = opposite && committed.status == ContactStatus::Slip && result->status == ContactStatus::Slip;
  return c;
}

SlaveNodeChange ContactInterface2D::unchanged(std::size_t k) const {
  SlaveNodeChange c;
  c.committedGap = c.trialGap = committedOutput_[k].gap;
  c.committedStatus = c.trialStatus = history_.committed(k).status;
  return c;
}

std::vector<SlaveNodeChange> ContactInterface2D::owned(const std::vector<SlaveNodeChange>& all) const {
  std::vector<SlaveNodeChange> out;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k)
    if (evaluatesSlave_[k]) out.push_back(all[k]);
  return out;
}

std::vector<SlaveNodeChange> ContactInterface2D::trialChanges() const { return owned(trialChanges_); }

std::vector<SlaveNodeChange> ContactInterface2D::committedIncrement() const { return owned(committedIncrement_); }

std::vector<SlaveNodeChange> ContactInterface2D::changesAt(const NodePosition& position, double loadFactor) const {
  const auto segments = masterSegments(position, loadFactor);
  std::vector<SlaveNodeChange> out;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k]) continue;
    const Vector<2> xs = position(spec_.slaveNodes[k]);
    const SegmentSelection selection = selector_.select(xs, segments);
    if (selection.kind == SelectionKind::None) {
      out.push_back(changeOf(k, std::numeric_limits<double>::infinity(), nullptr, history_.committed(k)));
      continue;
    }
    ContactHistory<1> committed = history_.committed(k);
    if (committed.isInContact() && committed.segment != selection.segment && committed.segment >= 0)
      committed = transferHistory(committed, committedMaster_[committed.segment], committedMaster_[selection.segment]);
    NodeToFacetGeometry<Line2Facet> geometry;
    geometry.slave = xs;
    geometry.master = segments[selection.segment].x;
    const NodeToFacetResult<Line2Facet> r = element_.evaluate(geometry, selection.segment, committed, spec_.slaveFacetLengths[k]);
    out.push_back(changeOf(k, selection.gap, &r, committed));
  }
  return out;
}

void ContactInterface2D::commit() {
  ContactCounts counts;
  for (std::size_t k = 0; k < spec_.slaveNodes.size(); ++k) {
    if (!evaluatesSlave_[k]) continue;
    const auto status = history_.trial(k).status;
    if (status == ContactStatus::Open) continue;
    ++counts.active;
    if (!history_.committed(k).isInContact()) ++counts.newlyActive;
    if (status == ContactStatus::Stick) ++counts.stick;
    if (status == ContactStatus::Slip) ++counts.slip;
  }
  history_.commit();
  damping_.reset();
  committedIncrement_ = trialChanges_;
  committedOutput_ = trialOutput_;
  committedForce_ = trialForce_;
  committedCounts_ = counts;
  if (!lastSegments_.empty()) {
    committedMaster_ = lastSegments_;
    committedSlave_ = lastSlave_;
  }
  for (std::size_t k = 0; k < trialChanges_.size(); ++k) trialChanges_[k] = unchanged(k);
}

void ContactInterface2D::rollback() {
  history_.rollback();
  damping_.reset();
  trialOutput_ = committedOutput_;
  trialForce_ = committedForce_;
  for (std::size_t k = 0; k < trialChanges_.size(); ++k) trialChanges_[k] = unchanged(k);
}

}  // namespace contessa::contact
