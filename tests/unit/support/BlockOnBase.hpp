#pragma once
// The contact deck the model tests share (ModelTest, JacobianCheckTest, FrictionModelTest): a Neo-Hookean
// block of Q4 Enhanced, 2 wide, its bottom 0.001 above a base at y = 0, its top pushed down by 0.05
// and sideways; the base is a rigid line, or a meshed block (3 × 1, clamped at its bottom) whose top
// is the master surface. Each test sets what it varies (mesh, penalties, friction) and builds the
// problem through the deck's own validation, as a run would.
#include <optional>
#include <string>

#include <Teuchos_Array.hpp>
#include <Teuchos_Tuple.hpp>
#include <Teuchos_ParameterList.hpp>

#include "deck/ProblemDefinition.hpp"
#include "TestDeck.hpp"

namespace contessa::test {

struct BlockOnBase {
  int elementsX = 4, elementsY = 2;   ///< the block's elements
  bool deformableBase = false;        ///< a meshed base (Parts "base" and "top") instead of a rigid line
  std::string blockName = "block_1";  ///< the block's name on a rigid base (a deformable one: "top")
  std::string shearName = "shear";    ///< the Dirichlet condition moving the top sideways, and its value
  double shear = 0.02;
  double normalPenalty = 1e4;
  std::optional<double> tangentialPenalty = 1e4;  ///< unset: the deck's default
  std::optional<double> slipTolerance = 0.0;      ///< unset: the deck's default (0: the paper's constant ε_T)
  double friction = 0;
  std::optional<bool> twoPass;  ///< deformable base only; unset: the deck's default

  Teuchos::RCP<Teuchos::ParameterList> deck() const {
    auto problem = newProblem();
    addMesh(*problem);
    addMaterial(*problem, "rubber", "Neo-Hookean", 100.0, 0.3);
    // The generated node and side sets of a Parts mesh carry the part's name as a prefix.
    const std::string top = deformableBase ? "top_" : "";
    addDirichlet(*problem, "press", top + "top", "y").set("Value", -0.05);
    addDirichlet(*problem, shearName, top + "top", "x").set("Value", shear);
    auto& contact = problem->sublist("Contact").sublist("base");
    contact.set("Slave Side Set", top + "bottom");
    contact.set("Normal Penalty", normalPenalty);
    if (tangentialPenalty) contact.set("Tangential Penalty", *tangentialPenalty);
    if (slipTolerance) contact.set("Slip Tolerance", *slipTolerance);
    contact.set("Friction Coefficient", friction);
    if (deformableBase) {
      contact.set("Master Side Set", std::string("base_top"));
      if (twoPass) contact.set("Two Pass", *twoPass);
      // The base is clamped at its bottom.
      for (const char* c : {"x", "y"}) addDirichlet(*problem, std::string("base ") + c, "base_bottom", c);
    } else {
      contact.sublist("Rigid Surface").set("Points", Teuchos::Array<double>(Teuchos::tuple<double>(3.0, 0.0, -1.0, 0.0)));
      contact.sublist("Rigid Surface").set("Motion", Teuchos::Array<double>(2, 0.0));
    }
    return problem;
  }

  /// The problem on `comm` (its mesh spread over those ranks).
  deck::ProblemDefinition problem(MPI_Comm comm) const { return buildOn(*deck(), comm); }

 private:
  static void addRectangle(Teuchos::ParameterList& mesh, int nx, int ny, double x0, double y0, double length) {
    mesh.set("Type", std::string("Rectangle"));
    if (x0 != 0) mesh.set("X Origin", x0);
    mesh.set("Y Origin", y0);
    mesh.set("Length X", length);
    mesh.set("Elements X", nx);
    mesh.set("Elements Y", ny);
  }

  void addMesh(Teuchos::ParameterList& problem) const {
    auto& mesh = problem.sublist("Mesh");
    if (!deformableBase) {
      addRectangle(mesh, elementsX, elementsY, 0.0, 0.001, 2.0);
      if (blockName != "block_1") mesh.set("Block Name", blockName);
      addBlock(problem, blockName, "Q4 Enhanced", "rubber");
      return;
    }
    mesh.set("Type", std::string("Parts"));
    addRectangle(mesh.sublist("base"), 5, 2, -0.5, -1.0, 3.0);
    addRectangle(mesh.sublist("top"), elementsX, elementsY, 0.0, 0.001, 2.0);
    addBlock(problem, "base", "Q4 Enhanced", "rubber");
    addBlock(problem, "top", "Q4 Enhanced", "rubber");
  }
};

}  // namespace contessa::test
