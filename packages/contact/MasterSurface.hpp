#pragma once
// The master side of an interface, deformable or rigid, behind one interface: its facets' node ids, their
// current positions, the DOF ids of their nodes and how their positions move with the load factor. The
// contact interface asks nothing else, so it never branches on "rigid".
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/ContactInterface.hpp"
#include "contact/MasterFacet.hpp"

namespace contessa::contact {

template <class Facet>
class MasterSurface {
 public:
  static constexpr int kDim = Facet::kSpaceDim;
  static constexpr int kNodes = Facet::kNodes;
  static constexpr int kFacetDofs = kDim * kNodes;
  using Point = typename Facet::Point;

  /// Deformable master: the spec's mesh-node facets. Rigid master: facets over the rigid points, numbered
  /// −1, −2, … (point i is node −1 − i), so shared vertices and edges are still recognised.
  explicit MasterSurface(const ContactInterfaceSpec& spec) : rigid_(spec.rigidMaster) {
    if (spec.nodesPerFacet() != kNodes || spec.dimension != kDim)
      throw std::logic_error("MasterSurface: interface '" + spec.label() + "' does not match the facet type");
    const std::size_t count = spec.numMasterFacets();
    nodes_.resize(count);
    for (std::size_t f = 0; f < count; ++f)
      for (int a = 0; a < kNodes; ++a)
        nodes_[f][a] = rigid_ ? -1 - static_cast<GlobalIndex>(spec.rigidSurface.facets[f * kNodes + a])
                              : spec.masterFacets[f * kNodes + a];
    if (rigid_) {
      const auto& p = spec.rigidSurface.points;
      points_.resize(p.size() / kDim);
      for (std::size_t i = 0; i < points_.size(); ++i)
        for (int c = 0; c < kDim; ++c) points_[i][c] = p[i * kDim + c];
      for (int c = 0; c < kDim; ++c) motion_[c] = spec.rigidSurface.motion.at(c);
    }
  }

  std::size_t size() const { return nodes_.size(); }

  /// A rigid master's points at X + offset + λ · motion (load steps: offset the step's start, motion its
  /// change); nothing for a deformable master.
  void setMotion(const std::vector<double>& offset, const std::vector<double>& motion) {
    if (!rigid_) return;
    for (int c = 0; c < kDim; ++c) {
      offset_[c] = offset.at(c);
      motion_[c] = motion.at(c);
    }
  }

  /// Every facet at the current positions (mesh nodes from `position`, rigid points at X + λ · motion).
  std::vector<MasterFacetNodes<Facet>> facets(const ContactInterfaceBase::NodePosition& position,
                                              double loadFactor) const {
    std::vector<MasterFacetNodes<Facet>> out(nodes_.size());
    for (std::size_t f = 0; f < nodes_.size(); ++f) {
      out[f].id = static_cast<int>(f);
      for (int a = 0; a < kNodes; ++a) {
        const GlobalIndex node = nodes_[f][a];
        out[f].nodes[a] = static_cast<int>(node);
        if (node >= 0) {
          position(node, out[f].x[a].data());
        } else {
          const Point& X = points_[static_cast<std::size_t>(-1 - node)];
          for (int c = 0; c < kDim; ++c) out[f].x[a][c] = X[c] + offset_[c] + loadFactor * motion_[c];
        }
      }
    }
    return out;
  }

  /// Global DOF ids of facet f's nodes, node by node (node·kDim + c); −1 for a rigid point (no unknown).
  std::array<GlobalIndex, kFacetDofs> dofs(int f) const {
    std::array<GlobalIndex, kFacetDofs> d{};
    for (int a = 0; a < kNodes; ++a)
      for (int c = 0; c < kDim; ++c) {
        const GlobalIndex node = nodes_[f][a];
        d[a * kDim + c] = node >= 0 ? kDim * node + c : -1;
      }
    return d;
  }

  /// ∂x/∂λ of facet f's node coordinates, in the order of dofs(f): the rigid motion, 0 for mesh nodes
  /// (their motion is in the unknowns).
  std::array<double, kFacetDofs> dPositiondLambda(int f) const {
    std::array<double, kFacetDofs> d{};
    for (int a = 0; a < kNodes; ++a)
      for (int c = 0; c < kDim; ++c) d[a * kDim + c] = nodes_[f][a] >= 0 ? 0.0 : motion_[c];
    return d;
  }

 private:
  bool rigid_;
  std::vector<std::array<GlobalIndex, kNodes>> nodes_;
  std::vector<Point> points_;
  Point motion_{};
  Point offset_{};  ///< 0 but in a load step after the one that moved the surface
};

}  // namespace contessa::contact
