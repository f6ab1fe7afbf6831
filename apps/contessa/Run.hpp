#pragma once
#include <Teuchos_Comm.hpp>

#include "CommandLine.hpp"

namespace contessa::app {

/// Reads and validates the deck, builds the model, runs the continuation and writes the results.
/// Returns the process exit status (see usage()). Throws InputError for bad input.
int run(const CommandLine& commandLine, const Teuchos::RCP<const Teuchos::Comm<int>>& comm);

}  // namespace contessa::app
