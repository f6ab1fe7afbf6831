#pragma once
// A nested-dissection fill-reducing ordering of MUMPS' input, computed with the METIS that Contessa
// already links (METIS_NodeND) and given to MUMPS as the user's ordering (ICNTL(7) = 1, PERM_IN).
// Debian's MUMPS is built without METIS and Scotch, so its own choices are AMD, AMF, QAMD and PORD; on
// 3D meshes a nested dissection needs several times fewer operations than AMD (bench/README.md,
// "Fill-reducing orderings").
#include <dmumps_c.h>
#include <mpi.h>

#include <vector>

#include "solvers/MumpsInput.hpp"

namespace contessa::solvers {

/// The pivot order of `local` (this rank's triplets, 1-based; the whole matrix on one rank) as MUMPS'
/// PERM_IN: entry i − 1 is the position (1-based) of variable i. The pattern is gathered on rank 0 of
/// `comm` and made symmetric (A + Aᵀ: a prescribed row of the general input keeps only its diagonal while
/// its column does not); METIS orders that graph with a fixed seed, so the same pattern always gets the
/// same order. Collective over `comm`; the order on rank 0, empty elsewhere. Empty on rank 0 too when the
/// matrix has no off-diagonal entry or METIS fails: MUMPS then orders with AMD.
std::vector<MUMPS_INT> nestedDissectionOrder(const MumpsMatrixView& local, MPI_Comm comm);

}  // namespace contessa::solvers
