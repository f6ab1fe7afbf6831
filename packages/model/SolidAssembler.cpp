#include "model/SolidAssembler.hpp"

#include "common/Error.hpp"

namespace contessa::model {

SolidAssembler::SolidAssembler(const deck::ProblemDefinition& problem, const std::function<int(GlobalIndex)>& localDof)
    : elements_(problem.mesh.part.globalElements) {
  const mesh::Mesh& mesh = problem.mesh.local();  // local numbering; global ids beside
  const auto& globalNodes = problem.mesh.part.globalNodes;
  const int dim = mesh.dimension;
  std::vector<std::vector<double>> setX;  // reference coordinates of each set's elements
  std::size_t stateSize = 0;
  data_.reserve(elements_.size());
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const mesh::ElementBlock& block = mesh.blocks[b];
    if (block.elements.empty()) continue;
    const deck::BlockPhysics& physics = problem.blocks[b];
    const int set = static_cast<int>(sets_.size());
    sets_.push_back({&physics, nullptr});
    setX.emplace_back();
    const int nn = mesh::nodesPerCell(block.cellType);
    for (GlobalIndex k = 0; k < block.numElements(); ++k) {
      ElementData d;
      d.set = set;
      d.indexInSet = static_cast<int>(k);
      d.numDofs = nn * dim;
      d.dofOffset = dofs_.size();
      d.stateOffset = stateSize;
      for (int a = 0; a < nn; ++a) {
        const GlobalIndex node = block.connectivity[k * nn + a];
        const GlobalIndex globalNode = globalNodes[node];
        for (int c = 0; c < dim; ++c) {
          setX[set].push_back(mesh.coordinates[node * dim + c]);
          dofs_.push_back(localDof(globalNode * dim + c));
        }
      }
      stateSize += physics.element->numStateValues();
      maxDofs_ = std::max(maxDofs_, d.numDofs);
      data_.push_back(d);
    }
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
