// Point-history requests (Problem/Output/History): the node nearest given coordinates, the columns, and
// a Reaction Force request's set handed to the model's reaction sets.
#include <gtest/gtest.h>

#include <Teuchos_XMLParameterListHelpers.hpp>

#include "deck/OutputRequests.hpp"
#include "deck/ProblemDefinition.hpp"

#include "TestDeck.hpp"

namespace {

using contessa::deck::HistoryQuantity;
using contessa::deck::HistoryRequest;

// The unit tests' deck (TestDeck.hpp: nodes at x = 0, 1, 2 and y = 0, 1, left held in x) with the
// requests `history` in Problem/Output/History.
contessa::deck::ProblemDefinition problemWith(const std::string& history) {
  auto p = contessa::test::goodProblem();
  p->sublist("Output").set("History",
                           *Teuchos::getParametersFromXmlString("<ParameterList name=\"History\">" + history + "</ParameterList>"));
  return contessa::deck::buildProblem(*p, "", MPI_COMM_SELF);
}

TEST(OutputRequests, NodeNearestCoordinates) {
  const auto def = problemWith(R"XML(
      <ParameterList name="tip"><Parameter name="Coordinates" type="Array(double)" value="{2.3, 0.8}"/></ParameterList>
      <ParameterList name="tie"><Parameter name="Coordinates" type="Array(double)" value="{0.5, 0.0}"/></ParameterList>)XML");
  ASSERT_EQ(def.history.size(), 2u);
  EXPECT_EQ(def.history[0].nodeCoordinates, (std::vector<double>{2.0, 1.0}));
  EXPECT_TRUE(def.history[0].nodeSet.empty());
  // Equally near (0, 0) and (1, 0): the lower global id, (0, 0).
  EXPECT_EQ(def.history[1].nodeCoordinates, (std::vector<double>{0.0, 0.0}));
  EXPECT_LT(def.history[1].node, def.history[0].node);
}

TEST(OutputRequests, ColumnsPerComponentOrOne) {
  HistoryRequest vector;
  vector.name = "top, mean";
  EXPECT_EQ(vector.columns(3), (std::vector<std::string>{"top__mean_x", "top__mean_y", "top__mean_z"}));
  HistoryRequest scalar;
  scalar.name = "corner pressure";
  scalar.quantity = HistoryQuantity::ContactPressure;
  EXPECT_EQ(scalar.columns(2), std::vector<std::string>{"corner_pressure"});
}

TEST(OutputRequests, ReactionSetHandedToTheModelOnce) {
  const auto def = problemWith(R"XML(
      <ParameterList name="a">
        <Parameter name="Quantity" type="string" value="Reaction Force"/>
        <Parameter name="Node Set" type="string" value="right"/>
      </ParameterList>
      <ParameterList name="b">
        <Parameter name="Quantity" type="string" value="Reaction Force"/>
        <Parameter name="Node Set" type="string" value="left"/>
      </ParameterList>
      <ParameterList name="c">
        <Parameter name="Quantity" type="string" value="Reaction Force"/>
        <Parameter name="Node Set" type="string" value="right"/>
      </ParameterList>)XML");
  EXPECT_EQ(def.reactionNodeSets, (std::vector<std::string>{"left", "right"}));
  EXPECT_TRUE(def.history[0].addedReactionSet);   // right: not a Reaction Node Set of the deck
  EXPECT_FALSE(def.history[1].addedReactionSet);  // left: one of the deck's
  EXPECT_EQ(def.history[0].quantity, HistoryQuantity::ReactionForce);
}

}  // namespace
