// The generators' parameter tables (mesh/MeshFactoryParameters.hpp, used by mesh/MeshFactory.cpp): what a
// table publishes is what it reads. A toy spec shows every kind of row publishing its parameter (order,
// default, doc, validator) and reading it into its own member, also through include() and a field reached
// by a function; then every generator's published defaults make the mesh its spec's defaults make, and a
// value given to each of its parameters reaches the member the generator reads.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>

#include "MeshTestSupport.hpp"
#include "mesh/Generators.hpp"
#include "mesh/MeshConversion.hpp"
#include "mesh/MeshFactory.hpp"
#include "mesh/MeshFactoryParameters.hpp"

namespace {

using namespace contessa::mesh;
using Teuchos::ParameterList;
using test_support::expectSameMesh;

struct Inner {
  double length = 0;
  int count = 0;
};

struct Toy {
  double origin = 0, size = 0;
  int count = 0;
  std::string name, side;
  double xyz[3] = {0, 0, 0};
  Inner inner;
};

ParameterTable<Toy> toyTable() {
  const auto inner = ParameterTable<Inner>()
                         .positive("Length", &Inner::length, 2.0, "a length")
                         .count("Count", &Inner::count, 3, "a count");
  return ParameterTable<Toy>("Toy")
      .real("Origin", &Toy::origin, -1.5, "an origin")
      .positive("Size", &Toy::size, 4.0, "a size")
      .count("Elements", &Toy::count, 7, "elements")
      .text("Name", &Toy::name, "block_1", "a name")
      .choice("Side", &Toy::side, "left", {"left", "right"}, "a side")
      .real("Z", [](Toy& t) -> double& { return t.xyz[2]; }, 0.25, "z")
      .include(inner, &Toy::inner);
}

TEST(ParameterTable, PublishesEveryRowInOrderWithItsDefaultDocAndRange) {
  const auto list = toyTable().publish();
  EXPECT_EQ(list->name(), "Toy");
  std::vector<std::string> names;
  for (auto it = list->begin(); it != list->end(); ++it) names.push_back(list->name(it));
  EXPECT_EQ(names, (std::vector<std::string>{"Origin", "Size", "Elements", "Name", "Side", "Z", "Length", "Count"}));
  EXPECT_EQ(list->get<double>("Origin"), -1.5);
  EXPECT_EQ(list->get<int>("Elements"), 7);
  EXPECT_EQ(list->get<std::string>("Side"), "left");
  EXPECT_EQ(list->get<double>("Length"), 2.0);
  EXPECT_EQ(list->getEntry("Origin").docString(), "an origin");
  EXPECT_EQ(list->getEntry("Size").docString(), "a size (> 0)");
  EXPECT_EQ(list->getEntry("Count").docString(), "a count (>= 1)");
  EXPECT_EQ(list->getEntry("Side").docString(), "a side (one of: left, right)");
  EXPECT_TRUE(list->getEntry("Origin").validator().is_null());
  EXPECT_FALSE(list->getEntry("Elements").validator().is_null());
}

TEST(ParameterTable, ReadsEveryParameterIntoItsOwnMember) {
  ParameterList list = *toyTable().publish();
  list.set("Origin", 0.5);
  list.set("Size", 6.0);
  list.set("Elements", 9);
  list.set("Name", std::string("wall"));
  list.set("Side", std::string("right"));
  list.set("Z", -2.0);
  list.set("Length", 8.0);
  list.set("Count", 11);
  const Toy toy = toyTable().read(list);
  EXPECT_EQ(toy.origin, 0.5);
  EXPECT_EQ(toy.size, 6.0);
  EXPECT_EQ(toy.count, 9);
  EXPECT_EQ(toy.name, "wall");
  EXPECT_EQ(toy.side, "right");
  EXPECT_EQ(toy.xyz[0], 0.0);
  EXPECT_EQ(toy.xyz[1], 0.0);
  EXPECT_EQ(toy.xyz[2], -2.0);
  EXPECT_EQ(toy.inner.length, 8.0);
  EXPECT_EQ(toy.inner.count, 11);
}

TEST(ParameterTable, ReadsThePublishedDefaults) {
  const Toy toy = toyTable().read(*toyTable().publish());
  EXPECT_EQ(toy.origin, -1.5);
  EXPECT_EQ(toy.size, 4.0);
  EXPECT_EQ(toy.count, 7);
  EXPECT_EQ(toy.name, "block_1");
  EXPECT_EQ(toy.side, "left");
  EXPECT_EQ(toy.xyz[2], 0.25);
  EXPECT_EQ(toy.inner.length, 2.0);
  EXPECT_EQ(toy.inner.count, 3);
}

// `type`'s published parameters, at their defaults.
ParameterList defaults(const std::string& type) { return *MeshFactory::validParameters(type); }

Mesh create(const std::string& type, const ParameterList& list) {
  return MeshFactory::create(type, list, "Problem/Mesh", "", MPI_COMM_SELF);
}

TEST(MeshFactoryTables, EveryGeneratorsPublishedDefaultsAreItsSpecsDefaults) {
  expectSameMesh(create("Rectangle", defaults("Rectangle")), generateRectangle(RectangleSpec{}));
  expectSameMesh(create("Annulus Sector", defaults("Annulus Sector")), generateAnnulusSector(AnnulusSectorSpec{}));
  expectSameMesh(create("Box", defaults("Box")), generateBox(BoxSpec{}));
  expectSameMesh(create("Hollow Cylinder Sector", defaults("Hollow Cylinder Sector")),
                 generateHollowCylinderSector(HollowCylinderSectorSpec{}));
  expectSameMesh(create("Sphere Octant", defaults("Sphere Octant")), generateSphereOctant(SphereOctantSpec{}));
}

// Each generator's parameters set in `list` to values that differ from each other (two members swapped
// would change the mesh), and the spec that says the same. First the rows a Box shares with a Rectangle
// (its x-y section), changed alike in both.
template <class Spec>
Spec changedSection(ParameterList& list) {
  Spec s;
  list.set("X Origin", s.x0 = 1.0);
  list.set("Y Origin", s.y0 = -2.0);
  list.set("Length X", s.lx = 3.0);
  list.set("Length Y", s.ly = 0.5);
  list.set("Elements X", s.nx = 3);
  list.set("Elements Y", s.ny = 2);
  list.set("Bias X", s.biasX = 2.0);
  list.set("Bias Y", s.biasY = 0.75);
  return s;
}

RectangleSpec changedRectangle(ParameterList& list) {
  RectangleSpec s = changedSection<RectangleSpec>(list);
  list.set("Block Name", s.blockName = "plate");
  return s;
}

// The rows a generator that extrudes its section along z adds (Box, Hollow Cylinder Sector), changed alike.
void changeExtrusion(ParameterList& list, double& z0, double& length, int& layers, double& bias) {
  list.set("Z Origin", z0 = -1.0);
  list.set("Length Z", length = 4.0);
  list.set("Elements Z", layers = 4);
  list.set("Bias Z", bias = 3.0);
}

BoxSpec changedBox(ParameterList& list) {
  BoxSpec s = changedSection<BoxSpec>(list);
  changeExtrusion(list, s.z0, s.lz, s.nz, s.biasZ);
  list.set("Block Name", s.blockName = "brick");
  return s;
}

AnnulusSectorSpec changedAnnulus(ParameterList& list) {
  AnnulusSectorSpec s;
  list.set("Inner Radius", s.innerRadius = 50.0);
  list.set("Thickness", s.thickness = 5.0);
  list.set("Start Angle", s.startAngleDeg = 10.0);
  list.set("End Angle", s.endAngleDeg = 80.0);
  list.set("Elements Through Thickness", s.elementsThroughThickness = 3);
  list.set("Elements Around Arc", s.elementsAroundArc = 7);
  list.set("Radial Bias", s.radialBias = 2.0);
  list.set("Arc Bias", s.arcBias = 0.5);
  list.set("Block Name", s.blockName = "ring");
  return s;
}

HollowCylinderSectorSpec changedTube(ParameterList& list) {
  HollowCylinderSectorSpec s;
  s.section = changedAnnulus(list);
  changeExtrusion(list, s.z0, s.length, s.layers, s.axialBias);
  list.set("Block Name", s.section.blockName = "tube");  // a row that fills the section's member
  return s;
}

SphereOctantSpec changedBall(ParameterList& list) {
  SphereOctantSpec s;
  list.set("Radius", s.radius = 10.0);
  list.set("X Center", s.center[0] = 1.0);
  list.set("Y Center", s.center[1] = 2.0);
  list.set("Z Center", s.center[2] = 3.0);
  list.set("Pole Direction", s.poleDirection = "+x");
  list.set("Elements Along Edge", s.elementsAlongEdge = 3);
  list.set("Elements Through Shell", s.elementsThroughShell = 2);
  list.set("Inner Cube Fraction", s.innerCubeFraction = 0.4);
  list.set("Pole Bias", s.poleBias = 2.0);
  list.set("Radial Bias", s.radialBias = 0.5);
  list.set("Block Name", s.blockName = "ball");
  return s;
}

TEST(MeshFactoryTables, EachParameterReachesTheMemberItsGeneratorReads) {
  ParameterList rectangle = defaults("Rectangle"), box = defaults("Box"), annulus = defaults("Annulus Sector"),
                tube = defaults("Hollow Cylinder Sector"), ball = defaults("Sphere Octant");
  const RectangleSpec rectangleSpec = changedRectangle(rectangle);
  const BoxSpec boxSpec = changedBox(box);
  const AnnulusSectorSpec annulusSpec = changedAnnulus(annulus);
  const HollowCylinderSectorSpec tubeSpec = changedTube(tube);
  const SphereOctantSpec ballSpec = changedBall(ball);
  expectSameMesh(create("Rectangle", rectangle), generateRectangle(rectangleSpec));
  expectSameMesh(create("Box", box), generateBox(boxSpec));
  expectSameMesh(create("Annulus Sector", annulus), generateAnnulusSector(annulusSpec));
  expectSameMesh(create("Hollow Cylinder Sector", tube), generateHollowCylinderSector(tubeSpec));
  expectSameMesh(create("Sphere Octant", ball), generateSphereOctant(ballSpec));
}

TEST(MeshFactoryTables, TheCellVariantRowsChooseTheCells) {
  ParameterList triangles = defaults("Rectangle"), tetrahedra = defaults("Box"), hex20 = defaults("Box");
  const RectangleSpec rectangleSpec = changedRectangle(triangles);
  triangles.set("Cell Type", std::string("Triangles"));
  triangles.set("Element Order", 2);
  expectSameMesh(create("Rectangle", triangles), withMidEdgeNodes(splitIntoSimplices(generateRectangle(rectangleSpec))));
  const BoxSpec boxSpec = changedBox(tetrahedra);
  tetrahedra.set("Cell Type", std::string("Tetrahedra"));
  expectSameMesh(create("Box", tetrahedra), splitIntoSimplices(generateBox(boxSpec)));
  hex20.set("Element Order", 2);
  expectSameMesh(create("Box", hex20), withMidEdgeNodes(generateBox(BoxSpec{})));
}

}  // namespace
