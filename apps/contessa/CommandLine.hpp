#pragma once
#include <string>
#include <vector>

namespace contessa::app {

struct CommandLine {
  std::string deck;
  std::string outputDirectory = ".";
  std::vector<std::string> overrides;
  std::vector<std::string> kokkosOptions;  ///< --kokkos-* options, passed on to Kokkos as written
  /// --check-jacobian[=N,M,...]: the increments whose first Newton iterate gets the finite-difference
  /// check of the Jacobian (empty with checkJacobian = every increment).
  bool checkJacobian = false;
  std::vector<int> checkJacobianIncrements;
  std::string restart;  ///< --restart FILE: continue from this restart file ("" = a new run; "auto", main.cpp)
  /// --job-end-margin SECONDS: kept free at the end of a batch job (ProcessEnvironment.hpp, BatchJobEnd).
  double jobEndMargin = 10;
  bool help = false, version = false, kokkosHelp = false, deckReference = false, quiet = false, timers = false;
};

/// Parses argv without starting MPI or Kokkos (so that --help is Contessa's own); throws InputError
/// with a one-line message on a malformed command line.
CommandLine parseCommandLine(int argc, char** argv);
std::string usage();
/// "contessa <version> (<git description>)".
std::string versionLine();

}  // namespace contessa::app
