// DofLayout's matrix graph, built directly in compressed rows (OverlapCouplings::gather, then the owned
// rows, the column map by Tpetra's rule and expertStaticFillComplete), against the graph Tpetra makes of
// the same couplings the way DofLayout made it before: a vector of column lists per overlapped row, an
// overlapped graph by insertion, exported (INSERT) to the owned rows, fillComplete. The same column map
// and the same local rows entry for entry, on a 3D punch (rigid master: the slave rows' own couplings),
// the 3D and 2D blocks sliding on a deformable base (couplings across the bodies) and the 2D tube (rigid
// plate); 1 and 2 ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include <Tpetra_Core.hpp>

#include "deck/DeckReader.hpp"
#include "deck/ProblemDefinition.hpp"
#include "model/ContactAssembly.hpp"
#include "model/DofLayout.hpp"
#include "model/SolidAssembler.hpp"
#include "ModelHarness.hpp"

namespace {

using namespace contessa;
using model::CrsGraph;
using model::LO;
using Teuchos::RCP;
using Teuchos::rcp;

/// What ContactMechanicsModel gathers for the graph: every element's DOFs and the contact couplings.
struct Couplings {
  std::vector<int> elementDofs;
  std::vector<std::size_t> elementBegin;
  std::vector<std::vector<LO>> contactRows;
};

Couplings couplingsOf(const deck::ProblemDefinition& problem, const model::DofLayout& layout) {
  Couplings c;
  model::SolidAssembler solids(problem, [&](mesh::GlobalIndex dof) { return layout.overlapMap()->getLocalElement(dof); });
  solids.assemble(std::vector<double>(layout.numOverlapDofs(), 0.0).data(), false,
                  [&](const int* dofs, int n, const double*, const double*) {
                    c.elementBegin.push_back(c.elementDofs.size());
                    c.elementDofs.insert(c.elementDofs.end(), dofs, dofs + n);
                  });
  c.elementBegin.push_back(c.elementDofs.size());
  c.contactRows.resize(layout.numOverlapDofs());
  model::ContactAssembly(problem, layout).addReservedCouplings(c.contactRows);
  return c;
}

/// Per overlapped row, its columns sorted and unique, by lists (as the model gathered them before).
std::vector<std::vector<LO>> listedRows(const Couplings& c, LO numRows) {
  std::vector<std::vector<LO>> rows(c.contactRows.begin(), c.contactRows.end());
  rows.resize(numRows);
  for (std::size_t e = 0; e + 1 < c.elementBegin.size(); ++e)
    for (std::size_t i = c.elementBegin[e]; i < c.elementBegin[e + 1]; ++i)
      rows[c.elementDofs[i]].insert(rows[c.elementDofs[i]].end(), c.elementDofs.begin() + c.elementBegin[e],
                                    c.elementDofs.begin() + c.elementBegin[e + 1]);
  for (auto& r : rows) {
    std::sort(r.begin(), r.end());
    r.erase(std::unique(r.begin(), r.end()), r.end());
  }
  return rows;
}

/// The owned graph by insertion, export and fillComplete (DofLayout::buildGraph before it built the rows
/// itself).
RCP<const CrsGraph> insertedGraph(const model::DofLayout& layout, const std::vector<std::vector<LO>>& rows) {
  std::size_t maxPerRow = 1;
  for (const auto& r : rows) maxPerRow = std::max(maxPerRow, r.size());
  auto overlapGraph = rcp(new CrsGraph(layout.overlapMap(), layout.overlapMap(), maxPerRow));
  for (LO i = 0; i < layout.numOverlapDofs(); ++i)
    if (!rows[i].empty()) overlapGraph->insertLocalIndices(i, Teuchos::ArrayView<const LO>(rows[i]));
  overlapGraph->fillComplete(layout.ownedMap(), layout.ownedMap());
  model::Vector overlapCounts(layout.overlapMap()), ownedCounts(layout.ownedMap());
  {
    auto c = overlapCounts.getDataNonConst(0);
    for (LO i = 0; i < layout.numOverlapDofs(); ++i) c[i] = static_cast<double>(rows[i].size());
  }
  ownedCounts.doExport(overlapCounts, layout.exporter(), Tpetra::ADD);
  std::vector<std::size_t> perRow;
  for (double c : ownedCounts.getData(0)) perRow.push_back(std::max<std::size_t>(1, static_cast<std::size_t>(c)));
  auto owned = rcp(new CrsGraph(layout.ownedMap(), Teuchos::ArrayView<const std::size_t>(perRow)));
  owned->doExport(*overlapGraph, layout.exporter(), Tpetra::INSERT);
  owned->fillComplete(layout.ownedMap(), layout.ownedMap());
  return owned;
}

template <class View>
std::vector<long long> entries(const View& v) {
  return std::vector<long long>(v.data(), v.data() + v.extent(0));
}

void expectSameGraph(const std::string& deckPath, const std::vector<std::string>& overrides, bool expectContact) {
  auto deck = deck::readDeck(deckPath);
  deck::applyOverrides(*deck, overrides);
  const auto problem = deck::buildProblem(deck->sublist("Problem"), deckPath.substr(0, deckPath.rfind('/')), test::everyRank());
  const auto comm = Tpetra::getDefaultComm();
  model::DofLayout layout(comm, problem.mesh, model::ContactAssembly::surfaceNodes(problem.contacts));
  const Couplings c = couplingsOf(problem, layout);
  const LO numRows = layout.numOverlapDofs();

  // The gathered rows are the lists' rows.
  const auto gathered = model::OverlapCouplings::gather(numRows, c.elementDofs, c.elementBegin, c.contactRows);
  const auto listed = listedRows(c, numRows);
  ASSERT_EQ(gathered.numRows(), numRows);
  std::size_t contactOnly = 0;  // rows with couplings beyond their elements' (the contact's)
  for (LO r = 0; r < numRows; ++r) {
    ASSERT_EQ(std::vector<LO>(gathered.row(r), gathered.row(r) + gathered.rowSize(r)), listed[r]) << "overlapped row " << r;
    if (!c.contactRows[r].empty()) ++contactOnly;
  }
  long long contactRows = static_cast<long long>(contactOnly), anyContact = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &contactRows, &anyContact);
  EXPECT_EQ(anyContact > 0, expectContact) << "contact couplings reserved: " << anyContact;

  // The owned graph: the same maps and local rows as Tpetra's from the lists.
  layout.buildGraph(gathered);
  const auto& built = *layout.ownedGraph();
  const auto reference = insertedGraph(layout, listed);
  ASSERT_TRUE(built.isFillComplete());
  EXPECT_TRUE(built.isSorted());
  EXPECT_TRUE(built.getRowMap()->isSameAs(*reference->getRowMap()));
  EXPECT_TRUE(built.getDomainMap()->isSameAs(*reference->getDomainMap()));
  EXPECT_TRUE(built.getRangeMap()->isSameAs(*reference->getRangeMap()));
  const auto builtColumns = built.getColMap()->getNodeElementList();
  const auto referenceColumns = reference->getColMap()->getNodeElementList();
  EXPECT_EQ(std::vector<long long>(builtColumns.begin(), builtColumns.end()),
            std::vector<long long>(referenceColumns.begin(), referenceColumns.end()));
  const auto a = built.getLocalGraphHost(), b = reference->getLocalGraphHost();
  EXPECT_EQ(entries(a.row_map), entries(b.row_map));
  EXPECT_EQ(entries(a.entries), entries(b.entries));
  EXPECT_EQ(built.getGlobalNumEntries(), reference->getGlobalNumEntries());
  EXPECT_EQ(built.getGlobalMaxNumRowEntries(), reference->getGlobalMaxNumRowEntries());
  EXPECT_EQ(built.getImporter().is_null(), reference->getImporter().is_null());
  if (comm->getSize() > 1) {
    EXPECT_FALSE(built.getImporter().is_null());  // two ranks share rows: the column map reaches the other's
  }
  // A second build (a rebuild) makes a new graph object of the same entries.
  const auto first = layout.ownedGraph();
  layout.buildGraph(gathered);
  EXPECT_NE(first.get(), layout.ownedGraph().get());
  EXPECT_EQ(entries(layout.ownedGraph()->getLocalGraphHost().entries), entries(b.entries));
}

// A rigid master reserves no couplings: the element rows alone.
TEST(DofLayoutGraph, PunchWithARigidMasterIsTpetrasGraph) {
  expectSameGraph(CONTESSA_INPUTS "/punch_3d.xml",
                  {"Problem/Mesh/Elements X=6", "Problem/Mesh/Elements Y=6", "Problem/Mesh/Elements Z=3"}, false);
}

TEST(DofLayoutGraph, BlockSlidingOnADeformableBaseIsTpetrasGraph) {
  expectSameGraph(CONTESSA_TESTS "/regression/contact_graph/sliding_block_3d.xml", {}, true);
}

TEST(DofLayoutGraph, TwoDimensionalBlockSlidingOnADeformableBaseIsTpetrasGraph) {
  expectSameGraph(CONTESSA_TESTS "/regression/contact_graph/sliding_block.xml", {}, true);
}

TEST(DofLayoutGraph, TwoDimensionalTubeIsTpetrasGraph) {
  expectSameGraph(CONTESSA_INPUTS "/tube_bending.xml",
                  {"Problem/Mesh/Elements Through Thickness=4", "Problem/Mesh/Elements Around Arc=30"}, false);
}

// Contact couplings given in any order and repeated, and a row no element holds, come out sorted, once.
TEST(DofLayoutGraph, GatherTakesEachColumnOncePerRowSorted) {
  const std::vector<int> elementDofs = {0, 1, 2, 2, 1, 3};
  const std::vector<std::size_t> elementBegin = {0, 3, 6};
  std::vector<std::vector<LO>> extra(5);
  extra[0] = {4, 2, 4};
  extra[4] = {3, 0, 3};
  const auto g = model::OverlapCouplings::gather(5, elementDofs, elementBegin, extra);
  const std::vector<std::vector<LO>> expected = {{0, 1, 2, 4}, {0, 1, 2, 3}, {0, 1, 2, 3}, {1, 2, 3}, {0, 3}};
  ASSERT_EQ(g.numRows(), 5);
  for (LO r = 0; r < 5; ++r) EXPECT_EQ(std::vector<LO>(g.row(r), g.row(r) + g.rowSize(r)), expected[r]) << "row " << r;
}

}  // namespace
