#include "model/PostProcessing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/ContactSurface.hpp"
#include "contact/MortarPressureRecovery.hpp"
#include "model/ContactAssembly.hpp"
#include "model/DofLayout.hpp"
#include "model/SolidAssembler.hpp"

namespace contessa::model {

using Teuchos::RCP;
using Teuchos::rcp;

PostProcessing::PostProcessing(const deck::ProblemDefinition& problem, const DofLayout& layout,
                               const SolidAssembler& solids, const ContactAssembly& contact)
    : problem_(problem), layout_(layout), solids_(solids), contact_(contact) {}

std::vector<std::string> PostProcessing::elementStressNames(int dimension, bool axisymmetric) {
  // Revolved about y (x = r): the out-of-plane component is the hoop stress σ_θθ.
  if (dimension == 2) return {"stress_xx", "stress_yy", axisymmetric ? "stress_hoop" : "stress_zz", "stress_xy", "von_mises"};
  return {"stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_xz", "von_mises"};
}

RCP<MultiVector> PostProcessing::elementStresses(const double* u) const {
  const int dim = layout_.dimension();
  const auto sigmas = solids_.elementStresses(u);
  const auto names = elementStressNames(dim, problem_.axisymmetric);
  auto out = rcp(new MultiVector(layout_.elementMap(), names.size()));
  const std::vector<std::pair<int, int>> comps = dim == 2
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

std::vector<NodeSetReaction> PostProcessing::reactions(const Vector& netForce) const {
  const int dim = layout_.dimension();
  const Map& owned = *layout_.ownedMap();
  auto fv = netForce.getData(0);
  std::vector<NodeSetReaction> out;
  for (const auto& name : problem_.reactionNodeSets) {
    std::vector<double> local(dim, 0.0), global(dim, 0.0);
    // The part's nodes of the set (owned or not): each owned node's row counted once, by its owner.
    for (GO localNode : problem_.mesh.local().nodeSet(name).nodes)
      for (int c = 0; c < dim; ++c) {
        const LO lo = owned.getLocalElement(problem_.mesh.part.globalNodes[localNode] * dim + c);
        if (lo != Teuchos::OrdinalTraits<LO>::invalid()) local[c] += fv[lo];
      }
    Teuchos::reduceAll(*layout_.comm(), Teuchos::REDUCE_SUM, dim, local.data(), global.data());
    out.push_back({name, global});
  }
  return out;
}

std::vector<std::string> PostProcessing::contactFieldNames() {
  return {"contact_pressure", "contact_gap", "contact_status", "contact_slip"};
}

namespace {

// A mortar interface's nodal pressures as it reports them: at a closed node the traction field's mean
// over its support, eq. (M6′) (contact/MortarPressureRecovery.hpp), from every slave node's p_k; an open
// node keeps 0, so that contact_pressure > 0 exactly where contact_status is closed (the first open node
// beside a closed one carries part of its neighbour's traction, which this output leaves out). Forces are
// not touched. Collective: a node's support may be evaluated on other ranks (each node on exactly one).
void reportMortarPressures(const contact::ContactInterfaceBase& interface, const Comm& comm,
                           std::vector<contact::SlaveNodeState>& states) {
  const auto& evaluates = interface.evaluatesSlave();
  std::vector<double> local(states.size(), 0.0), global(states.size(), 0.0);
  for (std::size_t k = 0; k < states.size(); ++k)
    if (evaluates[k]) local[k] = states[k].pressure;
  if (!local.empty()) Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), global.data());
  const std::vector<double> reported = contact::mortarPressureRecovery(interface.spec()).apply(global);
  for (std::size_t k = 0; k < states.size(); ++k)
    if (evaluates[k] && states[k].status != contact::ContactStatus::Open) states[k].pressure = reported[k];
}

// The committed output of an interface's slave nodes, those on the axis of revolved 3-node edges recovered
// from their edge (contact::AxisNode: ∫ H 2πr ds weighs them by 0, they carry no force and their own ε_N g_N
// or multiplier is no pressure): pressure and gap a + b r² through the edge's mid node and far corner
// (contact::valueOnAxis), the status of the nearest of them in contact. Forces are not touched. Collective:
// the edge's nodes may be evaluated on other ranks.
std::vector<contact::SlaveNodeState> outputStates(const contact::ContactInterfaceBase& interface, const Comm& comm) {
  std::vector<contact::SlaveNodeState> states = interface.committedStates();
  if (interface.spec().mortar) reportMortarPressures(interface, comm, states);
  const auto& axis = interface.spec().slaveAxisNodes;
  if (axis.empty()) return states;
  // Per axis node, for its mid node then its far corner: pressure, gap, status, from the rank evaluating each.
  constexpr int kFields = 3;
  std::vector<double> local(2 * kFields * axis.size(), 0.0), global(local.size(), 0.0);
  for (std::size_t i = 0; i < axis.size(); ++i) {
    const std::size_t neighbours[2] = {axis[i].mid, axis[i].far};
    for (int j = 0; j < 2; ++j) {
      if (!interface.evaluatesSlave()[neighbours[j]]) continue;
      const auto& st = states[neighbours[j]];
      double* to = &local[(2 * i + j) * kFields];
      to[0] = st.pressure;
      to[1] = st.gap;
      to[2] = static_cast<double>(static_cast<int>(st.status));
    }
  }
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, static_cast<int>(local.size()), local.data(), global.data());
  for (std::size_t i = 0; i < axis.size(); ++i) {
    const double* mid = &global[2 * kFields * i];
    const double* far = mid + kFields;
    auto& st = states[axis[i].node];
    st.pressure = std::max(0.0, contact::valueOnAxis(axis[i], mid[0], far[0]));
    if (std::isfinite(mid[1]) && std::isfinite(far[1])) st.gap = contact::valueOnAxis(axis[i], mid[1], far[1]);
    st.status = st.pressure <= 0.0 ? contact::ContactStatus::Open
                                   : static_cast<contact::ContactStatus>(static_cast<int>(mid[2] != 0.0 ? mid[2] : far[2]));
  }
  return states;
}

}  // namespace

RCP<MultiVector> PostProcessing::contactNodalFields() const {
  const auto& nodeMap = layout_.nodeMap();
  auto out = rcp(new MultiVector(nodeMap, 4));
  for (const auto& interface : contact_.interfaces()) {
    const auto& spec = interface->spec();
    const auto states = outputStates(*interface, *layout_.comm());
    for (std::size_t k = 0; k < spec.slaveNodes.size(); ++k) {
      if (!interface->evaluatesSlave()[k]) continue;
      const LO lo = nodeMap->getLocalElement(spec.slaveNodes[k]);
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

contact::ContactCounts PostProcessing::contactCounts() const {
  int local[4] = {0, 0, 0, 0}, global[4] = {0, 0, 0, 0};
  for (const auto& interface : contact_.interfaces()) {
    const auto c = interface->committedCounts();
    local[0] += c.active;
    local[1] += c.newlyActive;
    local[2] += c.stick;
    local[3] += c.slip;
  }
  Teuchos::reduceAll(*layout_.comm(), Teuchos::REDUCE_SUM, 4, local, global);
  return {global[0], global[1], global[2], global[3]};
}

std::vector<std::pair<std::string, std::vector<double>>> PostProcessing::contactForces() const {
  const int dim = layout_.dimension();
  std::vector<std::pair<std::string, std::vector<double>>> out;
  for (const auto& spec : problem_.contacts) {
    if (out.empty() || out.back().first != spec.name) out.push_back({spec.name, std::vector<double>(dim, 0.0)});
  }
  for (const auto& interface : contact_.interfaces()) {
    const std::string& name = interface->spec().name;
    const auto& f = interface->committedSlaveForce();
    for (auto& [n, total] : out)
      if (n == name) {
        // The second pass pushes the other body: the force on the first slave body is its opposite.
        const double sign = interface->spec().secondPass ? -1.0 : 1.0;
        for (int c = 0; c < dim; ++c) total[c] += sign * f[c];
      }
  }
  for (auto& [n, total] : out) {
    std::vector<double> g(dim);
    Teuchos::reduceAll(*layout_.comm(), Teuchos::REDUCE_SUM, dim, total.data(), g.data());
    total = g;
  }
  return out;
}

std::vector<std::pair<std::string, contact::RegularisationMeasures>> PostProcessing::contactRegularisation(
    const Vector& x) const {
  const int dim = layout_.dimension();
  const Map& owned = *layout_.ownedMap();
  const auto u = x.getData(0);
  std::vector<std::pair<std::string, contact::RegularisationMeasures>> out;
  for (const auto& spec : problem_.contacts)
    if (out.empty() || out.back().first != spec.name) out.push_back({spec.name, {}});
  for (const auto& interface : contact_.interfaces()) {
    const auto& spec = interface->spec();
    contact::RegularisationMeasures m = interface->committedRegularisation();
    for (std::size_t k = 0; k < spec.slaveNodes.size(); ++k) {
      if (!interface->evaluatesSlave()[k]) continue;
      double square = 0.0;
      for (int c = 0; c < dim; ++c) {
        const LO lo = owned.getLocalElement(spec.slaveNodes[k] * dim + c);
        if (lo != Teuchos::OrdinalTraits<LO>::invalid()) square += u[lo] * u[lo];
      }
      m.displacementScale = std::max(m.displacementScale, std::sqrt(square));
    }
    for (auto& [name, total] : out)
      if (name == spec.name) total.include(m);
  }
  for (auto& [name, total] : out) {
    double largest[4] = {total.penetration, total.elasticSlip, total.slip, total.displacementScale};
    double sums[2] = {total.slippingNodes, total.slipSum};
    double globalLargest[4], globalSums[2];
    Teuchos::reduceAll(*layout_.comm(), Teuchos::REDUCE_MAX, 4, largest, globalLargest);
    Teuchos::reduceAll(*layout_.comm(), Teuchos::REDUCE_SUM, 2, sums, globalSums);
    total.penetration = globalLargest[0];
    total.elasticSlip = globalLargest[1];
    total.slip = globalLargest[2];
    total.displacementScale = globalLargest[3];
    total.slippingNodes = globalSums[0];
    total.slipSum = globalSums[1];
  }
  return out;
}

namespace {
// Every rank needs every slave node's change to sort the β^k of eq. (12): gather them all, as
// continuation::SlaveNodeIncrement (12 numbers each), in rank order.
std::vector<continuation::SlaveNodeIncrement> gatherAll(const Comm& comm, const std::vector<contact::SlaveNodeChange>& local) {
  constexpr int kFields = 12;
  std::vector<double> packed;
  for (const auto& c : local) {
    packed.insert(packed.end(), {c.committedGap, c.trialGap, static_cast<double>(static_cast<int>(c.committedStatus)),
                                 static_cast<double>(static_cast<int>(c.trialStatus)), c.committedIndicator,
                                 c.trialIndicator, c.slipReversed ? 1.0 : 0.0, static_cast<double>(c.trialFacet),
                                 static_cast<double>(c.trialContactKind), static_cast<double>(c.trialContactNodes[0]),
                                 static_cast<double>(c.trialContactNodes[1]), c.frictional ? 1.0 : 0.0});
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
    n.trialContactKind = static_cast<int>(all[i + 8]);
    n.trialContactNodes[0] = static_cast<int>(all[i + 9]);
    n.trialContactNodes[1] = static_cast<int>(all[i + 10]);
    n.frictional = all[i + 11] != 0.0;
    out.push_back(n);
  }
  return out;
}
}  // namespace

std::vector<continuation::SlaveNodeIncrement> PostProcessing::trialIncrement() const {
  return gatherAll(*layout_.comm(), contact_.trialChanges());
}

std::vector<continuation::SlaveNodeIncrement> PostProcessing::incrementAt(const double* u, double loadFactor) const {
  return gatherAll(*layout_.comm(), contact_.changesAt(u, loadFactor));
}

std::vector<continuation::SlaveNodeIncrement> PostProcessing::committedIncrement() const {
  return gatherAll(*layout_.comm(), contact_.committedIncrement());
}

}  // namespace contessa::model
