// MumpsUnchangedMatrix (solvers/MumpsInput.hpp): MUMPS' last factors serve a matrix only when it is, on
// every rank, the remembered pattern generation with the remembered values bit for bit; a change on one
// rank alone (a contact pair closing in its rows) refactorises on all.
#include <gtest/gtest.h>

#include <mpi.h>

#include <cmath>
#include <vector>

#include "solvers/MumpsInput.hpp"

namespace contessa::solvers {
namespace {

MumpsMatrixView viewOf(std::vector<double>& values, long generation) {
  MumpsMatrixView view;
  view.numEntries = static_cast<MUMPS_INT8>(values.size());
  view.values = values.data();
  view.patternGeneration = generation;
  return view;
}

TEST(MumpsUnchangedMatrix, MatchesOnlyTheRememberedValuesAndPatternOnEveryRank) {
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  std::vector<double> values = {4.0, -1.0, 2.5e8, 0.0, -0.0};
  MumpsUnchangedMatrix last;
  EXPECT_FALSE(last.matches(viewOf(values, 1), MPI_COMM_WORLD)) << "nothing remembered yet";
  last.remember(viewOf(values, 1));
  EXPECT_TRUE(last.matches(viewOf(values, 1), MPI_COMM_WORLD));
  std::vector<double> copy = values;
  EXPECT_TRUE(last.matches(viewOf(copy, 1), MPI_COMM_WORLD)) << "equal values in other storage";
  EXPECT_FALSE(last.matches(viewOf(values, 2), MPI_COMM_WORLD)) << "a new pattern generation";

  // One value changed in its last bit, on the last rank only: no rank may reuse.
  std::vector<double> changed = values;
  if (rank == size - 1) changed[1] = std::nextafter(changed[1], 0.0);
  EXPECT_FALSE(last.matches(viewOf(changed, 1), MPI_COMM_WORLD));
  // -0.0 and 0.0 differ in their bits: treated as a change (a refactorisation, never a wrong reuse).
  std::vector<double> signedZero = values;
  signedZero[3] = -0.0;
  EXPECT_FALSE(last.matches(viewOf(signedZero, 1), MPI_COMM_WORLD));
  std::vector<double> shorter(values.begin(), values.end() - 1);
  EXPECT_FALSE(last.matches(viewOf(shorter, 1), MPI_COMM_WORLD));

  last.forget();  // a failed factorisation
  EXPECT_FALSE(last.matches(viewOf(values, 1), MPI_COMM_WORLD));
}

}  // namespace
}  // namespace contessa::solvers
