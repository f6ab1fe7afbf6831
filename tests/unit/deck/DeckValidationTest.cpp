// Deck validation: every kind of bad input gives a one-line InputError naming the deck parameter.
#include <gtest/gtest.h>

#include <functional>

#include <Teuchos_XMLParameterListHelpers.hpp>

#include "common/Error.hpp"
#include "deck/ContactLawFactory.hpp"
#include "deck/DeckReader.hpp"
#include "deck/ParameterValidation.hpp"
#include "deck/ProblemDefinition.hpp"
#include "solvers/SolverParameters.hpp"
#include "solvers/StepSizeMethods.hpp"

#include "TestDeck.hpp"

namespace {

using contessa::InputError;
using contessa::test::goodProblem;
using Teuchos::ParameterList;

// Expects buildProblem to throw an InputError whose one-line message contains `expected`.
void expectProblemError(ParameterList& problem, const std::string& expected) {
  try {
    contessa::deck::buildProblem(problem, "", MPI_COMM_SELF);
    FAIL() << "no error; expected: " << expected;
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(expected), std::string::npos) << "message: " << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "message is not one line: " << msg;
  }
}

TEST(DeckValidation, GoodDeckBuildsAndFillsDefaults) {
  auto p = goodProblem();
  const auto def = contessa::deck::buildProblem(*p, "", MPI_COMM_SELF);
  EXPECT_EQ(def.mesh.numGlobalElements, 2);
  ASSERT_EQ(def.blocks.size(), 1u);
  EXPECT_EQ(def.blocks[0].elementName, "Q4 Enhanced");
  EXPECT_EQ(def.dirichlet.size(), 1u);
  EXPECT_DOUBLE_EQ(def.dirichlet[0].value, 0.0);  // the published default
  EXPECT_DOUBLE_EQ(p->sublist("Mesh").get<double>("Length Y"), 1.0);
  EXPECT_EQ(def.reactionNodeSets, std::vector<std::string>{"left"});
}

TEST(DeckValidation, UnknownNameListsTheValidOnes) {
  auto p = goodProblem();
  p->sublist("Mesh").set("Lenght X", 3.0);
  expectProblemError(*p, "Problem/Mesh/Lenght X: unknown parameter (expected one of: Type, X Origin");
}

TEST(DeckValidation, WrongTypeIsNamed) {
  auto p = goodProblem();
  p->sublist("Mesh").set("Elements X", std::string("two"));
  expectProblemError(*p, "Problem/Mesh/Elements X: expected type int, got string 'two'");
}

TEST(DeckValidation, ValueOutOfRangeIsNamed) {
  auto p = goodProblem();
  p->sublist("Mesh").set("Length X", -1.0);
  expectProblemError(*p, "Problem/Mesh/Length X: expected a value > 0, got -1");
}

TEST(DeckValidation, ChoiceOutsideTheListIsNamed) {
  auto p = goodProblem();
  p->sublist("Blocks").sublist("block_1").set("Element", std::string("Q12"));
  expectProblemError(*p, "Problem/Blocks/block_1/Element: expected one of Q4");
}

TEST(DeckValidation, MissingMeshFileIsNamed) {
  auto p = goodProblem();
  auto& mesh = p->sublist("Mesh");
  mesh.set("Type", std::string("Exodus File"));
  mesh.remove("Length X");
  mesh.remove("Elements X");
  mesh.set("File Name", std::string("no_such_mesh.exo"));
  expectProblemError(*p, "Problem/Mesh/File Name: mesh file 'no_such_mesh.exo' does not exist");
}

TEST(DeckValidation, UnknownNodeSetListsTheKnownOnes) {
  auto p = goodProblem();
  p->sublist("Dirichlet Conditions").sublist("fix").set("Node Set", std::string("lefft"));
  expectProblemError(*p, "Problem/Dirichlet Conditions/fix/Node Set: node set 'lefft' does not exist in the mesh (known:");
}

TEST(DeckValidation, UnknownReactionNodeSet) {
  auto p = goodProblem();
  p->sublist("Output").set("Reaction Node Sets", Teuchos::Array<std::string>(1, "topp"));
  expectProblemError(*p, "Problem/Output/Reaction Node Sets: node set 'topp' does not exist");
}

TEST(DeckValidation, BlockThatIsNotInTheMesh) {
  auto p = goodProblem();
  p->sublist("Blocks").sublist("block_2") = p->sublist("Blocks").sublist("block_1");
  expectProblemError(*p, "Problem/Blocks/block_2: element block 'block_2' does not exist in the mesh");
}

TEST(DeckValidation, MeshBlockWithoutPhysics) {
  auto p = goodProblem();
  p->sublist("Mesh").set("Block Name", std::string("plate"));
  expectProblemError(*p, "Problem/Blocks/block_1: element block 'block_1' does not exist");
}

TEST(DeckValidation, UnknownMaterialModelListsTheKnownOnes) {
  auto p = goodProblem();
  p->sublist("Materials").sublist("steel").set("Model", std::string("Mooney"));
  expectProblemError(*p, "Problem/Materials/steel/Model: expected one of Saint Venant-Kirchhoff, Neo-Hookean, Linear Elastic; got 'Mooney'");
}

TEST(DeckValidation, MaterialReferenceMustExist) {
  auto p = goodProblem();
  p->sublist("Blocks").sublist("block_1").set("Material", std::string("stel"));
  expectProblemError(*p, "Problem/Blocks/block_1/Material: 'stel' is not a sublist of Problem/Materials (known: steel)");
}

TEST(DeckValidation, PoissonRatioOutOfRange) {
  auto p = goodProblem();
  p->sublist("Materials").sublist("steel").set("Poisson's Ratio", 0.5);
  expectProblemError(*p, "Problem/Materials/steel/Poisson's Ratio");
}

TEST(DeckValidation, ComponentZInTwoDimensions) {
  auto p = goodProblem();
  p->sublist("Dirichlet Conditions").sublist("fix").set("Component", std::string("z"));
  expectProblemError(*p, "Problem/Dirichlet Conditions/fix/Component: component 'z' is not valid in 2D");
}

TEST(DeckValidation, IntegerGivenForARealIsAccepted) {
  auto p = goodProblem();
  p->sublist("Mesh").set("Length X", 3);
  const auto def = contessa::deck::buildProblem(*p, "", MPI_COMM_SELF);
  EXPECT_DOUBLE_EQ(p->sublist("Mesh").get<double>("Length X"), 3.0);
}

TEST(DeckOverrides, ExistingParameterKeepsItsType) {
  auto p = goodProblem();
  ParameterList deck("deck");
  deck.sublist("Problem") = *p;
  const auto paths = contessa::deck::applyOverrides(deck, {"Problem/Mesh/Elements X=5"});
  EXPECT_EQ(paths.count("Problem/Mesh/Elements X"), 1u);
  EXPECT_EQ(deck.sublist("Problem").sublist("Mesh").get<int>("Elements X"), 5);
  EXPECT_THROW(contessa::deck::applyOverrides(deck, {"Problem/Mesh/Elements X=five"}), InputError);
}

TEST(DeckOverrides, NewParameterIsTypedByValidation) {
  auto p = goodProblem();
  contessa::deck::applyOverrides(*p, {"Mesh/Elements Y=3", "Mesh/Length Y=0.5"});
  const auto def = contessa::deck::buildProblem(*p, "", MPI_COMM_SELF);
  EXPECT_EQ(def.mesh.numGlobalElements, 6);
  EXPECT_DOUBLE_EQ(p->sublist("Mesh").get<double>("Length Y"), 0.5);
}

TEST(DeckOverrides, MalformedOverrides) {
  ParameterList deck("deck");
  EXPECT_THROW(contessa::deck::applyOverrides(deck, {"Problem/Mesh"}), InputError);  // no '='
  EXPECT_THROW(contessa::deck::applyOverrides(deck, {"=3"}), InputError);
  deck.sublist("A").set("b", 1.0);
  EXPECT_THROW(contessa::deck::applyOverrides(deck, {"A/b/c=1"}), InputError);  // through a parameter
  EXPECT_THROW(contessa::deck::applyOverrides(deck, {"A=1"}), InputError);      // a sublist
}

TEST(DeckOverrides, TextThatDoesNotParseIsATypeError) {
  auto p = goodProblem();
  contessa::deck::applyOverrides(*p, {"Mesh/Elements Y=many"});
  expectProblemError(*p, "Problem/Mesh/Elements Y: expected type int, got string 'many'");
}

// ---- Contact interfaces: every parameter has a bad-input case. ------------------------------------

Teuchos::RCP<ParameterList> contactProblem() {
  auto p = goodProblem();
  auto& c = p->sublist("Contact").sublist("plate");
  c.set("Slave Side Set", std::string("top"));
  c.sublist("Rigid Surface").set("Points", Teuchos::Array<double>(Teuchos::tuple<double>(-1.0, 1.5, 3.0, 1.5)));
  c.sublist("Rigid Surface").set("Motion", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, -1.0)));
  c.set("Normal Penalty", 1e6);
  return p;
}

TEST(ContactValidation, GoodRigidAndDeformableInterfaces) {
  auto p = contactProblem();
  auto def = contessa::deck::buildProblem(*p, "", MPI_COMM_SELF);
  ASSERT_EQ(def.contacts.size(), 1u);
  EXPECT_TRUE(def.contacts[0].rigidMaster);
  EXPECT_EQ(def.contacts[0].slaveNodes.size(), 3u);  // the top of a 2 × 1 mesh
  EXPECT_NEAR(def.contacts[0].slaveAreas[0] + def.contacts[0].slaveAreas[1] + def.contacts[0].slaveAreas[2], 2.0, 1e-14);
  // Facet lengths of the slip tolerance: the mean of the adjacent sides, 1 at the ends as in the middle.
  ASSERT_EQ(def.contacts[0].slaveFacetLengths.size(), 3u);
  for (double length : def.contacts[0].slaveFacetLengths) EXPECT_NEAR(length, 1.0, 1e-14);
  // Friction needs no Tangential Penalty with the default Slip Tolerance (ε_T = μ|t_N|/(0.005 L)).
  p->sublist("Contact").sublist("plate").set("Friction Coefficient", 0.2);
  def = contessa::deck::buildProblem(*p, "", MPI_COMM_SELF);
  EXPECT_EQ(def.contacts[0].law.slipTolerance, 0.005);
  EXPECT_EQ(def.contacts[0].law.tangentialPenalty, 0.0);  // no upper bound
  EXPECT_EQ(def.contacts[0].law.frictionCoefficient, 0.2);
  auto q = goodProblem();
  auto& c = q->sublist("Contact").sublist("self");
  c.set("Slave Side Set", std::string("top"));
  c.set("Master Side Set", std::string("bottom"));
  c.set("Normal Penalty", 1e6);
  c.set("Two Pass", true);
  def = contessa::deck::buildProblem(*q, "", MPI_COMM_SELF);
  EXPECT_EQ(def.contacts.size(), 2u);  // two-pass: the second pass with the roles swapped
  EXPECT_FALSE(def.contacts[0].secondPass);
  EXPECT_TRUE(def.contacts[1].secondPass);  // a role of the spec: the name stays the deck's
  EXPECT_EQ(def.contacts[1].name, "self");
  EXPECT_EQ(def.contacts[1].label(), "self (second pass)");
  EXPECT_EQ(def.contacts[1].slaveNodes.size(), def.contacts[0].numMasterFacets() + 1);  // 2D: a line of segments
}

// Contact laws come from a registry: Law defaults to the one law, so decks without it read as before, and the
// law's parameters are those its row publishes.
TEST(ContactValidation, LawRegistry) {
  using contessa::deck::ContactLawFactory;
  ASSERT_EQ(ContactLawFactory::names(), std::vector<std::string>{"Penalty Coulomb"});
  EXPECT_EQ(ContactLawFactory::defaultLaw(), "Penalty Coulomb");
  const auto params = ContactLawFactory::validParameters("Penalty Coulomb");
  for (const char* name : {"Normal Penalty", "Tangential Penalty", "Friction Coefficient", "Slip Tolerance"})
    EXPECT_TRUE(params->isParameter(name)) << name;
  try {
    ContactLawFactory::validParameters("Mortar");
    FAIL() << "no error for an unknown law";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown contact law 'Mortar' (known: Penalty Coulomb)"), std::string::npos)
        << e.what();
  }
  auto implicit = contactProblem();
  auto explicitLaw = contactProblem();
  explicitLaw->sublist("Contact").sublist("plate").set("Law", std::string("Penalty Coulomb"));
  for (auto* p : {implicit.get(), explicitLaw.get()}) p->sublist("Contact").sublist("plate").set("Friction Coefficient", 0.3);
  const auto a = contessa::deck::buildProblem(*implicit, "", MPI_COMM_SELF).contacts.at(0).law;
  const auto b = contessa::deck::buildProblem(*explicitLaw, "", MPI_COMM_SELF).contacts.at(0).law;
  EXPECT_EQ(a.normalPenalty, 1e6);
  EXPECT_EQ(a.frictionCoefficient, 0.3);
  EXPECT_EQ(a.normalPenalty, b.normalPenalty);
  EXPECT_EQ(a.tangentialPenalty, b.tangentialPenalty);
  EXPECT_EQ(a.frictionCoefficient, b.frictionCoefficient);
  EXPECT_EQ(a.slipTolerance, b.slipTolerance);
  EXPECT_EQ(implicit->sublist("Contact").sublist("plate").get<std::string>("Law"), "Penalty Coulomb");  // the default, filled in
}

// Issue 21, point 2: without a Normal Penalty, ε_N = Penalty Factor × max E'/h of the elements under the slave
// side (deck/AutomaticPenalty.hpp). The test deck's slave side is the top of one row of unit squares: h = 1,
// Neo-Hookean E = 200, ν = 0.3, so E' = 200/(1 − 0.09) and ε_N = 100 E'.
TEST(ContactValidation, AutomaticPenaltyFromTheElementsUnderTheSlaveSide) {
  const double planeStrain = 200.0 / (1.0 - 0.3 * 0.3);  // E'/h with h = 1
  const auto law = [](const std::function<void(ParameterList&)>& change) {
    auto p = contactProblem();
    p->sublist("Contact").sublist("plate").remove("Normal Penalty");
    change(*p);
    return contessa::deck::buildProblem(*p, "", MPI_COMM_SELF).contacts.at(0).law;
  };
  EXPECT_NEAR(law([](ParameterList&) {}).normalPenalty, 100.0 * planeStrain, 1e-10 * planeStrain);
  // E'/h: twice the modulus, or half the thickness, twice the penalty; the factor scales it.
  EXPECT_NEAR(law([](ParameterList& p) { p.sublist("Materials").sublist("steel").set("Young's Modulus", 400.0); }).normalPenalty,
              200.0 * planeStrain, 1e-10 * planeStrain);
  EXPECT_NEAR(law([](ParameterList& p) { p.sublist("Mesh").set("Length Y", 0.5); }).normalPenalty, 200.0 * planeStrain,
              1e-10 * planeStrain);
  EXPECT_NEAR(law([](ParameterList& p) { p.sublist("Contact").sublist("plate").set("Penalty Factor", 3.0); }).normalPenalty,
              3.0 * planeStrain, 1e-10 * planeStrain);
  // Units: lengths in m instead of mm and E in Pa instead of MPa (1e-3 and 1e6): ε_N in Pa/m is 1e9 times.
  const double si = law([](ParameterList& p) {
                      p.sublist("Mesh").set("Length X", 2e-3);
                      p.sublist("Mesh").set("Length Y", 1e-3);
                      p.sublist("Materials").sublist("steel").set("Young's Modulus", 200e6);
                      p.sublist("Contact").sublist("plate").sublist("Rigid Surface").set(
                          "Points", Teuchos::Array<double>(Teuchos::tuple<double>(-1e-3, 1.5e-3, 3e-3, 1.5e-3)));
                    }).normalPenalty;
  EXPECT_NEAR(si, 1e9 * 100.0 * planeStrain, 1e-9 * si);
  // A constant stick penalty left out is the normal one, given or automatic; a slip tolerance leaves ε_T alone.
  const auto stick = law([](ParameterList& p) {
    p.sublist("Contact").sublist("plate").set("Friction Coefficient", 0.3);
    p.sublist("Contact").sublist("plate").set("Slip Tolerance", 0.0);
  });
  EXPECT_EQ(stick.tangentialPenalty, stick.normalPenalty);
  EXPECT_EQ(law([](ParameterList& p) { p.sublist("Contact").sublist("plate").set("Friction Coefficient", 0.3); })
                .tangentialPenalty,
            0.0);
  auto given = contactProblem();
  given->sublist("Contact").sublist("plate").set("Friction Coefficient", 0.3);
  given->sublist("Contact").sublist("plate").set("Slip Tolerance", 0.0);
  EXPECT_EQ(contessa::deck::buildProblem(*given, "", MPI_COMM_SELF).contacts.at(0).law.tangentialPenalty, 1e6);
  // A given Normal Penalty is kept.
  EXPECT_EQ(contessa::deck::buildProblem(*contactProblem(), "", MPI_COMM_SELF).contacts.at(0).law.normalPenalty, 1e6);
}

TEST(ContactValidation, BadParametersAreNamed) {
  const std::vector<std::pair<std::function<void(ParameterList&)>, std::string>> cases = {
      {[](ParameterList& c) { c.set("Slave Side Set", std::string("")); }, "Problem/Contact/plate/Slave Side Set: required"},
      {[](ParameterList& c) { c.set("Slave Side Set", std::string("topp")); },
       "Problem/Contact/plate/Slave Side Set: side set 'topp' does not exist in the mesh (known:"},
      {[](ParameterList& c) { c.set("Master Side Set", std::string("bottom")); },
       "Problem/Contact/plate: give either Master Side Set (a deformable master) or Rigid Surface/Points (a rigid one), not both"},
      {[](ParameterList& c) { c.sublist("Rigid Surface").set("Points", Teuchos::Array<double>()); },
       "not neither"},
      {[](ParameterList& c) { c.sublist("Rigid Surface").set("Points", Teuchos::Array<double>(3, 1.0)); },
       "Problem/Contact/plate/Rigid Surface/Points: expected x0, y0, x1, y1"},
      {[](ParameterList& c) { c.sublist("Rigid Surface").set("Points", Teuchos::Array<double>(4, 1.0)); },
       "Problem/Contact/plate/Rigid Surface/Points: two consecutive points coincide"},
      {[](ParameterList& c) { c.sublist("Rigid Surface").set("Motion", Teuchos::Array<double>(3, 0.0)); },
       "Problem/Contact/plate/Rigid Surface/Motion: expected two values"},
      {[](ParameterList& c) { c.set("Penalty Factor", 0.0); }, "Problem/Contact/plate/Penalty Factor: expected a value"},
      {[](ParameterList& c) { c.set("Normal Penalty", -1.0); }, "Problem/Contact/plate/Normal Penalty: expected a value in [0"},
      {[](ParameterList& c) { c.set("Slip Tolerance", -0.1); }, "Problem/Contact/plate/Slip Tolerance: expected a value in [0, 1]"},
      {[](ParameterList& c) { c.set("Slip Tolerance", 2.0); }, "Problem/Contact/plate/Slip Tolerance: expected a value in [0, 1]"},
      {[](ParameterList& c) { c.set("Friction Coefficient", -0.1); }, "Problem/Contact/plate/Friction Coefficient: expected a value in [0"},
      {[](ParameterList& c) { c.set("Tangential Penalty", -1.0); }, "Problem/Contact/plate/Tangential Penalty: expected a value in [0"},
      {[](ParameterList& c) { c.set("Two Pass", true); }, "Problem/Contact/plate/Two Pass: a rigid master has no slave side of its own"},
      {[](ParameterList& c) { c.set("Penalty", 1.0); }, "Problem/Contact/plate/Penalty: unknown parameter"},
      {[](ParameterList& c) { c.set("Law", std::string("Augmented Lagrange")); },
       "Problem/Contact/plate/Law: expected one of Penalty Coulomb; got 'Augmented Lagrange'"},
      {[](ParameterList& c) { c.set("Law", 1); }, "Problem/Contact/plate/Law: expected a string, one of Penalty Coulomb"},
  };
  for (const auto& [breakIt, expected] : cases) {
    auto p = contactProblem();
    breakIt(p->sublist("Contact").sublist("plate"));
    expectProblemError(*p, expected);
  }
  auto q = goodProblem();
  auto& c = q->sublist("Contact").sublist("self");
  c.set("Slave Side Set", std::string("top"));
  c.set("Master Side Set", std::string("top"));
  c.set("Normal Penalty", 1e6);
  expectProblemError(*q, "Problem/Contact/self/Master Side Set: must differ from the Slave Side Set");
  q->sublist("Contact").sublist("self").set("Master Side Set", std::string("nowhere"));
  expectProblemError(*q, "Problem/Contact/self/Master Side Set: side set 'nowhere' does not exist");
}

// A small 3D problem: the automatic linear solver choice gives it to MUMPS.
const contessa::solvers::ProblemSize kSmall3D{3, 3000};

void expectPiroError(ParameterList& piro, int ranks, const std::string& expected) {
  try {
    contessa::solvers::validatePiro(piro, ranks, kSmall3D);
    FAIL() << "no error; expected: " << expected;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << "message: " << e.what();
  }
}

TEST(PiroValidation, DefaultsAndMumpsForASmallProblem) {
  ParameterList piro("Piro");
  const auto choice = contessa::solvers::validatePiro(piro, 2, kSmall3D);
  EXPECT_EQ(piro.sublist("Stratimikos").get<std::string>("Linear Solver Type"), "MUMPS");
  EXPECT_TRUE(choice.automatic);
  EXPECT_EQ(choice.solver, "MUMPS");
  EXPECT_EQ(piro.sublist("LOCA").sublist("Step Size").get<std::string>("Method"), "Constant");
  EXPECT_EQ(piro.sublist("NOX").sublist("Status Tests").get<int>("Maximum Iterations"), 25);
}

// The automatic linear solver choice (issue 23): MUMPS up to the limit of the dimension, Belos + MueLu
// above it; "Automatic" given or the parameter absent alike; a deck's solver or preconditioner kept.
TEST(PiroValidation, LinearSolverChosenBySizeAndDimension) {
  using contessa::solvers::chooseLinearSolver;
  using contessa::solvers::kDirectSolverLimit2D;
  using contessa::solvers::kDirectSolverLimit3D;
  const auto solverFor = [](ParameterList strat, int dim, long long unknowns) {
    const auto choice = chooseLinearSolver(strat, {dim, unknowns});
    EXPECT_EQ(strat.get<std::string>("Linear Solver Type"), choice.solver.substr(0, choice.solver.find(' ')));
    return choice;
  };
  ParameterList absent("Stratimikos");
  ParameterList automatic("Stratimikos");
  automatic.set("Linear Solver Type", std::string("Automatic"));
  for (const auto& strat : {absent, automatic}) {
    EXPECT_EQ(solverFor(strat, 3, kDirectSolverLimit3D).solver, "MUMPS");
    EXPECT_EQ(solverFor(strat, 3, kDirectSolverLimit3D + 1).solver, "Belos with MueLu");
    EXPECT_EQ(solverFor(strat, 2, kDirectSolverLimit3D + 1).solver, "MUMPS");
    EXPECT_EQ(solverFor(strat, 2, kDirectSolverLimit2D + 1).solver, "Belos with MueLu");
    EXPECT_TRUE(solverFor(strat, 3, 10).automatic);
  }
  const auto large = solverFor(absent, 3, 20000);
  EXPECT_NE(large.reason.find("3D, 20000 unknowns > 15000"), std::string::npos) << large.reason;
  ParameterList ifpack(automatic);
  ifpack.set("Preconditioner Type", std::string("Ifpack2"));
  EXPECT_EQ(solverFor(ifpack, 3, 20000).solver, "Belos with Ifpack2");
  ParameterList forcedBelos("Stratimikos");
  forcedBelos.set("Linear Solver Type", std::string("Belos"));
  const auto belos = solverFor(forcedBelos, 3, 10);
  EXPECT_EQ(belos.solver, "Belos without preconditioner");
  EXPECT_FALSE(belos.automatic);
  ParameterList forcedMumps("Stratimikos");
  forcedMumps.set("Linear Solver Type", std::string("MUMPS"));
  EXPECT_EQ(solverFor(forcedMumps, 3, 1000000).solver, "MUMPS");
}

TEST(PiroValidation, UnknownStepSizeMethod) {
  ParameterList piro("Piro");
  piro.sublist("LOCA").sublist("Step Size").set("Method", std::string("Bisection"));
  expectPiroError(piro, 1, "Piro/LOCA/Step Size/Method: expected one of Constant, Adaptive, Contact Beta; got 'Bisection'");
}

// Step-size methods come from a registry: each row publishes the Step Size parameters it reads, and only
// Contessa's own methods carry a factory (LOCA builds Constant and Adaptive from the same list).
TEST(PiroValidation, StepSizeRegistry) {
  using contessa::solvers::stepSizeMethodRegistry;
  EXPECT_EQ(contessa::solvers::stepSizeMethods(), (std::vector<std::string>{"Constant", "Adaptive", "Contact Beta"}));
  const auto valid = contessa::solvers::piroValidParameters();
  const auto& step = valid->sublist("LOCA").sublist("Step Size");
  for (const auto& method : stepSizeMethodRegistry()) {
    EXPECT_EQ(static_cast<bool>(method.create), method.name == "Contact Beta") << method.name;
    ParameterList own;
    ASSERT_NE(method.addParameters, nullptr) << method.name;
    method.addParameters(own);
    EXPECT_GT(own.numParams(), 0) << method.name;
    for (auto it = own.begin(); it != own.end(); ++it) EXPECT_TRUE(step.isParameter(own.name(it))) << own.name(it);
  }
  EXPECT_NE(step.getEntry("Method").docString().find("Contact Beta: N_c contacts per increment"), std::string::npos);
}

TEST(PiroValidation, StepSizesMustBeOrdered) {
  ParameterList piro("Piro");
  piro.sublist("LOCA").sublist("Step Size").set("Initial Step Size", 2.0);
  expectPiroError(piro, 1, "Piro/LOCA/Step Size: expected Min Step Size <= Initial Step Size <= Max Step Size");
}

TEST(PiroValidation, Klu2IsRefusedOnSeveralRanks) {
  ParameterList piro("Piro");
  piro.sublist("Stratimikos").set("Linear Solver Type", std::string("Amesos2"));
  EXPECT_NO_THROW(contessa::solvers::validatePiro(piro, 1, kSmall3D));
  expectPiroError(piro, 2, "gives wrong solutions on more than one MPI rank");
}

TEST(PiroValidation, StratimikosSolversThatTakeTpetraMatrices) {
  // Stratimikos' Epetra solvers would fail at the first solve: they are refused with the allowed list.
  const std::vector<std::pair<std::pair<std::string, std::string>, std::string>> cases = {
      {{"Linear Solver Type", "Pardiso"}, "Piro/Stratimikos/Linear Solver Type: expected one of Automatic, MUMPS, Amesos2, Belos; got 'Pardiso'"},
      {{"Linear Solver Type", "AztecOO"}, "Piro/Stratimikos/Linear Solver Type: expected one of Automatic, MUMPS, Amesos2, Belos; got 'AztecOO'"},
      {{"Preconditioner Type", "ML"}, "Piro/Stratimikos/Preconditioner Type: expected one of None, Ifpack2, MueLu; got 'ML'"},
  };
  for (const auto& [setting, expected] : cases) {
    ParameterList piro("Piro");
    piro.sublist("Stratimikos").set(setting.first, setting.second);
    expectPiroError(piro, 1, expected);
  }
  ParameterList piro("Piro");
  piro.sublist("Stratimikos").set("Linear Solver Type", 3);
  expectPiroError(piro, 1, "Piro/Stratimikos/Linear Solver Type: expected a string, one of Automatic, MUMPS, Amesos2, Belos");
  ParameterList amesos2("Piro");
  amesos2.sublist("Stratimikos").set("Linear Solver Type", std::string("Amesos2"));
  amesos2.sublist("Stratimikos").sublist("Linear Solver Types").sublist("Amesos2").set("Solver Type", std::string("SuperLU"));
  expectPiroError(amesos2, 1, "Piro/Stratimikos/Linear Solver Types/Amesos2/Solver Type: expected one of KLU2; got 'SuperLU'");
  // Stratimikos' default preconditioner (Ifpack) is an Epetra one: Contessa's default is None.
  ParameterList belos("Piro");
  belos.sublist("Stratimikos").set("Linear Solver Type", std::string("Belos"));
  contessa::solvers::validatePiro(belos, 2, kSmall3D);
  EXPECT_EQ(belos.sublist("Stratimikos").get<std::string>("Preconditioner Type"), "None");
}

TEST(PiroValidation, ContactBetaParameters) {
  const std::vector<std::pair<std::pair<std::string, std::string>, std::string>> cases = {
      {{"Contacts Per Step", "-1"}, "Piro/LOCA/Step Size/Contacts Per Step: expected an integer in [0, inf]"},  // 0: automatic
      {{"Mode", "Corrector"}, "Piro/LOCA/Step Size/Mode: expected one of Restart, Predictor; got 'Corrector'"},
      {{"Max Growth Factor", "0.5"}, "Piro/LOCA/Step Size/Max Growth Factor: expected a value in [1, 1000]"},
      {{"Max Shrink Factor", "2"}, "Piro/LOCA/Step Size/Max Shrink Factor: expected a value in [1e-06, 1]"},
      {{"Restart Tolerance", "-0.1"}, "Piro/LOCA/Step Size/Restart Tolerance: expected a value in [0, 1]"},
      {{"Next Contact Fraction", "1"}, "Piro/LOCA/Step Size/Next Contact Fraction: expected a value in [0, 0.999]"},
  };
  for (const auto& [setting, expected] : cases) {
    ParameterList deck("deck");
    deck.sublist("Piro").sublist("LOCA").sublist("Step Size").set("Method", std::string("Contact Beta"));
    contessa::deck::applyOverrides(deck, {"Piro/LOCA/Step Size/" + setting.first + "=" + setting.second});
    expectPiroError(deck.sublist("Piro"), 1, expected);
  }
}

TEST(PiroValidation, MistypedNoxParameter) {
  ParameterList piro("Piro");
  piro.sublist("NOX").sublist("Status Tests").set("Max Iterations", 10);
  expectPiroError(piro, 1, "Piro/NOX/Status Tests/Max Iterations: unknown parameter (expected one of: Maximum Iterations");
}

}  // namespace
