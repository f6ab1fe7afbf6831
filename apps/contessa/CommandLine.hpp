#pragma once
#include <string>
#include <vector>

namespace contessa::app {

struct CommandLine {
  std::string deck;
  std::string outputDirectory = ".";
  std::vector<std::string> overrides;
  bool help = false, deckReference = false, quiet = false, timers = false;
};

/// Parses argv; throws InputError with a one-line message on a malformed command line.
CommandLine parseCommandLine(int argc, char** argv);
std::string usage();

}  // namespace contessa::app
