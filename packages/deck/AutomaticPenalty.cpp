#include "deck/AutomaticPenalty.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/Error.hpp"
#include "mesh/MeshDistribution.hpp"

namespace contessa::deck {
namespace {

/// The centroid of the given local nodes of `mesh`.
std::vector<double> centroid(const mesh::Mesh& mesh, const std::vector<mesh::GlobalIndex>& nodes) {
  const int dim = mesh.dimension;
  std::vector<double> c(dim, 0.0);
  for (auto n : nodes)
    for (int d = 0; d < dim; ++d) c[d] += mesh.coordinates[static_cast<std::size_t>(n * dim + d)] / nodes.size();
  return c;
}

}  // namespace

double planeStrainModulus(const mechanics::Material& material) {
  mechanics::Tensor2 F{}, P{};
  for (int i = 0; i < 3; ++i) F[mechanics::idx2(i, i)] = 1.0;
  mechanics::Tensor4 A{};
  if (!material.firstPiolaKirchhoff(F, P, &A)) return 0.0;
  const double lambda = A[mechanics::idx4(0, 0, 1, 1)];
  const double mu = A[mechanics::idx4(0, 1, 0, 1)];
  return 4.0 * mu * (lambda + mu) / (lambda + 2.0 * mu);
}

double largestStiffnessOverSize(const mesh::DistributedMesh& part, const std::vector<BlockPhysics>& blocks,
                                const std::string& sideSet) {
  const mesh::Mesh& mesh = part.local();
  double largest = 0.0;
  const auto& set = mesh.sideSet(sideSet);
  for (std::size_t i = 0; i < set.elements.size(); ++i) {
    const auto at = mesh.locate(set.elements[i]);
    const auto& block = mesh.blocks[static_cast<std::size_t>(at.block)];
    const auto physics = std::find_if(blocks.begin(), blocks.end(), [&](const BlockPhysics& b) { return b.block == block.name; });
    if (physics == blocks.end() || !physics->material) continue;
    const int perCell = mesh::nodesPerCell(block.cellType);
    std::vector<mesh::GlobalIndex> cell(block.connectivity.begin() + at.local * perCell,
                                        block.connectivity.begin() + (at.local + 1) * perCell);
    std::vector<mesh::GlobalIndex> side;
    for (int s : mesh::sideNodes(block.cellType, set.sides[i])) side.push_back(cell[static_cast<std::size_t>(s)]);
    const auto ce = centroid(mesh, cell), cs = centroid(mesh, side);
    double distance = 0.0;
    for (std::size_t d = 0; d < ce.size(); ++d) distance += (ce[d] - cs[d]) * (ce[d] - cs[d]);
    const double h = 2.0 * std::sqrt(distance);
    if (h > 0.0) largest = std::max(largest, planeStrainModulus(*physics->material) / h);
  }
  return part.numRanks > 1 ? mesh::overRanks(part.comm, largest).max : largest;  // one rank: MPI may not be running
}

void warnSoftAugmentedPenalty(const contact::ContactInterfaceSpec& spec, const Teuchos::ParameterList& list,
                              const mesh::DistributedMesh& mesh, const std::vector<BlockPhysics>& blocks) {
  if (!spec.law.isAugmented()) return;
  const std::string set = list.get<std::string>(spec.secondPass ? "Master Side Set" : "Slave Side Set");
  const double stiffness = largestStiffnessOverSize(mesh, blocks, set);  // collective
  // A frictionless interface's penalty grows at its first update, by up to kMaxPenaltyGrowth (theory-contact
  // eq. 15.5): what counts is the penalty after that growth.
  const double penalty = spec.law.largestNormalPenalty();
  const double growth = penalty / spec.law.normalPenalty;
  if (!(penalty < 0.1 * stiffness) || mesh.rank != 0) return;
  char grown[64] = "";
  if (growth > 1.0) std::snprintf(grown, sizeof grown, " (%.3g times it once grown)", growth);
  std::fprintf(stderr,
               "contessa: warning: contact interface '%s': Problem/Contact/%s/Normal Penalty %.3g%s is below a tenth "
               "of E'/h = %.3g under side set '%s': each augmented Lagrangian update removes only %.0f %% of a "
               "penetration and nodes held off the surface by their multipliers make the contact set chatter (give "
               "at least %.3g)\n",
               spec.label().c_str(), spec.name.c_str(), spec.law.normalPenalty, grown, stiffness, set.c_str(),
               100.0 * penalty / (penalty + stiffness), 0.1 * stiffness / growth);
  std::fflush(stderr);
}

void setAutomaticPenalties(std::vector<contact::ContactInterfaceSpec>& passes, const Teuchos::ParameterList& list,
                           const mesh::DistributedMesh& mesh, const std::vector<BlockPhysics>& blocks) {
  for (auto& spec : passes) {
    auto& law = spec.law;
    if (law.normalPenalty > 0.0) {  // given in the deck
      warnSoftAugmentedPenalty(spec, list, mesh, blocks);
      continue;
    }
    const std::string set = list.get<std::string>(spec.secondPass ? "Master Side Set" : "Slave Side Set");
    const double stiffness = largestStiffnessOverSize(mesh, blocks, set);
    requireInput(stiffness > 0.0, "Problem/Contact/" + spec.name + "/Normal Penalty: required here (no element "
                                  "stiffness found under the side set '" + set + "' for an automatic penalty)");
    const double factor = list.get<double>("Penalty Factor");
    law.normalPenalty = factor * stiffness;
    const bool constantStick = !law.isFrictionless() && !law.hasSlipTolerance() && law.tangentialPenalty == 0.0;
    if (constantStick) law.tangentialPenalty = law.normalPenalty;
    if (mesh.rank == 0)
      std::printf("contessa: contact interface '%s': automatic Normal Penalty %.4g = %g x %.4g, the largest E'/h "
                  "under side set '%s'%s\n",
                  spec.label().c_str(), law.normalPenalty, factor, stiffness, set.c_str(),
                  constantStick ? " (and Tangential Penalty, the same)" : "");
  }
}

}  // namespace contessa::deck
