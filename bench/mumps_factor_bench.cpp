// mumps_factor_bench: CPU time of one MUMPS factorisation of a given matrix under variants of MUMPS'
// controls, to decide the ICNTL settings of solvers/MumpsSolver.cpp by measurement. Not a test:
//   build/bin/mumps_factor_bench MATRIX [--repeat N] [--ordering AMD|METIS-PORD code]
// MATRIX is a triplet file: a header "order entries symmetric" (symmetric 1: the lower triangle, MUMPS
// SYM = 2), then one "row column value" line per entry, 1-based. Contessa has no option that writes
// it: the figures in bench/README.md come from the 3D tube's first symmetric MUMPS input, written by a
// temporary fprintf loop over MumpsSymmetricInput::view() in MumpsLinearOpWithSolve::initialize.
// For each variant: one analysis (JOB = 1), then N factorisations (JOB = 2); prints the median and the
// smallest process CPU time per factorisation (CLOCK_PROCESS_CPUTIME_ID: user + system of this process,
// which a shared machine's load inflates far less than wall time; the smallest is the least disturbed),
// MUMPS' operation estimate RINFOG(1), the factor entries INFOG(29) and the delayed pivots INFOG(13).
#include <dmumps_c.h>
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <utility>
#include <vector>

namespace {

constexpr int icntl(int k) { return k - 1; }
constexpr int cntl(int k) { return k - 1; }

struct Matrix {
  int order = 0;
  bool symmetric = false;
  std::vector<MUMPS_INT> rows, columns;
  std::vector<double> values;
};

bool read(const char* path, Matrix& m) {
  std::FILE* f = std::fopen(path, "r");
  if (!f) return false;
  long long entries = 0;
  int sym = 0;
  if (std::fscanf(f, "%d %lld %d", &m.order, &entries, &sym) != 3) return false;
  m.symmetric = sym != 0;
  m.rows.resize(entries), m.columns.resize(entries), m.values.resize(entries);
  for (long long k = 0; k < entries; ++k)
    if (std::fscanf(f, "%d %d %lf", &m.rows[k], &m.columns[k], &m.values[k]) != 3) return false;
  std::fclose(f);
  return true;
}

double cpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

/// A variant: its name and the (ICNTL index, value) and (CNTL index, value) it changes from Contessa's
/// settings (MumpsContext in solvers/MumpsSolver.cpp).
struct Variant {
  std::string name;
  std::vector<std::pair<int, int>> icntls;
  std::vector<std::pair<int, double>> cntls;
};

void run(const Matrix& m, const Variant& v, int ordering, int repeat) {
  DMUMPS_STRUC_C id{};
  id.comm_fortran = static_cast<MUMPS_INT>(MPI_Comm_c2f(MPI_COMM_WORLD));
  id.par = 1;
  id.sym = m.symmetric ? 2 : 0;
  id.job = -1;
  dmumps_c(&id);
  id.icntl[icntl(1)] = -1, id.icntl[icntl(2)] = -1, id.icntl[icntl(3)] = -1, id.icntl[icntl(4)] = 0;
  id.icntl[icntl(5)] = 0, id.icntl[icntl(18)] = 0, id.icntl[icntl(20)] = 0, id.icntl[icntl(21)] = 0;
  id.icntl[icntl(7)] = ordering, id.icntl[icntl(14)] = 50, id.icntl[icntl(24)] = 1, id.icntl[icntl(13)] = 1;
  id.cntl[cntl(3)] = 1e-11;
  for (const auto& [k, value] : v.icntls) id.icntl[icntl(k)] = value;
  for (const auto& [k, value] : v.cntls) id.cntl[cntl(k)] = value;
  id.n = m.order;
  id.nnz = static_cast<MUMPS_INT8>(m.values.size());
  id.irn = const_cast<MUMPS_INT*>(m.rows.data());
  id.jcn = const_cast<MUMPS_INT*>(m.columns.data());
  std::vector<double> values = m.values;
  id.a = values.data();
  const double start = cpuSeconds();
  id.job = 1;
  dmumps_c(&id);
  const double analysis = cpuSeconds() - start;
  std::vector<double> times;
  for (int r = 0; r < repeat && id.infog[0] >= 0; ++r) {
    const double t0 = cpuSeconds();
    id.job = 2;
    dmumps_c(&id);
    times.push_back(cpuSeconds() - t0);
  }
  if (id.infog[0] < 0) {
    std::printf("| %s | MUMPS error INFOG(1) = %d |\n", v.name.c_str(), id.infog[0]);
  } else {
    std::sort(times.begin(), times.end());
    std::printf("| %s | %.1f | %.1f | %.1f | %.3g | %d | %d |\n", v.name.c_str(), 1e3 * analysis,
                1e3 * times[times.size() / 2], 1e3 * times.front(), id.rinfog[0], id.infog[28], id.infog[12]);
  }
  id.job = -2;
  dmumps_c(&id);
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  if (argc < 2) {
    std::fprintf(stderr, "usage: mumps_factor_bench MATRIX [--repeat N] [--ordering ICNTL7]\n");
    return 2;
  }
  int repeat = 15, ordering = 0;
  for (int a = 2; a + 1 < argc; a += 2) {
    if (!std::strcmp(argv[a], "--repeat")) repeat = std::atoi(argv[a + 1]);
    if (!std::strcmp(argv[a], "--ordering")) ordering = std::atoi(argv[a + 1]);
  }
  Matrix m;
  if (!read(argv[1], m)) {
    std::fprintf(stderr, "mumps_factor_bench: cannot read %s\n", argv[1]);
    return 2;
  }
  std::printf("%s: order %d, %zu entries, %s; ordering ICNTL(7) = %d; %d factorisations per variant\n\n", argv[1],
              m.order, m.values.size(), m.symmetric ? "symmetric (LDL^T)" : "general (LU)", ordering, repeat);
  const std::vector<Variant> variants = {
      {"Contessa's settings", {}, {}},
      {"no scaling, ICNTL(8) = 0", {{8, 0}}, {}},
      {"no null pivot detection, ICNTL(24) = 0", {{24, 0}}, {}},
      {"block low-rank, ICNTL(35) = 2, eps 1e-10", {{35, 2}}, {{7, 1e-10}}},
      {"pivot threshold CNTL(1) = 0 (none)", {}, {{1, 0.0}}},
      {"root by ScaLAPACK, ICNTL(13) = 0", {{13, 0}}, {}},
      {"tree parallelism off, ICNTL(48) = 0", {{48, 0}}, {}},
  };
  std::printf("| variant | analysis ms | factorisation ms, median | smallest | RINFOG(1) ops | INFOG(29) factor entries | INFOG(13) delayed |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
  for (const auto& v : variants) run(m, v, ordering, repeat);
  MPI_Finalize();
  return 0;
}
