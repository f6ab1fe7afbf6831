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

/// The committed position Σ N_a X_a of the facet point with shape values n (X_a: the committed nodes
/// first…first + count − 1, constants).
template <class T>
Point3<T> committedPoint(const FacetPairCommitted& then, int first, int count, const std::array<T, kMortarFacetNodes>& n) {
  Point3<T> p{T(0.0), T(0.0), T(0.0)};
  for (int a = 0; a < count; ++a) {
    const double* X = &then[3 * (first + a)];
    p = p + Point3<T>{n[a] * X[0], n[a] * X[1], n[a] * X[2]};
  }
  return p;
}

/// eq. M9′ at a Gauss point: the relative motion over the increment of the slave point ξ and the master
/// point η it sees (both material points moved from their committed positions), less its part along the
/// master's unit normal (that part is the gap's change): the tangential slip, a 3-vector.
template <class T>
Point3<T> tangentialSlip(const FacetMap<T>& slaveMap, const FacetMap<T>& masterMap, const LinearFacet<T>& slave,
                         const LinearFacet<T>& master, const std::array<T, 2>& xi, const std::array<T, 2>& eta,
                         const FacetPairCommitted& then) {
  const Point3<T> slaveMotion = slaveMap.at(xi) - committedPoint(then, 0, slave.count, slave.shape(xi[0], xi[1]));
  const Point3<T> masterMotion =
      masterMap.at(eta) - committedPoint(then, kMortarFacetNodes, master.count, master.shape(eta[0], eta[1]));
  const Point3<T> motion = slaveMotion - masterMotion;
  const Point3<T> n = masterMap.unitNormal(eta);
  return motion - times(n, dot(motion, n));
}

}  // namespace

template <class T>
MortarFacetPairGaps<T> integrateFacetPair(const FacetPairCoordinates<T>& x, double referenceArea,
                                          const MortarFacetPairShape& shape, const FacetPairCommitted* committed) {
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
      if (committed != nullptr) {  // eq. M9′: Δũ_a += w N_a(ξ) u_T, in T (values and derivatives alike)
        const Point3<T> u = tangentialSlip(slaveMap, masterMap, slave, master, xi, eta, *committed);
        const std::array<T, kMortarFacetNodes> nodeShape = slave.shape(xi[0], xi[1]);
        const T w = withValue(q.weight * triangleMeasure, weight);
        for (int a = 0; a < slave.count; ++a) {
          const T wa = w * nodeShape[a];
          std::array<T, 3>& slip = out.weightedSlip[a];
          slip = {slip[0] + wa * u.x, slip[1] + wa * u.y, slip[2] + wa * u.z};
        }
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
                                          const MortarFacetPairShape& shape, const FacetPairCommitted* committed) {
  return integrateFacetPair(x, referenceArea, shape, committed);
}

namespace {
/// The pair with its slip increments (friction) differentiated over `variables`: as
/// differentiatePairKernel (MortarDual.hpp), plus Δũ_a's three components.
template <int V>
MortarFacetPairDerivatives differentiateWithSlip(const FacetPairCoordinates<double>& x, double referenceArea,
                                                 const MortarFacetPairShape& shape, const FacetPairCommitted& committed,
                                                 const KernelVariables<kN>& variables) {
  std::vector<std::array<HessianDual<V>, kN>> seeded(1, variables.template seed<V>(x));  // large: on the heap
  const auto g = integrateFacetPair(seeded[0], referenceArea, shape, &committed);
  MortarFacetPairDerivatives out;
  out.overlaps = g.overlaps;
  out.slipGradient.resize(3 * kMortarFacetNodes);
  out.slipHessian.resize(3 * kMortarFacetNodes);
  for (int a = 0; a < kMortarFacetNodes; ++a) {
    out.weightedGap[a] = g.weightedGap[a].v;
    out.mortarArea[a] = g.mortarArea[a].v;
    variables.extract(g.weightedGap[a], out.gradient[a], out.hessian[a]);
    for (int c = 0; c < 3; ++c) {
      out.weightedSlip[a][c] = g.weightedSlip[a][c].v;
      variables.extract(g.weightedSlip[a][c], out.slipGradient[3 * a + c], out.slipHessian[3 * a + c]);
    }
  }
  return out;
}
}  // namespace

MortarFacetPairDerivatives facetPairDerivatives(const FacetPairCoordinates<double>& x, double referenceArea,
                                                const MortarFacetPairShape& shape, const double* masterMotion,
                                                const FacetPairCommitted* committed) {
  constexpr int kFirstMaster = 3 * kMortarFacetNodes;
  if (committed != nullptr) {
    if (masterMotion == nullptr) return differentiateWithSlip<kN>(x, referenceArea, shape, *committed, ownVariables<kN>());
    return differentiateWithSlip<kFirstMaster + 1>(x, referenceArea, shape, *committed,
                                                   rigidBodyVariables<kN>(kFirstMaster, kFirstMaster, masterMotion));
  }
  // A rigid master: the twelve slave coordinates and the motion (MortarDual.hpp, KernelVariables).
  return differentiatePairKernel<MortarFacetPairDerivatives, kFirstMaster>(
      x, masterMotion, [&](const auto& seeded) { return integrateFacetPair(seeded, referenceArea, shape); });
}

}  // namespace contessa::contact
