#include "model/SolidAssembler.hpp"

namespace contessa::model {

SolidAssembler::SolidAssembler(const deck::ProblemDefinition& problem, std::vector<GlobalIndex> elements,
                               const std::function<int(GlobalIndex)>& localDof)
    : elements_(std::move(elements)) {
  const mesh::Mesh& mesh = problem.mesh;
  const int dim = mesh.dimension;
  std::size_t internalSize = 0;
  data_.reserve(elements_.size());
  for (GlobalIndex e : elements_) {
    const auto loc = mesh.locate(e);
    const mesh::ElementBlock& block = mesh.blocks[loc.block];
    const deck::BlockPhysics& physics = problem.blocks[loc.block];
    const int nn = mesh::nodesPerCell(block.cellType);
    ElementData d;
    d.physics = &physics;
    d.X.resize(nn * dim);
    d.dofs.resize(nn * dim);
    for (int a = 0; a < nn; ++a) {
      const GlobalIndex node = block.connectivity[loc.local * nn + a];
      for (int c = 0; c < dim; ++c) {
        d.X[a * dim + c] = mesh.coordinates[node * dim + c];
        d.dofs[a * dim + c] = localDof(node * dim + c);
      }
    }
    d.internalOffset = internalSize;
    internalSize += physics.element->numInternalVariables();
    maxDofs_ = std::max(maxDofs_, nn * dim);
    data_.push_back(std::move(d));
  }
  trial_.assign(internalSize, 0.0);
  committed_ = trial_;
}

SolidAssembler::Status SolidAssembler::assemble(const double* u, bool withStiffness, const Sink& sink) {
  std::vector<double> ue(maxDofs_), fe(maxDofs_), ke(withStiffness ? maxDofs_ * maxDofs_ : 0);
  Status status;
  for (std::size_t k = 0; k < data_.size(); ++k) {
    auto& d = data_[k];
    const int n = static_cast<int>(d.dofs.size());
    for (int i = 0; i < n; ++i) ue[i] = u[d.dofs[i]];
    double* internal = trial_.empty() ? nullptr : trial_.data() + d.internalOffset;
    const auto s = d.physics->element->evaluate(d.X.data(), ue.data(), internal, *d.physics->material, fe.data(),
                                                withStiffness ? ke.data() : nullptr);
    if (s != mechanics::ElementStatus::Ok) {
      if (status.ok()) status = {s, elements_[k]};
      continue;
    }
    sink(d.dofs.data(), n, fe.data(), withStiffness ? ke.data() : nullptr);
  }
  return status;
}

std::vector<mechanics::Tensor2> SolidAssembler::elementStresses(const double* u) const {
  std::vector<mechanics::Tensor2> out(data_.size());
  std::vector<double> ue(maxDofs_);
  for (std::size_t k = 0; k < data_.size(); ++k) {
    const auto& d = data_[k];
    for (std::size_t i = 0; i < d.dofs.size(); ++i) ue[i] = u[d.dofs[i]];
    const double* internal = committed_.empty() ? nullptr : committed_.data() + d.internalOffset;
    mechanics::Tensor2 sigma{};
    if (d.physics->element->averageCauchyStress(d.X.data(), ue.data(), internal, *d.physics->material, sigma) !=
        mechanics::ElementStatus::Ok)
      sigma.fill(std::numeric_limits<double>::quiet_NaN());
    out[k] = sigma;
  }
  return out;
}

}  // namespace contessa::model
