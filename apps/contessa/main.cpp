// contessa: finite element solver for frictional contact (see README.md and docs/).
//   contessa DECK.xml [--output-dir DIR] [--set PATH=VALUE ...]
#include <iostream>
#include <vector>

#include <Tpetra_Core.hpp>

#include "Checkpoint.hpp"
#include "CommandLine.hpp"
#include "DeckReference.hpp"
#include "Failure.hpp"
#include "ProcessEnvironment.hpp"
#include "Run.hpp"
#include "common/Error.hpp"
#include "common/PhaseTimers.hpp"

int main(int argc, char** argv) {
  using namespace contessa;
  app::prepareProcess(argc, argv);  // before MPI_Init: fast MPI start, BLAS threads, --timers
  // Contessa's options are read before Kokkos starts: Kokkos::initialize prints a page of its own for
  // --help, so it is given only the --kokkos-* options (--kokkos-help shows that page).
  app::CommandLine cl;
  std::string commandLineError;
  try {
    cl = app::parseCommandLine(argc, argv);
  } catch (const InputError& e) {
    commandLineError = e.what();
  }
  std::vector<char*> kokkosArgs{argv[0]};
  for (auto& option : cl.kokkosOptions) kokkosArgs.push_back(option.data());
  int kokkosArgc = static_cast<int>(kokkosArgs.size());
  kokkosArgs.push_back(nullptr);
  char** kokkosArgv = kokkosArgs.data();
  Tpetra::ScopeGuard scope(&kokkosArgc, &kokkosArgv);
  timers::switchTo(timers::Phase::Setup);
  auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;

  app::FailureReporter reporter(comm, "running " + (cl.deck.empty() ? std::string("contessa") : cl.deck) + " on " +
                                          std::to_string(comm->getSize()) + " rank(s)");
  return reporter.run([&]() -> int {
    if (!commandLineError.empty()) throw InputError(commandLineError);
    if (cl.help) {
      if (root) std::cout << app::usage();
      return 0;
    }
    if (cl.version) {
      if (root) std::cout << app::versionLine() << "\n";
      return 0;
    }
    if (cl.kokkosHelp) return 0;  // Kokkos printed its options when it started
    if (cl.deckReference) {
      if (root) std::cout << app::deckReference();
      return 0;
    }
    app::setBatchJobEndMargin(cl.jobEndMargin);
    // --restart auto: this deck's restart file in the output directory, if any (a requeued batch job).
    cl.restart = app::resolveRestart(*comm, cl.restart, cl.deck, cl.outputDirectory, !cl.quiet);
    return app::run(cl, comm);
  });
}
