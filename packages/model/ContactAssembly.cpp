#include <cstdlib>
#include "model/ContactAssembly.hpp"

#include "common/NumberText.hpp"
#include "contact/MortarInterface.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "model/LoadStepping.hpp"

namespace contessa::model {

using contact::GlobalIndex;

namespace {
// The spec a reservation is made for: a mortar interface reaches one slave segment further.
contact::ContactInterfaceSpec reservationSpec(const contact::ContactInterfaceSpec& spec) {
  return spec.mortar ? contact::mortarReservationSpec(spec) : spec;
}
}  // namespace


ContactAssembly::ContactAssembly(const deck::ProblemDefinition& problem, const DofLayout& layout)
    : layout_(layout), numGlobalNodes_(problem.mesh.numGlobalNodes) {
  const mesh::DistributedMesh& part = problem.mesh;
  const int dim = layout.dimension();
  for (const auto& spec : problem.contacts) {
    std::vector<char> evaluates(spec.slaveNodes.size());
    for (std::size_t k = 0; k < spec.slaveNodes.size(); ++k) {
      const mesh::GlobalIndex local = part.localNode(spec.slaveNodes[k]);
      evaluates[k] = local >= 0 && part.nodeOwner[static_cast<std::size_t>(local)] == part.rank;
    }
    interfaces_.push_back(spec.mortar ? contact::makeMortarInterface(spec, evaluates)
                                      : contact::makeContactInterface(spec, evaluates));
  }
  referenceX_.assign(static_cast<std::size_t>(layout.numOverlapDofs()), 0.0);
  for (std::size_t k = 0; k < problem.contactNodes.size(); ++k)
    for (int c = 0; c < dim; ++c)
      referenceX_[layout.overlapDof(problem.contactNodes[k], c)] = problem.contactNodeCoordinates[k * dim + c];
  // The first reservation, around the reference configuration.
  const std::vector<double> zero(referenceX_.size(), 0.0);
  for (const auto& interface : interfaces_)
    reservations_.push_back(contact::reserveCouplings(reservationSpec(interface->spec()), positions(zero.data()),
                                                      interface->evaluatesSlave()));
  outsideByInterface_.assign(interfaces_.size(), 0);
}

std::vector<mesh::GlobalIndex> ContactAssembly::surfaceNodes(const std::vector<contact::ContactInterfaceSpec>& specs) {
  std::vector<mesh::GlobalIndex> nodes;
  for (const auto& spec : specs) {
    nodes.insert(nodes.end(), spec.slaveNodes.begin(), spec.slaveNodes.end());
    nodes.insert(nodes.end(), spec.masterFacets.begin(), spec.masterFacets.end());
  }
  return nodes;
}

void ContactAssembly::addMortarCouplings(const contact::ContactInterfaceSpec& spec, const std::vector<char>& evaluates,
                                         const contact::CouplingReservation& reservation,
                                         std::vector<std::vector<LO>>& rows) const {
  // A mortar slave node's term couples every node of its weighted gap's support with every other: its
  // neighbouring slave nodes and the master nodes reserved for it, in this rank's overlap rows.
  const int dim = layout_.dimension();
  std::vector<LO> support;
  for (std::size_t k = 0; k < spec.slaveNodes.size(); ++k) {
    if (!evaluates[k]) continue;
    support.clear();
    for (std::size_t j : contact::mortarSlaveNeighbours(spec, k))
      for (int c = 0; c < dim; ++c) support.push_back(layout_.overlapDof(spec.slaveNodes[j], c));
    if (!spec.rigidMaster)
      for (const GlobalIndex* m = reservation.begin(k); m != reservation.end(k); ++m)
        for (int c = 0; c < dim; ++c) support.push_back(layout_.overlapDof(*m, c));
    for (LO a : support) rows[a].insert(rows[a].end(), support.begin(), support.end());
  }
}

void ContactAssembly::addReservedCouplings(std::vector<std::vector<LO>>& rows) const {
  // The reach rule of contact::CouplingReservation: the whole master surface for a small interface, else
  // the master facets within reach of the slave node found by a box search, so the graph grows with the
  // surface, not its square. A rigid master has no unknowns: its slave nodes need only their own DOFs,
  // which their elements hold.
  const int dim = layout_.dimension();
  for (std::size_t i = 0; i < interfaces_.size(); ++i) {
    const auto& spec = interfaces_[i]->spec();
    const auto& evaluates = interfaces_[i]->evaluatesSlave();
    const auto& reservation = reservations_[i];
    // A mortar slave node's term also couples its neighbouring slave nodes, rigid master or not.
    if (spec.mortar) addMortarCouplings(spec, evaluates, reservation, rows);
    if (spec.rigidMaster) continue;
    const auto dofsOf = [&](GO node, LO* out) {
      for (int c = 0; c < dim; ++c) out[c] = layout_.overlapDof(node, c);
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
          for (int c = 0; c < dim; ++c)
            for (int d = 0; d < dim; ++d) rows[a[c]].push_back(b[d]);
        }
    // Only the facets contact::kValleyBlendable names (2-node segments, 4-node faces) are blended.
    const bool blended = spec.nodesPerFacet() == 2 || spec.nodesPerFacet() == 4;
    // With friction the blend is that of the penalty law only (contact::ContactInterface).
    const bool blends = spec.law.isFrictionless() || !spec.law.isAugmented();
    if (!spec.mortar && blends && blended) addAcrossEdgeCouplings(spec, rows);
    for (std::size_t k = 0; k < spec.slaveNodes.size(); ++k) {
      if (!evaluates[k] || spec.mortar) continue;
      dofsOf(spec.slaveNodes[k], a);
      for (const GlobalIndex* m = reservation.begin(k); m != reservation.end(k); ++m) {
        dofsOf(*m, b);
        for (int c = 0; c < dim; ++c)
          for (int d = 0; d < dim; ++d) {
            rows[a[c]].push_back(b[d]);
            rows[b[d]].push_back(a[c]);
          }
      }
    }
  }
}

void ContactAssembly::addAcrossEdgeCouplings(const contact::ContactInterfaceSpec& spec,
                                             std::vector<std::vector<LO>>& rows) const {
  // A node-to-facet element near a valley edge is blended over the two facets sharing it
  // (contact/ValleyBlend.hpp): it couples the nodes of both. Facets sharing an edge (2D: a vertex; 3D: at
  // least two nodes) reserve each other's nodes.
  const int dim = layout_.dimension();
  const std::size_t perFacet = spec.nodesPerFacet();
  const std::size_t numFacets = spec.masterFacets.size() / perFacet;
  const std::size_t sharedNeeded = dim == 2 ? 1 : 2;
  std::vector<std::pair<GlobalIndex, std::size_t>> byNode;  // (node, facet), sorted by node
  for (std::size_t f = 0; f < numFacets; ++f)
    for (std::size_t a = 0; a < perFacet; ++a) byNode.emplace_back(spec.masterFacets[f * perFacet + a], f);
  std::sort(byNode.begin(), byNode.end());
  std::vector<std::pair<std::size_t, std::size_t>> pairs;  // (f, g), one per shared node
  for (std::size_t i = 0; i < byNode.size();) {
    std::size_t j = i;
    while (j < byNode.size() && byNode[j].first == byNode[i].first) ++j;
    for (std::size_t x = i; x < j; ++x)
      for (std::size_t y = i; y < j; ++y)
        if (byNode[x].second != byNode[y].second) pairs.emplace_back(byNode[x].second, byNode[y].second);
    i = j;
  }
  std::sort(pairs.begin(), pairs.end());
  for (std::size_t i = 0; i < pairs.size();) {
    std::size_t j = i;
    while (j < pairs.size() && pairs[j] == pairs[i]) ++j;
    if (j - i >= sharedNeeded) {
      const std::size_t f = pairs[i].first, g = pairs[i].second;
      for (std::size_t ia = 0; ia < perFacet; ++ia)
        for (std::size_t ib = 0; ib < perFacet; ++ib)
          for (int c = 0; c < dim; ++c)
            for (int d = 0; d < dim; ++d)
              rows[layout_.overlapDof(spec.masterFacets[f * perFacet + ia], c)].push_back(
                  layout_.overlapDof(spec.masterFacets[g * perFacet + ib], d));
    }
    i = j;
  }
}

void ContactAssembly::reserveAround(const double* u) {
  // Every rank holds every contact surface node in its overlap (DofLayout's replicated nodes), so each
  // rank reserves for its own slave nodes without communication; the search's boxes are those of the
  // current configuration, as the run-time search's are.
  const auto position = positions(u);
  for (std::size_t i = 0; i < interfaces_.size(); ++i)
    if (outsideByInterface_[i] != 0)
      reservations_[i] = contact::reserveCouplings(reservationSpec(interfaces_[i]->spec()), position,
                                                   interfaces_[i]->evaluatesSlave());
}

contact::ContactInterfaceBase::NodePosition ContactAssembly::positions(const double* u) const {
  const int dim = layout_.dimension();
  return [this, u, dim](GlobalIndex node, double* p) {
    for (int c = 0; c < dim; ++c) {
      const LO dof = layout_.overlapDof(node, c);
      p[c] = referenceX_[dof] + u[dof];
    }
  };
}

void ContactAssembly::setLoadStep(const continuation::LoadSchedule& schedule, int step) {
  frictionStart_.assign(interfaces_.size(), 0.0);
  frictionChange_.assign(interfaces_.size(), 0.0);
  for (std::size_t i = 0; i < interfaces_.size(); ++i) {
    auto& c = *interfaces_[i];
    const std::string& name = c.spec().name;
    if (c.spec().rigidMaster) c.setRigidMotion(schedule.start(step, motionKey(name)), schedule.change(step, motionKey(name)));
    frictionStart_[i] = schedule.start(step, frictionKey(name))[0];
    frictionChange_[i] = schedule.change(step, frictionKey(name))[0];
    if (c.spec().law.frictionCoefficient != frictionStart_[i]) c.setFrictionCoefficient(frictionStart_[i]);
  }
  // A new load step loads otherwise: the multiplier predictor measures its rates afresh (eq. 15.8).
  if (step != predictorStep_) {
    predictorStep_ = step;
    committedAmplitude_ = std::numeric_limits<double>::quiet_NaN();
  }
}

void ContactAssembly::frictionAt(double a) const {
  for (std::size_t i = 0; i < frictionChange_.size(); ++i)
    if (frictionChange_[i] != 0.0) interfaces_[i]->setFrictionCoefficient(frictionStart_[i] + a * frictionChange_[i]);
}

bool ContactAssembly::assemble(const double* u, double lambda, bool updateTrial, double* fo, double* dl,
                               StiffnessScatter* scatter, double slope) {
  frictionAt(lambda);
  if (updateTrial) predictMultipliers(lambda);
  // Each slave node's owner adds its contact element; rigid masters have no DOFs.
  const int dim = layout_.dimension();
  const bool withStiffness = scatter != nullptr;
  const auto position = positions(u);
  std::vector<LO> local;
  std::vector<int> entry;
  std::vector<double> block;
  // The first contact pairing (this rank) outside the couplings the graph reserved: (interface, slave node).
  const long long none = std::numeric_limits<long long>::max();
  const long long numNodes = numGlobalNodes_;
  long long outsideReach = none;
  std::vector<int> outside(interfaces_.size(), 0);
  std::string missingCoupling;
  for (std::size_t i = 0; i < interfaces_.size(); ++i) {
    const auto& reservation = reservations_[i];
    interfaces_[i]->evaluate(position, lambda, updateTrial,
                             [&](const GlobalIndex* dofs, int n, const double* r, const double* k, const double* drdl) {
                               // The DOFs that are unknowns (not those of a rigid master), in local numbering.
                               local.clear();
                               entry.clear();
                               for (int j = 0; j < n; ++j)
                                 if (dofs[j] >= 0) {
                                   local.push_back(layout_.overlapMap()->getLocalElement(dofs[j]));
                                   entry.push_back(j);
                                 }
                               const int m = static_cast<int>(local.size());
                               for (int a = 0; a < m; ++a) {
                                 fo[local[a]] += r[entry[a]];
                                 dl[local[a]] += slope * drdl[entry[a]];
                               }
                               if (!withStiffness) return;
                               // dofs: the slave node's, then the master facet's nodes'. A master node beyond the
                               // reserved reach has no place in the graph: the pairing is agreed on below, so that
                               // every rank asks for the same rebuild.
                               const GlobalIndex slave = dofs[0] / dim;
                               const auto& slaves = interfaces_[i]->spec().slaveNodes;
                               const std::size_t slaveIndex = static_cast<std::size_t>(
                                   std::lower_bound(slaves.begin(), slaves.end(), slave) - slaves.begin());
                               // (A mortar term also holds the slave node's neighbours: reserved with it.)
                               for (int a = dim; a < n; a += dim)
                                 if (dofs[a] >= 0 && !contact::isReserved(reservation, slaveIndex, dofs[a] / dim) &&
                                     !(interfaces_[i]->spec().mortar &&
                                       std::binary_search(slaves.begin(), slaves.end(), dofs[a] / dim))) {
                                   outsideReach = std::min(outsideReach, static_cast<long long>(i) * numNodes + slave);
                                   outside[i] = 1;
                                   return;
                                 }
                               block.resize(static_cast<std::size_t>(m) * m);
                               for (int a = 0; a < m; ++a)
                                 for (int b = 0; b < m; ++b) block[a * m + b] = k[entry[a] * n + entry[b]];
                               try {  // inside the reservation the graph holds it; anything else is a defect
                                 scatter->addStiffness(local.data(), m, block.data());
                               } catch (const std::logic_error& e) {
                                 if (missingCoupling.empty()) missingCoupling = e.what();
                               }
                             });
  }
  if (!withStiffness) return true;
  const Comm& comm = *layout_.comm();
  int mine = missingCoupling.empty() ? 0 : 1, any = mine;
  if (comm.getSize() > 1) Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 1, &mine, &any);
  if (any != 0)
    throw std::logic_error(missingCoupling.empty()
                               ? "StiffnessScatter: a contact coupling on another rank is not in the matrix graph"
                               : missingCoupling);
  long long first = outsideReach;
  if (comm.getSize() > 1) Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 1, &outsideReach, &first);
  outside_.clear();
  if (first == none) {
    std::fill(outsideByInterface_.begin(), outsideByInterface_.end(), 0);
    return true;
  }
  // Which interfaces reserve again: those where any rank met a pairing outside.
  outsideByInterface_ = outside;
  if (comm.getSize() > 1)
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, static_cast<int>(outside.size()), outside.data(),
                       outsideByInterface_.data());
  const std::size_t i = static_cast<std::size_t>(first / numNodes);
  std::ostringstream message;
  // Node numbers are Exodus ids (1-based), as in the output file.
  message << "contact interface '" << interfaces_[i]->spec().label() << "': slave node " << first % numNodes + 1
          << " met a master facet beyond the reserved reach " << reservations_[i].reach;
  outside_ = message.str();
  return false;
}

template <class Changes>
std::vector<contact::SlaveNodeChange> ContactAssembly::collect(const Changes& changesOf) const {
  std::vector<contact::SlaveNodeChange> out;
  for (const auto& interface : interfaces_) {
    const auto c = changesOf(*interface);
    out.insert(out.end(), c.begin(), c.end());
  }
  return out;
}

std::vector<contact::SlaveNodeChange> ContactAssembly::changesAt(const double* u, double lambda) const {
  const auto position = positions(u);
  frictionAt(lambda);
  return collect([&](const contact::ContactInterfaceBase& c) { return c.changesAt(position, lambda); });
}

std::vector<contact::SlaveNodeChange> ContactAssembly::trialChanges() const {
  return collect([](const contact::ContactInterfaceBase& c) { return c.trialChanges(); });
}

std::vector<contact::SlaveNodeChange> ContactAssembly::committedIncrement() const {
  return collect([](const contact::ContactInterfaceBase& c) { return c.committedIncrement(); });
}

void ContactAssembly::commit() {
  const double loadChange = latestAmplitude_ - committedAmplitude_;
  for (auto& c : interfaces_) {
    c->measureTractionRates(loadChange);
    c->commit();
  }
  committedAmplitude_ = latestAmplitude_;
  predictionPending_ = true;
  augmentations_.assign(interfaces_.size(), 0);
  lastViolation_.assign(interfaces_.size(), HUGE_VAL);
}

void ContactAssembly::predictMultipliers(double a) {
  // The attempt's first evaluation at its own load factor: the continuation's predictor has moved u, the
  // multipliers follow (docs/theory-contact.md eq. 15.8). A pass at the commit's load factor predicts nothing.
  static const bool off = std::getenv("I21T_NOPRED") != nullptr;
  if (!off && predictionPending_ && a != committedAmplitude_ && std::isfinite(committedAmplitude_)) {
    for (auto& c : interfaces_) c->predictMultipliers(a - committedAmplitude_);
    predictionPending_ = false;
  }
  latestAmplitude_ = a;
}

void ContactAssembly::rollback() {
  // A penalty grown in the rejected attempt is kept where no slave node of the interface (on any rank) was
  // in contact at the increment's start: that start (t_N = 0 everywhere) is then an equilibrium with any
  // penalty, and the next attempt need not find the same growth again (theory-contact.md §15, "What the
  // Hertz sphere's cost is"). Elsewhere the growth is rolled back with the multipliers.
  std::vector<double> grown(interfaces_.size());
  std::vector<int> touching(interfaces_.size(), 0), anyTouching(interfaces_.size(), 0);
  for (std::size_t i = 0; i < interfaces_.size(); ++i) {
    grown[i] = interfaces_[i]->penaltyGrowth();
    for (const auto& state : interfaces_[i]->committedStates())
      if (state.status != contact::ContactStatus::Open) touching[i] = 1;
  }
  if (!interfaces_.empty())
    Teuchos::reduceAll(*layout_.comm(), Teuchos::REDUCE_MAX, static_cast<int>(touching.size()), touching.data(),
                       anyTouching.data());
  for (auto& c : interfaces_) c->rollback();
  for (std::size_t i = 0; i < interfaces_.size(); ++i)
    if (!anyTouching[i] && grown[i] > interfaces_[i]->penaltyGrowth()) interfaces_[i]->restorePenaltyGrowth(grown[i]);
  predictionPending_ = true;
  augmentations_.assign(interfaces_.size(), 0);
  lastViolation_.assign(interfaces_.size(), HUGE_VAL);
}

double ContactAssembly::earlyUpdateBound() const {
  // An update at an iterate whose gaps are still moving by more than a tenth of a tolerance would chase the
  // Newton error, not the violation (docs/theory-contact.md §15, "Updates before convergence").
  double bound = HUGE_VAL;
  for (const auto& c : interfaces_) {
    const auto& law = c->spec().law;
    if (!law.isAugmented()) continue;
    // With friction, none: a sticking node's multiplier takes the secant's step (ContactInterface, theory eq.
    // 15.7), whose gain K + ε_T passes on the difference between the iterates two runs read. Which iterate an
    // early update reads is decided by a test (the contraction, the bound) that round-off flips by one
    // Newton iteration: the Tet10 press-slide audit's 2-rank runs then ended 5.3e-5 N apart (bound 1e-6);
    // with updates at converged iterates only 1e-13 (theory §15, "The secant reads equilibria").
    if (!law.isFrictionless()) return -HUGE_VAL;
    const auto& lengths = c->spec().slaveFacetLengths;
    const double shortest = lengths.empty() ? 0.0 : *std::min_element(lengths.begin(), lengths.end());
    if (law.penetrationTolerance > 0.0) bound = std::min(bound, 0.1 * law.penetrationTolerance * shortest);
  }
  return bound;
}

bool ContactAssembly::augment(double lambda, const AugmentationPoint& at) {
  if (!at.converged && !(at.errorEstimate <= earlyUpdateBound())) return false;
  const Comm& comm = *layout_.comm();
  augmentations_.resize(interfaces_.size(), 0);
  augmentationWarned_.resize(interfaces_.size(), 0);
  lastViolation_.resize(interfaces_.size(), HUGE_VAL);
  bool updated = false;
  for (std::size_t i = 0; i < interfaces_.size(); ++i) {
    auto& interface = *interfaces_[i];
    const auto& law = interface.spec().law;
    if (!law.isAugmented()) continue;
    const contact::AugmentationViolation local = interface.trialViolation();
    double mine[2] = {local.penetration, local.elasticSlip}, all[2] = {0, 0};
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 2, mine, all);
    if (std::getenv("I21T_TRACE") && comm.getRank() == 0)
      std::fprintf(stderr, "I21T_AUG lambda %.6f converged %d pen %.3e slip %.3e done %d\n", lambda, (int)at.converged,
                   all[0], all[1], augmentations_[i]);
    if (all[0] <= law.penetrationTolerance && all[1] <= law.elasticSlipTolerance) continue;
    if (augmentations_[i] < law.maxAugmentations) {
      // The multipliers take the tractions of the penalties they were computed with; the grown penalties
      // apply from the next evaluation (the update changes the problem either way).
      // With friction not at the increment's first update, only where the update before it measured a slow
      // Uzawa rate (theory-contact.md §15, "Penalty growth with friction").
      const bool grows = law.isFrictionless() || lastViolation_[i] < HUGE_VAL;
      const double growth = grows ? grownPenalty(interface.penaltyGrowth(), all[0], law.penetrationTolerance,
                                                 lastViolation_[i])
                                  : interface.penaltyGrowth();
      interface.augment(at.converged);
      interface.setPenaltyGrowth(growth);
      lastViolation_[i] = all[0];
      ++augmentations_[i];
      updated = true;
    } else if (at.converged && !augmentationWarned_[i] && law.maxAugmentations > 0) {
      warnShortOfTolerance(i, all, lambda);
    }
  }
  return updated;
}

void ContactAssembly::warnShortOfTolerance(std::size_t i, const double violation[2], double lambda) {
  augmentationWarned_[i] = 1;
  if (layout_.comm()->getRank() != 0) return;
  const auto& law = interfaces_[i]->spec().law;
  const std::string path = "Problem/Contact/" + interfaces_[i]->spec().name + "/";
  const std::string missed =
      violation[0] > law.penetrationTolerance
          ? "penetration " + threeDigits(violation[0]) + " L > " + path + "Penetration Tolerance " + threeDigits(law.penetrationTolerance)
          : "elastic slip " + threeDigits(violation[1]) + " L > " + path + "Elastic Slip Tolerance " + threeDigits(law.elasticSlipTolerance);
  std::fprintf(stderr,
               "contessa: warning: contact interface '%s': %s after Max Augmentations = %d at load factor %s "
               "(increment accepted; said once: raise Max Augmentations or the Normal Penalty)\n",
               interfaces_[i]->spec().label().c_str(), missed.c_str(), law.maxAugmentations, threeDigits(lambda).c_str());
  std::fflush(stderr);
}

void ContactAssembly::saveState(StateRecord& contact, bool writer) const {
  for (std::size_t i = 0; i < interfaces_.size(); ++i) {
    auto& group = contact.child("interface_" + std::to_string(i));
    // The committed penalty growth (the same on every rank; the trial one is the committed one after a commit).
    group.put("penalty_growth", std::vector<double>{interfaces_[i]->penaltyGrowth()}, {});
    // The multiplier predictor's load factor of the commit and its load step (NaN: none yet in this step).
    group.put("predictor_load_factor", std::vector<double>{committedAmplitude_}, {});
    group.put("predictor_load_step", std::vector<double>{static_cast<double>(predictorStep_)}, {});
    interfaces_[i]->saveCommittedSlaves(group.child("slaves"));
    if (writer) interfaces_[i]->saveCommittedMaster(group.child("master"));
  }
}

void ContactAssembly::restore(const StateRecord& contact) {
  for (std::size_t i = 0; i < interfaces_.size(); ++i) {
    const auto& group = contact.child("interface_" + std::to_string(i));
    const double growth = group.getDouble("penalty_growth");
    if (!(growth >= 1.0)) group.fail("penalty_growth", "a factor >= 1 expected, got " + std::to_string(growth));
    interfaces_[i]->restorePenaltyGrowth(growth);
    committedAmplitude_ = group.getDouble("predictor_load_factor", StateValues::AnyDouble);
    predictorStep_ = static_cast<int>(group.getDouble("predictor_load_step"));
    predictionPending_ = true;
    interfaces_[i]->restoreSlaves(group.child("slaves"));
    interfaces_[i]->restoreMaster(group.child("master"));
  }
}

void ContactAssembly::setNewContactsFrozen(bool frozen) {
  for (auto& c : interfaces_) c->setNewContactsFrozen(frozen);
  frozen_ = frozen;
}

std::string ContactAssembly::tunnelling() const {
  // The lowest (interface, node) over all ranks names the case; the count says how many there are.
  const Comm& comm = *layout_.comm();
  const long long none = std::numeric_limits<long long>::max();
  const long long numNodes = numGlobalNodes_;
  long long local = none, first = none;
  int localCount = 0, count = 0;
  for (std::size_t i = 0; i < interfaces_.size(); ++i) {
    const auto nodes = interfaces_[i]->tunnellingNodes();
    localCount += static_cast<int>(nodes.size());
    for (const auto& t : nodes) local = std::min(local, static_cast<long long>(i) * numNodes + t.node);
  }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 1, &localCount, &count);
  if (count == 0) return "";
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 1, &local, &first);
  const auto& interface = interfaces_[first / numNodes]->spec();
  // Node numbers are Exodus ids (1-based), as in the output file.
  return "slave node " + std::to_string(first % numNodes + 1) + " of interface '" + interface.label() + "'" +
         (count > 1 ? " (and " + std::to_string(count - 1) + " more)" : "") + " passed through the master surface";
}

void ContactAssembly::setConsistentTangents(bool consistent) {
  for (auto& c : interfaces_) c->setConsistentTangents(consistent);
}

int ContactAssembly::secantTangentNodes() const {
  int n = 0;
  for (const auto& c : interfaces_) n += c->secantTangentNodes();
  return n;
}

ContactAssembly::Interfaces ContactAssembly::saveState() const {
  Interfaces copy;
  for (const auto& c : interfaces_) copy.push_back(c->clone());
  return copy;
}

void ContactAssembly::restoreState(const Interfaces& saved) {
  interfaces_.clear();
  for (const auto& c : saved) interfaces_.push_back(c->clone());
}

}  // namespace contessa::model
