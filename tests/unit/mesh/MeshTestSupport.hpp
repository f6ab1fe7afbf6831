#pragma once
// What the mesh tests share: the structured generators' specs in one line, the message of the
// InputError an action throws (or a generator given a changed spec), and two meshes compared field by field (coordinates, blocks, node sets,
// side sets).
#include <functional>
#include <string>

#include <gtest/gtest.h>

#include "common/Error.hpp"
#include "mesh/Generators.hpp"
#include "mesh/Mesh.hpp"

namespace contessa::mesh::test_support {

/// A Rectangle of nx × ny elements over [x0, x0 + lx] × [y0, y0 + ly] (the other fields at their defaults).
inline RectangleSpec rectangleSpec(int nx, int ny, double lx = 1, double ly = 1, double x0 = 0, double y0 = 0) {
  RectangleSpec spec;
  spec.nx = nx, spec.ny = ny, spec.lx = lx, spec.ly = ly, spec.x0 = x0, spec.y0 = y0;
  return spec;
}

/// An Annulus Sector of the given element counts over radii [innerRadius, innerRadius + thickness] and
/// angles [startDeg, endDeg] (the other fields at their defaults).
inline AnnulusSectorSpec annulusSpec(int throughThickness, int aroundArc, double innerRadius = 100, double thickness = 20,
                                     double startDeg = 0, double endDeg = 90) {
  AnnulusSectorSpec spec;
  spec.elementsThroughThickness = throughThickness, spec.elementsAroundArc = aroundArc;
  spec.innerRadius = innerRadius, spec.thickness = thickness;
  spec.startAngleDeg = startDeg, spec.endAngleDeg = endDeg;
  return spec;
}

/// A Hollow Cylinder Sector of `layers` layers over the default ring of the given element counts.
inline HollowCylinderSectorSpec tubeSpec(int throughThickness, int aroundArc, int layers) {
  HollowCylinderSectorSpec spec;
  spec.section = annulusSpec(throughThickness, aroundArc);
  spec.layers = layers;
  return spec;
}

/// A Sphere Octant of the default radius with the given element counts.
inline SphereOctantSpec octantSpec(int alongEdge, int throughShell) {
  SphereOctantSpec spec;
  spec.elementsAlongEdge = alongEdge;
  spec.elementsThroughShell = throughShell;
  return spec;
}

/// A Box of nx × ny × nz elements over [x0, x0 + lx] × [y0, y0 + ly] × [z0, z0 + lz] (the other fields at
/// their defaults).
inline BoxSpec boxSpec(int nx, int ny, int nz, double lx = 1, double ly = 1, double lz = 1, double x0 = 0, double y0 = 0,
                       double z0 = 0) {
  BoxSpec spec;
  spec.nx = nx, spec.ny = ny, spec.nz = nz, spec.lx = lx, spec.ly = ly, spec.lz = lz;
  spec.x0 = x0, spec.y0 = y0, spec.z0 = z0;
  return spec;
}

/// The InputError's message, or "<no InputError>" when `action` throws none.
inline std::string messageOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  }
  return "<no InputError>";
}

/// The message with which `generate` refuses its default spec changed by `change` (a callable taking
/// Spec&), "<no InputError>" when it builds the mesh.
template <class Spec, class Change>
std::string refusalOf(Mesh (*generate)(const Spec&), Change change) {
  Spec spec;
  change(spec);
  return messageOf([&] { generate(spec); });
}

/// How coordinates must agree: bit for bit (a mesh read two ways), or within 4 ulps (EXPECT_DOUBLE_EQ:
/// a mesh written to a file and read back).
enum class Coordinates { Exact, WithinFourUlps };

inline void expectSameMesh(const Mesh& a, const Mesh& b, Coordinates match = Coordinates::Exact) {
  EXPECT_EQ(a.dimension, b.dimension);
  if (match == Coordinates::Exact) {
    EXPECT_EQ(a.coordinates, b.coordinates);
  } else {
    ASSERT_EQ(a.coordinates.size(), b.coordinates.size());
    for (size_t k = 0; k < a.coordinates.size(); ++k) EXPECT_DOUBLE_EQ(a.coordinates[k], b.coordinates[k]) << k;
  }
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (size_t k = 0; k < a.blocks.size(); ++k) {
    EXPECT_EQ(a.blocks[k].name, b.blocks[k].name);
    EXPECT_EQ(a.blocks[k].cellType, b.blocks[k].cellType);
    EXPECT_EQ(a.blocks[k].elements, b.blocks[k].elements) << a.blocks[k].name;
    EXPECT_EQ(a.blocks[k].connectivity, b.blocks[k].connectivity) << a.blocks[k].name;
  }
  ASSERT_EQ(a.nodeSets.size(), b.nodeSets.size());
  for (size_t k = 0; k < a.nodeSets.size(); ++k) {
    EXPECT_EQ(a.nodeSets[k].name, b.nodeSets[k].name);
    EXPECT_EQ(a.nodeSets[k].nodes, b.nodeSets[k].nodes) << a.nodeSets[k].name;
  }
  ASSERT_EQ(a.sideSets.size(), b.sideSets.size());
  for (size_t k = 0; k < a.sideSets.size(); ++k) {
    EXPECT_EQ(a.sideSets[k].name, b.sideSets[k].name);
    EXPECT_EQ(a.sideSets[k].elements, b.sideSets[k].elements) << a.sideSets[k].name;
    EXPECT_EQ(a.sideSets[k].sides, b.sideSets[k].sides) << a.sideSets[k].name;
  }
}

}  // namespace contessa::mesh::test_support
