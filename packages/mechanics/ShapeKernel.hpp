#pragma once
// What every solid kernel over a reference element Shape (ReferenceElement.hpp) says of itself, whatever
// its formulation: its name, dimension, node count, whether it is revolved, and the parent coordinates of
// its nodes. The displacement and the enhanced-strain kernels derive from it and add the physics.
#include <string>
#include <utility>
#include <vector>

#include "mechanics/Element.hpp"

namespace contessa::mechanics {

template <class Shape, bool kAxisymmetric>
class ShapeKernel : public ElementKernel {
 public:
  explicit ShapeKernel(std::string name) : name_(std::move(name)) {}
  std::string name() const override { return name_; }
  int dimension() const override { return Shape::kDimension; }
  int numNodes() const override { return Shape::kNodes; }
  bool axisymmetric() const override { return kAxisymmetric; }
  std::vector<double> parentNodeCoordinates() const override {
    std::vector<double> xi;
    for (const auto& node : Shape::parentNodes()) xi.insert(xi.end(), node.begin(), node.end());
    return xi;
  }

 private:
  std::string name_;
};

}  // namespace contessa::mechanics
