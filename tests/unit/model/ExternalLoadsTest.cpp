// Loads on sets in the assembled model (model/ExternalLoads, BoundaryConditions): the total of every
// load equals its analytic resultant (pressure p·A·n, traction t·A, body force b·V, springs k·u), ∂f/∂λ
// and W of a deformed body under follower pressures and springs match differences of the residual; in
// 2D and 3D, on 1 and 2 ranks (the sums are over all ranks, so they are the same on any rank count).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>
#include <Tpetra_Core.hpp>

#include "deck/ProblemDefinition.hpp"
#include "ModelHarness.hpp"
#include "TestDeck.hpp"

namespace {

using namespace contessa;
using test::evaluate;
using Extract = Thyra::TpetraOperatorVectorExtraction<double, model::LO, model::GO, model::Node>;

const double kPressure = 2.5, kSpring[3] = {4.0, 6.0, 8.0};
const double kTraction[3] = {0.3, -1.1, 0.7}, kBody[3] = {-0.2, 0.5, -0.9};

// A block of Neo-Hookean enhanced elements, 4 × 3 (× 2), with a pressure on 'right' and 'top', a
// traction on 'top', a body force everywhere and springs on 'bottom'; clamped on 'left' when asked.
deck::ProblemDefinition makeProblem(int dim, bool clamped) {
  auto p = test::newProblem();
  if (dim == 2) test::setGrid(p->sublist("Mesh"), "Rectangle", {4, 3}, {4.0, 3.0});
  else test::setGrid(p->sublist("Mesh"), "Box", {4, 3, 2}, {4.0, 3.0, 2.0});
  test::addBlock(*p, "block_1", dim == 2 ? "Q4 Enhanced" : "Hex8 Enhanced", "rubber");
  test::addMaterial(*p, "rubber", "Neo-Hookean", 100.0, 0.3);
  auto& loads = p->sublist("Loads");
  const auto addLoad = [&loads](const std::string& name, const std::string& type, const std::string& setKind,
                                const std::string& set) -> Teuchos::ParameterList& {
    auto& load = loads.sublist(name);
    load.set("Type", type);
    if (!setKind.empty()) load.set(setKind, set);
    return load;
  };
  const auto array = [dim](const double* v) { return Teuchos::Array<double>(v, v + dim); };
  addLoad("push right", "Pressure", "Side Set", "right").set("Pressure", kPressure);
  addLoad("push top", "Pressure", "Side Set", "top").set("Pressure", 0.5 * kPressure);
  addLoad("drag", "Traction", "Side Set", "top").set("Traction", array(kTraction));
  addLoad("weight", "Body Force", "", "").set("Force Per Volume", array(kBody));
  addLoad("support", "Spring", "Node Set", "bottom").set("Stiffness", array(kSpring));
  test::setReactionSets(*p, {"top", "bottom"});
  if (clamped)
    for (int c = 0; c < dim; ++c) test::addDirichlet(*p, "clamp " + std::to_string(c), "left", std::string(1, "xyz"[c]));
  return test::buildOn(*p, test::everyRank());
}

// x with owned entries u(X) = a · (smooth field of the reference position), or a rigid translation.
Teuchos::RCP<Thyra::VectorBase<double>> displacement(const model::ContactMechanicsModel& m,
                                                     const deck::ProblemDefinition& problem, double a,
                                                     bool translation) {
  auto x = Thyra::createMember(m.get_x_space());
  auto xt = Extract::getTpetraVector(x);
  const int dim = problem.dimension();
  const auto& map = *xt->getMap();
  auto v = xt->getDataNonConst(0);
  for (std::size_t k = 0; k < static_cast<std::size_t>(v.size()); ++k) {
    const auto gid = map.getGlobalElement(static_cast<model::LO>(k));
    const auto node = problem.mesh.localNode(gid / dim);
    const int c = static_cast<int>(gid % dim);
    const double* X = problem.mesh.local().coordinates.data() + node * dim;
    v[k] = translation ? a * (c + 1) : a * (std::sin(0.4 * X[0] + c) * X[1] + 0.3 * X[(c + 1) % dim] * X[0]);
  }
  return x;
}

// Σ over all DOFs (all ranks) of component c of an owned vector.
std::vector<double> componentSums(const Thyra::VectorBase<double>& f, int dim) {
  auto ft = Extract::getConstTpetraVector(Teuchos::rcpFromRef(f));
  const auto& map = *ft->getMap();
  const auto v = ft->getData(0);
  std::vector<double> local(dim, 0.0), global(dim, 0.0);
  for (std::size_t k = 0; k < static_cast<std::size_t>(v.size()); ++k) local[map.getGlobalElement(static_cast<model::LO>(k)) % dim] += v[k];
  Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_SUM, dim, local.data(), global.data());
  return global;
}

class LoadsIn : public ::testing::TestWithParam<int> {};

TEST_P(LoadsIn, ResidualTotalsAreTheAnalyticResultants) {
  const int dim = GetParam();
  const double lx = 4, ly = 3, lz = dim == 3 ? 2 : 1;  // 2D: per unit thickness
  const auto problem = makeProblem(dim, false);
  auto m = test::makeModel(problem);
  const double lambda = 0.7;
  // At u = 0, f_int = 0 and the springs carry nothing: f = −λ (f_p + f_ext). The pressure on 'right'
  // (outward +x, area ly·lz) pushes in −x, the one on 'top' (outward +y, lx·lz) in −y.
  auto x0 = displacement(*m, problem, 0.0, false);
  const auto sums = componentSums(*evaluate(*m, *x0, lambda, false).f, dim);
  for (int c = 0; c < dim; ++c) {
    double load = kTraction[c] * lx * lz + kBody[c] * lx * ly * lz;
    if (c == 0) load -= kPressure * ly * lz;
    if (c == 1) load -= 0.5 * kPressure * lx * lz;
    EXPECT_NEAR(sums[c], -lambda * load, 1e-12 * std::abs(load)) << "component " << c;
  }
  // A rigid translation d: f_int = 0, the pressures' resultants unchanged (flat faces moved), and every
  // node of 'bottom' ((nx + 1)(nz + 1) of them) adds k_c d_c.
  const double d = 0.01;
  auto xt = displacement(*m, problem, d, true);
  const auto moved = componentSums(*evaluate(*m, *xt, lambda, false).f, dim);
  const double bottomNodes = dim == 2 ? 5 : 5 * 3;
  for (int c = 0; c < dim; ++c)
    EXPECT_NEAR(moved[c] - sums[c], kSpring[c] * d * (c + 1) * bottomNodes, 1e-10) << "component " << c;
}

TEST_P(LoadsIn, DerivativeInTheLoadFactorMatchesDifferencesUnderFollowerPressure) {
  const int dim = GetParam();
  const auto problem = makeProblem(dim, true);
  auto m = test::makeModel(problem);
  auto x = displacement(*m, problem, 0.05, false);
  const double lambda = 0.6, h = 1e-3;
  const auto e = evaluate(*m, *x, lambda, true);
  auto fd = Thyra::createMember(m->get_f_space());
  // f is affine in λ at fixed x (the pressure scales with λ): the central difference is exact.
  Thyra::V_StVpStV(fd.ptr(), 0.5 / h, *evaluate(*m, *x, lambda + h, false).f, -0.5 / h,
                   *evaluate(*m, *x, lambda - h, false).f);
  auto diff = fd->clone_v();
  Thyra::Vp_StV(diff.ptr(), -1.0, *e.dfdp->col(0));
  EXPECT_LT(Thyra::norm_inf(*diff), 1e-9 * Thyra::norm_inf(*fd));
  EXPECT_GT(Thyra::norm_inf(*fd), 1.0);
}

TEST_P(LoadsIn, JacobianMatchesDifferencesUnderFollowerPressureAndSprings) {
  const int dim = GetParam();
  const auto problem = makeProblem(dim, true);
  auto m = test::makeModel(problem);
  auto x = displacement(*m, problem, 0.05, false);
  auto v = displacement(*m, problem, 1.0, false);  // a direction touching every DOF
  const double lambda = 1.0, h = 1e-6;
  const auto e = evaluate(*m, *x, lambda, true);
  auto Wv = Thyra::createMember(m->get_f_space());
  e.W->apply(Thyra::NOTRANS, *v, Wv.ptr(), 1.0, 0.0);
  auto xp = x->clone_v(), xm = x->clone_v();
  Thyra::Vp_StV(xp.ptr(), h, *v);
  Thyra::Vp_StV(xm.ptr(), -h, *v);
  auto fd = Thyra::createMember(m->get_f_space());
  Thyra::V_StVpStV(fd.ptr(), 0.5 / h, *evaluate(*m, *xp, lambda, false).f, -0.5 / h, *evaluate(*m, *xm, lambda, false).f);
  Thyra::Vp_StV(fd.ptr(), -1.0, *Wv);
  EXPECT_LT(Thyra::norm_inf(*fd), 1e-7 * Thyra::norm_inf(*Wv));
  // Without the pressures' load stiffness W would be off by λ K_p v: the check must be able to see it.
  const auto problemWithout = [&] {
    auto q = problem;
    q.loads.erase(q.loads.begin(), q.loads.begin() + 2);  // the two pressures
    return q;
  }();
  auto without = test::makeModel(problemWithout);
  const auto ew = evaluate(*without, *x, lambda, true);
  auto Wv0 = Thyra::createMember(m->get_f_space());
  ew.W->apply(Thyra::NOTRANS, *v, Wv0.ptr(), 1.0, 0.0);
  Thyra::Vp_StV(Wv0.ptr(), -1.0, *Wv);
  EXPECT_GT(Thyra::norm_inf(*Wv0), 1e-3 * Thyra::norm_inf(*Wv));
}

TEST_P(LoadsIn, ReactionsSubtractTheLoadsAndReportTheSpringsForce) {
  // Reaction of a set = Σ (f_int − λ f_p − λ f_ext) over its nodes (theory-solids §7): the residual
  // minus the springs' k x. At any x (equilibrium is not needed for the identity): 'top' has pressure and
  // traction on it and no spring, so its reaction is the residual's sum; 'bottom' carries the springs,
  // whose force k x the reaction leaves out (at equilibrium it is −Σ k u, the springs' force on the body).
  const int dim = GetParam();
  const auto problem = makeProblem(dim, false);
  auto m = test::makeModel(problem);
  auto x = displacement(*m, problem, 0.05, false);
  const double lambda = 0.8;
  const auto e = evaluate(*m, *x, lambda, false);
  const auto reactions = m->reactions(*Extract::getConstTpetraVector(x), lambda);
  auto ft = Extract::getConstTpetraVector(e.f);
  auto xt = Extract::getConstTpetraVector(x);
  const auto& map = *ft->getMap();
  const auto f = ft->getData(0), xv = xt->getData(0);
  const mesh::Mesh& local = problem.mesh.local();
  for (const auto& reaction : reactions) {
    const auto& nodes = local.nodeSet(reaction.nodeSet).nodes;
    const bool springs = reaction.nodeSet == "bottom";
    std::vector<double> mine(dim, 0.0), expected(dim, 0.0);
    for (std::size_t k = 0; k < static_cast<std::size_t>(f.size()); ++k) {
      const auto gid = map.getGlobalElement(static_cast<model::LO>(k));
      const int c = static_cast<int>(gid % dim);
      if (!std::binary_search(nodes.begin(), nodes.end(), problem.mesh.localNode(gid / dim))) continue;
      mine[c] += f[k] - (springs ? kSpring[c] * xv[k] : 0.0);
    }
    Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_SUM, dim, mine.data(), expected.data());
    double scale = 0.0;
    for (int c = 0; c < dim; ++c) scale = std::max(scale, std::abs(expected[c]));
    EXPECT_GT(scale, 0.1) << reaction.nodeSet;  // loads and springs do act on both sets
    for (int c = 0; c < dim; ++c) EXPECT_NEAR(reaction.force[c], expected[c], 1e-11 * scale) << reaction.nodeSet << " " << c;
  }
}

INSTANTIATE_TEST_SUITE_P(Dimensions, LoadsIn, ::testing::Values(2, 3),
                         [](const ::testing::TestParamInfo<int>& info) { return std::to_string(info.param) + "D"; });

}  // namespace
