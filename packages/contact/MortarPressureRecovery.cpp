#include "contact/MortarPressureRecovery.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

#include "contact/MortarQuadraticFacetPair.hpp"
#include "contact/MortarQuadraticSegment.hpp"

namespace contessa::contact {

namespace {

/// ∫ Φ_a Φ_b over a 4-node piece on [−1, 1]² with J = j_0 + j_1 l_1 + j_2 l_2 (eq. M20; a Quad4 face: j_0 =
/// A / 4): 2 × 2 Gauss points, exact for the integrand's degree 3 in each coordinate.
std::array<std::array<double, 4>, 4> quadPieceMass(const double* j) {
  constexpr double kCorner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  const double g = 1.0 / std::sqrt(3.0);
  std::array<std::array<double, 4>, 4> m{};
  for (double l1 : {-g, g})
    for (double l2 : {-g, g}) {
      double phi[4];
      for (int a = 0; a < 4; ++a) phi[a] = 0.25 * (1 + kCorner[a][0] * l1) * (1 + kCorner[a][1] * l2);
      const double jacobian = j[0] + j[1] * l1 + j[2] * l2;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) m[a][b] += phi[a] * phi[b] * jacobian;
    }
  return m;
}

}  // namespace

std::vector<double> MortarPressureRecovery::apply(const std::vector<double>& pressure) const {
  std::vector<double> out(rowStart.empty() ? 0 : rowStart.size() - 1, 0.0);
  for (std::size_t a = 0; a < out.size(); ++a)
    for (std::size_t i = rowStart[a]; i < rowStart[a + 1]; ++i) out[a] += weight[i] * pressure[column[i]];
  return out;
}

MortarPressureRecovery mortarPressureRecovery(const ContactInterfaceSpec& spec) {
  const auto& nodes = spec.slaveNodes;
  const int perFacet = spec.slaveNodesPerFacet();
  const int measuresPerFacet = spec.dimension == 2 ? mortarSegmentPieces(perFacet) : mortarFaceMeasures(perFacet);
  const std::size_t stride = static_cast<std::size_t>(perFacet);
  const std::size_t facets = spec.slaveFacets.size() / stride;
  if (spec.slaveFacetMeasures.size() != facets * static_cast<std::size_t>(measuresPerFacet))
    throw std::logic_error("mortarPressureRecovery '" + spec.label() + "': a measure per slave facet (piece) expected");
  const auto index = [&](GlobalIndex node) {
    return static_cast<std::size_t>(std::lower_bound(nodes.begin(), nodes.end(), node) - nodes.begin());
  };
  std::vector<std::map<std::size_t, double>> mass(nodes.size());
  const auto add = [&](std::size_t f, const int* local, int count, const auto& m) {
    for (int a = 0; a < count; ++a)
      for (int b = 0; b < count; ++b)
        mass[index(spec.slaveFacets[f * stride + static_cast<std::size_t>(local[a])])]
            [index(spec.slaveFacets[f * stride + static_cast<std::size_t>(local[b])])] += m(a, b);
  };
  for (std::size_t f = 0; f < facets; ++f) {
    const double* measure = &spec.slaveFacetMeasures[f * static_cast<std::size_t>(measuresPerFacet)];
    if (spec.dimension == 2) {  // each piece of a segment (a Line3's two chords): L/6 (1 + δ_ab)
      for (int i = 0; i < mortarSegmentPieces(perFacet); ++i) {
        const std::array<int, 2> ends = mortarSegmentPieceNodes(perFacet, i);
        add(f, ends.data(), 2, [&](int a, int b) { return measure[i] / 6.0 * (a == b ? 2.0 : 1.0); });
      }
      continue;
    }
    int offset = 0;  // the piece's first measure: a triangle's area, a 4-node piece's (j_0, j_1, j_2)
    for (int i = 0; i < mortarFacePieces(perFacet); ++i) {
      const MortarFacePiece piece = mortarFacePiece(perFacet, i);
      if (piece.count == 3) {  // a flat triangle: A/12 (1 + δ_ab)
        add(f, piece.node.data(), 3, [&](int a, int b) { return measure[offset] / 12.0 * (a == b ? 2.0 : 1.0); });
        offset += 1;
        continue;
      }
      // A Quad4 face keeps its area only: the parallelogram's J = A/4.
      const double linearFace[3] = {measure[0] / 4.0, 0.0, 0.0};
      const auto m = quadPieceMass(perFacet == 4 ? linearFace : measure + offset);
      add(f, piece.node.data(), 4, [&](int a, int b) { return m[a][b]; });
      offset += 3;
    }
  }
  MortarPressureRecovery out;
  out.rowStart.push_back(0);
  for (std::size_t a = 0; a < mass.size(); ++a) {
    double sum = 0;
    for (const auto& [b, m] : mass[a]) sum += m;
    if (!(sum > 0.0)) {  // no facet measure at the node: its own value
      out.column.push_back(a);
      out.weight.push_back(1.0);
    }
    for (const auto& [b, m] : mass[a]) {
      if (!(sum > 0.0)) break;
      out.column.push_back(b);
      out.weight.push_back(m / sum);
    }
    out.rowStart.push_back(out.column.size());
  }
  return out;
}

}  // namespace contessa::contact
