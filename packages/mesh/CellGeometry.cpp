#include "mesh/CellGeometry.hpp"

#include "mesh/ShapeFunctions.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace contessa::mesh {

namespace {

constexpr int kMaxDimension = 3;
constexpr int kMaxCorners = 8;

// Exodus node order of the linear cells: the bottom face (ζ = −1) counter-clockwise seen from +ζ,
// then the top face in the same order; Quad4 is the bottom face of Hex8.
constexpr int kCornerSigns[kMaxCorners][kMaxDimension] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                                          {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

// For each corner a and reference direction k: the corner b reached along ξ_k, and the sign of
// ξ_k(b) − ξ_k(a). At corner a, ∂x/∂ξ_k = sign · (x_b − x_a) / 2.
struct CornerEdges {
  int dimension = 0;
  int corners = 0;
  int neighbour[kMaxCorners][kMaxDimension] = {};
  int sign[kMaxCorners][kMaxDimension] = {};

  explicit CornerEdges(CellType type) : dimension(cellDimension(type)), corners(nodesPerCell(type)) {
    for (int a = 0; a < corners; ++a)
      for (int k = 0; k < dimension; ++k)
        for (int b = 0; b < corners; ++b) {
          bool alongK = kCornerSigns[b][k] != kCornerSigns[a][k];
          for (int j = 0; j < dimension && alongK; ++j)
            if (j != k && kCornerSigns[b][j] != kCornerSigns[a][j]) alongK = false;
          if (!alongK) continue;
          neighbour[a][k] = b;
          sign[a][k] = kCornerSigns[b][k] > kCornerSigns[a][k] ? 1 : -1;
        }
  }
};

const CornerEdges& cornerEdges(CellType type) {
  static const CornerEdges quad(CellType::Quad4), hex(CellType::Hex8);
  switch (type) {
    case CellType::Quad4: return quad;
    case CellType::Hex8: return hex;
    default: break;
  }
  throw std::logic_error(std::string("cornerEdges: ") + exodusCellName(type) + " is not a Quad4 or Hex8");
}

// The d edge vectors leaving corner a, oriented along +ξ_k: the columns of 2·∂x/∂ξ there.
void edgeColumns(const CornerEdges& t, const double* x, int a, double columns[kMaxDimension][kMaxDimension]) {
  const int d = t.dimension;
  for (int k = 0; k < d; ++k)
    for (int i = 0; i < d; ++i) columns[k][i] = t.sign[a][k] * (x[t.neighbour[a][k] * d + i] - x[a * d + i]);
}

// The only dimension-specific piece: the determinant of the d columns.
double determinant(int d, const double c[kMaxDimension][kMaxDimension]) {
  if (d == 2) return c[0][0] * c[1][1] - c[0][1] * c[1][0];
  return c[0][0] * (c[1][1] * c[2][2] - c[1][2] * c[2][1]) - c[0][1] * (c[1][0] * c[2][2] - c[1][2] * c[2][0]) +
         c[0][2] * (c[1][0] * c[2][1] - c[1][1] * c[2][0]);
}

double length(int d, const double* v) {
  double sum = 0;
  for (int i = 0; i < d; ++i) sum += v[i] * v[i];
  return std::sqrt(sum);
}

}  // namespace

std::vector<int> referenceCorner(CellType type, int corner) {
  if (type != CellType::Quad4 && type != CellType::Hex8)
    throw std::logic_error(std::string("referenceCorner: ") + exodusCellName(type) + " is not a Quad4 or Hex8");
  if (corner < 0 || corner >= nodesPerCell(type))
    throw std::out_of_range("referenceCorner: corner " + std::to_string(corner) + " does not exist on " +
                            exodusCellName(type));
  return std::vector<int>(kCornerSigns[corner], kCornerSigns[corner] + cellDimension(type));
}

void cornerJacobians(CellType type, const double* x, double* jacobians) {
  const CornerEdges& t = cornerEdges(type);
  double columns[kMaxDimension][kMaxDimension];
  for (int a = 0; a < t.corners; ++a) {
    edgeColumns(t, x, a, columns);
    jacobians[a] = determinant(t.dimension, columns);
  }
}

void scaledCornerJacobians(CellType type, const double* x, double* jacobians) {
  const CornerEdges& t = cornerEdges(type);
  double columns[kMaxDimension][kMaxDimension];
  for (int a = 0; a < t.corners; ++a) {
    edgeColumns(t, x, a, columns);
    double lengths = 1;
    for (int k = 0; k < t.dimension; ++k) lengths *= length(t.dimension, columns[k]);
    jacobians[a] = lengths > 0 ? determinant(t.dimension, columns) / lengths : 0.0;
  }
}

namespace {

// det(∂x/∂ξ) and the columns' lengths at reference point xi, from the shape functions.
double jacobianAt(CellType type, const double* x, const double* xi, double* lengthProduct) {
  const int d = cellDimension(type), n = nodesPerCell(type);
  double gradients[kMaxNodesPerCell * kMaxDimension];
  shapeGradients(type, xi, gradients);
  double columns[kMaxDimension][kMaxDimension] = {};  // columns[k][i] = ∂x_i/∂ξ_k
  for (int a = 0; a < n; ++a)
    for (int k = 0; k < d; ++k)
      for (int i = 0; i < d; ++i) columns[k][i] += gradients[a * d + k] * x[a * d + i];
  if (lengthProduct) {
    *lengthProduct = 1;
    for (int k = 0; k < d; ++k) *lengthProduct *= length(d, columns[k]);
  }
  return determinant(d, columns);
}

// Gauss-Legendre points and weights on [−1, 1].
void gauss(int count, std::vector<double>& x, std::vector<double>& w) {
  if (count == 2) {
    x = {-1 / std::sqrt(3.0), 1 / std::sqrt(3.0)};
    w = {1, 1};
  } else {
    x = {-std::sqrt(0.6), 0, std::sqrt(0.6)};
    w = {5.0 / 9, 8.0 / 9, 5.0 / 9};
  }
}

// Symmetric rules on the unit triangle and tetrahedron (degree 1: the centroid; degree 2: 3 and 4 points).
void simplexRule(int d, int order, std::vector<double>& points, std::vector<double>& weights) {
  const double measure = d == 2 ? 0.5 : 1.0 / 6;
  if (order == 1) {
    points.assign(d, 1.0 / (d + 1));
    weights = {measure};
    return;
  }
  // Points at barycentric (a, b, b[, b]) and permutations: a = 2/3, b = 1/6 (triangle);
  // a = (5 + 3√5)/20, b = (5 − √5)/20 (tetrahedron).
  const double a = d == 2 ? 2.0 / 3 : (5 + 3 * std::sqrt(5.0)) / 20, b = d == 2 ? 1.0 / 6 : (5 - std::sqrt(5.0)) / 20;
  points.clear();
  for (int p = 0; p <= d; ++p)
    for (int k = 0; k < d; ++k) points.push_back(p == k + 1 ? a : b);
  weights.assign(d + 1, measure / (d + 1));
}

}  // namespace

void integrationPoints(CellType type, std::vector<double>& points, std::vector<double>& weights) {
  const int d = cellDimension(type), order = cellOrder(type);
  const bool simplex = type == CellType::Tri3 || type == CellType::Tri6 || type == CellType::Tet4 || type == CellType::Tet10;
  const bool wedge = type == CellType::Wedge6 || type == CellType::Wedge15;
  if (simplex) return simplexRule(d, order, points, weights);
  std::vector<double> g, gw;
  gauss(order + 1, g, gw);
  points.clear();
  weights.clear();
  if (wedge) {
    std::vector<double> tri, triWeights;
    simplexRule(2, 2, tri, triWeights);
    for (std::size_t z = 0; z < g.size(); ++z)
      for (std::size_t t = 0; t < triWeights.size(); ++t) {
        points.insert(points.end(), {tri[2 * t], tri[2 * t + 1], g[z]});
        weights.push_back(triWeights[t] * gw[z]);
      }
    return;
  }
  const int m = static_cast<int>(g.size());
  const int count = d == 2 ? m * m : m * m * m;
  for (int p = 0; p < count; ++p) {
    double w = 1;
    for (int k = 0, rest = p; k < d; ++k, rest /= m) {
      points.push_back(g[rest % m]);
      w *= gw[rest % m];
    }
    weights.push_back(w);
  }
}

int shapeCheckJacobians(CellType type, const double* x, double* scaled) {
  const int n = nodesPerCell(type);
  int count = 0;
  auto record = [&](const double* xi) {
    double lengths = 0;
    const double det = jacobianAt(type, x, xi, &lengths);
    scaled[count++] = lengths > 0 ? det / lengths : 0.0;
  };
  for (int a = 0; a < n; ++a) record(referenceNode(type, a).data());
  std::vector<double> points, weights;
  integrationPoints(type, points, weights);
  const int d = cellDimension(type);
  for (std::size_t p = 0; p < weights.size(); ++p) record(&points[p * d]);
  return count;
}

double cellMeasure(CellType type, const double* x) {
  std::vector<double> points, weights;
  integrationPoints(type, points, weights);
  const int d = cellDimension(type);
  double measure = 0;
  for (std::size_t p = 0; p < weights.size(); ++p) measure += weights[p] * jacobianAt(type, x, &points[p * d], nullptr);
  return measure;
}

}  // namespace contessa::mesh
