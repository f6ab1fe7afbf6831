// Factories: registries, deck parameter validation and error messages.
#include "MechanicsTestUtilities.hpp"

#include "common/Error.hpp"

namespace contessa::mechanics::test {
namespace {

std::string messageOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError thrown";
  return {};
}

Teuchos::ParameterList deck(const std::string& model, double E, double nu) {
  Teuchos::ParameterList p;
  p.set<std::string>("Model", model);
  p.set<double>("Young's Modulus", E);
  p.set<double>("Poisson's Ratio", nu);
  return p;
}

TEST(MaterialFactory, ListsTheThreeLaws) {
  const auto names = MaterialFactory::names();
  EXPECT_EQ(names, (std::vector<std::string>{"Saint Venant-Kirchhoff", "Neo-Hookean", "Linear Elastic"}));
  for (const auto& n : names) {
    const auto valid = MaterialFactory::validParameters(n);
    EXPECT_EQ(valid->get<std::string>("Model"), n);
    EXPECT_TRUE(valid->isType<double>("Young's Modulus"));
    EXPECT_EQ(valid->get<double>("Poisson's Ratio"), 0.0);
    EXPECT_FALSE(valid->getEntry("Young's Modulus").docString().empty());
    EXPECT_NE(MaterialFactory::create(deck(n, 100.0, 0.2), "M"), nullptr);
  }
}

TEST(MaterialFactory, ValidatedDeckWithDefaultPoissonRatioCreates) {
  Teuchos::ParameterList p;
  p.set<std::string>("Model", "Neo-Hookean");
  p.set<double>("Young's Modulus", 10.0);
  p.validateParametersAndSetDefaults(*MaterialFactory::validParameters("Neo-Hookean"));
  EXPECT_EQ(p.get<double>("Poisson's Ratio"), 0.0);
  EXPECT_NE(MaterialFactory::create(p, "Problem/Materials/rubber"), nullptr);
  // Integral spelling of a number is accepted too.
  Teuchos::ParameterList q;
  q.set<std::string>("Model", "Linear Elastic");
  q.set<int>("Young's Modulus", 200);
  EXPECT_NE(MaterialFactory::create(q, "Problem/Materials/steel"), nullptr);
}

TEST(MaterialFactory, UnknownModelListsKnownNames) {
  const std::string expected =
      "Problem/Materials/steel/Model: unknown material model 'Mooney' (known: Saint Venant-Kirchhoff, "
      "Neo-Hookean, Linear Elastic)";
  EXPECT_EQ(messageOf([] { MaterialFactory::create(deck("Mooney", 1, 0), "Problem/Materials/steel"); }), expected);
  const std::string v = messageOf([] { MaterialFactory::validParameters("Mooney"); });
  EXPECT_NE(v.find("known: Saint Venant-Kirchhoff, Neo-Hookean, Linear Elastic"), std::string::npos) << v;
  Teuchos::ParameterList noModel;
  const std::string m = messageOf([&] { MaterialFactory::create(noModel, "Problem/Materials/steel"); });
  EXPECT_EQ(m.rfind("Problem/Materials/steel/Model:", 0), 0u) << m;
}

TEST(MaterialFactory, RejectsPoissonRatioOutOfRange) {
  for (const auto& model : MaterialFactory::names()) {
    EXPECT_EQ(messageOf([&] { MaterialFactory::create(deck(model, 200, 0.5), "Problem/Materials/steel"); }),
              "Problem/Materials/steel/Poisson's Ratio: expected a value in (-1, 0.5), got 0.5");
    EXPECT_EQ(messageOf([&] { MaterialFactory::create(deck(model, 200, 0.7), "Problem/Materials/steel"); }),
              "Problem/Materials/steel/Poisson's Ratio: expected a value in (-1, 0.5), got 0.7");
    EXPECT_EQ(messageOf([&] { MaterialFactory::create(deck(model, 200, -1), "Problem/Materials/steel"); }),
              "Problem/Materials/steel/Poisson's Ratio: expected a value in (-1, 0.5), got -1");
  }
}

TEST(MaterialFactory, RejectsMissingOrNonPositiveYoungsModulus) {
  for (double E : {0.0, -3.0}) {
    const std::string m = messageOf([&] { MaterialFactory::create(deck("Neo-Hookean", E, 0.3), "Problem/Materials/a"); });
    EXPECT_EQ(m.rfind("Problem/Materials/a/Young's Modulus: expected a value > 0", 0), 0u) << m;
  }
  Teuchos::ParameterList p;
  p.set<std::string>("Model", "Linear Elastic");
  const std::string missing = messageOf([&] { MaterialFactory::create(p, "Problem/Materials/a"); });
  EXPECT_EQ(missing.rfind("Problem/Materials/a/Young's Modulus:", 0), 0u) << missing;
  // A deck validated against the published defaults (E = 0) is still rejected by create().
  p.validateParametersAndSetDefaults(*MaterialFactory::validParameters("Linear Elastic"));
  const std::string defaulted = messageOf([&] { MaterialFactory::create(p, "Problem/Materials/a"); });
  EXPECT_EQ(defaulted, "Problem/Materials/a/Young's Modulus: expected a value > 0, got 0");
}

TEST(ElementFactory, CreatesRegisteredKernels) {
  EXPECT_EQ(ElementFactory::names(), (std::vector<std::string>{"Q4", "Q4 Enhanced", "Q4 Axisymmetric", "Q4 Enhanced Axisymmetric", "Hex8",
                                                              "Hex8 Enhanced", "Tri3", "Tri6", "Q8", "Q9", "Tri3 Axisymmetric",
                                                              "Tri6 Axisymmetric", "Q8 Axisymmetric", "Q9 Axisymmetric", "Tet4",
                                                              "Tet10", "Hex20", "Hex27", "Wedge6", "Wedge15"}));
  const auto q4 = ElementFactory::create("Q4", "E");
  EXPECT_EQ(q4->name(), "Q4");
  EXPECT_EQ(q4->numDofs(), 8);
  EXPECT_EQ(q4->numInternalVariables(), 0);
  const auto eas = ElementFactory::create("Q4 Enhanced", "E");
  EXPECT_EQ(eas->name(), "Q4 Enhanced");
  EXPECT_EQ(eas->dimension(), 2);
  EXPECT_EQ(eas->numNodes(), 4);
  EXPECT_EQ(eas->numInternalVariables(), 4);
  const auto hex = ElementFactory::create("Hex8", "E");
  EXPECT_EQ(hex->name(), "Hex8");
  EXPECT_EQ(hex->dimension(), 3);
  EXPECT_EQ(hex->numNodes(), 8);
  EXPECT_EQ(hex->numDofs(), 24);
  EXPECT_EQ(hex->numInternalVariables(), 0);
  const auto hexEas = ElementFactory::create("Hex8 Enhanced", "E");
  EXPECT_EQ(hexEas->name(), "Hex8 Enhanced");
  EXPECT_EQ(hexEas->dimension(), 3);
  EXPECT_EQ(hexEas->numInternalVariables(), 9);
  // State: α (9), the displacements it belongs to (24), dα/du (9 × 24).
  EXPECT_EQ(hexEas->numStateValues(), 9 + 24 + 9 * 24);
}

TEST(ElementFactory, UnknownNameListsKnownNames) {
  EXPECT_EQ(messageOf([] { ElementFactory::create("Q12", "Problem/Discretization/Element"); }),
            "Problem/Discretization/Element: unknown element 'Q12' (known: Q4, Q4 Enhanced, Q4 Axisymmetric, Q4 "
            "Enhanced Axisymmetric, Hex8, Hex8 Enhanced, Tri3, Tri6, Q8, Q9, Tri3 Axisymmetric, Tri6 Axisymmetric, Q8 "
            "Axisymmetric, Q9 Axisymmetric, Tet4, Tet10, Hex20, Hex27, Wedge6, Wedge15)");
}

}  // namespace
}  // namespace contessa::mechanics::test
