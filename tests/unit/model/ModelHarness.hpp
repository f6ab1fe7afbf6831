#pragma once
// What the model tests share: a model with MUMPS, one evaluation through the Thyra ModelEvaluator
// (f, and W with ∂f/∂λ when asked), and a plain full Newton at a fixed load factor.
#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_VectorStdOps.hpp>
#include <Tpetra_Core.hpp>

#include "common/MpiCommOf.hpp"
#include "deck/ProblemDefinition.hpp"
#include "mesh/MeshDistribution.hpp"
#include "model/ContactMechanicsModel.hpp"
#include "solvers/LinearSolverFactory.hpp"

namespace contessa::test {

/// The communicator of every rank of the test (Tpetra's default): the model tests' problems are built
/// on it unless a test builds one on fewer ranks.
inline MPI_Comm everyRank() { return mpiCommOf(*Tpetra::getDefaultComm()); }

/// The model of a copy of `problem` (the model shares what it is given; a test's problem may go).
inline Teuchos::RCP<model::ContactMechanicsModel> makeModel(
    const deck::ProblemDefinition& problem,
    const Teuchos::RCP<const Teuchos::Comm<int>>& comm = Tpetra::getDefaultComm()) {
  Teuchos::ParameterList strat("Stratimikos");
  strat.set("Linear Solver Type", std::string("MUMPS"));
  return Teuchos::rcp(new model::ContactMechanicsModel(comm, std::make_shared<const deck::ProblemDefinition>(problem),
                                                       solvers::createLinearSolverFactory(strat, comm)));
}

/// The same problem with the whole mesh as one part (for a model on MPI_COMM_SELF beside the model on
/// every rank): collective, meaningful on rank 0 only.
inline deck::ProblemDefinition onOneRank(const deck::ProblemDefinition& problem) {
  deck::ProblemDefinition whole = problem;
  const mesh::Mesh mesh = mesh::gatherMeshOnRoot(problem.mesh);
  whole.mesh = mesh::PartExtractor(mesh, std::vector<int>(static_cast<std::size_t>(mesh.numElements()), 0), 1).part(0);
  return whole;
}

struct Evaluation {
  Teuchos::RCP<Thyra::VectorBase<double>> f;
  Teuchos::RCP<Thyra::LinearOpBase<double>> W;         ///< when asked for
  Teuchos::RCP<Thyra::MultiVectorBase<double>> dfdp;   ///< ∂f/∂λ, with W
};

inline Evaluation evaluate(model::ContactMechanicsModel& m, const Thyra::VectorBase<double>& x, double lambda,
                           bool withW) {
  auto in = m.createInArgs();
  auto p = Thyra::createMember(m.get_p_space(0));
  Thyra::set_ele(0, lambda, p.ptr());
  in.set_x(Teuchos::rcpFromRef(x));
  in.set_p(0, p);
  Evaluation e;
  e.f = Thyra::createMember(m.get_f_space());
  auto out = m.createOutArgs();
  out.set_f(e.f);
  if (withW) {
    e.W = m.create_W_op();
    e.dfdp = Thyra::createMembers(m.get_f_space(), 1);
    out.set_W_op(e.W);
    out.set_DfDp(0, Thyra::ModelEvaluatorBase::Derivative<double>(e.dfdp, Thyra::ModelEvaluatorBase::DERIV_MV_JACOBIAN_FORM));
  }
  m.evalModel(in, out);
  return e;
}

/// Full Newton at load factor λ from x (in place), MUMPS for the linear solves: the residual norms, the
/// last below `tolerance` when it converged within `maxIterations`.
inline std::vector<double> newtonAt(model::ContactMechanicsModel& m, Thyra::VectorBase<double>& x, double lambda,
                                    double tolerance = 1e-10, int maxIterations = 30) {
  std::vector<double> norms;
  for (int it = 0; it < maxIterations; ++it) {
    auto e = evaluate(m, x, lambda, true);
    norms.push_back(Thyra::norm_2(*e.f));
    if (norms.back() < tolerance || !std::isfinite(norms.back())) break;
    auto lows = Thyra::linearOpWithSolve<double>(*m.get_W_factory(), e.W.getConst());
    auto dx = Thyra::createMember(m.get_x_space());
    Thyra::assign(dx.ptr(), 0.0);
    const auto status = Thyra::solve<double>(*lows, Thyra::NOTRANS, *e.f, dx.ptr());
    EXPECT_EQ(status.solveStatus, Thyra::SOLVE_STATUS_CONVERGED);
    Thyra::Vp_StV(Teuchos::ptrFromRef(x), -1.0, *dx);
  }
  return norms;
}

/// x moved half a Newton step towards λ (x ← x − ½ W⁻¹ f): a state away from equilibrium where the
/// contact stays active, for the Jacobian checks.
inline void halfNewtonStep(model::ContactMechanicsModel& m, Thyra::VectorBase<double>& x, double lambda) {
  auto e = evaluate(m, x, lambda, true);
  auto lows = Thyra::linearOpWithSolve<double>(*m.get_W_factory(), e.W.getConst());
  auto dx = Thyra::createMember(m.get_x_space());
  Thyra::assign(dx.ptr(), 0.0);
  Thyra::solve<double>(*lows, Thyra::NOTRANS, *e.f, dx.ptr());
  Thyra::Vp_StV(Teuchos::ptrFromRef(x), -0.5, *dx);
}

/// The model's W at (x, λ) against central differences of its residual with step h, column by column:
/// the largest max-norm of a column's difference W e_j − D e_j, the largest |W| entry it is measured
/// against, and the column of the largest difference.
struct JacobianDifference {
  double worst = 0, scale = 0;
  Thyra::Ordinal worstColumn = -1;
};

inline JacobianDifference differenceJacobian(model::ContactMechanicsModel& m, const Thyra::VectorBase<double>& x,
                                             double lambda, double h) {
  const auto e = evaluate(m, x, lambda, true);
  JacobianDifference d;
  auto unit = Thyra::createMember(m.get_x_space());
  auto column = Thyra::createMember(m.get_f_space());
  auto fd = Thyra::createMember(m.get_f_space());
  for (Thyra::Ordinal j = 0; j < m.get_x_space()->dim(); ++j) {
    Thyra::assign(unit.ptr(), 0.0);
    Thyra::set_ele(j, 1.0, unit.ptr());
    Thyra::apply(*e.W, Thyra::NOTRANS, *unit, column.ptr());
    auto xp = x.clone_v(), xm = x.clone_v();
    Thyra::Vp_StV(xp.ptr(), h, *unit);
    Thyra::Vp_StV(xm.ptr(), -h, *unit);
    // f(x − h e_j) first: the enhanced elements start their local solve from the last evaluation's α,
    // so the order shows in the last bits of the differences.
    const auto fm = evaluate(m, *xm, lambda, false).f;
    const auto fp = evaluate(m, *xp, lambda, false).f;
    Thyra::V_StVpStV(fd.ptr(), 0.5 / h, *fp, -0.5 / h, *fm);
    d.scale = std::max(d.scale, Thyra::norm_inf(*column));
    Thyra::Vp_StV(fd.ptr(), -1.0, *column);
    if (Thyra::norm_inf(*fd) > d.worst) d.worstColumn = j;
    d.worst = std::max(d.worst, Thyra::norm_inf(*fd));
  }
  return d;
}

}  // namespace contessa::test
