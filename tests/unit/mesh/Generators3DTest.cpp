// The Hex8 generators (Box, Hollow Cylinder Sector, Sphere Octant): counts and numbering, sets,
// orientation (positive cell volumes, outward side normals), volumes and areas against the exact
// geometry, and refused specs.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "MeshTestSupport.hpp"
#include "common/Error.hpp"
#include "mesh/CellGeometry.hpp"
#include "mesh/Generators.hpp"

using namespace contessa;
using namespace contessa::mesh;
using test_support::refusalOf;

namespace {

const double kPi = std::acos(-1.0);
using Vec = std::array<double, 3>;

Vec point(const Mesh& m, GlobalIndex n) { return {m.coordinates[3 * n], m.coordinates[3 * n + 1], m.coordinates[3 * n + 2]}; }
Vec minus(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const Vec& a) { return std::sqrt(dot(a, a)); }

std::vector<double> cellCoordinates(const Mesh& m, const ElementBlock& b, size_t e) {
  std::vector<double> x;
  for (int a = 0; a < 8; ++a) {
    const Vec p = point(m, b.connectivity[8 * e + a]);
    x.insert(x.end(), p.begin(), p.end());
  }
  return x;
}

// Sum of the cell volumes; every cell must have a positive volume.
double volume(const Mesh& m) {
  double total = 0;
  for (const auto& b : m.blocks)
    for (size_t e = 0; e < b.elements.size(); ++e) {
      const double v = cellMeasure(CellType::Hex8, cellCoordinates(m, b, e).data());
      EXPECT_GT(v, 0) << "element " << b.elements[e];
      total += v;
    }
  return total;
}

// The side's corners (Exodus order, counter-clockwise seen from outside).
std::array<Vec, 4> sideCorners(const Mesh& m, GlobalIndex element, int side) {
  const auto loc = m.locate(element);
  const auto& b = m.blocks[loc.block];
  const auto local = sideNodes(b.cellType, side);
  std::array<Vec, 4> p;
  for (int a = 0; a < 4; ++a) p[a] = point(m, b.connectivity[8 * loc.local + local[a]]);
  return p;
}

// Area vector of a bilinear quadrilateral: half the cross product of its diagonals (exact).
Vec areaVector(const std::array<Vec, 4>& p) {
  Vec n = cross(minus(p[2], p[0]), minus(p[3], p[1]));
  for (double& c : n) c /= 2;
  return n;
}

// For every side of the set, `check` gets the side's area vector (outward by its node order) and its centroid.
void forSides(const Mesh& m, const std::string& name, const std::function<void(const Vec&, const Vec&)>& check) {
  const auto& s = m.sideSet(name);
  ASSERT_EQ(s.elements.size(), s.sides.size());
  for (size_t k = 0; k < s.elements.size(); ++k) {
    const auto p = sideCorners(m, s.elements[k], s.sides[k]);
    Vec c{0, 0, 0};
    for (const auto& q : p)
      for (int i = 0; i < 3; ++i) c[i] += q[i] / 4;
    check(areaVector(p), c);
  }
}

// Every side of set `name` points along `direction` (unit outward normal = direction).
void expectOutward(const Mesh& m, const std::string& name, const Vec& direction) {
  forSides(m, name, [&](const Vec& n, const Vec&) {
    EXPECT_NEAR(dot(n, direction) / norm(n), 1.0, 1e-12) << name;
  });
}

// The node set of the same name holds exactly the nodes of the side set.
void expectNodeSetIsSideSetNodes(const Mesh& m, const std::string& name) {
  std::vector<GlobalIndex> nodes;
  const auto& s = m.sideSet(name);
  for (size_t k = 0; k < s.elements.size(); ++k) {
    const auto loc = m.locate(s.elements[k]);
    for (int a : sideNodes(CellType::Hex8, s.sides[k])) nodes.push_back(m.blocks[loc.block].connectivity[8 * loc.local + a]);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  EXPECT_EQ(m.nodeSet(name).nodes, nodes) << name;
}

}  // namespace

TEST(BoxGenerator, CountsNumberingAndCoordinates) {
  BoxSpec spec;
  spec.x0 = 1, spec.y0 = -2, spec.z0 = 3;
  spec.lx = 4, spec.ly = 2, spec.lz = 1;
  spec.nx = 4, spec.ny = 3, spec.nz = 2;
  spec.blockName = "solid";
  const Mesh m = generateBox(spec);
  EXPECT_EQ(m.dimension, 3);
  EXPECT_EQ(m.numNodes(), 5 * 4 * 3);
  EXPECT_EQ(m.numElements(), 4 * 3 * 2);
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].name, "solid");
  EXPECT_EQ(m.blocks[0].cellType, CellType::Hex8);
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j <= 3; ++j)
      for (int i = 0; i <= 4; ++i) {
        const Vec p = point(m, (k * 4 + j) * 5 + i);
        EXPECT_DOUBLE_EQ(p[0], 1 + i);
        EXPECT_DOUBLE_EQ(p[1], -2 + 2.0 * j / 3);
        EXPECT_DOUBLE_EQ(p[2], 3 + 0.5 * k);
      }
  // Element (i, j, k) = (1, 2, 1): id (1*3 + 2)*4 + 1 = 21, z = z_k face first, counter-clockwise from +z.
  auto node = [](int i, int j, int k) -> GlobalIndex { return (k * 4 + j) * 5 + i; };
  const std::vector<GlobalIndex> expected{node(1, 2, 1), node(2, 2, 1), node(2, 3, 1), node(1, 3, 1),
                                          node(1, 2, 2), node(2, 2, 2), node(2, 3, 2), node(1, 3, 2)};
  EXPECT_EQ(m.blocks[0].elements[21], 21);
  EXPECT_EQ(std::vector<GlobalIndex>(m.blocks[0].connectivity.begin() + 8 * 21, m.blocks[0].connectivity.begin() + 8 * 22),
            expected);
  EXPECT_NEAR(volume(m), 4 * 2 * 1, 1e-12);
}

TEST(BoxGenerator, SetsAreTheSixFacesWithOutwardSides) {
  BoxSpec spec;
  spec.nx = 3, spec.ny = 4, spec.nz = 5;
  const Mesh m = generateBox(spec);
  const struct {
    const char* name;
    size_t nodes, sides;
    Vec normal;
  } faces[] = {{"left", 5 * 6, 4 * 5, {-1, 0, 0}}, {"right", 5 * 6, 4 * 5, {1, 0, 0}},
               {"bottom", 4 * 6, 3 * 5, {0, -1, 0}}, {"top", 4 * 6, 3 * 5, {0, 1, 0}},
               {"back", 4 * 5, 3 * 4, {0, 0, -1}}, {"front", 4 * 5, 3 * 4, {0, 0, 1}}};
  for (const auto& f : faces) {
    EXPECT_EQ(m.nodeSet(f.name).nodes.size(), f.nodes) << f.name;
    EXPECT_EQ(m.sideSet(f.name).elements.size(), f.sides) << f.name;
    expectOutward(m, f.name, f.normal);
    expectNodeSetIsSideSetNodes(m, f.name);
    double area = 0;
    forSides(m, f.name, [&](const Vec& n, const Vec&) { area += norm(n); });
    EXPECT_NEAR(area, 1.0, 1e-12) << f.name;  // a face of the unit cube
  }
  EXPECT_EQ(m.nodeSet("all").nodes.size(), static_cast<size_t>(m.numNodes()));
}

TEST(BoxGenerator, GradedInEachDirection) {
  BoxSpec spec;
  spec.nx = 3, spec.ny = 2, spec.nz = 4;
  spec.lz = 10;
  spec.biasZ = 8;  // sizes h, 2h, 4h, 8h: h = 10/15
  spec.biasX = 0.25;
  const Mesh m = generateBox(spec);
  const double h = 10.0 / 15;
  for (int k = 0; k <= 4; ++k) EXPECT_NEAR(point(m, k * 3 * 4)[2], h * (std::pow(2.0, k) - 1), 1e-12) << k;
  EXPECT_EQ(point(m, 4 * 3 * 4)[2], 10.0);  // the last node exactly at z0 + lz
  // x: sizes shrink by 0.5 per element: h, h/2, h/4 with h = 1/1.75.
  EXPECT_NEAR(point(m, 1)[0], 1 / 1.75, 1e-12);
  EXPECT_NEAR(volume(m), 10, 1e-12);
}

TEST(BoxGenerator, RejectsBadSpecs) {
  auto message = [](auto change) { return refusalOf(&generateBox, change); };
  EXPECT_EQ(message([](BoxSpec& s) { s.lz = 0; }), "Length Z: expected a positive number, got 0");
  EXPECT_EQ(message([](BoxSpec& s) { s.nz = 0; }), "Elements Z: expected a positive integer, got 0");
  EXPECT_EQ(message([](BoxSpec& s) { s.biasZ = -1; }), "Bias Z: expected a value > 0, got -1");
  EXPECT_EQ(message([](BoxSpec& s) { s.z0 = NAN; }), "Z Origin: expected a finite number, got nan");
  const std::string tooLarge = message([](BoxSpec& s) { s.nx = s.ny = s.nz = 100000; });
  EXPECT_EQ(tooLarge.rfind("Elements X = 100000, Elements Y = 100000, Elements Z = 100000: 1e15 elements need about ", 0), 0u)
      << tooLarge;
  EXPECT_NE(tooLarge.find("reduce Elements X, Elements Y or Elements Z"), std::string::npos) << tooLarge;
}

TEST(HollowCylinderSectorGenerator, LayerZeroIsTheAnnulusSector) {
  HollowCylinderSectorSpec spec;
  spec.section = test_support::annulusSpec(3, 7, 100, 20);
  spec.section.radialBias = 0.5;
  spec.section.arcBias = 2;
  spec.section.blockName = "tube";
  spec.z0 = -1;
  spec.length = 5;
  spec.layers = 1;
  const Mesh tube = generateHollowCylinderSector(spec);
  const Mesh ring = generateAnnulusSector(spec.section);
  ASSERT_EQ(tube.numNodes(), 2 * ring.numNodes());
  ASSERT_EQ(tube.numElements(), ring.numElements());
  for (GlobalIndex n = 0; n < ring.numNodes(); ++n) {
    EXPECT_EQ(tube.coordinates[3 * n], ring.coordinates[2 * n]) << n;  // bit for bit
    EXPECT_EQ(tube.coordinates[3 * n + 1], ring.coordinates[2 * n + 1]) << n;
    EXPECT_EQ(tube.coordinates[3 * n + 2], -1.0);
    const GlobalIndex above = n + ring.numNodes();
    EXPECT_EQ(tube.coordinates[3 * above], ring.coordinates[2 * n]);
    EXPECT_EQ(tube.coordinates[3 * above + 2], 4.0);
  }
  // Each hexahedron's first face is the 2D element, its second the same one layer up.
  const auto& hex = tube.blocks[0];
  const auto& quad = ring.blocks[0];
  EXPECT_EQ(hex.name, "tube");
  EXPECT_EQ(hex.elements, quad.elements);
  for (size_t e = 0; e < quad.elements.size(); ++e)
    for (int a = 0; a < 4; ++a) {
      EXPECT_EQ(hex.connectivity[8 * e + a], quad.connectivity[4 * e + a]);
      EXPECT_EQ(hex.connectivity[8 * e + 4 + a], quad.connectivity[4 * e + a] + ring.numNodes());
    }
  // The 2D side sets carry over (same elements and sides); the z-faces are new.
  for (const char* name : {"inner", "outer", "start", "end"}) {
    EXPECT_EQ(tube.sideSet(name).elements, ring.sideSet(name).elements) << name;
    EXPECT_EQ(tube.sideSet(name).sides, ring.sideSet(name).sides) << name;
    expectNodeSetIsSideSetNodes(tube, name);
  }
  EXPECT_EQ(tube.sideSet("back").elements.size(), 21u);
  EXPECT_EQ(tube.sideSet("front").elements.size(), 21u);
  expectOutward(tube, "back", {0, 0, -1});
  expectOutward(tube, "front", {0, 0, 1});
  expectNodeSetIsSideSetNodes(tube, "back");
  expectNodeSetIsSideSetNodes(tube, "front");
}

TEST(HollowCylinderSectorGenerator, LayersVolumeAndOutwardSides) {
  HollowCylinderSectorSpec spec;
  spec.section = test_support::annulusSpec(2, 6, 2, 1, 30, 120);
  spec.length = 3;
  spec.layers = 4;
  spec.axialBias = 3;
  const Mesh m = generateHollowCylinderSector(spec);
  EXPECT_EQ(m.numNodes(), 3 * 7 * 5);
  EXPECT_EQ(m.numElements(), 2 * 6 * 4);
  EXPECT_EQ(m.sideSet("inner").elements.size(), 6u * 4);
  EXPECT_EQ(m.sideSet("start").elements.size(), 2u * 4);
  EXPECT_EQ(m.nodeSet("outer").nodes.size(), 7u * 5);
  // Volume: the hexahedra fill the polygonal annulus (chords between nodes) times the length exactly.
  const double dTheta = 15 * kPi / 180;
  const double polygonArea = 6 * 0.5 * (3.0 * 3.0 - 2.0 * 2.0) * std::sin(dTheta);
  EXPECT_NEAR(volume(m), polygonArea * 3, 1e-12 * polygonArea * 3);
  // The sector itself: the chords lose the factor sin(Δθ)/Δθ = 0.9886 of its area.
  const double sectorVolume = 0.5 * (kPi / 2) * (9 - 4) * 3;
  EXPECT_NEAR(volume(m) / sectorVolume, std::sin(dTheta) / dTheta, 1e-12);
  // Inner sides face the axis, outer sides away from it; start and end face out of the sector.
  forSides(m, "inner", [](const Vec& n, const Vec& c) { EXPECT_LT(dot(n, {c[0], c[1], 0}), 0); });
  forSides(m, "outer", [](const Vec& n, const Vec& c) { EXPECT_GT(dot(n, {c[0], c[1], 0}), 0); });
  const double t0 = 30 * kPi / 180, t1 = 120 * kPi / 180;
  expectOutward(m, "start", {std::sin(t0), -std::cos(t0), 0});
  expectOutward(m, "end", {-std::sin(t1), std::cos(t1), 0});
  expectOutward(m, "back", {0, 0, -1});
  expectOutward(m, "front", {0, 0, 1});
  // Axial grading: layer sizes h, √3 h, 3h, ... ratio 3^(1/3) between layers.
  const double q = std::cbrt(3.0), h = 3 / (1 + q + q * q + q * q * q);
  EXPECT_NEAR(point(m, 21)[2], h, 1e-12);
  EXPECT_EQ(point(m, 4 * 21)[2], 3.0);
}

TEST(HollowCylinderSectorGenerator, RejectsBadSpecs) {
  auto message = [](auto change) { return refusalOf(&generateHollowCylinderSector, change); };
  EXPECT_EQ(message([](HollowCylinderSectorSpec& s) { s.length = -2; }), "Length Z: expected a positive number, got -2");
  EXPECT_EQ(message([](HollowCylinderSectorSpec& s) { s.layers = 0; }), "Elements Z: expected a positive integer, got 0");
  EXPECT_EQ(message([](HollowCylinderSectorSpec& s) { s.section.thickness = 0; }),
            "Thickness: expected a positive number, got 0");
  EXPECT_EQ(message([](HollowCylinderSectorSpec& s) { s.section.endAngleDeg = -5; }),
            "End Angle: expected an angle greater than Start Angle (0), got -5");
  const std::string tooLarge = message([](HollowCylinderSectorSpec& s) { s.layers = INT_MAX; });
  EXPECT_EQ(tooLarge.rfind("Elements Through Thickness = 13, Elements Around Arc = 101, Elements Z = 2147483647: ", 0), 0u)
      << tooLarge;
}

TEST(SphereOctantGenerator, CountsSetsAndPlacement) {
  SphereOctantSpec spec;
  spec.radius = 50;
  spec.center[0] = 1, spec.center[1] = 2, spec.center[2] = 3;
  spec.elementsAlongEdge = 3;
  spec.elementsThroughShell = 2;
  const Mesh m = generateSphereOctant(spec);
  EXPECT_EQ(m.numNodes(), 4 * 4 * 4 + 2 * (3 * 9 + 3 * 3 + 1));
  EXPECT_EQ(m.numElements(), 27 + 3 * 9 * 2);
  ASSERT_EQ(m.blocks.size(), 1u);
  const Vec c{1, 2, 3};
  // "-z": the octant x ≥ 1, y ≥ 2, z ≤ 3, the pole at (1, 2, -47).
  ASSERT_EQ(m.nodeSet("pole").nodes.size(), 1u);
  const Vec pole = point(m, m.nodeSet("pole").nodes[0]);
  EXPECT_NEAR(pole[0], 1, 1e-12);
  EXPECT_NEAR(pole[1], 2, 1e-12);
  EXPECT_NEAR(pole[2], -47, 1e-12);
  for (GlobalIndex n = 0; n < m.numNodes(); ++n) {
    const Vec p = point(m, n);
    EXPECT_GE(p[0], 1 - 1e-12);
    EXPECT_GE(p[1], 2 - 1e-12);
    EXPECT_LE(p[2], 3 + 1e-12);
    EXPECT_LE(norm(minus(p, c)), 50 * (1 + 1e-12));
  }
  for (GlobalIndex n : m.nodeSet("surface").nodes) EXPECT_NEAR(norm(minus(point(m, n), c)), 50, 1e-12);
  for (GlobalIndex n : m.nodeSet("equator").nodes) EXPECT_EQ(point(m, n)[2], 3.0);
  for (GlobalIndex n : m.nodeSet("symmetry_x").nodes) EXPECT_EQ(point(m, n)[0], 1.0);
  for (GlobalIndex n : m.nodeSet("symmetry_y").nodes) EXPECT_EQ(point(m, n)[1], 2.0);
  // Each set: the cube's 3×3 faces and the shells' 3×2 on each plane, the three 3×3 patches on the sphere.
  EXPECT_EQ(m.sideSet("surface").elements.size(), 27u);
  for (const char* plane : {"equator", "symmetry_x", "symmetry_y"}) {
    EXPECT_EQ(m.sideSet(plane).elements.size(), 9u + 2 * 6) << plane;
    expectNodeSetIsSideSetNodes(m, plane);
  }
  expectNodeSetIsSideSetNodes(m, "surface");
  expectOutward(m, "symmetry_x", {-1, 0, 0});
  expectOutward(m, "symmetry_y", {0, -1, 0});
  expectOutward(m, "equator", {0, 0, 1});
  forSides(m, "surface", [&](const Vec& n, const Vec& centroid) {
    const Vec r = minus(centroid, c);
    EXPECT_GT(dot(n, r) / (norm(n) * norm(r)), 0.95);  // nearly radial on a 3 × 3 patch
  });
  EXPECT_EQ(m.nodeSet("all").nodes.size(), static_cast<size_t>(m.numNodes()));
  EXPECT_GT(volume(m), 0);
}

TEST(SphereOctantGenerator, EveryPoleDirectionIsARotation) {
  // Right-handed cells (validate) and the pole, planes and sets where the direction puts them.
  for (const char* direction : {"-x", "+x", "-y", "+y", "-z", "+z"}) {
    SphereOctantSpec spec;
    spec.radius = 2;
    spec.poleDirection = direction;
    spec.elementsAlongEdge = 2;
    spec.elementsThroughShell = 2;
    const Mesh m = generateSphereOctant(spec);  // validates: positive Jacobians, boundary sides
    const int axis = direction[1] - 'x';
    const double sign = direction[0] == '-' ? -1 : 1;
    const Vec pole = point(m, m.nodeSet("pole").nodes[0]);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(pole[i], i == axis ? 2 * sign : 0, 1e-12) << direction;
    Vec outward{0, 0, 0};
    outward[axis] = -sign;
    expectOutward(m, "equator", outward);
    for (int other = 0; other < 3; ++other) {
      if (other == axis) continue;
      const std::string name = std::string("symmetry_") + "xyz"[other];
      Vec n{0, 0, 0};
      n[other] = -1;
      expectOutward(m, name, n);
    }
    EXPECT_FALSE(m.hasSideSet(std::string("symmetry_") + "xyz"[axis])) << direction;
  }
}

TEST(SphereOctantGenerator, VolumeAndAreaConvergeToTheSphere) {
  // The nodes of the curved surface lie on the sphere; the bilinear faces between them cut inside
  // it, so volume and area approach π R³/6 and π R²/2 from below, at second order in the element size.
  const double R = 50, exactVolume = kPi * R * R * R / 6, exactArea = kPi * R * R / 2;
  double previousVolumeError = 0, previousAreaError = 0;
  for (int n : {2, 4, 8, 16}) {
    SphereOctantSpec spec;
    spec.radius = R;
    spec.elementsAlongEdge = n;
    spec.elementsThroughShell = n;
    const Mesh m = generateSphereOctant(spec);
    double area = 0;
    forSides(m, "surface", [&](const Vec& a, const Vec&) { area += norm(a); });
    const double volumeError = (exactVolume - volume(m)) / exactVolume;
    const double areaError = (exactArea - area) / exactArea;
    EXPECT_GT(volumeError, 0) << n;
    EXPECT_GT(areaError, 0) << n;
    if (previousVolumeError > 0) {
      EXPECT_NEAR(previousVolumeError / volumeError, 4, 0.5) << n;  // O(h²)
      EXPECT_NEAR(previousAreaError / areaError, 4, 0.5) << n;
    }
    std::printf("sphere octant n = m = %2d: %6lld elements, volume error %.3e, area error %.3e\n", n,
                static_cast<long long>(m.numElements()), volumeError, areaError);
    previousVolumeError = volumeError;
    previousAreaError = areaError;
  }
  EXPECT_LT(previousVolumeError, 2e-3);
  EXPECT_LT(previousAreaError, 2e-3);
}

TEST(SphereOctantGenerator, GradingRefinesAtThePoleAndTheSurface) {
  SphereOctantSpec spec = test_support::octantSpec(6, 5);
  spec.radius = 1;
  spec.poleBias = 10;
  spec.radialBias = 0.2;
  spec.innerCubeFraction = 0.4;
  const Mesh m = generateSphereOctant(spec);
  const Vec pole = point(m, m.nodeSet("pole").nodes[0]);
  // Surface nodes around the pole: the nearest is about 10× closer than the patch's far nodes are to
  // their neighbours; radial layers thin towards the surface.
  double nearest = 1e9;
  for (GlobalIndex n : m.nodeSet("surface").nodes) {
    const double d = norm(minus(point(m, n), pole));
    if (d > 0) nearest = std::min(nearest, d);
  }
  EXPECT_LT(nearest, 0.06);
  // Along the axis through the pole: layer thicknesses shrink by 0.2 from the cube to the surface.
  std::vector<double> depths;
  for (GlobalIndex n = 0; n < m.numNodes(); ++n) {
    const Vec p = point(m, n);
    if (p[0] == 0 && p[1] == 0 && p[2] <= -0.4) depths.push_back(-p[2]);
  }
  std::sort(depths.begin(), depths.end());
  ASSERT_EQ(depths.size(), 6u);
  EXPECT_NEAR((depths[5] - depths[4]) / (depths[1] - depths[0]), 0.2, 1e-9);
  EXPECT_GT(volume(m), 0);
}

TEST(SphereOctantGenerator, RejectsBadSpecs) {
  auto message = [](auto change) { return refusalOf(&generateSphereOctant, change); };
  EXPECT_EQ(message([](SphereOctantSpec& s) { s.radius = 0; }), "Radius: expected a positive number, got 0");
  EXPECT_EQ(message([](SphereOctantSpec& s) { s.poleDirection = "z"; }),
            "Pole Direction: expected one of -x, +x, -y, +y, -z, +z, got 'z'");
  EXPECT_EQ(message([](SphereOctantSpec& s) { s.innerCubeFraction = 0.6; }),
            "Inner Cube Fraction: expected a value in (0, 0.57735) (the inner cube's corner inside the sphere: "
            "fraction < 1/sqrt(3)), got 0.6");
  EXPECT_EQ(message([](SphereOctantSpec& s) { s.elementsThroughShell = 0; }),
            "Elements Through Shell: expected a positive integer, got 0");
  EXPECT_EQ(message([](SphereOctantSpec& s) { s.poleBias = 0; }), "Pole Bias: expected a value > 0, got 0");
  const std::string tooLarge = message([](SphereOctantSpec& s) { s.elementsAlongEdge = 100000; });
  EXPECT_EQ(tooLarge.rfind("Elements Along Edge = 100000, Elements Through Shell = 4: 1e15 elements need about ", 0), 0u)
      << tooLarge;
}

TEST(SphereOctantGenerator, NoDegenerateElements) {
  // The worst corner of any element (scaled Jacobian: 1 = right angles, 0 = degenerate) stays well
  // away from 0 for the default cube fraction, with and without grading.
  for (double poleBias : {1.0, 5.0}) {
    SphereOctantSpec spec = test_support::octantSpec(8, 6);
    spec.poleBias = poleBias;
    spec.radialBias = poleBias == 1 ? 1 : 0.3;
    const Mesh m = generateSphereOctant(spec);
    const auto& b = m.blocks[0];
    double worst = 1;
    for (size_t e = 0; e < b.elements.size(); ++e) {
      double j[8];
      scaledCornerJacobians(CellType::Hex8, cellCoordinates(m, b, e).data(), j);
      worst = std::min(worst, *std::min_element(j, j + 8));
    }
    std::printf("sphere octant, pole bias %g: worst scaled corner Jacobian %.3f\n", poleBias, worst);
    EXPECT_GT(worst, 0.5);
  }
}
