#include "contact/MortarFacetPair.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include "contact/MortarFacetGeometry.hpp"

namespace contessa::contact {

namespace {

constexpr int kN = kMortarFacetPairCoordinates;

using namespace mortar3d;
static_assert(kLinearFacetNodes == kMortarFacetNodes, "one facet layout");

template <class T>
LinearFacet<T> facetOf(const FacetPairCoordinates<T>& x, int first, int count) {
  LinearFacet<T> f;
  f.count = count;
  for (int a = 0; a < count; ++a) f.node[a] = {x[3 * (first + a)], x[3 * (first + a) + 1], x[3 * (first + a) + 2]};
  return f;
}

}  // namespace

template <class T>
MortarFacetPairGaps<T> integrateFacetPair(const FacetPairCoordinates<T>& x, double referenceArea,
                                          const MortarFacetPairShape& shape) {
  MortarFacetPairGaps<T> out;
  const LinearFacet<T> slave = facetOf(x, 0, shape.slaveNodes), master = facetOf(x, kMortarFacetNodes, shape.masterNodes);
  const ProjectionPlane<T> plane(slave);
  const double size = std::max(facetDiameter(slave), facetDiameter(master));
  if (!facing(slave, master, plane, size)) return out;
  // eq. M14: the projected slave polygon (anticlockwise about n_0) clipped by the projected master
  // polygon, which runs clockwise about n_0 (its normal is about −n_0): reversed first.
  const std::vector<PlanePoint<T>> slavePolygon = plane.project(slave), masterProjected = plane.project(master);
  std::vector<PlanePoint<T>> masterPolygon(masterProjected.rbegin(), masterProjected.rend());
  const T slaveArea2 = twiceSignedArea(slavePolygon);
  if (!(twiceSignedAreaValue(masterPolygon) > 0.0) || !(valueOf(slaveArea2) > 0.0)) return out;
  const std::vector<PlanePoint<T>> clip = clipConvexPolygon(slavePolygon, masterPolygon, kMortarClipSnap * size);
  if (clip.size() < 3 || !(twiceSignedAreaValue(clip) > kMortarSnap * valueOf(slaveArea2))) return out;
  out.overlaps = true;
  // eq. M15–M17: triangles (c, v_i, v_i+1) about the vertex centroid c, Gauss points p on each; at p the
  // slave and master points x_s(ξ), x_m(η) projecting onto p, the gap g = (x_s − x_m) · n_m(η), and
  // g̃_a += w N_a(ξ) g |T| A_0 / A_projected.
  // Values: the formulas of eq. M16–M17 in doubles (facetPairGaps's, to the bit). Derivatives (T a
  // differentiated number): the points and the master normal through FacetMap (fewer products of
  // differentiated numbers for the same quantities). The mortar areas are values only (no caller
  // differentiates them).
  const PlanePoint<T> c = vertexCentroid(clip);
  const T measure = referenceArea / (0.5 * slaveArea2);
  const FacetMap<T> slaveMap(slave), masterMap(master);
  // A master normal without derivatives (FacetMap::fixedNormal): its value at every Gauss point is
  // LinearFacet's formula's, and the gap's derivatives are those of the products with the constant.
  const bool fixedNormal = masterMap.fixedNormal();
  std::array<double, kMortarFacetNodes> weightedGap{}, mortarArea{};
  std::array<T, kMortarFacetNodes> differentiated{};  // the weighted gaps' derivatives (T not double)
  for (std::size_t i = 0; i < clip.size(); ++i) {
    const PlanePoint<T> u = clip[i] - c, v = clip[(i + 1) % clip.size()] - c;
    const T triangleArea = 0.5 * planeCross(u, v);
    const T triangleMeasure = triangleArea * measure;
    for (const TrianglePoint& q : triangleRule()) {
      const PlanePoint<T> p = c + scaled(u, q.l1) + scaled(v, q.l2);
      const std::array<T, 2> xi = inverseMap(slave, slavePolygon, p), eta = inverseMap(master, masterProjected, p);
      const std::array<double, 2> xiValue{valueOf(xi[0]), valueOf(xi[1])}, etaValue{valueOf(eta[0]), valueOf(eta[1])};
      const std::array<double, kMortarFacetNodes> ns = slave.shape(xiValue[0], xiValue[1]);
      const double g = dot(slaveMap.valueAt(xiValue) - masterMap.valueAt(etaValue), masterMap.valueNormal(etaValue));
      const double weight = q.weight * valueOf(triangleArea) * valueOf(measure);
      for (int a = 0; a < slave.count; ++a) {
        weightedGap[a] = weightedGap[a] + weight * ns[a] * g;
        mortarArea[a] = mortarArea[a] + weight * ns[a];
      }
      if constexpr (!std::is_same_v<T, double>) {
        const Point3<double> normal = masterMap.valueNormal(etaValue);
        const std::array<T, kMortarFacetNodes> nodeShape = slave.shape(xi[0], xi[1]);
        const Point3<T> d = slaveMap.at(xi) - masterMap.at(eta);
        const T gap = fixedNormal ? d.x * normal.x + d.y * normal.y + d.z * normal.z : dot(d, masterMap.unitNormal(eta));
        const T weightedG = withValue(q.weight * triangleMeasure, weight) * gap;
        for (int a = 0; a < slave.count; ++a) differentiated[a] = differentiated[a] + nodeShape[a] * weightedG;
      }
    }
  }
  for (int a = 0; a < slave.count; ++a) {
    out.mortarArea[a] = T(mortarArea[a]);
    out.weightedGap[a] = withValue(differentiated[a], weightedGap[a]);
  }
  return out;
}

MortarFacetPairGaps<double> facetPairGaps(const FacetPairCoordinates<double>& x, double referenceArea,
                                          const MortarFacetPairShape& shape) {
  return integrateFacetPair(x, referenceArea, shape);
}

MortarFacetPairDerivatives facetPairDerivatives(const FacetPairCoordinates<double>& x, double referenceArea,
                                                const MortarFacetPairShape& shape, const double* masterMotion) {
  // A rigid master: the twelve slave coordinates and the motion (MortarDual.hpp, KernelVariables).
  return differentiatePairKernel<MortarFacetPairDerivatives, 3 * kMortarFacetNodes>(
      x, masterMotion, [&](const auto& seeded) { return integrateFacetPair(seeded, referenceArea, shape); });
}

}  // namespace contessa::contact
