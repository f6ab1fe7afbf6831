#include "mesh/ShapeFunctions.hpp"

#include <stdexcept>
#include <string>

namespace contessa::mesh {

namespace {

enum class Family { Simplex, Lagrange, Serendipity, Wedge };

Family family(CellType type) {
  switch (type) {
    case CellType::Tri3:
    case CellType::Tri6:
    case CellType::Tet4:
    case CellType::Tet10: return Family::Simplex;
    case CellType::Quad8:
    case CellType::Hex20: return Family::Serendipity;
    case CellType::Wedge6:
    case CellType::Wedge15: return Family::Wedge;
    default: return Family::Lagrange;
  }
}

// Corners of the reference cells in Exodus order: the bottom face (ζ = −1) counter-clockwise seen
// from +ζ, then the top face; the simplex's corners are its origin and the unit points.
constexpr double kBoxCorners[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                      {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
constexpr double kSimplexCorners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
constexpr double kWedgeCorners[6][3] = {{0, 0, -1}, {1, 0, -1}, {0, 1, -1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}};

std::array<double, 3> corner(CellType type, int a) {
  const double* c = family(type) == Family::Simplex ? kSimplexCorners[a]
                    : family(type) == Family::Wedge ? kWedgeCorners[a]
                                                    : kBoxCorners[a];
  return {c[0], c[1], c[2]};
}

// Barycentric coordinates λ_0 = 1 − Σ ξ_k, λ_k = ξ_k of a triangle or tetrahedron.
double barycentric(int a, const double* xi, int d) {
  if (a > 0) return xi[a - 1];
  double rest = 1;
  for (int k = 0; k < d; ++k) rest -= xi[k];
  return rest;
}

// The corner a node sits on, or the two it sits between (−1 for a corner node).
MidEdgeNode edgeOf(CellType type, int node) {
  for (const MidEdgeNode& e : midEdgeNodes(type))
    if (e.middle == node) return e;
  return {node, -1, node};
}

// 1D Lagrange polynomials through −1, 0, 1 (order 2) or −1, 1 (order 1), the one equal to 1 at s.
double lagrange1d(int order, double s, double x) {
  if (order == 1) return (1 + s * x) / 2;
  if (s == 0) return 1 - x * x;
  return x * (x + s) / 2;
}

double simplexShape(CellType type, int a, const double* xi) {
  const int d = cellDimension(type);
  if (cellOrder(type) == 1) return barycentric(a, xi, d);
  const MidEdgeNode e = edgeOf(type, a);
  if (e.second < 0) {
    const double l = barycentric(a, xi, d);
    return l * (2 * l - 1);
  }
  return 4 * barycentric(e.first, xi, d) * barycentric(e.second, xi, d);
}

// Quad8, Hex20: corner N = 2^−d Π(1 + s_k ξ_k) (Σ s_k ξ_k − d + 1); mid-edge node (s_m = 0)
// N = 2^−(d−1) (1 − ξ_m²) Π_{k≠m} (1 + s_k ξ_k) (Zienkiewicz & Taylor, vol. 1, §6.3).
double serendipityShape(CellType type, int a, const double* xi) {
  const int d = cellDimension(type);
  const auto s = referenceNode(type, a);
  double product = 1, sum = 0;
  int zero = -1;
  for (int k = 0; k < d; ++k) {
    if (s[k] == 0) {
      zero = k;
      continue;
    }
    product *= (1 + s[k] * xi[k]) / 2;
    sum += s[k] * xi[k];
  }
  if (zero < 0) return product * (sum - d + 1);
  return product * (1 - xi[zero] * xi[zero]);
}

// Wedge6: λ_i (1 + s ζ)/2. Wedge15: corner ½ λ_i (1 + s ζ)(2 λ_i + s ζ − 2); mid-edge of a triangle
// edge 2 λ_i λ_j (1 + s ζ); mid-edge of a vertical edge λ_i (1 − ζ²).
double wedgeShape(CellType type, int a, const double* xi) {
  const double zeta = xi[2];
  const MidEdgeNode e = edgeOf(type, a);
  const int cornerA = e.first % 3;
  const double s = referenceNode(type, e.first)[2];
  const double li = barycentric(cornerA, xi, 2);
  if (cellOrder(type) == 1) return li * (1 + s * zeta) / 2;
  if (e.second < 0) return li * (1 + s * zeta) * (2 * li + s * zeta - 2) / 2;
  const int cornerB = e.second % 3;
  if (cornerA == cornerB) return li * (1 - zeta * zeta);
  return 2 * li * barycentric(cornerB, xi, 2) * (1 + s * zeta);
}

double shape(CellType type, int a, const double* xi) {
  switch (family(type)) {
    case Family::Simplex: return simplexShape(type, a, xi);
    case Family::Serendipity: return serendipityShape(type, a, xi);
    case Family::Wedge: return wedgeShape(type, a, xi);
    case Family::Lagrange: break;
  }
  const auto s = referenceNode(type, a);
  double value = 1;
  for (int k = 0; k < cellDimension(type); ++k) value *= lagrange1d(cellOrder(type), s[k], xi[k]);
  return value;
}

}  // namespace

std::array<double, 3> referenceNode(CellType type, int node) {
  if (node < 0 || node >= nodesPerCell(type))
    throw std::out_of_range("referenceNode: node " + std::to_string(node) + " does not exist on " +
                            exodusCellName(type));
  if (node < numCorners(type)) return corner(type, node);
  const MidEdgeNode e = edgeOf(type, node);
  if (e.second >= 0) {  // the middle of its edge
    const auto a = corner(type, e.first), b = corner(type, e.second);
    return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
  }
  // Quad9's node 8 and Hex27's node 20 are the centre; Hex27's 21-26 the centres of its sides 5, 6,
  // 4, 2, 1, 3 (a coordinate at 0, one at ±1).
  if (node == nodesPerCell(type) - 1 && type == CellType::Quad9) return {0, 0, 0};
  static const std::array<double, 3> kHex27Centres[7] = {{0, 0, 0}, {0, 0, -1}, {0, 0, 1}, {-1, 0, 0},
                                                         {1, 0, 0}, {0, -1, 0}, {0, 1, 0}};
  return kHex27Centres[node - 20];
}

void shapeValues(CellType type, const double* xi, double* values) {
  for (int a = 0; a < nodesPerCell(type); ++a) values[a] = shape(type, a, xi);
}

void shapeGradients(CellType type, const double* xi, double* gradients) {
  // Every shape function here is a polynomial of degree at most 2 in each single ξ_k (the others
  // fixed), for which the central difference (N(ξ + h e_k) − N(ξ − h e_k)) / 2h is the exact
  // derivative whatever h; h = 1/2 keeps the round-off at the level of the values themselves.
  const int d = cellDimension(type), n = nodesPerCell(type);
  constexpr double h = 0.5;
  double plus[kMaxNodesPerCell], minus[kMaxNodesPerCell];
  for (int k = 0; k < d; ++k) {
    double p[3] = {xi[0], xi[1], d == 3 ? xi[2] : 0.0}, m[3] = {p[0], p[1], p[2]};
    p[k] += h;
    m[k] -= h;
    shapeValues(type, p, plus);
    shapeValues(type, m, minus);
    for (int a = 0; a < n; ++a) gradients[a * d + k] = (plus[a] - minus[a]) / (2 * h);
  }
}

}  // namespace contessa::mesh
