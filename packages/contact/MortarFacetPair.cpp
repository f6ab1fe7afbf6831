#include "contact/MortarFacetPair.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

#include "contact/MortarFacetGeometry.hpp"
#include "contact/MortarSlipVariation.hpp"

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

/// One Gauss point's virtual slips δũ_a = W_a P (Σ_j N_j δx_j − Σ_l M_l δy_l) (MortarSlipVariation.hpp,
/// eq. M11″): the weights W_a = w N_a(ξ), the slave and master shape values at ξ and η, n_m(η).
template <int V>
void addSlipVariation(SlipVariationSum<HessianDual<V>>& sum, const std::array<HessianDual<V>, kMortarFacetNodes>& weights,
                      const LinearFacet<HessianDual<V>>& slave, const LinearFacet<HessianDual<V>>& master,
                      const std::array<HessianDual<V>, kMortarFacetNodes>& slaveShape,
                      const std::array<HessianDual<V>, kMortarFacetNodes>& masterShape,
                      const Point3<HessianDual<V>>& normal, const FacetPairCoordinates<HessianDual<V>>& x) {
  using Term = typename SlipVariationSum<HessianDual<V>>::Term;
  std::array<Term, 2 * kMortarFacetNodes> terms;
  int count = 0;
  for (int j = 0; j < slave.count; ++j) terms[count++] = {&slaveShape[j], {&x[3 * j], &x[3 * j + 1], &x[3 * j + 2]}, 1.0};
  for (int l = 0; l < master.count; ++l) {
    const int i = 3 * (kMortarFacetNodes + l);
    terms[count++] = {&masterShape[l], {&x[i], &x[i + 1], &x[i + 2]}, -1.0};
  }
  const auto rows = tangentialProjectorRows<V>({firstOrder(normal.x), firstOrder(normal.y), firstOrder(normal.z)});
  sum.template add<3, 3>(kMortarFacetNodes, weights.data(), slave.count, rows, terms.data(), count);
}

/// Whether the fused Gauss-point kernel below applies to a pair: a Quad4 slave whose monomial terms are
/// linear in the variables (the seeded nodes' combinations: zero Hessians) and a master whose point is
/// x_0 + η_1 x_η1 + η_2 x_η2 with constant x_η (a rigid master, moved by a translation) and a fixed normal
/// (FacetMap::fixedNormal): the block and the tube on their rigid bases. Values (T = double) never.
template <class T>
bool fusedGaussPoints(const LinearFacet<T>&, const FacetMap<T>&, const FacetMap<T>&) {
  return false;
}
template <int V>
bool fusedGaussPoints(const LinearFacet<HessianDual<V>>& slave, const FacetMap<HessianDual<V>>& slaveMap,
                      const FacetMap<HessianDual<V>>& masterMap) {
  const auto linear = [](const Point3<HessianDual<V>>& p) {
    for (const HessianDual<V>* c : {&p.x, &p.y, &p.z})
      for (double d : c->h)
        if (d != 0.0) return false;
    return true;
  };
  bool slaveTerms = slave.count == 4 && slaveMap.twisted;
  for (int k = 0; k < 4; ++k) slaveTerms = slaveTerms && !slaveMap.fixed[k] && linear(slaveMap.term[k]);
  return slaveTerms && !masterMap.twisted && masterMap.fixed[1] && masterMap.fixed[2] && linear(masterMap.term[0]) &&
         masterMap.fixedNormal();
}

/// One Gauss point's term of the differentiated weighted gaps, g̃_a += N_a(ξ) (w |T| A_0/A_p) g (eq. M17),
/// where fusedGaussPoints holds: the same operations as the generic path (FacetMap::at for x_s(ξ) and
/// x_m(η), g = (x_s − x_m) · n_m with n_m fixed, LinearFacet::shape, the products of HessianDual.hpp), entry
/// by entry of the gradient and the packed Hessian, in the same order, so the same bits (bar the signs of
/// zeros: the terms dropped are the products with the linear terms' zero Hessians). One pass over the
/// entries instead of some thirty HessianDual temporaries of N(N+1)/2 entries each.
/// `gapValue`: g at the point (the doubles'); `slaveValue`/`masterValue`: x_s, x_m's values.
template <int V>
void addFusedGaussPoint(const FacetMap<HessianDual<V>>& slaveMap, const FacetMap<HessianDual<V>>& masterMap,
                        const std::array<HessianDual<V>, 2>& xi, const std::array<HessianDual<V>, 2>& eta,
                        const Point3<double>& normal, double gapValue, const HessianDual<V>& triangleMeasure,
                        double ruleWeight, double weight, std::array<HessianDual<V>, kMortarFacetNodes>& sum) {
  using H = HessianDual<V>;
  const H& s = xi[0];
  const H& t = xi[1];
  const double n[3] = {normal.x, normal.y, normal.z};
  const auto component = [](const Point3<H>& p, int c) -> const H& { return c == 0 ? p.x : (c == 1 ? p.y : p.z); };
  const auto value = [](const Point3<double>& p, int c) { return c == 0 ? p.x : (c == 1 ? p.y : p.z); };
  // Gradients: P = ξ η; per coordinate the slave terms T_k and the master's x_0 and constant x_η.
  const double pv = s.v * t.v;
  std::array<double, V> pg, dg[3], gapG, wg, wgG;
  for (int i = 0; i < V; ++i) pg[i] = t.v * s.g[i] + s.v * t.g[i];
  const H* term[3][4];
  double m1[3], m2[3];
  for (int c = 0; c < 3; ++c) {
    for (int k = 0; k < 4; ++k) term[c][k] = &component(slaveMap.term[k], c);
    const H& m0 = component(masterMap.term[0], c);
    m1[c] = value(masterMap.termValue[1], c);
    m2[c] = value(masterMap.termValue[2], c);
    const H &t0 = *term[c][0], &t1 = *term[c][1], &t2 = *term[c][2], &t3 = *term[c][3];
    for (int i = 0; i < V; ++i) {
      const double x = ((t0.g[i] + (s.v * t1.g[i] + t1.v * s.g[i])) + (t.v * t2.g[i] + t2.v * t.g[i])) +
                       (pv * t3.g[i] + t3.v * pg[i]);
      const double y = (m0.g[i] + eta[0].g[i] * m1[c]) + eta[1].g[i] * m2[c];
      dg[c][i] = x - y;
    }
  }
  for (int i = 0; i < V; ++i) {
    gapG[i] = (dg[0][i] * n[0] + dg[1][i] * n[1]) + dg[2][i] * n[2];
    wg[i] = triangleMeasure.g[i] * ruleWeight;
    wgG[i] = gapValue * wg[i] + weight * gapG[i];
  }
  const double wgV = weight * gapValue;
  // The shape functions N_a = (0.25 (1 ± ξ)) (1 ± η) (LinearFacet::shape): B = 0.25 (1 ± ξ), C = 1 ± η.
  constexpr double kSign[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  double bv[4], cv[4], nv[4];
  std::array<double, V> bg[4], cg[4], ng[4];
  for (int a = 0; a < 4; ++a) {
    const bool minusXi = kSign[a][0] < 0, minusEta = kSign[a][1] < 0;
    bv[a] = (minusXi ? -s.v + 1.0 : s.v + 1.0) * 0.25;
    cv[a] = minusEta ? -t.v + 1.0 : t.v + 1.0;
    nv[a] = bv[a] * cv[a];
    for (int i = 0; i < V; ++i) {
      bg[a][i] = (minusXi ? -s.g[i] : s.g[i]) * 0.25;
      cg[a][i] = minusEta ? -t.g[i] : t.g[i];
      ng[a][i] = cv[a] * bg[a][i] + bv[a] * cg[a][i];
    }
    H& r = sum[a];
    r.v = r.v + nv[a] * wgV;
    for (int i = 0; i < V; ++i) r.g[i] = r.g[i] + (wgV * ng[a][i] + nv[a] * wgG[i]);
  }
  // The packed Hessian, entry (i, j ≥ i) at k.
  int k = 0;
  for (int i = 0; i < V; ++i) {
    const double si = s.g[i], ti = t.g[i], pi = pg[i], wi = wg[i], gi = gapG[i], wgi = wgG[i];
    double ti1[3], ti2[3], ti3[3];
    for (int c = 0; c < 3; ++c) ti1[c] = term[c][1]->g[i], ti2[c] = term[c][2]->g[i], ti3[c] = term[c][3]->g[i];
    double bi[4], ci[4], ni[4];
    for (int a = 0; a < 4; ++a) bi[a] = bg[a][i], ci[a] = cg[a][i], ni[a] = ng[a][i];
    for (int j = i; j < V; ++j, ++k) {
      const double sh = s.h[k], th = t.h[k];
      const double ph = ((t.v * sh + s.v * th) + si * t.g[j]) + ti * s.g[j];
      double d[3];
      for (int c = 0; c < 3; ++c) {
        const H &t1 = *term[c][1], &t2 = *term[c][2], &t3 = *term[c][3];
        const double r1 = (t1.v * sh + ti1[c] * s.g[j]) + si * t1.g[j];
        const double r2 = (t2.v * th + ti2[c] * t.g[j]) + ti * t2.g[j];
        const double r3 = (t3.v * ph + ti3[c] * pg[j]) + pi * t3.g[j];
        d[c] = ((r1 + r2) + r3) - (eta[0].h[k] * m1[c] + eta[1].h[k] * m2[c]);
      }
      const double gh = (d[0] * n[0] + d[1] * n[1]) + d[2] * n[2];
      const double wh = triangleMeasure.h[k] * ruleWeight;
      const double wgh = ((gapValue * wh + weight * gh) + wi * gapG[j]) + gi * wg[j];
      for (int a = 0; a < 4; ++a) {
        const double bh = (kSign[a][0] < 0 ? -sh : sh) * 0.25, ch = kSign[a][1] < 0 ? -th : th;
        const double nh = ((cv[a] * bh + bv[a] * ch) + bi[a] * cg[a][j]) + ci[a] * bg[a][j];
        sum[a].h[k] = sum[a].h[k] + (((wgV * nh + nv[a] * wgh) + ni[a] * wgG[j]) + wgi * ng[a][j]);
      }
    }
  }
}

/// The pair's segmentation (eq. M13–M14): the projected slave polygon, the projected master facet and
/// their clip polygon, and whether they overlap (the master faces the slave, both polygons have positive
/// area, the clip polygon more than kMortarSnap of the slave's). Every decision is on the values, so a
/// differentiated number type decides as the doubles do.
template <class T>
struct Segmentation {
  bool overlaps = false;
  std::vector<PlanePoint<T>> slavePolygon, masterProjected, clip;
  T slaveArea2{};
};
template <class T>
Segmentation<T> segment(const LinearFacet<T>& slave, const LinearFacet<T>& master, const ProjectionPlane<T>& plane) {
  Segmentation<T> s;
  const double size = std::max(facetDiameter(slave), facetDiameter(master));
  if (!facing(slave, master, plane, size)) return s;
  // eq. M14: the projected slave polygon (anticlockwise about n_0) clipped by the projected master
  // polygon, which runs clockwise about n_0 (its normal is about −n_0): reversed first.
  s.slavePolygon = plane.project(slave);
  s.masterProjected = plane.project(master);
  const std::vector<PlanePoint<T>> masterPolygon(s.masterProjected.rbegin(), s.masterProjected.rend());
  s.slaveArea2 = twiceSignedArea(s.slavePolygon);
  if (!(twiceSignedAreaValue(masterPolygon) > 0.0) || !(valueOf(s.slaveArea2) > 0.0)) return s;
  s.clip = clipConvexPolygon(s.slavePolygon, masterPolygon, kMortarClipSnap * size);
  s.overlaps = s.clip.size() >= 3 && twiceSignedAreaValue(s.clip) > kMortarSnap * valueOf(s.slaveArea2);
  return s;
}

/// Whether the pair overlaps, decided on the values alone (in doubles: the decisions integrateFacetPair
/// takes on any number type's values).
bool overlapsOnValues(const FacetPairCoordinates<double>& x, const MortarFacetPairShape& shape) {
  const LinearFacet<double> slave = facetOf(x, 0, shape.slaveNodes);
  return segment(slave, facetOf(x, kMortarFacetNodes, shape.masterNodes), ProjectionPlane<double>(slave)).overlaps;
}

}  // namespace

template <class T>
MortarFacetPairGaps<T> integrateFacetPair(const FacetPairCoordinates<T>& x, double referenceArea,
                                          const MortarFacetPairShape& shape, const FacetPairCommitted* committed) {
  MortarFacetPairGaps<T> out;
  if constexpr (!std::is_same_v<T, double>) {
    // A pair without overlap on the values has none differentiated (the same decisions on the same
    // values): found in doubles, before any differentiated number is formed (the projection plane, the
    // projections and the clip cost about a sixth of an overlapping pair's derivatives).
    FacetPairCoordinates<double> values;
    for (std::size_t i = 0; i < x.size(); ++i) values[i] = valueOf(x[i]);
    if (!overlapsOnValues(values, shape)) return out;
  }
  const LinearFacet<T> slave = facetOf(x, 0, shape.slaveNodes), master = facetOf(x, kMortarFacetNodes, shape.masterNodes);
  const ProjectionPlane<T> plane(slave);
  const Segmentation<T> segmentation = segment(slave, master, plane);
  if (!segmentation.overlaps) return out;
  const std::vector<PlanePoint<T>>& slavePolygon = segmentation.slavePolygon;
  const std::vector<PlanePoint<T>>& masterProjected = segmentation.masterProjected;
  const std::vector<PlanePoint<T>>& clip = segmentation.clip;
  const T& slaveArea2 = segmentation.slaveArea2;
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
  // The fused Gauss-point kernel where it applies (a rigid master: the block's and the tube's bases).
  const bool fused = fusedGaussPoints(slave, slaveMap, masterMap);
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
        if (fused) {
          addFusedGaussPoint(slaveMap, masterMap, xi, eta, normal, g, triangleMeasure, q.weight, weight, differentiated);
        } else {
          const std::array<T, kMortarFacetNodes> nodeShape = slave.shape(xi[0], xi[1]);
          const Point3<T> d = slaveMap.at(xi) - masterMap.at(eta);
          const T gap = fixedNormal ? d.x * normal.x + d.y * normal.y + d.z * normal.z : dot(d, masterMap.unitNormal(eta));
          const T weightedG = withValue(q.weight * triangleMeasure, weight) * gap;
          for (int a = 0; a < slave.count; ++a) differentiated[a] = differentiated[a] + nodeShape[a] * weightedG;
        }
      }
      if (committed != nullptr) {  // eq. M9′: Δũ_a += w N_a(ξ) u_T, in T (values and derivatives alike)
        const Point3<T> u = tangentialSlip(slaveMap, masterMap, slave, master, xi, eta, *committed);
        const std::array<T, kMortarFacetNodes> nodeShape = slave.shape(xi[0], xi[1]);
        const T w = withValue(q.weight * triangleMeasure, weight);
        std::array<T, kMortarFacetNodes> wa{};
        for (int a = 0; a < slave.count; ++a) {
          wa[a] = w * nodeShape[a];
          std::array<T, 3>& slip = out.weightedSlip[a];
          slip = {slip[0] + wa[a] * u.x, slip[1] + wa[a] * u.y, slip[2] + wa[a] * u.z};
        }
        if constexpr (!std::is_same_v<T, double>)  // the virtual slip (MortarSlipVariation.hpp)
          addSlipVariation(out.slipVariation, wa, slave, master, nodeShape, master.shape(eta[0], eta[1]),
                           masterMap.unitNormal(eta), x);
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
void differentiateWithSlip(const FacetPairCoordinates<double>& x, double referenceArea, const MortarFacetPairShape& shape,
                           const FacetPairCommitted& committed, const KernelVariables<kN>& variables,
                           MortarFacetPairDerivatives& out) {
  std::vector<std::array<HessianDual<V>, kN>> seeded(1, variables.template seed<V>(x));  // large: on the heap
  const auto g = integrateFacetPair(seeded[0], referenceArea, shape, &committed);
  extractGapsAndSlips<kMortarFacetNodes>(g, variables, out);  // every field but the virtual slips'
  extractSlipVariation<kN, V>(g.slipVariation, variables, kMortarFacetNodes, 3, out.slipVariation,
                              out.slipVariationGradient);
}
}  // namespace

void facetPairDerivatives(const FacetPairCoordinates<double>& x, double referenceArea, const MortarFacetPairShape& shape,
                          const double* masterMotion, const FacetPairCommitted* committed,
                          MortarFacetPairDerivatives& out) {
  constexpr int kFirstMaster = 3 * kMortarFacetNodes;
  if (committed != nullptr) {
    if (masterMotion == nullptr)
      return differentiateWithSlip<kN>(x, referenceArea, shape, *committed, ownVariables<kN>(), out);
    if (motionless(masterMotion, kFirstMaster))
      return differentiateWithSlip<kFirstMaster>(x, referenceArea, shape, *committed,
                                                 motionlessBodyVariables<kN>(kFirstMaster, kFirstMaster), out);
    return differentiateWithSlip<kFirstMaster + 1>(x, referenceArea, shape, *committed,
                                                   rigidBodyVariables<kN>(kFirstMaster, kFirstMaster, masterMotion), out);
  }
  // A frictionless pair carries no slip entries (a record reused from a frictional evaluation loses them).
  out.weightedSlip = {};
  out.slipGradient.clear();
  out.slipHessian.clear();
  out.slipVariation.clear();
  out.slipVariationGradient.clear();
  // Without overlap (on the values) every entry is zero: no differentiated number seeded or extracted.
  if (!overlapsOnValues(x, shape)) {
    out.overlaps = false;
    out.weightedGap = {};
    out.mortarArea = {};
    for (auto& g : out.gradient) g.fill(0.0);
    for (auto& h : out.hessian) h.fill(0.0);
    return;
  }
  // A rigid master: the twelve slave coordinates and the motion (MortarDual.hpp, KernelVariables).
  differentiatePairKernelInto<kFirstMaster>(
      out, x, masterMotion, [&](const auto& seeded) { return integrateFacetPair(seeded, referenceArea, shape); });
}

MortarFacetPairDerivatives facetPairDerivatives(const FacetPairCoordinates<double>& x, double referenceArea,
                                                const MortarFacetPairShape& shape, const double* masterMotion,
                                                const FacetPairCommitted* committed) {
  MortarFacetPairDerivatives out;
  facetPairDerivatives(x, referenceArea, shape, masterMotion, committed, out);
  return out;
}

}  // namespace contessa::contact
