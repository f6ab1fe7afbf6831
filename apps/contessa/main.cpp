// contessa: finite element solver for frictional contact (see README.md and docs/).
//   contessa DECK.xml [--output-dir DIR] [--set PATH=VALUE ...]
#include <cstdio>
#include <iostream>

#include <Tpetra_Core.hpp>

#include "CommandLine.hpp"
#include "DeckReference.hpp"
#include "ProcessEnvironment.hpp"
#include "Run.hpp"
#include "common/Error.hpp"
#include "common/PhaseTimers.hpp"

int main(int argc, char** argv) {
  contessa::app::prepareProcess(argc, argv);  // before MPI_Init: fast MPI start, BLAS threads, --timers
  Tpetra::ScopeGuard scope(&argc, &argv);
  contessa::timers::switchTo(contessa::timers::Phase::Setup);
  auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  try {
    const auto cl = contessa::app::parseCommandLine(argc, argv);
    if (cl.help) {
      if (root) std::cout << contessa::app::usage();
      return 0;
    }
    if (cl.deckReference) {
      if (root) std::cout << contessa::app::deckReference();
      return 0;
    }
    return contessa::app::run(cl, comm);
  } catch (const contessa::InputError& e) {
    // Every rank validates the same deck, so every rank gets here: no rank is left waiting.
    if (root) std::fprintf(stderr, "contessa: error: %s\n", e.what());
    return 2;
  }
}
