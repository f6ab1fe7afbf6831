#include "model/SolidAssembler.hpp"

#include "common/Error.hpp"

#include <map>

namespace contessa::model {

SolidAssembler::SolidAssembler(const deck::ProblemDefinition& problem, std::vector<GlobalIndex> elements,
                               const std::function<int(GlobalIndex)>& localDof)
    : elements_(std::move(elements)) {
  const mesh::Mesh& mesh = problem.mesh;
  const int dim = mesh.dimension;
  std::map<int, int> setOfBlock;           // mesh block → index into sets_
  std::vector<std::vector<double>> setX;   // reference coordinates of each set's elements
  std::size_t stateSize = 0;
  data_.reserve(elements_.size());
  for (GlobalIndex e : elements_) {
    const auto loc = mesh.locate(e);
    const mesh::ElementBlock& block = mesh.blocks[loc.block];
    const deck::BlockPhysics& physics = problem.blocks[loc.block];
    const auto [it, added] = setOfBlock.emplace(static_cast<int>(loc.block), static_cast<int>(sets_.size()));
    if (added) {
      sets_.push_back({&physics, nullptr});
      setX.emplace_back();
    }
    const int nn = mesh::nodesPerCell(block.cellType);
    ElementData d;
    d.set = it->second;
    d.indexInSet = static_cast<int>(setX[d.set].size() / (nn * dim));
    d.numDofs = nn * dim;
    d.dofOffset = dofs_.size();
    d.stateOffset = stateSize;
    for (int a = 0; a < nn; ++a) {
      const GlobalIndex node = block.connectivity[loc.local * nn + a];
      for (int c = 0; c < dim; ++c) {
        setX[d.set].push_back(mesh.coordinates[node * dim + c]);
        dofs_.push_back(localDof(node * dim + c));
      }
    }
    stateSize += physics.element->numStateValues();
    maxDofs_ = std::max(maxDofs_, d.numDofs);
    data_.push_back(d);
  }
  for (std::size_t s = 0; s < sets_.size(); ++s) {
    const auto& element = *sets_[s].physics->element;
    const int count = static_cast<int>(setX[s].size() / element.numDofs());
    sets_[s].geometry = element.referenceGeometry(count, setX[s].data());
  }
  trial_.assign(stateSize, 0.0);
  committed_ = trial_;
}

SolidAssembler::Status SolidAssembler::assemble(const double* u, bool withStiffness, const Sink& sink) {
  std::vector<double> ue(maxDofs_), fe(maxDofs_), ke(withStiffness ? maxDofs_ * maxDofs_ : 0);
  Status status;
  for (std::size_t k = 0; k < data_.size(); ++k) {
    const auto& d = data_[k];
    const ElementSet& set = sets_[d.set];
    const int* dofs = dofs_.data() + d.dofOffset;
    for (int i = 0; i < d.numDofs; ++i) ue[i] = u[dofs[i]];
    const auto s = set.physics->element->evaluate(*set.geometry, d.indexInSet, ue.data(), trial_.data() + d.stateOffset,
                                                  *set.physics->material, fe.data(),
                                                  withStiffness ? ke.data() : nullptr);
    if (s != mechanics::ElementStatus::Ok) {
      if (status.ok()) status = {s, elements_[k]};
      continue;
    }
    sink(dofs, d.numDofs, fe.data(), withStiffness ? ke.data() : nullptr);
  }
  return status;
}

std::vector<mechanics::Tensor2> SolidAssembler::elementStresses(const double* u) const {
  std::vector<mechanics::Tensor2> out(data_.size());
  std::vector<double> ue(maxDofs_);
  for (std::size_t k = 0; k < data_.size(); ++k) {
    const auto& d = data_[k];
    const ElementSet& set = sets_[d.set];
    const int* dofs = dofs_.data() + d.dofOffset;
    for (int i = 0; i < d.numDofs; ++i) ue[i] = u[dofs[i]];
    // The committed internal variables: the first values of the element's committed state.
    mechanics::Tensor2 sigma{};
    if (set.physics->element->averageCauchyStress(*set.geometry, d.indexInSet, ue.data(),
                                                  committed_.data() + d.stateOffset, *set.physics->material,
                                                  sigma) != mechanics::ElementStatus::Ok)
      sigma.fill(std::numeric_limits<double>::quiet_NaN());
    out[k] = sigma;
  }
  return out;
}

std::vector<double> SolidAssembler::committedState(std::size_t i) const {
  const auto begin = committed_.begin() + static_cast<std::ptrdiff_t>(data_[i].stateOffset);
  return {begin, begin + static_cast<std::ptrdiff_t>(stateSize(i))};
}

void SolidAssembler::restoreState(std::size_t i, const std::vector<double>& values) {
  requireInput(values.size() == stateSize(i), "restart file: element " + std::to_string(elements_[i] + 1) + " has " +
                                                  std::to_string(values.size()) + " state values, its element type " +
                                                  std::to_string(stateSize(i)));
  std::copy(values.begin(), values.end(), committed_.begin() + static_cast<std::ptrdiff_t>(data_[i].stateOffset));
  std::copy(values.begin(), values.end(), trial_.begin() + static_cast<std::ptrdiff_t>(data_[i].stateOffset));
}

}  // namespace contessa::model
