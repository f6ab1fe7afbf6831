#include "mesh/CellGeometry.hpp"

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
  }
  throw std::logic_error("cornerEdges: unknown cell type");
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

}  // namespace contessa::mesh
