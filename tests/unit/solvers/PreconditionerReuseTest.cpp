// The MueLu reuse guard (solvers/PreconditionerReuse): a preconditioner keeps its set-up while the
// Jacobians it is given share one matrix graph, and is started over (uninitialised first, so that MueLu
// builds a new hierarchy) when the graph changes, as after a contact rebuild. The inner factory here
// records the calls instead of building MueLu.
#include <gtest/gtest.h>

#include <Thyra_DefaultLinearOpSource.hpp>
#include <Thyra_DefaultPreconditioner.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_Core.hpp>

#include "solvers/PreconditionerReuse.hpp"

namespace {

using contessa::model::CrsGraph;
using contessa::model::CrsMatrix;
using contessa::model::GO;
using contessa::model::Map;
using Teuchos::RCP;
using Teuchos::rcp;

class RecordingFactory : public Thyra::PreconditionerFactoryBase<double> {
 public:
  mutable int initializations = 0, uninitializations = 0;
  bool isCompatible(const Thyra::LinearOpSourceBase<double>&) const override { return true; }
  RCP<Thyra::PreconditionerBase<double>> createPrec() const override {
    return rcp(new Thyra::DefaultPreconditioner<double>());
  }
  void initializePrec(const RCP<const Thyra::LinearOpSourceBase<double>>&, Thyra::PreconditionerBase<double>*,
                      const Thyra::ESupportSolveUse) const override {
    ++initializations;
  }
  void uninitializePrec(Thyra::PreconditionerBase<double>*, RCP<const Thyra::LinearOpSourceBase<double>>*,
                        Thyra::ESupportSolveUse*) const override {
    ++uninitializations;
  }
  void setParameterList(const RCP<Teuchos::ParameterList>& list) override { list_ = list; }
  RCP<Teuchos::ParameterList> getNonconstParameterList() override { return list_; }
  RCP<Teuchos::ParameterList> unsetParameterList() override { return list_; }

 private:
  RCP<Teuchos::ParameterList> list_;
};

// A tridiagonal graph on 6 rows of this rank, or a pentadiagonal one (`wide`: the couplings a rebuild adds).
RCP<const CrsGraph> bandGraph(const RCP<const Map>& map, bool wide) {
  auto graph = rcp(new CrsGraph(map, wide ? 5 : 3));
  const GO n = static_cast<GO>(map->getGlobalNumElements());
  const GO reach = wide ? 2 : 1;
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i) {
    const GO row = map->getGlobalElement(static_cast<int>(i));
    std::vector<GO> cols;
    for (GO c = std::max<GO>(0, row - reach); c <= std::min<GO>(n - 1, row + reach); ++c) cols.push_back(c);
    graph->insertGlobalIndices(row, Teuchos::ArrayView<const GO>(cols));
  }
  graph->fillComplete();
  return graph;
}

// A Jacobian on `graph` with the values `scale` (new values, same graph: a later Newton iteration).
RCP<const Thyra::LinearOpSourceBase<double>> jacobianOn(const RCP<const CrsGraph>& graph, double scale) {
  auto matrix = rcp(new CrsMatrix(graph));
  matrix->resumeFill();
  matrix->setAllToScalar(scale);
  matrix->fillComplete();
  auto op = Thyra::createConstLinearOp(Teuchos::rcp_implicit_cast<const contessa::model::Operator>(matrix));
  return Thyra::defaultLinearOpSource(op);
}

TEST(PreconditionerReuse, SetUpKeptWhileTheGraphIsUnchangedAndStartedOverOnARebuild) {
  auto comm = Tpetra::getDefaultComm();
  auto map = rcp(new Map(static_cast<Tpetra::global_size_t>(6 * comm->getSize()), 6, 0, comm));
  auto recording = rcp(new RecordingFactory());
  contessa::solvers::GraphKeyedPreconditionerFactory factory(recording);
  auto prec = factory.createPrec();
  const long freshBefore = contessa::solvers::GraphKeyedPreconditionerFactory::freshSetUps();

  const auto first = bandGraph(map, false);
  factory.initializePrec(jacobianOn(first, 1.0), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->initializations, 1);
  EXPECT_EQ(recording->uninitializations, 1);  // a new preconditioner starts from nothing
  for (double scale : {2.0, 3.0, 4.0})  // Newton iterations and increments on the same graph
    factory.initializePrec(jacobianOn(first, scale), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->initializations, 4);
  EXPECT_EQ(recording->uninitializations, 1) << "the set-up must be reused while the graph is unchanged";

  const auto rebuilt = bandGraph(map, true);  // contact added couplings: a new graph
  factory.initializePrec(jacobianOn(rebuilt, 5.0), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->uninitializations, 2) << "a new graph must start the hierarchy over";
  EXPECT_EQ(contessa::solvers::GraphKeyedPreconditionerFactory::freshSetUps(), freshBefore + 1);
  factory.initializePrec(jacobianOn(rebuilt, 6.0), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->uninitializations, 2);

  // A second preconditioner (another NOX group) keeps its own record.
  auto other = factory.createPrec();
  factory.initializePrec(jacobianOn(rebuilt, 1.0), other.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->uninitializations, 3);
  factory.initializePrec(jacobianOn(rebuilt, 7.0), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->uninitializations, 3);
}

}  // namespace
