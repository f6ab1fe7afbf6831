// The rows of common/ParameterTable.hpp that the mesh tables' toy test (tests/unit/mesh/MeshFactoryTableTest.cpp)
// does not show: a choice read into an enum, a flag and an array, a row with a declare of its own (a
// range), a sublist read into a member, and rows published into a list that holds other parameters.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "common/ParameterTable.hpp"

namespace {

using contessa::ParameterTable;
using Teuchos::ParameterList;

enum class Shape { Round, Square, Flat };

struct Corner {
  Teuchos::Array<double> point;
  int index = 0;
};

struct Part {
  Shape shape = Shape::Round;
  bool hollow = false;
  double fraction = 0;
  Corner corner;
};

Teuchos::Array<double> array(const std::vector<double>& values) { return Teuchos::Array<double>(values); }

ParameterTable<Corner> cornerTable() {
  return ParameterTable<Corner>()
      .value("Point", &Corner::point, array({1.0, 2.0}), "a point")
      .count("Index", &Corner::index, 2, "an index");
}

// A range [0, 1] declared by the row itself.
void unitInterval(ParameterList& p, const std::string& name, const double& value, const std::string& doc) {
  p.set(name, value, doc + " ([0, 1])", Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>(0.0, 1.0)));
}

ParameterTable<Part> partTable() {
  return ParameterTable<Part>("Part")
      .enumChoice("Shape", &Part::shape, Shape::Square, {"Round", "Square", "Flat"}, "a shape")
      .value("Hollow", &Part::hollow, true, "a flag")
      .declared("Fraction", &Part::fraction, 0.25, "a fraction", unitInterval)
      .sublist("Corner", "the corner", cornerTable(), &Part::corner);
}

TEST(ParameterTable, PublishesAnEnumChoiceByNameAFlagARangeAndASublist) {
  const auto list = partTable().publish();
  EXPECT_EQ(list->get<std::string>("Shape"), "Square");
  EXPECT_EQ(list->getEntry("Shape").docString(), "a shape (one of: Round, Square, Flat)");
  EXPECT_FALSE(list->getEntry("Shape").validator().is_null());
  EXPECT_TRUE(list->get<bool>("Hollow"));
  EXPECT_EQ(list->get<double>("Fraction"), 0.25);
  EXPECT_EQ(list->getEntry("Fraction").docString(), "a fraction ([0, 1])");
  EXPECT_FALSE(list->getEntry("Fraction").validator().is_null());
  ASSERT_TRUE(list->isSublist("Corner"));
  EXPECT_EQ(list->getEntry("Corner").docString(), "the corner");
  EXPECT_EQ(list->sublist("Corner").get<Teuchos::Array<double>>("Point"), (array({1.0, 2.0})));
  EXPECT_EQ(list->sublist("Corner").getEntry("Index").docString(), "an index (>= 1)");
}

TEST(ParameterTable, ReadsTheChoiceAsItsEnumValueAndTheSublistIntoItsMember) {
  const Part defaults = partTable().read(*partTable().publish());
  EXPECT_EQ(defaults.shape, Shape::Square);
  EXPECT_TRUE(defaults.hollow);
  EXPECT_EQ(defaults.corner.index, 2);
  ParameterList list = *partTable().publish();
  list.set("Shape", std::string("Flat"));
  list.set("Hollow", false);
  list.set("Fraction", 0.75);
  list.sublist("Corner").set("Point", array({-1.0, 0.5, 3.0}));
  list.sublist("Corner").set("Index", 7);
  const Part part = partTable().read(list);
  EXPECT_EQ(part.shape, Shape::Flat);
  EXPECT_FALSE(part.hollow);
  EXPECT_EQ(part.fraction, 0.75);
  EXPECT_EQ(part.corner.point, array({-1.0, 0.5, 3.0}));
  EXPECT_EQ(part.corner.index, 7);
}

TEST(ParameterTable, PublishesIntoAListOthersPublishIntoAndReadsOnlyItsRows) {
  ParameterList shared("Shared");
  shared.set("Before", 1);
  partTable().publishInto(shared);
  shared.set("After", 2);
  std::vector<std::string> names;
  for (auto it = shared.begin(); it != shared.end(); ++it) names.push_back(shared.name(it));
  EXPECT_EQ(names, (std::vector<std::string>{"Before", "Shape", "Hollow", "Fraction", "Corner", "After"}));
  Part part;
  part.fraction = -1.0;
  shared.set("Shape", std::string("Round"));
  partTable().readInto(shared, part);
  EXPECT_EQ(part.shape, Shape::Round);
  EXPECT_EQ(part.fraction, 0.25);
}

}  // namespace
