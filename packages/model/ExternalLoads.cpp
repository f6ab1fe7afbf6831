#include "model/ExternalLoads.hpp"

#include <map>
#include <stdexcept>
#include <string>

namespace contessa::model {
namespace {

using mesh::GlobalIndex;

// Appends the overlapped DOFs and reference coordinates of the local nodes `nodes` to `entries`.
template <class Entries>
void appendNodes(Entries& entries, const std::vector<GlobalIndex>& nodes, const deck::ProblemDefinition& problem,
                 const std::function<int(GlobalIndex)>& localDof) {
  const mesh::Mesh& mesh = problem.mesh.local();
  const int dim = mesh.dimension;
  for (GlobalIndex node : nodes)
    for (int c = 0; c < dim; ++c) {
      entries.X.push_back(mesh.coordinates[node * dim + c]);
      entries.dofs.push_back(localDof(problem.mesh.part.globalNodes[node] * dim + c));
    }
  entries.nodes = static_cast<int>(nodes.size());
  ++entries.count;
}

}  // namespace

ExternalLoads::ExternalLoads(const deck::ProblemDefinition& problem, const std::function<int(GlobalIndex)>& localDof)
    : dim_(problem.dimension()) {
  // A solid of revolution (Axisymmetry.hpp) takes its loads over the full circumference: w = 2πr.
  if (problem.axisymmetric) measure_ = std::make_unique<mechanics::RevolvedMeasure>();
  else measure_ = std::make_unique<mechanics::UnitMeasure>(dim_);
  const mesh::Mesh& mesh = problem.mesh.local();  // the part: local numbering, its own elements' sides
  for (const auto& load : problem.loads) {
    Entries entries;
    entries.name = load.name;
    entries.change = load.type == deck::LoadType::Pressure ? std::vector<double>{load.pressure} : load.vector;
    entries.start.assign(entries.change.size(), 0.0);
    if (load.type == deck::LoadType::Pressure || load.type == deck::LoadType::Traction) {
      const mesh::SideSet& set = mesh.sideSet(load.set);
      // One Entries per side shape: the entries of one hold sides of one node count, and a side set may mix
      // them (a wedge's triangles and quadrilaterals, the sides of blocks of different families).
      std::map<int, Entries> bySize;
      for (std::size_t k = 0; k < set.elements.size(); ++k) {
        const auto where = mesh.locate(set.elements[k]);
        const mesh::ElementBlock& block = mesh.blocks[where.block];
        const int npe = mesh::nodesPerCell(block.cellType);
        std::vector<GlobalIndex> nodes;
        for (int a : mesh::sideNodes(block.cellType, set.sides[k])) nodes.push_back(block.connectivity[where.local * npe + a]);
        // The kernels take the sides of every cell family (mechanics::isLoadFacet).
        if (!mechanics::isLoadFacet(dim_, static_cast<int>(nodes.size())))
          throw std::logic_error("ExternalLoads: a side of " + std::to_string(nodes.size()) + " nodes in side set '" +
                                 load.set + "', which no load kernel takes");
        auto group = bySize.try_emplace(static_cast<int>(nodes.size()), entries).first;
        appendNodes(group->second, nodes, problem, localDof);
      }
      for (auto& [size, facets] : bySize)
        (load.type == deck::LoadType::Pressure ? pressureFacets_ : tractionFacets_).push_back(std::move(facets));
    } else if (load.type == deck::LoadType::BodyForce) {
      for (const auto& name : load.blocks) {
        const mesh::ElementBlock& block = mesh.block(name);
        const int npe = mesh::nodesPerCell(block.cellType);
        // The deck refuses a cell no kernel takes (deck/LoadDefinitions.cpp); this is the model's own guard.
        if (!mechanics::isLoadCell(dim_, npe))
          throw std::logic_error("ExternalLoads: block '" + name + "' has " + std::to_string(npe) +
                                 "-node cells, which no body-force kernel takes");
        // One Entries per block: the entries of one hold cells of one node count, and the blocks of a
        // mesh may mix families (triangles and quadrilaterals, tetrahedra and wedges).
        Entries cells = entries;
        for (GlobalIndex e = 0; e < block.numElements(); ++e)
          appendNodes(cells, std::vector<GlobalIndex>(block.connectivity.begin() + e * npe,
                                                      block.connectivity.begin() + (e + 1) * npe),
                      problem, localDof);
        if (cells.count > 0) bodyCells_.push_back(std::move(cells));
      }
    }  // springs are supports, not loads: BoundaryConditions
  }
}

void ExternalLoads::setStepValues(const std::function<std::vector<double>(const std::string&)>& start,
                                  const std::function<std::vector<double>(const std::string&)>& change) {
  for (auto* group : {&pressureFacets_, &tractionFacets_, &bodyCells_})
    for (auto& entries : *group) {
      entries.start = start(entries.name);
      entries.change = change(entries.name);
    }
}

void ExternalLoads::addDeadLoads(double* f, bool change) const {
  std::vector<double> fe;
  const auto add = [&](const Entries& entries, bool cells) {
    const std::vector<double>& value = change ? entries.change : entries.start;
    const int n = entries.nodes * dim_;
    fe.resize(static_cast<std::size_t>(n));
    for (std::size_t k = 0; k < entries.count; ++k) {
      const double* X = entries.X.data() + k * n;
      if (cells) {
        if (dim_ == 2) mechanics::bodyForce<2>(entries.nodes, X, value.data(), *measure_, fe.data());
        else mechanics::bodyForce<3>(entries.nodes, X, value.data(), *measure_, fe.data());
      } else {
        if (dim_ == 2) mechanics::facetTraction<2>(entries.nodes, X, value.data(), *measure_, fe.data());
        else mechanics::facetTraction<3>(entries.nodes, X, value.data(), *measure_, fe.data());
      }
      for (int i = 0; i < n; ++i) f[entries.dofs[k * n + i]] += fe[i];
    }
  };
  for (const auto& entries : tractionFacets_) add(entries, false);
  for (const auto& entries : bodyCells_) add(entries, true);
}

void ExternalLoads::assembleFollowerLoads(const double* u, double a, double slope, double* force,
                                          double* dForcedLambda, const StiffnessSink* stiffness) const {
  std::vector<double> x, fe, ke, fe0, ke0;
  for (const auto& entries : pressureFacets_) {
    const int n = entries.nodes * dim_;
    x.resize(static_cast<std::size_t>(n));
    fe.resize(static_cast<std::size_t>(n));
    fe0.resize(static_cast<std::size_t>(n));
    ke.resize(stiffness ? static_cast<std::size_t>(n * n) : 0);
    ke0.resize(ke.size());
    const double p0 = entries.start[0], dp = entries.change[0];
    for (std::size_t k = 0; k < entries.count; ++k) {
      const int* dofs = entries.dofs.data() + k * n;
      for (int i = 0; i < n; ++i) x[i] = entries.X[k * n + i] + u[dofs[i]];  // current position
      double* K = stiffness ? ke.data() : nullptr;
      facetPressure(entries.nodes, x.data(), dp, fe.data(), K);
      // f_p is linear in p: f_p(p_0 + a Δp) = f_p(p_0) + a f_p(Δp), ∂/∂λ = a' f_p(Δp); the residual
      // carries −f_ext. Without load steps p_0 = 0 and a = λ.
      for (int i = 0; i < n; ++i) {
        force[dofs[i]] -= a * fe[i];
        dForcedLambda[dofs[i]] -= slope * fe[i];
      }
      if (K) for (double& v : ke) v *= -a;
      if (p0 != 0.0) {
        facetPressure(entries.nodes, x.data(), p0, fe0.data(), K ? ke0.data() : nullptr);
        for (int i = 0; i < n; ++i) force[dofs[i]] -= fe0[i];
        if (K) for (std::size_t i = 0; i < ke.size(); ++i) ke[i] -= ke0[i];
      }
      if (K) (*stiffness)(dofs, n, K);
    }
  }
}

void ExternalLoads::facetPressure(int nodes, const double* x, double p, double* fe, double* K) const {
  if (dim_ == 2) mechanics::followerPressure<2>(nodes, x, p, *measure_, fe, K);
  else mechanics::followerPressure<3>(nodes, x, p, *measure_, fe, K);
}

}  // namespace contessa::model
