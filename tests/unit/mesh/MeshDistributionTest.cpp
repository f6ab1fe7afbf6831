// Distributed meshes over real MPI ranks (run on 1, 2 and 3 ranks): parts generated alone agree on
// node ownership across ranks; a mesh read once on rank 0 (an Exodus file) arrives at every rank as
// the part the replicated path would give it; a failed read fails on every rank; contact surfaces
// gathered from the parts equal the replicated mesh's.
#include <gtest/gtest.h>
#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <climits>
#include <cstdio>
#include <functional>

#include "common/Error.hpp"
#include "contact/ContactSurface.hpp"
#include "io/DecomposedMesh.hpp"
#include "io/ExodusWriter.hpp"
#include "mesh/DecomposedExodusReader.hpp"
#include "mesh/ExodusMeshReader.hpp"
#include "mesh/Generators.hpp"
#include "mesh/MeshDistribution.hpp"
#include "mesh/MeshFactory.hpp"
#include "mesh/MeshJoin.hpp"
#include "mesh/MeshMerge.hpp"
#include "mesh/Partition.hpp"
#include "MeshTestSupport.hpp"
#include "DistributedMeshChecks.hpp"

using namespace contessa::mesh;
using contessa::mesh::test::expectSameMesh;
using contessa::mesh::test::expectSameParts;

namespace {

int rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

int ranks() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}

// A rank's part made alone (generated or extracted: on MPI_COMM_SELF) placed on every rank's, as
// MeshFactory places the parts it makes.
DistributedMesh onWorld(DistributedMesh part) {
  part.comm = MPI_COMM_WORLD;
  return part;
}

// Every rank holding a node gives it the same owner, the owner holds it, and the owned nodes of all
// ranks are the mesh's nodes, each once.
void expectConsistentOwnership(const DistributedMesh& part) {
  const auto numNodes = static_cast<std::size_t>(part.numGlobalNodes);
  std::vector<int> lowest(numNodes, INT_MAX), highest(numNodes, -1), owners(numNodes, 0);
  for (std::size_t n = 0; n < part.nodeOwner.size(); ++n) {
    const auto g = static_cast<std::size_t>(part.part.globalNodes[n]);
    lowest[g] = highest[g] = part.nodeOwner[n];
    if (part.nodeOwner[n] == part.rank) owners[g] = 1;
  }
  MPI_Allreduce(MPI_IN_PLACE, lowest.data(), static_cast<int>(numNodes), MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, highest.data(), static_cast<int>(numNodes), MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Allreduce(MPI_IN_PLACE, owners.data(), static_cast<int>(numNodes), MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  for (std::size_t g = 0; g < numNodes; ++g) {
    EXPECT_EQ(lowest[g], highest[g]) << "ranks disagree on the owner of node " << g;
    EXPECT_EQ(owners[g], 1) << "node " << g << " owned by " << owners[g] << " ranks";
  }
  // The ranks listed as sharing a node hold it: the sum of the holders' counts is consistent.
  std::vector<int> holders(numNodes, 0), listed(numNodes, 0);
  for (std::size_t n = 0; n < part.nodeOwner.size(); ++n) {
    holders[part.part.globalNodes[n]] = 1;
    listed[part.part.globalNodes[n]] = static_cast<int>(part.part.sharedWith[n].size()) + 1;
  }
  MPI_Allreduce(MPI_IN_PLACE, holders.data(), static_cast<int>(numNodes), MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  for (std::size_t n = 0; n < part.nodeOwner.size(); ++n)
    EXPECT_EQ(listed[part.part.globalNodes[n]], holders[part.part.globalNodes[n]]);
}

void expectSameSurface(const ReplicatedSurface& a, const ReplicatedSurface& b) {
  using S = ReplicatedSurface;
  contessa::mesh::test::expectSameMembers(a, b, &S::name, &S::dimension, &S::nodesPerFacet, &S::elements, &S::sides,
                                          &S::facetNodes, &S::nodes, &S::coordinates);
}

// Two boxes one above the other (two blocks), maybe with the upper one's bottom side set listed
// backwards: a file's side sets need not be in element order.
Mesh twoBodies(bool reversedSideSet = true) {
  const BoxSpec lower = test_support::boxSpec(4, 2, 3);
  BoxSpec upper = test_support::boxSpec(3, 2, 2, 1, 1, 1, 0, 1);
  upper.biasX = 2;
  Mesh mesh = mergeMeshes({{"lower", generateBox(lower)}, {"upper", generateBox(upper)}});
  for (auto& set : mesh.sideSets)
    if (set.name == "upper_bottom" && reversedSideSet) {
      std::reverse(set.elements.begin(), set.elements.end());
      std::reverse(set.sides.begin(), set.sides.end());
    }
  return mesh;
}

std::string sharedPath(const std::string& stem) {
  // One name for all ranks: rank 0's process id, broadcast.
  long long pid = getpid();
  MPI_Bcast(&pid, 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  return ::testing::TempDir() + "contessa_" + info->name() + "_" + stem + "_" + std::to_string(pid) + ".exo";
}

}  // namespace

TEST(MeshDistribution, GeneratedPartsAgreeOnOwnershipAcrossRanks) {
  BoxSpec box = test_support::boxSpec(5, 3, 4);
  const DistributedMesh part = onWorld(generateBoxPart(box, rank(), ranks()));
  const Mesh whole = generateBox(box);
  expectSameParts(part, PartExtractor(whole, GridPartition(5, 3, 4, ranks()).owners(), ranks()).part(rank()));
  expectConsistentOwnership(part);

  RectangleSpec rectangle;
  rectangle.nx = 7;
  rectangle.ny = 2;
  expectConsistentOwnership(onWorld(generateRectanglePart(rectangle, rank(), ranks())));

  const SphereOctantSpec octant = test_support::octantSpec(3, 2);
  const Mesh ball = generateSphereOctant(octant);
  const DistributedMesh octantPart = onWorld(generateSphereOctantPart(octant, rank(), ranks()));
  expectSameParts(octantPart,
                  PartExtractor(ball, ElementRanges{ball.numElements(), ranks()}.owners(), ranks()).part(rank()));
  expectConsistentOwnership(octantPart);
  for (const auto& set : ball.sideSets)
    expectSameSurface(gatherSurface(octantPart, set.name), surfaceOfSideSet(ball, set.name));
}

TEST(MeshDistribution, AnExodusFileReadOnRankZeroArrivesAsTheReplicatedPathsParts) {
  const Mesh mesh = twoBodies();
  const std::string path = sharedPath("two_bodies");
  if (rank() == 0) contessa::io::ExodusWriter(path, mesh, {});
  MPI_Barrier(MPI_COMM_WORLD);
  int reads = 0;
  const DistributedMesh part = distributeMesh(MPI_COMM_WORLD, [&] {
    ++reads;
    return readExodusMesh(path);
  });
  EXPECT_EQ(reads, rank() == 0 ? 1 : 0);  // only rank 0 touched the file
  // Today's path: every rank reads the file and partitions it alike (METIS).
  const Mesh replicated = readExodusMesh(path);
  const Partition partition = partitionMesh(replicated, ranks());
  expectSameParts(part, PartExtractor(replicated, partition.elementOwner, ranks()).part(rank()));
  EXPECT_EQ(part.ownedNodes(), partition.ownedNodes(rank()));
  expectConsistentOwnership(part);
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank() == 0) std::remove(path.c_str());
}

TEST(MeshDistribution, AFailedReadOnRankZeroIsTheSameInputErrorOnEveryRank) {
  const std::string path = "/nonexistent/dir/mesh.exo";
  try {
    distributeMesh(MPI_COMM_WORLD, [&] { return readExodusMesh(path); });
    FAIL() << "expected an InputError";
  } catch (const contessa::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(path, 0), 0u) << e.what();
  }
  // The ranks are still in step: a collective after the failure completes.
  int one = 1, sum = 0;
  MPI_Allreduce(&one, &sum, 1, MPI_INT, MPI_SUM, MPI_COMM_WORLD);
  EXPECT_EQ(sum, ranks());
}

TEST(MeshDistribution, TooManyRanksForTheMeshIsAnInputErrorOnEveryRank) {
  if (ranks() == 1) GTEST_SKIP() << "needs 2 ranks";
  RectangleSpec one;  // one element
  EXPECT_THROW(distributeMesh(MPI_COMM_WORLD, [&] { return generateRectangle(one); }), contessa::InputError);
}

TEST(MeshDistribution, GatheredSurfacesAreTheReplicatedMeshs) {
  const Mesh mesh = twoBodies();
  const DistributedMesh part = distributeMesh(MPI_COMM_WORLD, [&] { return mesh; });
  for (const auto& set : mesh.sideSets) expectSameSurface(gatherSurface(part, set.name), surfaceOfSideSet(mesh, set.name));

  const HollowCylinderSectorSpec tube = test_support::tubeSpec(2, 6, 2);
  const Mesh whole = generateHollowCylinderSector(tube);
  const DistributedMesh generated = onWorld(generateHollowCylinderSectorPart(tube, rank(), ranks()));
  for (const auto& set : whole.sideSets)
    expectSameSurface(gatherSurface(generated, set.name), surfaceOfSideSet(whole, set.name));
}

// Contact's view of a side set (slave nodes, tributary areas, facet sizes, master facets) built from the
// surface gathered from the parts is the one built from the replicated mesh, bit for bit.
TEST(MeshDistribution, ContactSurfacesFromGatheredFacetsAreTheReplicatedOnes) {
  RectangleSpec rectangle;
  rectangle.nx = 6;
  rectangle.ny = 2;
  rectangle.biasX = 3;
  for (const Mesh& mesh : {twoBodies(), generateRectangle(rectangle)}) {
    const DistributedMesh part = distributeMesh(MPI_COMM_WORLD, [&] { return mesh; });
    for (const auto& set : mesh.sideSets) {
      const auto expected = contessa::contact::ContactSurface::fromSideSet(mesh, set, "test");
      const auto gathered = contessa::contact::ContactSurface::fromSurface(gatherSurface(part, set.name), "test");
      EXPECT_EQ(gathered.nodesPerFacet, expected.nodesPerFacet);
      EXPECT_EQ(gathered.nodes, expected.nodes);
      EXPECT_EQ(gathered.areas, expected.areas);
      EXPECT_EQ(gathered.facetLengths, expected.facetLengths);
      EXPECT_EQ(gathered.facets, expected.facets);
    }
  }
}

TEST(MeshDistribution, ASurfaceHoldsItsFacetsNodesAndCoordinates) {
  BoxSpec box = test_support::boxSpec(3, 2, 4, 1, 2.5);
  const ReplicatedSurface top = surfaceOfSideSet(generateBox(box), "top");
  EXPECT_EQ(top.nodesPerFacet, 4);
  EXPECT_EQ(top.elements.size(), 12u);
  EXPECT_EQ(top.nodes.size(), 20u);  // (3 + 1) × (4 + 1)
  for (std::size_t n = 0; n < top.nodes.size(); ++n) EXPECT_EQ(top.coordinates[3 * n + 1], 2.5);
}

TEST(MeshDistribution, AnUnknownSideSetIsAnInputErrorNamingTheKnownOnes) {
  BoxSpec box;
  box.nx = 3;
  const DistributedMesh part = onWorld(generateBoxPart(box, rank(), ranks()));
  try {
    gatherSurface(part, "nowhere");
    FAIL() << "expected an InputError";
  } catch (const contessa::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nowhere"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("top"), std::string::npos) << e.what();
  }
}

namespace {

// This rank's file of `part`'s set, as the per-rank output writes it (Nemesis records, id maps);
// `processors` as written in the file.
void writeDecomposedFile(const std::string& base, const DistributedMesh& part, int processors) {
  contessa::io::ExodusDecomposition d = contessa::io::decompositionOf(part);
  d.processors = processors;
  contessa::io::ExodusWriter(decomposedFileName(base, part.numRanks, part.rank), part.local(), {}, {}, {}, &d);
}

// `part` with its local nodes listed backwards (decomp tools need not number them in global order).
DistributedMesh nodesReversed(DistributedMesh part) {
  const std::size_t n = part.part.globalNodes.size();
  const int dim = part.local().dimension;
  Mesh& mesh = part.part.mesh;
  std::vector<double> coordinates(mesh.coordinates.size());
  for (std::size_t k = 0; k < n; ++k)
    std::copy(mesh.coordinates.begin() + k * dim, mesh.coordinates.begin() + (k + 1) * dim,
              coordinates.begin() + (n - 1 - k) * dim);
  mesh.coordinates = coordinates;
  for (auto& b : mesh.blocks)
    for (GlobalIndex& node : b.connectivity) node = static_cast<GlobalIndex>(n - 1) - node;
  for (auto& set : mesh.nodeSets) {
    for (GlobalIndex& node : set.nodes) node = static_cast<GlobalIndex>(n - 1) - node;
    std::reverse(set.nodes.begin(), set.nodes.end());
  }
  std::reverse(part.part.globalNodes.begin(), part.part.globalNodes.end());
  std::reverse(part.part.sharedWith.begin(), part.part.sharedWith.end());
  return part;
}

void removeDecomposedFile(const std::string& base) {
  MPI_Barrier(MPI_COMM_WORLD);
  std::remove(decomposedFileName(base, ranks(), rank()).c_str());
}

}  // namespace

TEST(DecomposedExodus, FileNamesPadTheRankToTheDigitsOfTheCount) {
  EXPECT_EQ(decomposedFileName("a.exo", 4, 3), "a.exo.4.3");
  EXPECT_EQ(decomposedFileName("a.exo", 12, 3), "a.exo.12.03");
  EXPECT_EQ(decomposedFileName("a.exo", 100, 7), "a.exo.100.007");
}

TEST(DecomposedExodus, EachRankReadsItsOwnFileAndGetsTheReplicatedPathsPart) {
  const Mesh mesh = twoBodies(false);  // side sets in element order: the order a file set can give back
  const Partition partition = partitionMesh(mesh, ranks());
  const DistributedMesh expected = PartExtractor(mesh, partition.elementOwner, ranks()).part(rank());
  const std::string base = sharedPath("split");
  writeDecomposedFile(base, expected, ranks());
  MPI_Barrier(MPI_COMM_WORLD);
  const DistributedMesh part = readDecomposedExodus(base, MPI_COMM_WORLD);
  expectSameParts(part, expected);
  expectConsistentOwnership(part);
  for (const auto& set : mesh.sideSets) expectSameSurface(gatherSurface(part, set.name), surfaceOfSideSet(mesh, set.name));
  removeDecomposedFile(base);

  // Nodes not in global order in the file: renumbered on reading, the same part.
  writeDecomposedFile(base, nodesReversed(expected), ranks());
  MPI_Barrier(MPI_COMM_WORLD);
  expectSameParts(readDecomposedExodus(base, MPI_COMM_WORLD), expected);
  removeDecomposedFile(base);
}

TEST(DecomposedExodus, AMissingFileIsAnInputErrorNamingItOnEveryRank) {
  const std::string base = sharedPath("absent");
  try {
    readDecomposedExodus(base, MPI_COMM_WORLD);
    FAIL() << "expected an InputError";
  } catch (const contessa::InputError& e) {
    // Every rank reports rank 0's file: the lowest failing rank speaks for all.
    EXPECT_EQ(std::string(e.what()).rfind(decomposedFileName(base, ranks(), 0), 0), 0u) << e.what();
  }
}

TEST(DecomposedExodus, ASetSplitForAnotherRankCountIsAnInputErrorOnEveryRank) {
  BoxSpec box;
  box.nx = 3;
  const DistributedMesh part = onWorld(generateBoxPart(box, rank(), ranks()));
  const std::string base = sharedPath("other_count");
  writeDecomposedFile(base, part, ranks() + 1);
  MPI_Barrier(MPI_COMM_WORLD);
  try {
    readDecomposedExodus(base, MPI_COMM_WORLD);
    FAIL() << "expected an InputError";
  } catch (const contessa::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("split for " + std::to_string(ranks() + 1) + " ranks; the run has " +
                                         std::to_string(ranks())),
              std::string::npos)
        << e.what();
  }
  removeDecomposedFile(base);
}

TEST(DecomposedExodus, AnUndecomposedFileIsAnInputErrorSayingSo) {
  BoxSpec box;
  box.nx = 3;
  const std::string base = sharedPath("plain");
  contessa::io::ExodusWriter(decomposedFileName(base, ranks(), rank()), generateBox(box), {});
  MPI_Barrier(MPI_COMM_WORLD);
  try {
    readDecomposedExodus(base, MPI_COMM_WORLD);
    FAIL() << "expected an InputError";
  } catch (const contessa::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a file of a decomposed mesh"), std::string::npos) << e.what();
  }
  removeDecomposedFile(base);
}

TEST(MeshFactoryPart, EveryGeneratorsPartIsThePartOfItsWholeMesh) {
  for (const std::string& type :
       {std::string("Rectangle"), std::string("Annulus Sector"), std::string("Box"),
        std::string("Hollow Cylinder Sector"), std::string("Sphere Octant")}) {
    SCOPED_TRACE(type);
    Teuchos::ParameterList list = *MeshFactory::validParameters(type);
    if (type == "Rectangle" || type == "Box") {
      list.set("Elements X", 4);
      list.set("Elements Y", 3);
      if (type == "Box") list.set("Elements Z", 2);
    }
    if (type == "Annulus Sector" || type == "Hollow Cylinder Sector") list.set("Elements Around Arc", 7);
    const Mesh whole = MeshFactory::create(type, list, "Problem/Mesh", "", MPI_COMM_WORLD);
    const DistributedMesh part = MeshFactory::createPart(type, list, "Problem/Mesh", "", MPI_COMM_WORLD);
    // The element owners the parts chose (every rank's elements, all-gathered): the extraction under
    // them from the whole mesh must give this rank's part exactly.
    std::vector<GlobalIndex> mine;
    for (GlobalIndex e : part.part.globalElements) mine.insert(mine.end(), {e, static_cast<GlobalIndex>(rank())});
    const auto all = allGather(MPI_COMM_WORLD, mine);
    std::vector<int> owners(static_cast<std::size_t>(whole.numElements()), -1);
    for (std::size_t k = 0; k < all.size(); k += 2) owners[static_cast<std::size_t>(all[k])] = static_cast<int>(all[k + 1]);
    ASSERT_EQ(std::count(owners.begin(), owners.end(), -1), 0) << "an element in no part";
    expectSameParts(part, PartExtractor(whole, owners, ranks()).part(rank()));
  }
}

TEST(MeshFactoryPart, AMeshFileIsReadOnRankZeroAndPartitionedByMetis) {
  const Mesh mesh = twoBodies();
  const std::string path = sharedPath("factory");
  if (rank() == 0) contessa::io::ExodusWriter(path, mesh, {});
  MPI_Barrier(MPI_COMM_WORLD);
  Teuchos::ParameterList list = *MeshFactory::validParameters("Mesh File");
  list.set("File Name", path);
  const DistributedMesh part = MeshFactory::createPart("Mesh File", list, "Problem/Mesh", "", MPI_COMM_WORLD);
  const Mesh replicated = MeshFactory::create("Mesh File", list, "Problem/Mesh", "", MPI_COMM_WORLD);
  expectSameParts(part, PartExtractor(replicated, partitionMesh(replicated, ranks()).elementOwner, ranks()).part(rank()));
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank() == 0) std::remove(path.c_str());
}

TEST(MeshFactoryPart, AGmshFileIsReadOnRankZeroAndPartitionedByMetis) {
  Teuchos::ParameterList list = *MeshFactory::validParameters("Gmsh File");
  list.set("File Name", std::string(CONTESSA_TEST_MESHES "/two_blocks.msh"));
  const DistributedMesh part = MeshFactory::createPart("Gmsh File", list, "Problem/Mesh", "", MPI_COMM_WORLD);
  const Mesh replicated = MeshFactory::create("Gmsh File", list, "Problem/Mesh", "", MPI_COMM_WORLD);
  expectSameParts(part, PartExtractor(replicated, partitionMesh(replicated, ranks()).elementOwner, ranks()).part(rank()));
  expectConsistentOwnership(part);
}

TEST(MeshFactoryPart, AMissingMeshFileIsTheDeckErrorOnEveryRank) {
  Teuchos::ParameterList list = *MeshFactory::validParameters("Exodus File");
  list.set("File Name", std::string("no_such_mesh.exo"));
  try {
    MeshFactory::createPart("Exodus File", list, "Problem/Mesh", "/nonexistent", MPI_COMM_WORLD);
    FAIL() << "expected an InputError";
  } catch (const contessa::InputError& e) {
    EXPECT_EQ(std::string(e.what()), "Problem/Mesh/File Name: mesh file '/nonexistent/no_such_mesh.exo' does not exist");
  }
}

TEST(MeshFactoryPart, AGeneratorsErrorNamesTheDeckParameterOnEveryRank) {
  Teuchos::ParameterList list = *MeshFactory::validParameters("Annulus Sector");
  list.set("End Angle", -10.0);
  try {
    MeshFactory::createPart("Annulus Sector", list, "Problem/Mesh", "", MPI_COMM_WORLD);
    FAIL() << "expected an InputError";
  } catch (const contessa::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("Problem/Mesh/End Angle: expected an angle greater than Start Angle", 0), 0u)
        << e.what();
  }
}

namespace {

// A whole set base.numFiles.r of `mesh` (METIS parts, maybe with their nodes listed backwards), written
// by rank 0 alone as a decomposition tool would; and removed again.
void writeSetOnRankZero(const std::string& base, const Mesh& mesh, int numFiles, bool reversed = false) {
  if (rank() == 0) {
    const PartExtractor extractor(mesh, partitionMesh(mesh, numFiles).elementOwner, numFiles);
    for (int r = 0; r < numFiles; ++r)
      writeDecomposedFile(base, reversed ? nodesReversed(extractor.part(r)) : extractor.part(r), numFiles);
  }
  MPI_Barrier(MPI_COMM_WORLD);
}

void removeSetOnRankZero(const std::string& base, int numFiles) {
  MPI_Barrier(MPI_COMM_WORLD);
  if (rank() == 0)
    for (int r = 0; r < numFiles; ++r) std::remove(decomposedFileName(base, numFiles, r).c_str());
}

// The deck's Exodus File list for a per-rank set at `base`, named relative to the deck's directory.
struct PerRankDeck {
  Teuchos::ParameterList list;
  std::string directory;
};

PerRankDeck perRankDeck(const std::string& base) {
  PerRankDeck deck{*MeshFactory::validParameters("Exodus File"), base.substr(0, base.rfind('/'))};
  deck.list.set("Layout", std::string("Per Rank"));
  deck.list.set("File Name", base.substr(base.rfind('/') + 1));
  return deck;
}

std::string inputErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const contessa::InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

}  // namespace

TEST(MeshFactoryPart, APerRankSetIsReadByEachRankFromItsOwnFile) {
  const Mesh mesh = twoBodies(false);
  const DistributedMesh expected = PartExtractor(mesh, partitionMesh(mesh, ranks()).elementOwner, ranks()).part(rank());
  const std::string base = sharedPath("per_rank");
  writeDecomposedFile(base, expected, ranks());
  MPI_Barrier(MPI_COMM_WORLD);
  const PerRankDeck deck = perRankDeck(base);
  const DistributedMesh part = MeshFactory::createPart("Exodus File", deck.list, "Problem/Mesh", deck.directory, MPI_COMM_WORLD);
  expectSameParts(part, expected);
  expectConsistentOwnership(part);
  // The whole mesh of the same deck: the set of the run's rank count, joined.
  expectSameMesh(MeshFactory::create("Exodus File", deck.list, "Problem/Mesh", deck.directory, MPI_COMM_WORLD), mesh);
  removeDecomposedFile(base);
}

TEST(MeshFactory, APerRankSetIsJoinedIntoTheWholeMeshItWasSplitFrom) {
  const Mesh mesh = twoBodies(false);  // side sets in element order, as joining gives them back
  for (bool reversed : {false, true}) {
    SCOPED_TRACE(reversed ? "nodes listed backwards in the files" : "nodes in global order");
    const std::string base = sharedPath(reversed ? "join_reversed" : "join");
    writeSetOnRankZero(base, mesh, 3, reversed);  // the only set present: joined whatever the rank count
    const PerRankDeck deck = perRankDeck(base);
    expectSameMesh(MeshFactory::create("Exodus File", deck.list, "Problem/Mesh", deck.directory, MPI_COMM_WORLD), mesh);
    removeSetOnRankZero(base, 3);
  }
  // A generated 2D mesh, split in 4.
  RectangleSpec rectangle;
  rectangle.nx = 5;
  rectangle.ny = 3;
  rectangle.biasX = 1.5;
  const Mesh flat = generateRectangle(rectangle);
  const std::string base = sharedPath("join_2d");
  writeSetOnRankZero(base, flat, 4);
  EXPECT_EQ(decomposedFileSets(base), std::vector<int>{4});
  expectSameMesh(joinDecomposedExodus(base, 4), flat);
  removeSetOnRankZero(base, 4);
}

TEST(MeshFactoryPart, AMissingPerRankFileIsOneLineNamingItAndTheRankCountOnEveryRank) {
  const std::string base = sharedPath("absent");
  const PerRankDeck deck = perRankDeck(base);
  const std::string reads = "(Layout = Per Rank on " + std::to_string(ranks()) + (ranks() == 1 ? " rank" : " ranks") + " reads " + decomposedFileName(base, ranks(), 0) +
                            (ranks() > 1 ? " to " + decomposedFileName(base, ranks(), ranks() - 1) : "") + "; ";
  auto readPart = [&] { MeshFactory::createPart("Exodus File", deck.list, "Problem/Mesh", deck.directory, MPI_COMM_WORLD); };
  EXPECT_EQ(inputErrorOf(readPart), "Problem/Mesh/File Name: per-rank mesh file '" +
                                        decomposedFileName(base, ranks(), 0) + "' does not exist " + reads +
                                        "none found)");
  MPI_Barrier(MPI_COMM_WORLD);

  // A set split for another rank count: said so.
  writeSetOnRankZero(base, twoBodies(false), ranks() + 1);
  EXPECT_EQ(inputErrorOf(readPart), "Problem/Mesh/File Name: per-rank mesh file '" +
                                        decomposedFileName(base, ranks(), 0) + "' does not exist " + reads +
                                        "found: the set for " + std::to_string(ranks() + 1) + " ranks)");
  removeSetOnRankZero(base, ranks() + 1);

  // Only rank 0's file of the run's set: the last rank's file is named, on every rank.
  if (ranks() > 1) {
    const Mesh mesh = twoBodies(false);
    if (rank() == 0)
      writeDecomposedFile(base, PartExtractor(mesh, partitionMesh(mesh, ranks()).elementOwner, ranks()).part(0), ranks());
    MPI_Barrier(MPI_COMM_WORLD);
    const std::string message = inputErrorOf(readPart);
    EXPECT_EQ(message.rfind("Problem/Mesh/File Name: per-rank mesh file '" + decomposedFileName(base, ranks(), 1) +
                                "' does not exist " + reads,
                            0),
              0u)
        << message;
    MPI_Barrier(MPI_COMM_WORLD);
    if (rank() == 0) std::remove(decomposedFileName(base, ranks(), 0).c_str());
  }
}

TEST(MeshFactory, APerRankSetToJoinMustBeTheRunsOrTheOnlyOne) {
  const std::string base = sharedPath("which_set");
  const PerRankDeck deck = perRankDeck(base);
  auto join = [&] { MeshFactory::create("Exodus File", deck.list, "Problem/Mesh", deck.directory, MPI_COMM_WORLD); };
  const std::string needs = "Problem/Mesh/File Name: Layout = Per Rank needs one set " + base + ".N.r to join into the whole mesh (";
  EXPECT_EQ(inputErrorOf(join), needs + "none found)");
  MPI_Barrier(MPI_COMM_WORLD);  // every rank looked before rank 0 writes
  const Mesh mesh = twoBodies(false);
  writeSetOnRankZero(base, mesh, ranks() + 1);
  writeSetOnRankZero(base, mesh, ranks() + 2);
  EXPECT_EQ(inputErrorOf(join), needs + "found: the sets for " + std::to_string(ranks() + 1) + ", " +
                                    std::to_string(ranks() + 2) + " ranks)");
  removeSetOnRankZero(base, ranks() + 1);
  removeSetOnRankZero(base, ranks() + 2);
}

TEST(MeshJoiner, PartsWithTheirSideSetPositionsJoinIntoTheWholeMeshInItsOrder) {
  // A side set listed backwards in the whole mesh: the parts' positions put it back in that order.
  const Mesh mesh = twoBodies(true);
  for (int numParts : {1, 2, 3}) {
    SCOPED_TRACE(std::to_string(numParts) + " parts");
    const PartExtractor extractor(mesh, partitionMesh(mesh, numParts).elementOwner, numParts);
    MeshJoiner joiner;
    for (int r = numParts - 1; r >= 0; --r) joiner.add(extractor.part(r), "part " + std::to_string(r));
    expectSameMesh(joiner.finish("parts"), mesh);
  }
}

TEST(MeshFactory, FilesOfASetListingOtherBlocksAreRefusedNamingTheFile) {
  // A set of 2 whose second file names its first block otherwise (a file from another split).
  const Mesh mesh = twoBodies(false);
  const std::string base = sharedPath("mixed");
  if (rank() == 0) {
    const PartExtractor extractor(mesh, partitionMesh(mesh, 2).elementOwner, 2);
    DistributedMesh second = extractor.part(1);
    second.part.mesh.blocks[0].name = "other";
    writeDecomposedFile(base, extractor.part(0), 2);
    writeDecomposedFile(base, second, 2);
  }
  MPI_Barrier(MPI_COMM_WORLD);
  EXPECT_EQ(inputErrorOf([&] { joinDecomposedExodus(base, 2); }),
            decomposedFileName(base, 2, 1) + ": its dimension, element blocks, node sets or side sets differ from those "
                                             "of the first part (the parts of a mesh list the same)");
  // Read as parts on 2 ranks: every rank says so.
  if (ranks() == 2) {
    EXPECT_EQ(inputErrorOf([&] { readDecomposedExodus(base, MPI_COMM_WORLD); }),
              decomposedFileName(base, 2, 0) + " ...: the files of the set list different element blocks, node sets or "
                                               "side sets (names and order must agree)");
  }
  removeSetOnRankZero(base, 2);
}

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  // Only rank 0 reports, so a run on several ranks prints one result.
  if (rank() != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int result = RUN_ALL_TESTS();
  // A failure on any rank fails the run.
  int worst = result;
  MPI_Allreduce(&result, &worst, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
  return worst;
}

// The single-file output's view: the parts gathered on rank 0 are the whole mesh again (coordinates,
// blocks, node sets, side sets in their order), for generated parts and for a file's METIS parts.
TEST(MeshDistribution, PartsGatheredOnRankZeroAreTheWholeMesh) {
  const HollowCylinderSectorSpec tube = test_support::tubeSpec(2, 7, 3);
  const SphereOctantSpec ball = test_support::octantSpec(3, 2);
  const Mesh wholeTube = generateHollowCylinderSector(tube), wholeBall = generateSphereOctant(ball);
  const Mesh bodies = twoBodies();
  const std::vector<std::pair<const Mesh*, DistributedMesh>> cases = {
      {&wholeTube, onWorld(generateHollowCylinderSectorPart(tube, rank(), ranks()))},
      {&wholeBall, onWorld(generateSphereOctantPart(ball, rank(), ranks()))},
      {&bodies, distributeMesh(MPI_COMM_WORLD, [&] { return bodies; })}};
  for (const auto& [whole, part] : cases) {
    const Mesh gathered = gatherMeshOnRoot(part);
    if (rank() == 0) expectSameMesh(gathered, *whole);
    else EXPECT_EQ(gathered.numNodes(), 0);
  }
}

// Every rank checks its own part; a bad element is named with the whole mesh's numbers, by the lowest
// rank that holds one, exactly as the check of the whole mesh names it.
TEST(MeshDistribution, APartsCheckNamesTheWholeMeshsNumbers) {
  RectangleSpec spec;
  spec.nx = 9;
  spec.ny = 3;
  Mesh mesh = generateRectangle(spec);
  const GlobalIndex node = 2 * (spec.nx + 1) + 7;  // an interior node near the right end, moved far left
  mesh.coordinates[2 * node] = -5.0;
  std::string whole;
  try {
    mesh.validate("Problem/Mesh");
  } catch (const contessa::InputError& e) {
    whole = e.what();
  }
  ASSERT_NE(whole.find("element"), std::string::npos) << whole;
  const DistributedMesh part =
      onWorld(PartExtractor(mesh, ElementRanges{mesh.numElements(), ranks()}.owners(), ranks()).part(rank()));
  try {
    validatePart(part, "Problem/Mesh");
    ADD_FAILURE() << "no rank found the tangled element";
  } catch (const contessa::InputError& e) {
    EXPECT_EQ(std::string(e.what()), whole);
  }
}
