// MumpsSymmetricInput: the lower triangle MUMPS' LDLᵀ is given, the coupled rows only with the columns
// of decoupled (prescribed) rows moved to the right-hand side, solves the same system as the general
// matrix; an unsymmetric matrix is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "solvers/MumpsInput.hpp"

namespace contessa::solvers {
namespace {

using Dense = std::vector<std::vector<double>>;

// Gaussian elimination with partial pivoting (the reference solution).
std::vector<double> solveDense(Dense a, std::vector<double> b) {
  const std::size_t n = b.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t p = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
    std::swap(a[c], a[p]);
    std::swap(b[c], b[p]);
    for (std::size_t r = c + 1; r < n; ++r) {
      const double f = a[r][c] / a[c][c];
      for (std::size_t k = c; k < n; ++k) a[r][k] -= f * a[c][k];
      b[r] -= f * b[c];
    }
  }
  std::vector<double> x(n);
  for (std::size_t r = n; r-- > 0;) {
    double s = b[r];
    for (std::size_t k = r + 1; k < n; ++k) s -= a[r][k] * x[k];
    x[r] = s / a[r][r];
  }
  return x;
}

// Every entry of a dense matrix as 1-based triplets (zeros included where `pattern` says so).
struct Triplets {
  std::vector<MUMPS_INT> rows, cols;
  std::vector<double> values;
  MumpsMatrixView view(long generation = 1) {
    return {*std::max_element(rows.begin(), rows.end()),
            static_cast<MUMPS_INT8>(values.size()), rows.data(), cols.data(), values.data(), generation};
  }
};

Triplets triplets(const Dense& a) {
  Triplets t;
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < a.size(); ++j)
      if (a[i][j] != 0.0 || a[j][i] != 0.0) {  // a structurally symmetric pattern, as a FE graph is
        t.rows.push_back(static_cast<MUMPS_INT>(i + 1));
        t.cols.push_back(static_cast<MUMPS_INT>(j + 1));
        t.values.push_back(a[i][j]);
      }
  return t;
}

// The full symmetric matrix MUMPS factorises from the lower triangle it is given.
Dense expandLower(MumpsMatrixView v, std::size_t n) {
  Dense s(n, std::vector<double>(n, 0.0));
  for (MUMPS_INT8 k = 0; k < v.numEntries; ++k) {
    const auto i = static_cast<std::size_t>(v.rows[k] - 1), j = static_cast<std::size_t>(v.columns[k] - 1);
    EXPECT_GE(i, j) << "an entry above the diagonal";
    s[i][j] += v.values[k];
    if (i != j) s[j][i] += v.values[k];
  }
  return s;
}

// A symmetric stiffness-like matrix whose row 2 is prescribed: an identity row, its column kept.
Dense stiffnessWithPrescribedRow() {
  Dense a = {{4, -1, 2, 0, 0.5}, {-1, 5, -2, 1, 0}, {2, -2, 6, -1, 1}, {0, 1, -1, 3, -0.5}, {0.5, 0, 1, -0.5, 2}};
  for (std::size_t j = 0; j < 5; ++j) a[2][j] = j == 2 ? 1.0 : 0.0;
  return a;
}

// The whole solution through MumpsSymmetricInput, with the dense solver in MUMPS' place.
std::vector<double> solveThrough(MumpsSymmetricInput& input, const std::vector<double>& b) {
  std::vector<double> reduced;
  input.reduce(b, reduced);
  const MumpsMatrixView given = input.view();
  EXPECT_EQ(static_cast<std::size_t>(given.order), reduced.size());
  if (!reduced.empty()) reduced = solveDense(expandLower(given, reduced.size()), reduced);
  std::vector<double> x = b;
  input.expand(reduced, x);
  return x;
}

TEST(MumpsSymmetricInput, EliminatedPrescribedColumnsGiveTheGeneralSolution) {
  const Dense a = stiffnessWithPrescribedRow();
  const std::vector<double> b = {1.0, -2.0, 0.3, 0.7, -1.1};  // 0.3: the prescribed increment
  Triplets t = triplets(a);
  MumpsSymmetricInput input;
  ASSERT_TRUE(input.update(t.view()));
  const std::vector<double> expected = solveDense(a, b);
  const std::vector<double> x = solveThrough(input, b);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(x[i], expected[i], 1e-13) << "row " << i;
  EXPECT_DOUBLE_EQ(x[2], 0.3);
  // A prescribed value already met (b_3 = 0, the Newton iterates after the first): the same.
  const std::vector<double> met = {1.0, -2.0, 0.0, 0.7, -1.1};
  const std::vector<double> expectedMet = solveDense(a, met), xMet = solveThrough(input, met);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(xMet[i], expectedMet[i], 1e-13) << "row " << i;
}

TEST(MumpsSymmetricInput, ADecoupledRowIsNotGivenToMumps) {
  // Left in MUMPS' matrix, a prescribed row is a tree of its own in the elimination forest (a third
  // of the 3D tube's unknowns are prescribed), and its couplings, as zeros, fill-in for the ordering.
  Dense a = stiffnessWithPrescribedRow();
  Triplets t = triplets(a);
  MumpsSymmetricInput input;
  ASSERT_TRUE(input.update(t.view()));
  const MumpsMatrixView given = input.view();
  EXPECT_EQ(given.order, 4);  // rows 1, 2, 4, 5 as MUMPS' 1 .. 4
  for (MUMPS_INT8 k = 0; k < given.numEntries; ++k) {
    EXPECT_GE(given.rows[k], given.columns[k]);
    EXPECT_LE(given.rows[k], 4);
  }
  // 4 diagonals and the lower entries of the coupled rows: (2,1) (4,2) (5,1) (5,4).
  EXPECT_EQ(given.numEntries, 8);
  // The same decoupled rows at the next call: the same pattern (MUMPS keeps its analysis); a new
  // decoupled row: a new one.
  const long generation = given.patternGeneration;
  ASSERT_TRUE(input.update(t.view()));
  EXPECT_EQ(input.view().patternGeneration, generation);
  for (std::size_t j = 0; j < 5; ++j) a[4][j] = a[j][4] = j == 4 ? 2.0 : 0.0;
  Triplets prescribed5 = triplets(stiffnessWithPrescribedRow());  // the old pattern, new values
  for (std::size_t k = 0; k < prescribed5.values.size(); ++k) {
    const auto i = static_cast<std::size_t>(prescribed5.rows[k] - 1), j = static_cast<std::size_t>(prescribed5.cols[k] - 1);
    prescribed5.values[k] = a[i][j];
  }
  ASSERT_TRUE(input.update(prescribed5.view()));
  EXPECT_NE(input.view().patternGeneration, generation);
  EXPECT_EQ(input.view().order, 3);
  EXPECT_EQ(input.view().numEntries, 5);  // 3 diagonals, (2,1), (4,2)
  const std::vector<double> b = {1.0, -2.0, 0.3, 0.7, -1.1};
  const std::vector<double> expected = solveDense(a, b), x = solveThrough(input, b);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(x[i], expected[i], 1e-13) << "row " << i;
  // A null space vector over MUMPS' rows comes back over all rows, zero in the decoupled ones.
  EXPECT_EQ(input.expandNullVector({1.0, 2.0, 3.0}), (std::vector<double>{1.0, 2.0, 0.0, 3.0, 0.0}));
}

TEST(MumpsSymmetricInput, EveryRowDecoupledLeavesNothingForMumps) {
  const Dense a = {{2, 0}, {0, 4}};
  Triplets t = triplets(a);
  MumpsSymmetricInput input;
  ASSERT_TRUE(input.update(t.view()));
  EXPECT_EQ(input.view().order, 0);
  EXPECT_EQ(input.view().numEntries, 0);
  EXPECT_EQ(solveThrough(input, {1.0, 2.0}), (std::vector<double>{0.5, 0.5}));
}

TEST(MumpsSymmetricInput, RoundOffPassesAndARealAsymmetryIsRefused) {
  Dense a = stiffnessWithPrescribedRow();
  Triplets t = triplets(a);
  MumpsSymmetricInput input;
  // 1e-14 relative: what round-off leaves in a symmetric tangent.
  a[3][1] *= 1 + 1e-14;
  t = triplets(a);
  EXPECT_TRUE(input.update(t.view()));
  // 1e-6 relative of the row: an unsymmetric tangent (the slip tangent's asymmetry is of order μ).
  a[3][1] = 1.0 + 6e-6;
  t = triplets(a);
  EXPECT_FALSE(input.update(t.view()));
  // The pattern is kept: the symmetric values are taken again once they are symmetric.
  a[3][1] = 1.0;
  t = triplets(a);
  EXPECT_TRUE(input.update(t.view()));
}

// The triplets in column-major order, columns descending: no row's entries together, none in order.
Triplets columnMajorDescending(const Triplets& t) {
  std::vector<std::size_t> order(t.values.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&t](std::size_t p, std::size_t q) {
    return t.cols[p] != t.cols[q] ? t.cols[p] > t.cols[q] : t.rows[p] > t.rows[q];
  });
  Triplets u;
  for (const std::size_t k : order) {
    u.rows.push_back(t.rows[k]);
    u.cols.push_back(t.cols[k]);
    u.values.push_back(t.values[k]);
  }
  return u;
}

TEST(MumpsSymmetricInput, EntriesInAnyOrderFindTheirTransposes) {
  // The pattern pairs each a_ij with its a_ji wherever the two stand in the input (the rows grouped and
  // ordered by column inside MumpsSymmetricInput): the same solution, and an asymmetry still refused.
  Dense a = stiffnessWithPrescribedRow();
  Triplets t = columnMajorDescending(triplets(a));
  MumpsSymmetricInput input;
  ASSERT_TRUE(input.update(t.view()));
  const std::vector<double> b = {1.0, -2.0, 0.3, 0.7, -1.1};
  const std::vector<double> expected = solveDense(a, b), x = solveThrough(input, b);
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(x[i], expected[i], 1e-13) << "row " << i;
  a[4][3] = -0.5 + 1e-3;  // a_43 no longer a_34
  t = columnMajorDescending(triplets(a));
  EXPECT_FALSE(MumpsSymmetricInput().update(t.view()));
}

TEST(MumpsSymmetricInput, AnEmptyRowWithoutDiagonalStaysInTheMatrix) {
  // Row 1 has no value at all: singular, which MUMPS' null-pivot check must still see; it is not
  // "decoupled" (no x_j = b_j / a_jj to take), so nothing is divided by its zero diagonal.
  Dense a = {{2, 0, 1}, {0, 0, 0}, {1, 0, 3}};
  Triplets t = triplets(a);
  t.rows.push_back(2);  // the diagonal entry exists in the pattern, with the value 0
  t.cols.push_back(2);
  t.values.push_back(0.0);
  MumpsSymmetricInput input;
  ASSERT_TRUE(input.update(t.view()));
  std::vector<double> reduced;
  input.reduce({1, 2, 3}, reduced);
  EXPECT_EQ(reduced, (std::vector<double>{1, 2, 3}));
  const Dense s = expandLower(input.view(), 3);
  EXPECT_EQ(s[1][1], 0.0);
  EXPECT_EQ(s[0][2], 1.0);
}

}  // namespace
}  // namespace contessa::solvers
