#include "contact/ContactSurface.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "common/Error.hpp"
#include "contact/BoundingBoxTree.hpp"
#include "contact/MasterFacet.hpp"
#include "contact/Projection.hpp"

namespace contessa::contact {

namespace {

/// The consistent ∫ H_i dA of each node of a facet (in 2D with `revolved`: ∫ H_i 2π r ds) and its area, by
/// the facet's quadrature rule (MasterFacet.hpp), exact on an undistorted facet.
template <class Facet>
std::array<double, Facet::kNodes> consistentAreas(const std::array<typename Facet::Point, Facet::kNodes>& x,
                                                  bool revolved, double& area) {
  std::array<double, Facet::kNodes> a{};
  area = 0;
  for (const auto& q : Facet::quadrature()) {
    const auto p = Projection<Facet>::evaluateAt(typename Facet::Point{}, x, q.xi);
    const double jacobian = norm(Facet::areaNormal(p.covariantBasis)) * q.weight;
    area += jacobian;
    const double w = revolved ? 2.0 * M_PI * p.position[0] : 1.0;
    for (int i = 0; i < Facet::kNodes; ++i) a[i] += p.shape[i] * jacobian * w;
  }
  return a;
}

/// The tributary areas of a quadratic face whose ∫ H_i dA is not positive at the corners (Tri6, Quad8):
/// the sum of the consistent areas of its linear sub-facets (Tri3 or Quad4 pieces, tributaryPieces()).
/// Positive, and their sum is the face's area (docs/theory-contact.md).
template <class Facet>
std::array<double, Facet::kNodes> subFacetAreas(const std::array<typename Facet::Point, Facet::kNodes>& x,
                                                double& area) {
  std::array<double, Facet::kNodes> a{};
  area = 0;
  for (const auto& piece : Facet::tributaryPieces()) {
    double pieceArea = 0;
    if (piece[3] < 0) {
      const std::array<Tri3Facet::Point, 3> corners{x[piece[0]], x[piece[1]], x[piece[2]]};
      const auto w = consistentAreas<Tri3Facet>(corners, false, pieceArea);
      for (int v = 0; v < 3; ++v) a[piece[v]] += w[v];
    } else {
      const std::array<Quad4Facet::Point, 4> corners{x[piece[0]], x[piece[1]], x[piece[2]], x[piece[3]]};
      const auto w = consistentAreas<Quad4Facet>(corners, false, pieceArea);
      for (int v = 0; v < 4; ++v) a[piece[v]] += w[v];
    }
    area += pieceArea;
  }
  // Scaled to the face's own area (its quadrature): the sum is exact on a curved face too, not the area of
  // the inscribed sub-facets.
  double faceArea = 0;
  consistentAreas<Facet>(x, false, faceArea);
  for (double& w : a) w *= faceArea / area;
  area = faceArea;
  return a;
}

}  // namespace

/// Tributary area of each node of a facet (a traction times it is the nodal force) and the facet's area.
/// A straight segment: l/2 each, or revolved about the y axis, ∫ H_i 2π r ds = 2π l (2 r_i + r_j)/6 (exact
/// for r linear along it; `area` stays the segment's length, the facet size L_k). The others: the
/// consistent ∫ H_i dA where it is positive at every node (Tri3, Quad4, Line3, Quad9), the linear
/// sub-facets' where it is not (Tri6, Quad8: MasterFacet.hpp, kSubFacetTributary).
template <class Facet>
std::array<double, Facet::kNodes> tributaryAreas(const std::array<typename Facet::Point, Facet::kNodes>& x,
                                                 bool revolved, double& area) {
  if constexpr (std::is_same_v<Facet, Line2Facet>) {
    // hypot, as the 2D code always measured sides: the 2D histories stay bit-identical.
    area = std::hypot(x[1][0] - x[0][0], x[1][1] - x[0][1]);
    if (revolved)
      return {M_PI * area * (2.0 * x[0][0] + x[1][0]) / 3.0, M_PI * area * (x[0][0] + 2.0 * x[1][0]) / 3.0};
    return {0.5 * area, 0.5 * area};
  } else if constexpr (Facet::kSubFacetTributary) {
    (void)revolved;  // 3D faces only
    return subFacetAreas<Facet>(x, area);
  } else {
    return consistentAreas<Facet>(x, revolved, area);
  }
}

namespace {

template <class Facet>
void addFacets(const mesh::ReplicatedSurface& facets, bool revolved, ContactSurface& surface) {
  constexpr int n = Facet::kNodes, dim = Facet::kSpaceDim;
  std::map<GlobalIndex, double> area, size;
  std::map<GlobalIndex, int> count;
  for (std::size_t i = 0; i < facets.elements.size(); ++i) {
    std::array<typename Facet::Point, n> x{};
    std::array<GlobalIndex, n> nodes{};
    for (int a = 0; a < n; ++a) {
      nodes[a] = facets.facetNodes[i * n + a];
      const auto at = static_cast<std::size_t>(
          std::lower_bound(facets.nodes.begin(), facets.nodes.end(), nodes[a]) - facets.nodes.begin());
      for (int c = 0; c < dim; ++c) x[a][c] = facets.coordinates[at * dim + c];
      surface.facets.push_back(nodes[a]);
    }
    double facetArea = 0;
    const auto nodal = tributaryAreas<Facet>(x, revolved, facetArea);
    // L_k: the side's length in 2D, √(area) of the face in 3D.
    const double facetSize = Facet::kSurfaceDim == 1 ? facetArea : std::sqrt(facetArea);
    for (int a = 0; a < n; ++a) {
      area[nodes[a]] += nodal[a];
      size[nodes[a]] += facetSize;
      ++count[nodes[a]];
    }
  }
  for (const auto& [node, tributary] : area) {
    surface.nodes.push_back(node);
    surface.areas.push_back(tributary);
    surface.facetLengths.push_back(size[node] / count[node]);  // mean of the adjacent facets
  }
}

/// The nodes on the axis (r = x = 0 within round-off of the edge's length) of a revolved surface of 3-node
/// edges (Line3Facet order: corner, corner, mid), each with its edge reaching off the axis.
std::vector<AxisNode> axisNodesOf(const mesh::ReplicatedSurface& facets, const ContactSurface& surface) {
  std::vector<AxisNode> out;
  const auto indexOf = [&](GlobalIndex node) {
    return static_cast<std::size_t>(std::lower_bound(surface.nodes.begin(), surface.nodes.end(), node) -
                                    surface.nodes.begin());
  };
  const auto radius = [&](GlobalIndex node) {
    const auto at = static_cast<std::size_t>(std::lower_bound(facets.nodes.begin(), facets.nodes.end(), node) -
                                             facets.nodes.begin());
    return facets.coordinates[at * 2];
  };
  for (std::size_t f = 0; f + 3 <= surface.facets.size(); f += 3) {
    const GlobalIndex corners[2] = {surface.facets[f], surface.facets[f + 1]}, mid = surface.facets[f + 2];
    const double length = surface.facetLengths[indexOf(corners[0])];
    for (int c = 0; c < 2; ++c) {
      const double rMid = radius(mid), rFar = radius(corners[1 - c]);
      // An edge along the axis, or one whose mid node is not between its corners in r, recovers nothing.
      if (std::abs(radius(corners[c])) > 1e-9 * length || !(rMid > 1e-9 * length && rFar > rMid)) continue;
      const std::size_t node = indexOf(corners[c]);
      if (std::any_of(out.begin(), out.end(), [&](const AxisNode& a) { return a.node == node; })) continue;
      out.push_back({node, indexOf(mid), indexOf(corners[1 - c]), rMid, rFar});
    }
  }
  return out;
}

}  // namespace

double valueOnAxis(const AxisNode& axis, double atMid, double atFar) {
  // a + b r² through (r_mid, f_mid), (r_far, f_far), at r = 0.
  const double m = axis.rMid * axis.rMid, f = axis.rFar * axis.rFar;
  return (f * atMid - m * atFar) / (f - m);
}

ContactSurface ContactSurface::fromSideSet(const mesh::Mesh& mesh, const mesh::SideSet& set, const std::string& where) {
  requireInput(mesh.dimension == 2 || mesh.dimension == 3, where + ": contact needs a 2D or 3D mesh");
  requireInput(!set.elements.empty(), where + ": side set '" + set.name + "' is empty");
  return fromSurface(mesh::surfaceOfSideSet(mesh, set.name), where);
}

ContactSurface ContactSurface::fromSurface(const mesh::ReplicatedSurface& facets, const std::string& where,
                                           bool revolved) {
  requireInput(facets.dimension == 2 || facets.dimension == 3, where + ": contact needs a 2D or 3D mesh");
  if (revolved && facets.dimension != 2) throw std::logic_error("ContactSurface: only a 2D surface can be revolved");
  requireInput(!facets.elements.empty(), where + ": side set '" + facets.name + "' is empty");
  ContactSurface surface;
  surface.nodesPerFacet = facets.nodesPerFacet;
  // The facet type of the side's node count (mesh::sideNodes): 2D edges of 2 or 3 nodes, 3D faces of 3, 4, 6,
  // 8 or 9 (MasterFacet.hpp).
  switch (facets.dimension * 100 + facets.nodesPerFacet) {
    case 202: addFacets<Line2Facet>(facets, revolved, surface); break;
    case 203: addFacets<Line3Facet>(facets, revolved, surface); break;
    case 303: addFacets<Tri3Facet>(facets, revolved, surface); break;
    case 304: addFacets<Quad4Facet>(facets, revolved, surface); break;
    case 306: addFacets<Tri6Facet>(facets, revolved, surface); break;
    case 308: addFacets<Quad8Facet>(facets, revolved, surface); break;
    case 309: addFacets<Quad9Facet>(facets, revolved, surface); break;
    default:
      throw std::logic_error("ContactSurface: no facet type of " + std::to_string(facets.nodesPerFacet) +
                             " nodes in " + std::to_string(facets.dimension) + "D");
  }
  // ∫ H_i 2πr ds of a 3-node edge is 0 at a corner on the axis ((1 − 3t + 2t²) t integrates to 0).
  if (revolved && facets.nodesPerFacet == 3) surface.axisNodes = axisNodesOf(facets, surface);
  return surface;
}

void validateRigidSurface(const RigidSurface& surface, int dimension, const std::string& where) {
  const int perFacet = dimension == 2 ? 2 : 4;
  const std::string coords = dimension == 2 ? "x, y" : "x, y, z";
  requireInput(surface.points.size() >= static_cast<std::size_t>(perFacet * dimension) &&
                   surface.points.size() % dimension == 0,
               where + (dimension == 2 ? "/Points: expected x0, y0, x1, y1, ... (at least two points)"
                                       : "/Points: expected x0, y0, z0, x1, y1, z1, ... (3 coordinates per point, at "
                                         "least four points), got " + std::to_string(surface.points.size()) + " values"));
  const std::size_t numPoints = surface.points.size() / dimension;
  requireInput(surface.motion.size() == static_cast<std::size_t>(dimension),
               where + "/Motion: expected " + std::string(dimension == 2 ? "two" : "three") + " values (" + coords +
                   " displacement at load factor 1), got " + std::to_string(surface.motion.size()));
  requireInput(!surface.facets.empty() && surface.facets.size() % perFacet == 0,
               where + "/Facets: expected " + std::to_string(perFacet) + " point indices per facet");
  for (std::size_t f = 0; f * perFacet < surface.facets.size(); ++f) {
    const std::string which = where + "/Facets: facet " + std::to_string(f + 1);
    std::array<std::array<double, 3>, 4> x{};
    for (int a = 0; a < perFacet; ++a) {
      const int i = surface.facets[f * perFacet + a];
      requireInput(i >= 0 && static_cast<std::size_t>(i) < numPoints,
                   which + ": point index " + std::to_string(i) + " out of range (0 to " +
                       std::to_string(numPoints - 1) + ")");
      for (int c = 0; c < dimension; ++c) x[a][c] = surface.points[i * dimension + c];
    }
    if (dimension == 2) {
      const bool polyline = surface.facets[2 * f + 1] == surface.facets[2 * f] + 1;
      requireInput(x[0] != x[1], polyline ? where + "/Points: two consecutive points coincide (segment " +
                                                std::to_string(f + 1) + ")"
                                          : which + ": its two points coincide");
      continue;
    }
    // A bilinear quad: its area Jacobian must keep one sign (the normal's) and stay away from zero at the
    // corners, where it is smallest on a convex quad.
    std::array<Quad4Facet::Point, 4> q{};
    for (int a = 0; a < 4; ++a) q[a] = {x[a][0], x[a][1], x[a][2]};
    const auto centre = Projection<Quad4Facet>::evaluateAt(Quad4Facet::Point{}, q, Quad4Facet::center());
    const Quad4Facet::Point n0 = Quad4Facet::areaNormal(centre.covariantBasis);
    double size = 0;
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) size = std::max(size, norm(subtract(q[b], q[a])));
    for (int a = 0; a < 4; ++a) {
      const auto corner = Projection<Quad4Facet>::evaluateAt(Quad4Facet::Point{}, q, Quad4Facet::nodeCoords(a));
      const double jacobian = dot(Quad4Facet::areaNormal(corner.covariantBasis), n0) / std::max(norm(n0), 1e-300);
      requireInput(jacobian > 1e-10 * size * size,
                   which + ": degenerate or folded quadrilateral (its points must be distinct, not collinear, and "
                           "ordered around it)");
    }
  }
}

namespace {

/// Facet: the rigid surface's (Line2Facet, Quad4Facet); SlaveFacet: the slave side set's.
template <class Facet, class SlaveFacet>
void checkFacing(const RigidSurface& surface, const mesh::ReplicatedSurface& slave, const std::string& where) {
  using Point = typename Facet::Point;
  constexpr int n = Facet::kNodes, dim = Facet::kSpaceDim, ns = SlaveFacet::kNodes;
  constexpr double kCos60 = 0.5;
  // The rigid facets at λ = 0, each with a box enlarged by its size: the slave faces near it.
  const std::size_t numFacets = surface.facets.size() / n;
  std::vector<std::array<Point, n>> rigid(numFacets);
  std::vector<BoundingBox<dim>> boxes(numFacets);
  std::vector<double> sizes(numFacets, 0.0);
  for (std::size_t f = 0; f < numFacets; ++f) {
    for (int a = 0; a < n; ++a) {
      for (int c = 0; c < dim; ++c) rigid[f][a][c] = surface.points[surface.facets[f * n + a] * dim + c];
      boxes[f].include(rigid[f][a]);
    }
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) sizes[f] = std::max(sizes[f], norm(subtract(rigid[f][b], rigid[f][a])));
    boxes[f].enlarge(sizes[f]);
  }
  const BoundingBoxTree<dim> tree(std::move(boxes));
  std::vector<int> facing(numFacets, 0), backwards(numFacets, 0), hits;
  const Projection<Facet> projection;
  for (std::size_t i = 0; i < slave.elements.size(); ++i) {
    std::array<Point, ns> x{};
    for (int a = 0; a < ns; ++a) {
      const auto at = static_cast<std::size_t>(
          std::lower_bound(slave.nodes.begin(), slave.nodes.end(), slave.facetNodes[i * ns + a]) - slave.nodes.begin());
      for (int c = 0; c < dim; ++c) x[a][c] = slave.coordinates[at * dim + c];
    }
    // The slave face's centre and outward normal (the side orderings make the facet normal outward).
    const auto centre = Projection<SlaveFacet>::evaluateAt(Point{}, x, SlaveFacet::center());
    if (!(determinant(centre.metric) > 0.0)) continue;
    hits.clear();
    tree.query(centre.position, hits);
    for (int f : hits) {
      const auto p = projection.project(centre.position, rigid[f]);
      if (!p.converged || !p.isInside(1e-8) || std::abs(p.gap) > sizes[f]) continue;
      const double tolerance = 1e-8 * sizes[f];
      const double turned = dot(centre.normal, p.normal);
      if (turned < -kCos60 && p.gap >= -tolerance) ++facing[f];
      if (turned > kCos60 && p.gap <= tolerance) ++backwards[f];
    }
  }
  for (std::size_t f = 0; f < numFacets; ++f)
    requireInput(!(backwards[f] > 0 && facing[f] == 0),
                 where + "/Facets: facet " + std::to_string(f + 1) + " faces away from the slave side set '" +
                     slave.name + "' (its normal points into the slave body: " + std::to_string(backwards[f]) +
                     " slave faces lie behind it, none in front); list its points in the opposite order (" +
                     (dim == 2 ? "the rigid body on the left of the direction point 1 -> point 2"
                               : "counter-clockwise seen from the slave body") +
                     ")");
}

}  // namespace

void checkRigidSurfaceFacesSlave(const RigidSurface& surface, const mesh::ReplicatedSurface& slave,
                                 const std::string& where) {
  switch (slave.dimension * 100 + slave.nodesPerFacet) {
    case 202: checkFacing<Line2Facet, Line2Facet>(surface, slave, where); break;
    case 203: checkFacing<Line2Facet, Line3Facet>(surface, slave, where); break;
    case 303: checkFacing<Quad4Facet, Tri3Facet>(surface, slave, where); break;
    case 304: checkFacing<Quad4Facet, Quad4Facet>(surface, slave, where); break;
    case 306: checkFacing<Quad4Facet, Tri6Facet>(surface, slave, where); break;
    case 308: checkFacing<Quad4Facet, Quad8Facet>(surface, slave, where); break;
    case 309: checkFacing<Quad4Facet, Quad9Facet>(surface, slave, where); break;
    default: throw std::logic_error("checkRigidSurfaceFacesSlave: no facet type of " + std::to_string(slave.nodesPerFacet) + " nodes");
  }
}

template std::array<double, Line2Facet::kNodes> tributaryAreas<Line2Facet>(
    const std::array<Line2Facet::Point, Line2Facet::kNodes>&, bool, double&);
template std::array<double, Line3Facet::kNodes> tributaryAreas<Line3Facet>(
    const std::array<Line3Facet::Point, Line3Facet::kNodes>&, bool, double&);
template std::array<double, Tri3Facet::kNodes> tributaryAreas<Tri3Facet>(
    const std::array<Tri3Facet::Point, Tri3Facet::kNodes>&, bool, double&);
template std::array<double, Quad4Facet::kNodes> tributaryAreas<Quad4Facet>(
    const std::array<Quad4Facet::Point, Quad4Facet::kNodes>&, bool, double&);
template std::array<double, Tri6Facet::kNodes> tributaryAreas<Tri6Facet>(
    const std::array<Tri6Facet::Point, Tri6Facet::kNodes>&, bool, double&);
template std::array<double, Quad8Facet::kNodes> tributaryAreas<Quad8Facet>(
    const std::array<Quad8Facet::Point, Quad8Facet::kNodes>&, bool, double&);
template std::array<double, Quad9Facet::kNodes> tributaryAreas<Quad9Facet>(
    const std::array<Quad9Facet::Point, Quad9Facet::kNodes>&, bool, double&);

}  // namespace contessa::contact
