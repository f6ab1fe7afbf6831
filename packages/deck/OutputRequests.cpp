#include "deck/OutputRequests.hpp"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <Teuchos_Array.hpp>

#include "common/Error.hpp"
#include "deck/ParameterValidation.hpp"
#include "deck/ProblemDefinition.hpp"
#include "mesh/MeshDistribution.hpp"

namespace contessa::deck {
namespace {

using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;

const std::vector<std::pair<std::string, HistoryQuantity>> kQuantities = {
    {"Displacement", HistoryQuantity::Displacement},
    {"Reaction Force", HistoryQuantity::ReactionForce},
    {"Applied Force", HistoryQuantity::AppliedForce},
    {"Contact Pressure", HistoryQuantity::ContactPressure},
    {"Contact Slip", HistoryQuantity::ContactSlip},
};

std::string joinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

bool isContactQuantity(HistoryQuantity q) {
  return q == HistoryQuantity::ContactPressure || q == HistoryQuantity::ContactSlip;
}

// MPI_Allreduce over the mesh's communicator in place, skipped on one rank (a unit test may run without MPI).
void allReduce(const mesh::DistributedMesh& mesh, void* values, int count, MPI_Datatype type, MPI_Op op) {
  if (mesh::ranksOf(mesh.comm).size > 1) MPI_Allreduce(MPI_IN_PLACE, values, count, type, op, mesh.comm);
}

// The node nearest `x` over every rank's part (reference coordinates; of two at the same distance, the
// lower global id), the same on every rank. Collective over the mesh's communicator.
mesh::GlobalIndex nearestMeshNode(const mesh::DistributedMesh& mesh, const std::vector<double>& x) {
  const mesh::Mesh& local = mesh.local();
  const int dim = local.dimension;
  double best = std::numeric_limits<double>::infinity();
  long long bestId = std::numeric_limits<long long>::max();
  for (std::size_t n = 0; n < mesh.part.globalNodes.size(); ++n) {
    double d2 = 0;
    for (int c = 0; c < dim; ++c) d2 += std::pow(local.coordinates[n * dim + c] - x[c], 2);
    const long long id = mesh.part.globalNodes[n];
    if (d2 < best || (d2 == best && id < bestId)) {
      best = d2;
      bestId = id;
    }
  }
  double nearest = best;
  allReduce(mesh, &nearest, 1, MPI_DOUBLE, MPI_MIN);
  long long id = best == nearest ? bestId : std::numeric_limits<long long>::max();
  allReduce(mesh, &id, 1, MPI_LONG_LONG, MPI_MIN);
  return id;
}

// The reference coordinates of a node on every rank: its holders send them (the others zeros), summed
// once per holder and divided by their number. Collective over the mesh's communicator.
std::vector<double> nodeCoordinates(const mesh::DistributedMesh& mesh, mesh::GlobalIndex node) {
  const int dim = mesh.local().dimension;
  std::vector<double> sum(dim + 1, 0.0);
  const auto& ids = mesh.part.globalNodes;  // ascending
  const auto at = std::lower_bound(ids.begin(), ids.end(), node);
  if (at != ids.end() && *at == node) {
    const auto n = static_cast<std::size_t>(at - ids.begin());
    for (int c = 0; c < dim; ++c) sum[c] = mesh.local().coordinates[n * dim + c];
    sum[dim] = 1;
  }
  allReduce(mesh, sum.data(), dim + 1, MPI_DOUBLE, MPI_SUM);
  for (int c = 0; c < dim; ++c) sum[c] /= sum[dim];
  sum.resize(dim);
  return sum;
}

// The slave node of the interface nearest `x` (every pass of it; the contact nodes' coordinates are on
// every rank) and its coordinates.
std::pair<mesh::GlobalIndex, std::vector<double>> nearestSlaveNode(const ProblemDefinition& problem,
                                                                   const std::string& interface,
                                                                   const std::vector<double>& x) {
  const int dim = problem.dimension();
  double best = std::numeric_limits<double>::infinity();
  std::pair<mesh::GlobalIndex, std::vector<double>> nearest{-1, {}};
  for (const auto& spec : problem.contacts) {
    if (spec.name != interface) continue;
    for (mesh::GlobalIndex node : spec.slaveNodes) {
      const auto at = std::lower_bound(problem.contactNodes.begin(), problem.contactNodes.end(), node);
      const auto k = static_cast<std::size_t>(at - problem.contactNodes.begin());
      const double* y = problem.contactNodeCoordinates.data() + k * dim;
      double d2 = 0;
      for (int c = 0; c < dim; ++c) d2 += std::pow(y[c] - x[c], 2);
      if (d2 < best || (d2 == best && node < nearest.first)) {
        best = d2;
        nearest = {node, std::vector<double>(y, y + dim)};
      }
    }
  }
  return nearest;
}

// Where a request measures: a node set, or the node nearest Coordinates (exactly one of them); a contact
// quantity at an interface's slave node.
void resolvePlace(HistoryRequest& request, const ParameterList& list, ProblemDefinition& problem,
                  const std::string& where) {
  const mesh::Mesh& mesh = problem.mesh.local();
  const int dim = mesh.dimension;
  const auto& x = list.get<Teuchos::Array<double>>("Coordinates");
  const bool contact = isContactQuantity(request.quantity);
  const std::string quantity = list.get<std::string>("Quantity");
  request.nodeSet = list.get<std::string>("Node Set");
  request.interface = list.get<std::string>("Interface");
  requireInput(x.empty() || static_cast<int>(x.size()) == dim,
               where + "/Coordinates: expected " + std::to_string(dim) + " values (" + (dim == 2 ? "x, y" : "x, y, z") +
                   "), got " + std::to_string(x.size()));
  if (contact) {
    requireInput(request.nodeSet.empty(), where + "/Node Set: not taken by Quantity " + quantity +
                                              " (it is measured at the slave node nearest Coordinates)");
    std::vector<std::string> known;
    for (const auto& spec : problem.contacts)
      if (!spec.secondPass) known.push_back(spec.name);
    requireInput(!request.interface.empty(), where + "/Interface: required for Quantity " + quantity +
                                                 " (a sublist of Problem/Contact: " + joinNames(known) + ")");
    requireInput(std::find(known.begin(), known.end(), request.interface) != known.end(),
                 where + "/Interface: '" + request.interface + "' is not a contact interface (known: " +
                     joinNames(known) + ")");
    requireInput(!x.empty(), where + "/Coordinates: required for Quantity " + quantity +
                                 " (the slave node nearest them is measured)");
    std::tie(request.node, request.nodeCoordinates) =
        nearestSlaveNode(problem, request.interface, std::vector<double>(x.begin(), x.end()));
    return;
  }
  requireInput(request.interface.empty(), where + "/Interface: not taken by Quantity " + quantity);
  const bool setOnly = request.quantity != HistoryQuantity::Displacement;
  requireInput(!(setOnly && !x.empty()), where + "/Coordinates: not taken by Quantity " + quantity +
                                             " (a force is summed over a Node Set)");
  requireInput(request.nodeSet.empty() != x.empty(),
               where + (setOnly ? "/Node Set: required for Quantity " + quantity
                                : ": give either Node Set or Coordinates (the node nearest them)"));
  if (!request.nodeSet.empty()) {
    if (mesh.hasNodeSet(request.nodeSet)) return;
    std::vector<std::string> known;
    for (const auto& ns : mesh.nodeSets) known.push_back(ns.name);
    throw InputError(where + "/Node Set: node set '" + request.nodeSet + "' does not exist in the mesh (known: " +
                     joinNames(known) + ")");
  }
  request.node = nearestMeshNode(problem.mesh, std::vector<double>(x.begin(), x.end()));
  request.nodeCoordinates = nodeCoordinates(problem.mesh, request.node);
}

}  // namespace

std::vector<std::string> HistoryRequest::columns(int dimension) const {
  std::string base = name;
  for (auto& c : base)
    if (c == ' ' || c == ',') c = '_';
  if (!isVector()) return {base};
  const char* axes[] = {"x", "y", "z"};
  std::vector<std::string> out;
  for (int c = 0; c < dimension; ++c) out.push_back(base + "_" + axes[c]);
  return out;
}

std::vector<std::string> historyQuantityNames() {
  std::vector<std::string> names;
  for (const auto& [name, quantity] : kQuantities) names.push_back(name);
  return names;
}

RCP<const ParameterList> historyRequestValidParameters() {
  auto p = rcp(new ParameterList("History Request"));
  setChoice(*p, "Quantity", "Displacement", historyQuantityNames(),
            "What is written every increment: Displacement (of the node nearest Coordinates, or the mean over "
            "Node Set; columns <name>_x, <name>_y[, <name>_z]), Reaction Force (summed over Node Set, as Reaction "
            "Node Sets), Applied Force (the Nodal Forces and the loads of Problem/Loads on Node Set's nodes, summed), Contact "
            "Pressure or Contact Slip (accumulated slip) at the slave node of Interface nearest Coordinates "
            "(column <name>)");
  p->set("Node Set", std::string(""), "Node set measured (Displacement: its mean; the forces: their sum)");
  p->set("Coordinates", Teuchos::Array<double>(),
         "x, y[, z]: the node nearest this point in the reference configuration is measured (Displacement: "
         "instead of Node Set; contact quantities: the nearest slave node of Interface)");
  p->set("Interface", std::string(""), "Contact quantities: a sublist of Problem/Contact");
  return p;
}

RCP<const ParameterList> historyListValidParameters() {
  auto p = rcp(new ParameterList("History"));
  p->sublist("<name>", false, "One sublist per request, named as its history columns and Exodus globals begin")
      .setParameters(*historyRequestValidParameters());
  return p;
}

std::vector<HistoryRequest> buildHistoryRequests(ParameterList& history, ProblemDefinition& problem) {
  const std::string path = "Problem/Output/History";
  std::vector<std::string> names;
  for (auto it = history.begin(); it != history.end(); ++it) {
    const std::string& name = history.name(it);
    requireInput(history.isSublist(name), path + "/" + name + ": expected a sublist (one per history request)");
    names.push_back(name);
  }
  std::vector<HistoryRequest> requests;
  for (const auto& name : names) {
    const std::string where = path + "/" + name;
    auto& list = history.sublist(name);
    validateAndSetDefaults(list, *historyRequestValidParameters(), where);
    HistoryRequest request;
    request.name = name;
    const std::string quantity = list.get<std::string>("Quantity");
    for (const auto& [n, q] : kQuantities)
      if (n == quantity) request.quantity = q;
    resolvePlace(request, list, problem, where);
    auto& sets = problem.reactionNodeSets;
    if (request.quantity == HistoryQuantity::ReactionForce &&
        std::find(sets.begin(), sets.end(), request.nodeSet) == sets.end()) {
      sets.push_back(request.nodeSet);
      request.addedReactionSet = true;
    }
    requests.push_back(std::move(request));
  }
  return requests;
}

}  // namespace contessa::deck
