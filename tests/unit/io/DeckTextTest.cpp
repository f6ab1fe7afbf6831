// The deck recorded in the results file reads back as the same deck.
#include <gtest/gtest.h>

#include <algorithm>

#include <Teuchos_Array.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>

#include "output/DeckText.hpp"

TEST(DeckText, ReadsBackAsTheSameValues) {
  Teuchos::ParameterList deck("ANONYMOUS");
  auto& problem = deck.sublist("Problem");
  problem.set("Title", std::string("a <title> with \"quotes\" & ampersands"));
  problem.sublist("Mesh").set("Inner Radius", 100.0);
  problem.sublist("Mesh").set("Elements Around Arc", 101);
  deck.sublist("Piro").sublist("LOCA").set("Initial Step Size", 1.0 / 47.0);
  problem.set("Motion", Teuchos::Array<double>(Teuchos::tuple(0.0, -75.2, 1e-300)));
  problem.set("Sets", Teuchos::Array<std::string>(Teuchos::tuple<std::string>("end", "start")));
  problem.set("Flag", true);

  const auto lines = contessa::output::deckText(deck);
  EXPECT_EQ(lines.front(), "<ParameterList name=\"Contessa\">");
  EXPECT_NE(std::find(lines.begin(), lines.end(), "      <Parameter name=\"Inner Radius\" type=\"double\" value=\"100\"/>"),
            lines.end());
  std::string text;
  for (const auto& l : lines) text += l + "\n";
  const auto back = Teuchos::getParametersFromXmlString(text);
  const auto& p = back->sublist("Problem");
  EXPECT_EQ(p.get<std::string>("Title"), "a <title> with \"quotes\" & ampersands");
  EXPECT_EQ(p.sublist("Mesh").get<double>("Inner Radius"), 100.0);
  EXPECT_EQ(p.sublist("Mesh").get<int>("Elements Around Arc"), 101);
  EXPECT_EQ(back->sublist("Piro").sublist("LOCA").get<double>("Initial Step Size"), 1.0 / 47.0);  // bit for bit
  EXPECT_EQ(p.get<Teuchos::Array<double>>("Motion"), (Teuchos::Array<double>(Teuchos::tuple(0.0, -75.2, 1e-300))));
  EXPECT_EQ(p.get<Teuchos::Array<std::string>>("Sets"), (Teuchos::Array<std::string>(Teuchos::tuple<std::string>("end", "start"))));
  EXPECT_TRUE(p.get<bool>("Flag"));
}
