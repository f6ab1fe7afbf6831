// distributed_mesh_bench: memory per rank of the mesh on the replicated path (every rank builds or
// reads the whole mesh and partitions it, as runs do today) against the distributed paths (each rank
// generates only its part; rank 0 reads the file once and sends the parts out), and the size of the
// replicated contact surfaces gathered from the parts. Run by bench/distributed_mesh_bench.py, or:
//   build/bin/distributed_mesh_bench write N FILE        a box of N^3 Hex8 written as Exodus (1 rank)
//   mpiexec -n P build/bin/distributed_mesh_bench split N BASE   the same box as a set BASE.P.r, one
//                                                               file per rank (each writes its part)
//   mpiexec -n P build/bin/distributed_mesh_bench MODE N|FILE|BASE
// MODE: replicated-box N, generated-box N, replicated-exodus FILE, distributed-exodus FILE,
// decomposed-exodus BASE (each rank reads its own file of the set), replicated-octant N and
// generated-octant N (the sphere octant, N elements along each edge and through the shell).
// Prints one line: mode, ranks, the largest and summed peak resident memory of the ranks (VmHWM) and
// the same above the process's start (MPI and libraries loaded; also rank 0's alone and the largest of
// the other ranks', since rank 0 alone reads a file on the distributed path), the mesh containers held afterwards
// (largest rank), the gathered surfaces, and the time.
#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "io/DecomposedMesh.hpp"
#include "io/ExodusWriter.hpp"
#include "mesh/DecomposedExodusReader.hpp"
#include "mesh/DistributedMesh.hpp"
#include "mesh/ExodusMeshReader.hpp"
#include "mesh/Generators.hpp"
#include "mesh/MemoryEstimate.hpp"
#include "mesh/MeshDistribution.hpp"
#include "mesh/Partition.hpp"

using namespace contessa::mesh;

namespace {

// Peak resident memory of this process so far (VmHWM), bytes.
double peakResident() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::atof(line.c_str() + 6) * 1024.0;
  return 0;
}

BoxSpec cube(int n) {
  BoxSpec spec;
  spec.nx = spec.ny = spec.nz = n;
  return spec;
}

double mib(double bytes) { return bytes / (1024.0 * 1024.0); }

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  if (argc < 3) {
    if (rank == 0) std::fprintf(stderr, "usage: distributed_mesh_bench MODE N|FILE [FILE]\n");
    MPI_Finalize();
    return 2;
  }
  const std::string mode = argv[1], arg = argv[2];
  // The mesh alone is measured: a 10^6-node box would be refused for the memory of a MUMPS run on it.
  skipRunMemoryCheck();
  if (mode == "write") {
    if (rank == 0) contessa::io::ExodusWriter(argv[3], generateBox(cube(std::atoi(arg.c_str()))), {});
    MPI_Finalize();
    return 0;
  }
  if (mode == "split") {
    const DistributedMesh part = generateBoxPart(cube(std::atoi(arg.c_str())), rank, ranks);
    const contessa::io::ExodusDecomposition d = contessa::io::decompositionOf(part);
    contessa::io::ExodusWriter(decomposedFileName(argv[3], ranks, rank), part.local(), {}, {}, {}, &d);
    MPI_Finalize();
    return 0;
  }

  const double start = peakResident();
  const auto t0 = std::chrono::steady_clock::now();
  double held = 0;  // mesh containers this rank keeps for the run
  DistributedMesh part;
  if (mode == "replicated-box" || mode == "replicated-exodus") {
    // Today: the whole mesh and the partition on every rank, for the whole run.
    const Mesh mesh = mode == "replicated-box" ? generateBox(cube(std::atoi(arg.c_str()))) : readExodusMesh(arg);
    const Partition partition = partitionMesh(mesh, ranks);
    held = static_cast<double>(meshBytes(mesh)) +
           static_cast<double>((partition.elementOwner.size() + partition.nodeOwner.size()) * sizeof(int));
    part = PartExtractor(mesh, partition.elementOwner, ranks).part(rank);  // what the rank works on
  } else if (mode == "replicated-octant") {
    SphereOctantSpec spec;
    spec.elementsAlongEdge = spec.elementsThroughShell = std::atoi(arg.c_str());
    const Mesh mesh = generateSphereOctant(spec);
    const Partition partition = partitionMesh(mesh, ranks);
    held = static_cast<double>(meshBytes(mesh)) +
           static_cast<double>((partition.elementOwner.size() + partition.nodeOwner.size()) * sizeof(int));
    part = PartExtractor(mesh, partition.elementOwner, ranks).part(rank);
  } else if (mode == "generated-octant") {
    SphereOctantSpec spec;
    spec.elementsAlongEdge = spec.elementsThroughShell = std::atoi(arg.c_str());
    part = generateSphereOctantPart(spec, rank, ranks);
    held = static_cast<double>(part.bytes());
  } else if (mode == "generated-box") {
    part = generateBoxPart(cube(std::atoi(arg.c_str())), rank, ranks);
    held = static_cast<double>(part.bytes());
  } else if (mode == "distributed-exodus") {
    part = distributeMesh(MPI_COMM_WORLD, [&] { return readExodusMesh(arg); });
    held = static_cast<double>(part.bytes());
  } else if (mode == "decomposed-exodus") {
    part = readDecomposedExodus(arg, MPI_COMM_WORLD);
    held = static_cast<double>(part.bytes());
  } else {
    if (rank == 0) std::fprintf(stderr, "distributed_mesh_bench: unknown mode '%s'\n", mode.c_str());
    MPI_Finalize();
    return 2;
  }
  part.comm = MPI_COMM_WORLD;  // the parts made here for every rank are spread over all of them
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double peak = peakResident();

  // The contact surfaces contact would replicate: one face of the box, and all six.
  double oneFace = 0, allFaces = 0;
  for (const auto& set : part.local().sideSets) {
    const double bytes = static_cast<double>(gatherSurface(part, set.name).bytes());
    allFaces += bytes;
    if (set.name == "top") oneFace = bytes;
  }

  const auto overAll = [](double value) { return overRanks(MPI_COMM_WORLD, value); };
  const RankFigures peaks = overAll(peak), above = overAll(peak - start), kept = overAll(held),
                    partBytes = overAll(static_cast<double>(part.bytes())), time = overAll(seconds),
                    others = overAll(rank == 0 ? 0.0 : peak - start);
  if (rank == 0)
    std::printf(
        "%-18s ranks %d  nodes %lld  peak/rank max %.1f MiB (sum %.1f)  above start max %.1f MiB (sum %.1f, "
        "rank 0 %.1f, others max %.1f)  "
        "held/rank max %.1f MiB  part max %.1f MiB  surface top %.3f MiB, all %.3f MiB  time %.2f s\n",
        mode.c_str(), ranks, static_cast<long long>(part.numGlobalNodes), mib(peaks.max), mib(peaks.sum),
        mib(above.max), mib(above.sum), mib(peak - start), mib(others.max), mib(kept.max), mib(partBytes.max), mib(oneFace), mib(allFaces), time.max);
  MPI_Finalize();
  return 0;
}
