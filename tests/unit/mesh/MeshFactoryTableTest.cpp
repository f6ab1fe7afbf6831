// The generators' parameter tables (common/ParameterTable.hpp, used by mesh/MeshFactory.cpp): what a
// table publishes is what it reads. A toy spec shows every kind of row publishing its parameter (order,
// default, doc, validator) and reading it into its own member, also through include() and a field reached
// by a function; then every generator's published defaults make the mesh its spec's defaults make, and a
// value given to each of its parameters reaches the member the generator reads.
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>

#include "MeshTestSupport.hpp"
#include "mesh/Generators.hpp"
#include "mesh/MeshConversion.hpp"
#include "mesh/MeshFactory.hpp"
#include "common/ParameterTable.hpp"

namespace {

using namespace contessa::mesh;
using contessa::ParameterTable;
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

// Each generator's parameters given values that differ from each other (two members swapped would change
// the mesh), each row with the spec member the generator reads it from: written here, apart from the
// tables, so that a table row that fills another member than its name says is caught.
template <class Spec>
struct Given {
  std::string name;
  std::function<void(ParameterList&, Spec&)> apply;  ///< sets the parameter in the list and the member alike
};

// `name` = `value`, read into `member` (a data member, or a function returning a reference to one).
template <class Spec, class T, class Member>
Given<Spec> given(const std::string& name, Member member, T value) {
  return {name, [=](ParameterList& list, Spec& s) { list.set(name, std::invoke(member, s) = value); }};
}

// The rows of a part's spec, given through the `part` member of an `Outer` spec.
template <class Outer, class Spec>
std::vector<Given<Outer>> within(Spec Outer::*part, const std::vector<Given<Spec>>& rows) {
  std::vector<Given<Outer>> out;
  for (const auto& r : rows) out.push_back({r.name, [=](ParameterList& list, Outer& o) { r.apply(list, o.*part); }});
  return out;
}

template <class T>
std::vector<T> operator+(std::vector<T> a, const std::vector<T>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// The x-y section a Box shares with a Rectangle, changed alike in both.
template <class S>
std::vector<Given<S>> sectionRows() {
  return {given<S>("X Origin", &S::x0, 1.0),  given<S>("Y Origin", &S::y0, -2.0), given<S>("Length X", &S::lx, 3.0),
          given<S>("Length Y", &S::ly, 0.5),  given<S>("Elements X", &S::nx, 3),  given<S>("Elements Y", &S::ny, 2),
          given<S>("Bias X", &S::biasX, 2.0), given<S>("Bias Y", &S::biasY, 0.75)};
}

// The rows a generator that extrudes its section along z adds (Box, Hollow Cylinder Sector), changed alike.
template <class S>
std::vector<Given<S>> extrusionRows(double S::*z0, double S::*length, int S::*layers, double S::*bias) {
  return {given<S>("Z Origin", z0, -1.0), given<S>("Length Z", length, 4.0), given<S>("Elements Z", layers, 4),
          given<S>("Bias Z", bias, 3.0)};
}

std::vector<Given<RectangleSpec>> rectangleRows() {
  return sectionRows<RectangleSpec>() + std::vector{given<RectangleSpec>("Block Name", &RectangleSpec::blockName, "plate")};
}

std::vector<Given<BoxSpec>> boxRows() {
  using S = BoxSpec;
  return sectionRows<S>() + extrusionRows<S>(&S::z0, &S::lz, &S::nz, &S::biasZ) +
         std::vector{given<S>("Block Name", &S::blockName, "brick")};
}

std::vector<Given<AnnulusSectorSpec>> annulusRows() {
  using S = AnnulusSectorSpec;
  return {given<S>("Inner Radius", &S::innerRadius, 50.0),
          given<S>("Thickness", &S::thickness, 5.0),
          given<S>("Start Angle", &S::startAngleDeg, 10.0),
          given<S>("End Angle", &S::endAngleDeg, 80.0),
          given<S>("Elements Through Thickness", &S::elementsThroughThickness, 3),
          given<S>("Elements Around Arc", &S::elementsAroundArc, 7),
          given<S>("Radial Bias", &S::radialBias, 2.0),
          given<S>("Arc Bias", &S::arcBias, 0.5),
          given<S>("Block Name", &S::blockName, "ring")};
}

std::vector<Given<HollowCylinderSectorSpec>> tubeRows() {
  using S = HollowCylinderSectorSpec;
  const auto sectionBlockName = [](S& s) -> std::string& { return s.section.blockName; };
  return within(&S::section, annulusRows()) + extrusionRows<S>(&S::z0, &S::length, &S::layers, &S::axialBias) +
         std::vector{given<S>("Block Name", sectionBlockName, "tube")};  // a row that fills the section's member
}

std::vector<Given<SphereOctantSpec>> ballRows() {
  using S = SphereOctantSpec;
  const auto center = [](int k) { return [k](S& s) -> double& { return s.center[k]; }; };
  return {given<S>("Radius", &S::radius, 10.0),
          given<S>("X Center", center(0), 1.0),
          given<S>("Y Center", center(1), 2.0),
          given<S>("Z Center", center(2), 3.0),
          given<S>("Pole Direction", &S::poleDirection, "+x"),
          given<S>("Elements Along Edge", &S::elementsAlongEdge, 3),
          given<S>("Elements Through Shell", &S::elementsThroughShell, 2),
          given<S>("Inner Cube Fraction", &S::innerCubeFraction, 0.4),
          given<S>("Pole Bias", &S::poleBias, 2.0),
          given<S>("Radial Bias", &S::radialBias, 0.5),
          given<S>("Block Name", &S::blockName, "ball")};
}

// `rows` given in `list` (a type's defaults before): the spec that says the same.
template <class Spec>
Spec applied(ParameterList& list, const std::vector<Given<Spec>>& rows) {
  Spec s;
  for (const auto& r : rows) r.apply(list, s);
  return s;
}

// The mesh `type` makes from its defaults with `rows` given is the one `generate` makes from their spec.
template <class Spec>
void expectRowsReachTheirMembers(const std::string& type, const std::vector<Given<Spec>>& rows,
                                 Mesh (*generate)(const Spec&)) {
  ParameterList list = defaults(type);
  const Spec spec = applied(list, rows);
  expectSameMesh(create(type, list), generate(spec));
}

TEST(MeshFactoryTables, EachParameterReachesTheMemberItsGeneratorReads) {
  expectRowsReachTheirMembers("Rectangle", rectangleRows(), &generateRectangle);
  expectRowsReachTheirMembers("Box", boxRows(), &generateBox);
  expectRowsReachTheirMembers("Annulus Sector", annulusRows(), &generateAnnulusSector);
  expectRowsReachTheirMembers("Hollow Cylinder Sector", tubeRows(), &generateHollowCylinderSector);
  expectRowsReachTheirMembers("Sphere Octant", ballRows(), &generateSphereOctant);
}

TEST(MeshFactoryTables, TheCellVariantRowsChooseTheCells) {
  ParameterList triangles = defaults("Rectangle"), tetrahedra = defaults("Box"), hex20 = defaults("Box");
  const RectangleSpec rectangleSpec = applied(triangles, rectangleRows());
  triangles.set("Cell Type", std::string("Triangles"));
  triangles.set("Element Order", 2);
  expectSameMesh(create("Rectangle", triangles), withMidEdgeNodes(splitIntoSimplices(generateRectangle(rectangleSpec))));
  const BoxSpec boxSpec = applied(tetrahedra, boxRows());
  tetrahedra.set("Cell Type", std::string("Tetrahedra"));
  expectSameMesh(create("Box", tetrahedra), splitIntoSimplices(generateBox(boxSpec)));
  hex20.set("Element Order", 2);
  expectSameMesh(create("Box", hex20), withMidEdgeNodes(generateBox(BoxSpec{})));
}

}  // namespace
