// The MueLu reuse guard (solvers/PreconditionerReuse): a preconditioner keeps its set-up while the
// Jacobians it is given share one matrix graph, and is started over (uninitialised first, so that MueLu
// builds a new hierarchy) when the graph changes, as after a contact rebuild. The inner factory here
// records the calls instead of building MueLu.
#include <cmath>

#include <gtest/gtest.h>

#include <Thyra_DefaultLinearOpSource.hpp>
#include <Thyra_DefaultPreconditioner.hpp>
#include <Thyra_TpetraLinearOp.hpp>
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

// A matrix on `graph` with every value `scale`.
RCP<CrsMatrix> uniformMatrix(const RCP<const CrsGraph>& graph, double scale) {
  auto matrix = rcp(new CrsMatrix(graph));
  matrix->resumeFill();
  matrix->setAllToScalar(scale);
  matrix->fillComplete();
  return matrix;
}

// What the factory is given: the matrix as a Thyra linear-operator source.
RCP<const Thyra::LinearOpSourceBase<double>> sourceOf(const RCP<const CrsMatrix>& matrix) {
  auto op = Thyra::createConstLinearOp(Teuchos::rcp_implicit_cast<const contessa::model::Operator>(matrix));
  return Thyra::defaultLinearOpSource(op);
}

// A Jacobian on `graph` with the values `scale` (new values, same graph: a later Newton iteration).
RCP<const Thyra::LinearOpSourceBase<double>> jacobianOn(const RCP<const CrsGraph>& graph, double scale) {
  return sourceOf(uniformMatrix(graph, scale));
}

// The reuse wrapper over a recording factory, one preconditioner of it, and 6 rows on each rank.
struct ReuseOnSixRowsPerRank {
  RCP<const Teuchos::Comm<int>> comm = Tpetra::getDefaultComm();
  RCP<const Map> map = rcp(new Map(static_cast<Tpetra::global_size_t>(6 * comm->getSize()), 6, 0, comm));
  RCP<RecordingFactory> recording = rcp(new RecordingFactory());
  contessa::solvers::GraphKeyedPreconditionerFactory factory{recording};
  RCP<Thyra::PreconditionerBase<double>> prec = factory.createPrec();
};

TEST(PreconditionerReuse, SetUpKeptWhileTheGraphIsUnchangedAndStartedOverOnARebuild) {
  ReuseOnSixRowsPerRank setting;
  auto& [comm, map, recording, factory, prec] = setting;
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

// A Jacobian on `graph` with every value 1 but the entries of the rows in `zeroRows` (local rows), which
// are 0: couplings reserved in the graph that are not active yet (an open contact pair).
RCP<const Thyra::LinearOpSourceBase<double>> jacobianWithZeroRows(const RCP<const CrsGraph>& graph,
                                                                  const std::vector<int>& zeroRows) {
  auto matrix = rcp(new CrsMatrix(graph));
  matrix->resumeFill();
  matrix->setAllToScalar(1.0);
  for (int row : zeroRows) {
    Teuchos::ArrayView<const int> columns;
    graph->getLocalRowView(row, columns);
    std::vector<double> zeros(columns.size(), 0.0);
    matrix->replaceLocalValues(row, columns, Teuchos::ArrayView<const double>(zeros));
  }
  matrix->fillComplete();
  auto op = Thyra::createConstLinearOp(Teuchos::rcp_implicit_cast<const contessa::model::Operator>(matrix));
  return Thyra::defaultLinearOpSource(op);
}

// MueLu's re-set-up multiplies into the patterns of the first set-up's products, which hold only the
// entries that were nonzero then: an entry that fills in later must start the hierarchy over, and on every
// rank alike, also when only one rank holds it (before, the rank that held it failed alone: MPI_ERR_TRUNCATE).
TEST(PreconditionerReuse, AnEntryZeroAtTheSetUpThatFillsInStartsOverOnEveryRank) {
  ReuseOnSixRowsPerRank setting;
  auto& [comm, map, recording, factory, prec] = setting;
  auto& counts = contessa::solvers::GraphKeyedPreconditionerFactory::counts();
  const long grewBefore = counts.patternGrew, reusedBefore = counts.reused;
  const auto graph = bandGraph(map, false);

  // Row 2 of the last rank is zero at the set-up.
  const bool last = comm->getRank() == comm->getSize() - 1;
  const std::vector<int> open = last ? std::vector<int>{2} : std::vector<int>{};
  factory.initializePrec(jacobianWithZeroRows(graph, open), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  factory.initializePrec(jacobianWithZeroRows(graph, open), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->uninitializations, 1) << "zeros that stay zero keep the set-up";
  EXPECT_EQ(counts.reused, reusedBefore + 1);
  // More zeros than at the set-up: a subset of its nonzeros, still reusable.
  factory.initializePrec(jacobianWithZeroRows(graph, {1, 2}), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->uninitializations, 1);

  // The row fills in (the pair closes) on the last rank only: every rank starts over.
  factory.initializePrec(jacobianWithZeroRows(graph, {}), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->uninitializations, 2) << "a filled-in entry on any rank must start the set-up over on all";
  EXPECT_EQ(counts.patternGrew, grewBefore + 1);
  // The new set-up has no zeros: closing nothing more, it is kept.
  factory.initializePrec(jacobianWithZeroRows(graph, {}), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->uninitializations, 2);
}

// The same Jacobian with the same values as at the last set-up (LOCA's tangent predictor at a converged
// state the last Newton iteration already had) is not set up again; new values on one rank only are, on
// every rank.
TEST(PreconditionerReuse, UnchangedValuesOfTheSameMatrixSkipTheSetUpOnEveryRankAlike) {
  ReuseOnSixRowsPerRank setting;
  auto& [comm, map, recording, factory, prec] = setting;
  auto& counts = contessa::solvers::GraphKeyedPreconditionerFactory::counts();
  const long unchangedBefore = counts.unchanged, reusedBefore = counts.reused;
  auto matrix = uniformMatrix(bandGraph(map, false), 3.0);
  const auto source = sourceOf(matrix);
  factory.initializePrec(source, prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  factory.initializePrec(source, prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->initializations, 1) << "the values of the set-up: nothing to redo";
  EXPECT_EQ(counts.unchanged, unchangedBefore + 1);

  // Another matrix object with equal values is set up (its hierarchy would point at the other matrix).
  factory.initializePrec(jacobianOn(matrix->getCrsGraph(), 3.0), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->initializations, 2);
  factory.initializePrec(source, prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->initializations, 3);

  // One value of the last rank changed in place: every rank re-sets-up.
  matrix->resumeFill();
  if (comm->getRank() == comm->getSize() - 1) {
    Teuchos::ArrayView<const int> columns;
    matrix->getCrsGraph()->getLocalRowView(4, columns);
    std::vector<double> values(columns.size(), 3.0);
    values[0] = 3.0 + 1e-15;
    matrix->replaceLocalValues(4, columns, Teuchos::ArrayView<const double>(values));
  }
  matrix->fillComplete();
  factory.initializePrec(source, prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->initializations, 4) << "a changed value on any rank must re-set-up on all";
  EXPECT_EQ(counts.reused, reusedBefore + 3);
  EXPECT_EQ(recording->uninitializations, 1);
}

// The exact zeros that the inner factory sees in the matrix it sets up from (what MueLu's products skip).
class ZeroCountingFactory : public RecordingFactory {
 public:
  mutable std::vector<std::size_t> zerosSeen;
  void initializePrec(const RCP<const Thyra::LinearOpSourceBase<double>>& src, Thyra::PreconditionerBase<double>* prec,
                      const Thyra::ESupportSolveUse use) const override {
    using TpetraOp = Thyra::TpetraLinearOp<double, contessa::model::LO, GO, contessa::model::Node>;
    const auto op = Teuchos::rcp_dynamic_cast<const TpetraOp>(src->getOp(), true);
    const auto matrix = Teuchos::rcp_dynamic_cast<const CrsMatrix>(op->getConstTpetraOperator(), true);
    zerosSeen.push_back(contessa::solvers::zeroEntryPositions(*matrix).size());
    RecordingFactory::initializePrec(src, prec, use);
  }
};

// A row whose values changed between two set-ups (a contact row) is volatile: at the next fresh set-up its
// zeros hold a tiny value while the inner factory sets up, so that a later fill-in there is inside the
// products' patterns and keeps the set-up; the zeros are restored afterwards, and a row that never changed
// keeps its zeros (and a fill-in there still starts over).
TEST(PreconditionerReuse, ZerosOfRowsThatChangedAreFilledForAFreshSetUpSoThatTheirFillInIsReused) {
  auto comm = Tpetra::getDefaultComm();
  auto map = rcp(new Map(static_cast<Tpetra::global_size_t>(6 * comm->getSize()), 6, 0, comm));
  auto counting = rcp(new ZeroCountingFactory());
  contessa::solvers::GraphKeyedPreconditionerFactory factory{counting};
  auto prec = factory.createPrec();
  auto& counts = contessa::solvers::GraphKeyedPreconditionerFactory::counts();
  const auto graph = bandGraph(map, false);
  // Row 2 holds [0 0 0] (an open pair), rows 3 and 4 [0 1 1] (a coupling zero at first). Row 3's zero fills
  // in (a fresh set-up; row 3 is volatile now) and is zero again (reused); row 4's fills in (a fresh set-up,
  // which fills row 3's zero for MueLu), and row 3's next fill-in is reused.
  auto jacobian = [&](double row2, double row3Middle, double row4) {  // the rows' first entries
    auto matrix = rcp(new CrsMatrix(graph));
    matrix->resumeFill();
    matrix->setAllToScalar(1.0);
    for (auto [row, values] : {std::pair<int, std::vector<double>>{2, {0.0, row2, 0.0}}, {3, {row3Middle, 1.0, 1.0}},
                               {4, {row4, 1.0, 1.0}}}) {
      Teuchos::ArrayView<const int> columns;
      graph->getLocalRowView(row, columns);
      std::vector<double> v(columns.size());
      for (std::size_t k = 0; k < v.size(); ++k) v[k] = values[k];
      matrix->replaceLocalValues(row, columns, Teuchos::ArrayView<const double>(v));
    }
    matrix->fillComplete();
    return matrix;
  };
  const long grewBefore = counts.patternGrew;
  auto set = [&](const RCP<CrsMatrix>& m) { factory.initializePrec(sourceOf(m), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED); };
  set(jacobian(0.0, 0.0, 0.0));  // fresh: 3 + 1 + 1 zeros on each rank, no volatile row yet
  EXPECT_EQ(counting->zerosSeen.back(), 5u);
  set(jacobian(0.0, 2.0, 0.0));  // row 3's zero fills in: start over; rows 3 changed -> volatile
  EXPECT_EQ(counts.patternGrew, grewBefore + 1);
  EXPECT_EQ(counting->uninitializations, 2);
  EXPECT_EQ(counting->zerosSeen.back(), 4u) << "row 3 holds no zero at this set-up: nothing to fill";
  set(jacobian(0.0, 0.0, 0.0));  // row 3 back to zero: a subset of the set-up's nonzeros, reused
  EXPECT_EQ(counting->uninitializations, 2);
  const auto fourth = jacobian(0.0, 0.0, 5.0);  // row 4 (never changed) fills in: start over, row 3's zero filled
  set(fourth);
  EXPECT_EQ(counts.patternGrew, grewBefore + 2);
  EXPECT_EQ(counting->zerosSeen.back(), 3u) << "the volatile row 3's zero must hold the fill while MueLu sets up";
  EXPECT_EQ(contessa::solvers::zeroEntryPositions(*fourth).size(), 4u) << "the zeros must be restored after the set-up";
  set(jacobian(0.0, 7.0, 5.0));  // row 3 fills in again: inside the patterns now, reused
  EXPECT_EQ(counts.patternGrew, grewBefore + 2) << "a fill-in of a volatile row must keep the set-up";
  EXPECT_EQ(counting->uninitializations, 3);
  set(jacobian(3.0, 7.0, 5.0));  // row 2's diagonal (never changed, not filled) fills in: start over
  EXPECT_EQ(counting->uninitializations, 4) << "a fill-in of a row not filled at the set-up must start over";
}

TEST(PreconditionerReuse, ZeroEntriesFoundAndTheirFillInSeen) {
  auto comm = Tpetra::getDefaultComm();
  auto map = rcp(new Map(static_cast<Tpetra::global_size_t>(6 * comm->getSize()), 6, 0, comm));
  const auto graph = bandGraph(map, false);
  auto matrix = rcp(new CrsMatrix(graph));
  matrix->resumeFill();
  matrix->setAllToScalar(2.0);
  Teuchos::ArrayView<const int> columns;
  graph->getLocalRowView(3, columns);
  std::vector<double> values(columns.size(), 2.0);
  values[0] = 0.0;
  matrix->replaceLocalValues(3, columns, Teuchos::ArrayView<const double>(values));
  matrix->fillComplete();
  const auto zeros = contessa::solvers::zeroEntryPositions(*matrix);
  ASSERT_EQ(zeros.size(), 1u);
  EXPECT_FALSE(contessa::solvers::anyFilledIn(*matrix, zeros));
  matrix->resumeFill();
  matrix->setAllToScalar(-1e-300);  // tiny is not zero: Tpetra's products skip only exact zeros
  matrix->fillComplete();
  EXPECT_TRUE(contessa::solvers::anyFilledIn(*matrix, zeros));
}

}  // namespace

// A Jacobian on `graph` with every value 1 but the entries of local row `row` on rank `rank`, which are
// 1 + `delta` (a contact row whose penalty or tangent changed by `delta` times its diagonal).
RCP<const Thyra::LinearOpSourceBase<double>> jacobianWithRowChanged(const RCP<const CrsGraph>& graph, int rank,
                                                                    std::size_t row, double delta) {
  auto matrix = uniformMatrix(graph, 1.0);
  matrix->resumeFill();
  if (graph->getComm()->getRank() == rank) {
    auto values = matrix->getLocalMatrixHost().values;
    const auto& rowStart = matrix->getLocalMatrixHost().graph.row_map;
    for (std::size_t k = rowStart(row); k < rowStart(row + 1); ++k) values(k) = 1.0 + delta;
  }
  matrix->fillComplete();  // collective
  return sourceOf(matrix);
}

// With "reuse: type = RAP" MueLu keeps the coarse matrices at a re-set-up: that is allowed while the
// Jacobian differs from the one they were computed from only in rows held at that fresh set-up (rows that
// had changed before: contact rows) and there by at most its diagonal (kCoarseKeptRowChange); a penalty
// that switches on (a change of many diagonals) or a change in a row not held starts over, on every rank.
TEST(PreconditionerReuse, KeptCoarseLevelsServeSmallChangesOfContactRowsAndLargeOnesStartOver) {
  ReuseOnSixRowsPerRank setting;
  auto& [comm, map, recording, factory, prec] = setting;
  auto list = rcp(new Teuchos::ParameterList("MueLu"));
  list->set("reuse: type", std::string("RAP"));
  recording->setParameterList(list);
  const auto graph = bandGraph(map, false);
  const long before = contessa::solvers::GraphKeyedPreconditionerFactory::counts().largeChange;
  const auto setUp = [&](const RCP<const Thyra::LinearOpSourceBase<double>>& jacobian) {
    factory.initializePrec(jacobian, prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  };
  setUp(jacobianWithRowChanged(graph, 0, 2, 0.0));
  EXPECT_EQ(recording->uninitializations, 1);
  setUp(jacobianWithRowChanged(graph, 0, 2, 0.5));  // no row held yet: the first change starts over
  EXPECT_EQ(recording->uninitializations, 2);
  setUp(jacobianWithRowChanged(graph, 0, 2, 0.9));  // 0.4 of the smaller diagonal: coarse levels kept
  setUp(jacobianWithRowChanged(graph, 0, 2, 1.4));  // 0.9 from the set-up's 1.5: still kept
  EXPECT_EQ(recording->uninitializations, 2);
  EXPECT_EQ(recording->initializations, 4);
  setUp(jacobianWithRowChanged(graph, 0, 2, 100.0));  // a penalty switched on, on rank 0 only: every rank starts over
  EXPECT_EQ(recording->uninitializations, 3);
  setUp(jacobianWithRowChanged(graph, 0, 2, 0.5));  // and off again: 100 of the smaller diagonal
  EXPECT_EQ(recording->uninitializations, 4);
  const auto other = uniformMatrix(graph, 1.0);  // row 2 back to the set-up's values, row 4 changed a little
  other->resumeFill();
  {
    auto values = other->getLocalMatrixHost().values;
    const auto& rowStart = other->getLocalMatrixHost().graph.row_map;
    values(rowStart(4)) = 1.01;
  }
  other->fillComplete();
  setUp(sourceOf(other));
  EXPECT_EQ(recording->uninitializations, 5) << "a row not held at the set-up has no reference to compare with";
  EXPECT_EQ(contessa::solvers::GraphKeyedPreconditionerFactory::counts().largeChange, before + 4);

  // The measure itself: the largest change over the changed rows, relative to the smaller diagonal.
  const auto a = uniformMatrix(graph, 2.0);
  contessa::solvers::RowValues held;
  std::vector<char> rows(6, 0);
  rows[1] = 1;
  held.hold(*a, rows, contessa::solvers::rowValueHashes(*a));
  EXPECT_EQ(held.largestChange(*a, contessa::solvers::rowValueHashes(*a)), 0.0);
  const auto b = uniformMatrix(graph, 2.0);
  b->resumeFill();
  {
    auto values = b->getLocalMatrixHost().values;
    const auto& rowStart = b->getLocalMatrixHost().graph.row_map;
    for (std::size_t k = rowStart(1); k < rowStart(2); ++k) values(k) = 3.0;  // diagonal 2 -> 3, change 1
  }
  b->fillComplete();
  EXPECT_DOUBLE_EQ(held.largestChange(*b, contessa::solvers::rowValueHashes(*b)), 0.5);
  const auto c = uniformMatrix(graph, 3.0);
  EXPECT_TRUE(std::isinf(held.largestChange(*c, contessa::solvers::rowValueHashes(*c)))) << "rows not held";
}

// Without the deck's "reuse: type" the wrapper chooses it per hierarchy: "RAP" while few rows changed
// between set-ups, "RP" once more than kCoarseKeptRowFraction of them did (a nonlinear solid), so that such a
// Jacobian does not start the hierarchy over at every Newton iteration.
TEST(PreconditionerReuse, ReuseTypeChosenFromTheShareOfRowsThatChange) {
  RCP<const Teuchos::Comm<int>> comm = Tpetra::getDefaultComm();
  RCP<const Map> map = rcp(new Map(static_cast<Tpetra::global_size_t>(6 * comm->getSize()), 6, 0, comm));
  auto recording = rcp(new RecordingFactory());
  auto list = rcp(new Teuchos::ParameterList("MueLu"));
  list->set("reuse: type", std::string("RAP"));
  recording->setParameterList(list);
  contessa::solvers::GraphKeyedPreconditionerFactory factory(recording, true);
  auto prec = factory.createPrec();
  const auto graph = bandGraph(map, false);
  factory.initializePrec(jacobianOn(graph, 1.0), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(list->get<std::string>("reuse: type"), "RAP") << "no row has changed yet";
  factory.initializePrec(jacobianOn(graph, 2.0), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->uninitializations, 2) << "rows not held at the set-up changed";
  EXPECT_EQ(list->get<std::string>("reuse: type"), "RP") << "every row changed";
  for (double scale : {3.0, 4.0}) factory.initializePrec(jacobianOn(graph, scale), prec.get(), Thyra::SUPPORT_SOLVE_UNSPECIFIED);
  EXPECT_EQ(recording->uninitializations, 2) << "an RP hierarchy is re-set-up, not started over";
}
