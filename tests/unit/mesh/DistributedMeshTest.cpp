// Distributed mesh parts in one process: every rank's part generated alone equals the part extracted
// from the replicated mesh; the parts of all ranks put together give back the replicated mesh; node
// ownership follows mesh::Partition's rule and every holder of a node agrees on its owner.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <functional>
#include <map>

#include "common/Error.hpp"
#include "mesh/DistributedMesh.hpp"
#include "mesh/Generators.hpp"
#include "mesh/Partition.hpp"
#include "MeshTestSupport.hpp"
#include "DistributedMeshChecks.hpp"

using namespace contessa::mesh;
using contessa::mesh::test::expectSameParts;

namespace {

// The parts of all ranks put together are the replicated mesh, and they agree on node ownership under
// `elementOwner`: each node's owner is the lowest owner among its elements (rank 0 for a node of none).
void expectPartsMakeTheMesh(const Mesh& mesh, const std::vector<int>& elementOwner,
                            const std::vector<DistributedMesh>& parts) {
  const int dim = mesh.dimension;
  const GlobalIndex numNodes = mesh.numNodes();
  std::vector<int> expectedOwner(static_cast<std::size_t>(numNodes), static_cast<int>(parts.size()));
  for (const auto& b : mesh.blocks)
    for (std::size_t k = 0; k < b.elements.size(); ++k)
      for (int a = 0; a < nodesPerCell(b.cellType); ++a) {
        int& owner = expectedOwner[b.connectivity[k * nodesPerCell(b.cellType) + a]];
        owner = std::min(owner, elementOwner[b.elements[k]]);
      }
  for (int& owner : expectedOwner)
    if (owner == static_cast<int>(parts.size())) owner = 0;

  std::vector<std::vector<int>> holders(static_cast<std::size_t>(numNodes));
  std::vector<int> elementSeen(static_cast<std::size_t>(mesh.numElements()), 0);
  for (const DistributedMesh& part : parts) {
    const Mesh& local = part.local();
    EXPECT_EQ(part.numGlobalNodes, numNodes);
    EXPECT_EQ(part.numGlobalElements, mesh.numElements());
    for (std::size_t n = 0; n < part.part.globalNodes.size(); ++n) {
      const GlobalIndex g = part.part.globalNodes[n];
      holders[g].push_back(part.rank);
      EXPECT_EQ(part.nodeOwner[n], expectedOwner[g]) << "node " << g << " on rank " << part.rank;
      for (int d = 0; d < dim; ++d) EXPECT_EQ(local.coordinates[n * dim + d], mesh.coordinates[g * dim + d]);
    }
    ASSERT_EQ(local.blocks.size(), mesh.blocks.size());
    for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
      EXPECT_EQ(local.blocks[b].name, mesh.blocks[b].name);
      EXPECT_EQ(part.globalBlockSizes[b], mesh.blocks[b].numElements());
      const int npe = nodesPerCell(mesh.blocks[b].cellType);
      for (std::size_t k = 0; k < local.blocks[b].elements.size(); ++k) {
        const GlobalIndex g = part.part.globalElements[local.blocks[b].elements[k]];
        ++elementSeen[g];
        EXPECT_EQ(elementOwner[g], part.rank);
        const auto where = mesh.locate(g);
        EXPECT_EQ(where.block, static_cast<int>(b));
        for (int a = 0; a < npe; ++a)
          EXPECT_EQ(part.part.globalNodes[local.blocks[b].connectivity[k * npe + a]],
                    mesh.blocks[b].connectivity[where.local * npe + a]);
      }
    }
  }
  for (GlobalIndex e = 0; e < mesh.numElements(); ++e) EXPECT_EQ(elementSeen[e], 1) << "element " << e;
  // Every node is held by the ranks of its elements, each of which lists the others as sharing it.
  for (GlobalIndex g = 0; g < numNodes; ++g) {
    ASSERT_FALSE(holders[g].empty()) << "node " << g << " in no part";
    EXPECT_EQ(*std::min_element(holders[g].begin(), holders[g].end()), expectedOwner[g]);
    for (int r : holders[g]) {
      const DistributedMesh& part = parts[r];
      std::vector<int> others;
      for (int o : holders[g])
        if (o != r) others.push_back(o);
      std::sort(others.begin(), others.end());
      EXPECT_EQ(part.part.sharedWith[part.localNode(g)], others) << "node " << g << " on rank " << r;
    }
  }
  // Node sets: the union of the parts' sets; side sets: each entry once, at its position.
  for (std::size_t s = 0; s < mesh.nodeSets.size(); ++s) {
    std::vector<GlobalIndex> together;
    for (const DistributedMesh& part : parts) {
      EXPECT_EQ(part.globalNodeSetSizes[s], static_cast<GlobalIndex>(mesh.nodeSets[s].nodes.size()));
      for (GlobalIndex n : part.local().nodeSets[s].nodes) together.push_back(part.part.globalNodes[n]);
    }
    std::sort(together.begin(), together.end());
    together.erase(std::unique(together.begin(), together.end()), together.end());
    EXPECT_EQ(together, mesh.nodeSets[s].nodes) << mesh.nodeSets[s].name;
  }
  for (std::size_t s = 0; s < mesh.sideSets.size(); ++s) {
    const SideSet& whole = mesh.sideSets[s];
    std::vector<GlobalIndex> elements(whole.elements.size(), -1);
    std::vector<int> sides(whole.elements.size(), -1);
    for (const DistributedMesh& part : parts) {
      const SideSet& set = part.local().sideSets[s];
      EXPECT_EQ(set.name, whole.name);
      EXPECT_EQ(part.globalSideSetSizes[s], static_cast<GlobalIndex>(whole.elements.size()));
      ASSERT_EQ(part.sideSetPositions[s].size(), set.elements.size());
      for (std::size_t k = 0; k < set.elements.size(); ++k) {
        const GlobalIndex at = part.sideSetPositions[s][k];
        ASSERT_LT(at, static_cast<GlobalIndex>(elements.size()));
        EXPECT_EQ(elements[at], -1) << whole.name << " entry " << at << " twice";
        elements[at] = part.part.globalElements[set.elements[k]];
        sides[at] = set.sides[k];
      }
    }
    EXPECT_EQ(elements, whole.elements) << whole.name;
    EXPECT_EQ(sides, whole.sides) << whole.name;
  }
}

// For 1 to 7 ranks: each rank's generated part equals the part extracted from the replicated mesh
// under the same element owners (`owners(numRanks)`: GridPartition's for the grid generators, ElementRanges'
// for the sphere octant), and all parts together are the replicated mesh.
void expectGeneratedPartsMatch(const Mesh& mesh, const std::function<std::vector<int>(int numRanks)>& ownersFor,
                               const std::function<DistributedMesh(int rank, int numRanks)>& generatePart) {
  for (int numRanks : {1, 2, 3, 5, 7}) {
    SCOPED_TRACE("ranks " + std::to_string(numRanks));
    const std::vector<int> owners = ownersFor(numRanks);
    const PartExtractor extractor(mesh, owners, numRanks);
    std::vector<DistributedMesh> parts;
    for (int rank = 0; rank < numRanks; ++rank) {
      parts.push_back(generatePart(rank, numRanks));
      expectSameParts(parts.back(), extractor.part(rank));
    }
    expectPartsMakeTheMesh(mesh, owners, parts);
  }
}

std::function<std::vector<int>(int)> gridOwners(int n0, int n1, int n2) {
  return [=](int numRanks) { return GridPartition(n0, n1, n2, numRanks).owners(); };
}

}  // namespace

TEST(ElementRanges, ContiguousNonEmptyRangesCoverTheElementsAndOwnerInvertsThem) {
  for (GlobalIndex numElements : {7, 12, 1000}) {
    for (int numRanks : {1, 2, 3, 7}) {
      const ElementRanges ranges{numElements, numRanks};
      EXPECT_EQ(ranges.begin(0), 0);
      EXPECT_EQ(ranges.begin(numRanks), numElements);
      for (int r = 0; r < numRanks; ++r) {
        EXPECT_LT(ranges.begin(r), ranges.begin(r + 1));
        for (GlobalIndex e = ranges.begin(r); e < ranges.begin(r + 1); ++e) EXPECT_EQ(ranges.owner(e), r);
      }
    }
  }
}

// Index boxes with the fewest cut faces; every cell in exactly one box, each box its bounds; without a
// fitting factorisation, id ranges.
TEST(GridPartition, BoxesWithTheFewestCutFacesCoverTheGrid) {
  const auto parts = [](int n0, int n1, int n2, int ranks) {
    const GridPartition partition(n0, n1, n2, ranks);
    return std::vector<int>(partition.parts(), partition.parts() + 3);
  };
  EXPECT_EQ(parts(8, 8, 4, 4), (std::vector<int>{2, 2, 1}));      // cut 64 faces; 4 slabs along z would cut 192
  EXPECT_EQ(parts(40, 40, 20, 2), (std::vector<int>{1, 2, 1}));   // across y (800 faces; x ties), not z (1600)
  EXPECT_EQ(parts(13, 101, 1, 6), (std::vector<int>{1, 6, 1}));   // the thin ring sector: along the arc
  for (const auto& [n, ranks] : std::vector<std::pair<std::array<int, 3>, int>>{
           {{8, 8, 4}, 4}, {{5, 7, 3}, 6}, {{4, 3, 2}, 7}, {{9, 1, 1}, 3}, {{3, 4, 2}, 5}}) {
    const GridPartition partition(n[0], n[1], n[2], ranks);
    EXPECT_EQ(partition.boxes(), !(ranks == 7 || ranks == 5)) << ranks;
    std::vector<int> seen(static_cast<std::size_t>(n[0]) * n[1] * n[2], 0);
    for (int r = 0; r < ranks; ++r) {
      int lo[3], hi[3];
      partition.bounds(r, lo, hi);
      int inside = 0;
      for (int k = lo[2]; k < hi[2]; ++k)
        for (int j = lo[1]; j < hi[1]; ++j)
          for (int i = lo[0]; i < hi[0]; ++i)
            if (partition.owner(i, j, k) == r) {
              ++seen[(static_cast<std::size_t>(k) * n[1] + j) * n[0] + i];
              ++inside;
            }
      EXPECT_GT(inside, 0) << "rank " << r << " of " << ranks << " has no cell";
      if (partition.boxes()) {
        EXPECT_EQ(inside, (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]));
      }
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<long>(seen.size())) << "a cell outside its rank's bounds";
    EXPECT_EQ(partition.owners().size(), seen.size());
  }
}

TEST(DistributedMesh, GeneratedRectanglePartsAreTheReplicatedMeshs) {
  RectangleSpec spec = test_support::rectangleSpec(5, 4, 3, 1, -1);
  spec.biasX = 2.5;
  spec.biasY = 0.7;
  const Mesh mesh = generateRectangle(spec);
  expectGeneratedPartsMatch(mesh, gridOwners(5, 4, 1), [&](int r, int p) { return generateRectanglePart(spec, r, p); });
}

TEST(DistributedMesh, GeneratedAnnulusSectorPartsAreTheReplicatedMeshs) {
  AnnulusSectorSpec spec = test_support::annulusSpec(3, 6);
  spec.radialBias = 0.5;
  const Mesh mesh = generateAnnulusSector(spec);
  expectGeneratedPartsMatch(mesh, gridOwners(3, 6, 1),
                            [&](int r, int p) { return generateAnnulusSectorPart(spec, r, p); });
}

TEST(DistributedMesh, GeneratedBoxPartsAreTheReplicatedMeshs) {
  BoxSpec spec = test_support::boxSpec(3, 4, 2, 1, 1, 2);
  spec.biasZ = 3;
  const Mesh mesh = generateBox(spec);
  expectGeneratedPartsMatch(mesh, gridOwners(3, 4, 2), [&](int r, int p) { return generateBoxPart(spec, r, p); });
}

TEST(DistributedMesh, GeneratedHollowCylinderSectorPartsAreTheReplicatedMeshs) {
  const HollowCylinderSectorSpec spec = test_support::tubeSpec(2, 5, 3);
  const Mesh mesh = generateHollowCylinderSector(spec);
  expectGeneratedPartsMatch(mesh, gridOwners(2, 5, 3),
                            [&](int r, int p) { return generateHollowCylinderSectorPart(spec, r, p); });
}

TEST(DistributedMesh, SphereOctantPartsAreTheReplicatedMeshs) {
  const SphereOctantSpec spec = test_support::octantSpec(2, 2);
  const Mesh mesh = generateSphereOctant(spec);
  expectGeneratedPartsMatch(
      mesh, [&](int numRanks) { return ElementRanges{mesh.numElements(), numRanks}.owners(); },
      [&](int r, int p) { return generateSphereOctantPart(spec, r, p); });
}

TEST(DistributedMesh, ExtractedPartsFollowTheMetisPartitionsNodeOwners) {
  BoxSpec spec = test_support::boxSpec(4, 3, 3);
  const Mesh mesh = generateBox(spec);
  for (int numRanks : {2, 3, 5}) {
    const Partition partition = partitionMesh(mesh, numRanks);
    const PartExtractor extractor(mesh, partition.elementOwner, numRanks);
    std::vector<DistributedMesh> parts;
    for (int rank = 0; rank < numRanks; ++rank) {
      parts.push_back(extractor.part(rank));
      const DistributedMesh& part = parts.back();
      // The model's maps: owned nodes, and the overlap (every node of the rank's elements).
      EXPECT_EQ(part.ownedNodes(), partition.ownedNodes(rank));
      EXPECT_EQ(part.part.globalNodes, partition.overlapNodes(mesh, rank));
      EXPECT_EQ(part.part.globalElements, partition.ownedElements(rank));
      for (GlobalIndex g : part.haloNodes()) EXPECT_NE(partition.nodeOwner[g], rank);
    }
    expectPartsMakeTheMesh(mesh, partition.elementOwner, parts);
  }
}

TEST(DistributedMesh, ANodeOfNoElementIsInRankZerosPartAndOwnedThere) {
  RectangleSpec spec;
  spec.nx = 2;
  Mesh mesh = generateRectangle(spec);
  mesh.coordinates.insert(mesh.coordinates.end(), {5.0, 5.0});  // node 6, in no element
  mesh.nodeSets.push_back({"lonely", {6}});
  const std::vector<int> owners{1, 0};
  const PartExtractor extractor(mesh, owners, 2);
  const DistributedMesh zero = extractor.part(0), one = extractor.part(1);
  EXPECT_EQ(zero.localNode(6), static_cast<GlobalIndex>(zero.part.globalNodes.size()) - 1);
  EXPECT_EQ(zero.nodeOwner.back(), 0);
  EXPECT_EQ(one.localNode(6), -1);
  EXPECT_EQ(zero.local().nodeSet("lonely").nodes.size(), 1u);
  expectPartsMakeTheMesh(mesh, owners, {zero, one});
}

TEST(DistributedMesh, MoreRanksThanElementsIsAnInputErrorNamingBoth) {
  RectangleSpec spec;
  spec.nx = 2;
  try {
    generateRectanglePart(spec, 0, 3);
    FAIL() << "expected an InputError";
  } catch (const contessa::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot split a mesh of 2 elements over 3 ranks"), std::string::npos)
        << e.what();
  }
}

TEST(DistributedMesh, AGeneratorsBadParameterIsTheSameErrorForAPart) {
  BoxSpec spec;
  spec.ny = 0;
  EXPECT_THROW(
      {
        try {
          generateBoxPart(spec, 0, 1);
        } catch (const contessa::InputError& e) {
          EXPECT_NE(std::string(e.what()).find("Elements Y: expected a positive integer"), std::string::npos);
          throw;
        }
      },
      contessa::InputError);
}

TEST(DistributedMesh, APartOfManyRanksHoldsAFractionOfTheMesh) {
  BoxSpec spec;
  spec.nx = spec.ny = spec.nz = 20;
  const Mesh mesh = generateBox(spec);
  const DistributedMesh part = generateBoxPart(spec, 3, 8);
  // A slab of 1/8 of the cells plus one layer of nodes, with the halo bookkeeping (owner and sharing
  // ranks of each node): under a quarter of the whole mesh's containers.
  EXPECT_LT(part.bytes(), meshBytes(mesh) / 4);
  EXPECT_EQ(part.part.globalElements.size(), 1000u);
}
