#include "CommandLine.hpp"

#include <cmath>
#include <stdexcept>

#include "common/Error.hpp"
#include "common/Version.hpp"

namespace contessa::app {

std::string usage() {
  return "usage: contessa DECK.xml [--output-dir DIR] [--set PATH=VALUE ...] [--quiet] [--timers]\n"
         "                       [--check-jacobian[=N,M,...]] [--restart FILE|auto] [--job-end-margin SECONDS]\n"
         "       contessa --deck-reference     print the deck reference (Markdown)\n"
         "       contessa --version            print the version and the git description of the build\n"
         "       contessa --help               print this text\n"
         "       contessa --kokkos-help        print Kokkos' options (--kokkos-... options go to Kokkos)\n"
         "\n"
         "Runs the finite element model described by the XML deck DECK.xml and writes\n"
         "DIR/<deck name>.exo (Exodus II) and DIR/<deck name>.history.csv (DIR defaults to '.').\n"
         "--set overrides a deck value: PATH names it with '/' between sublists; an array is\n"
         "written {a, b, ...} (quote the whole argument), e.g.\n"
         "  --set \"Piro/LOCA/Step Size/Initial Step Size=0.05\"\n"
         "  --set \"Problem/Contact/plate/Rigid Surface/Motion={0.0, -75.2}\"\n"
         "--timers prints a table of wall time per phase at the end (maximum over the ranks).\n"
         "--check-jacobian compares, at the first Newton iterate of every increment (or of increments\n"
         "N, M, ... with --check-jacobian=N,M,...; 1 = the first after the initial state), the assembled\n"
         "Jacobian with central differences of the residual and prints one line per increment: the worst\n"
         "relative error |W_ij - FD_ij| / max(|W_ij|, 1e-4 max_k |W_ik|), where (row and column node and\n"
         "component, element or contact slave node) and ||W - W_FD||/||W||. The run goes on unchanged.\n"
         "A debugging option: 2 residual evaluations per unknown (a few seconds per increment for the\n"
         "tube's 2856 unknowns).\n"
         "--restart FILE continues the run of the same deck from its restart file DIR/<deck name>.restart,\n"
         "written every Problem/Output/Checkpoint/Every N Increments, before Max Wall Time runs out, and on\n"
         "SIGTERM, SIGUSR1 or SIGINT, and before the time limit of the Slurm job the run is in; the\n"
         "Exodus file and the history are continued. --restart auto continues from DIR/<deck name>.restart\n"
         "when it exists and starts a new run when it does not (a batch job that may be requeued).\n"
         "--job-end-margin SECONDS: in a Slurm job, the run stops with its restart file when its next\n"
         "increment would not end SECONDS before the job's time limit (default 10; the job's end time is\n"
         "read from Slurm, no signal is needed).\n"
         "Exit status: 0 the run reached its final load (and its regression checks passed);\n"
         "1 the run stopped early or failed; 2 bad input; 3 a regression check of the deck failed;\n"
         "4 the run wrote its restart file and stopped (a signal, Max Wall Time or the job's time limit):\n"
         "continue with --restart.\n"
         "Every error is one line on stderr: contessa: error: ...\n";
}

std::string versionLine() { return std::string("contessa ") + kVersion + " (" + kGitDescription + ")"; }

namespace {
// "1,5,10" → {1, 5, 10}: increment numbers ≥ 1 separated by commas.
std::vector<int> parseIncrementList(const std::string& arg, const std::string& list) {
  const std::string expected = arg + ": expected increment numbers >= 1 separated by commas (e.g. --check-jacobian=1,5,10)";
  std::vector<int> out;
  std::size_t at = 0;
  while (true) {
    const std::size_t comma = list.find(',', at);
    const std::string item = list.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    requireInput(!item.empty() && item.size() <= 9 && item.find_first_not_of("0123456789") == std::string::npos, expected);
    const int n = std::stoi(item);
    requireInput(n >= 1, expected);
    out.push_back(n);
    if (comma == std::string::npos) break;
    at = comma + 1;
  }
  return out;
}
// "--job-end-margin 40" → 40: seconds, a finite number >= 0.
double parseSeconds(const std::string& option, const std::string& text) {
  const std::string expected = option + ": expected seconds >= 0, got '" + text + "'";
  std::size_t used = 0;
  double value = 0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    throw InputError(expected);
  }
  requireInput(used == text.size() && std::isfinite(value) && value >= 0, expected);
  return value;
}

}  // namespace

CommandLine parseCommandLine(int argc, char** argv) {
  CommandLine cl;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&](const std::string& option) {
      requireInput(i + 1 < argc, option + ": expected a value");
      return std::string(argv[++i]);
    };
    if (arg == "--help" || arg == "-h") cl.help = true;
    else if (arg == "--version") cl.version = true;
    else if (arg == "--deck-reference") cl.deckReference = true;
    else if (arg == "--quiet") cl.quiet = true;
    else if (arg == "--timers") cl.timers = true;  // switched on in main, before MPI_Init
    else if (arg == "--check-jacobian") cl.checkJacobian = true;
    else if (arg.rfind("--check-jacobian=", 0) == 0) {
      cl.checkJacobian = true;
      cl.checkJacobianIncrements = parseIncrementList(arg, arg.substr(17));
    } else if (arg == "--output-dir") cl.outputDirectory = value(arg);
    else if (arg.rfind("--output-dir=", 0) == 0) cl.outputDirectory = arg.substr(13);
    else if (arg == "--restart") cl.restart = value(arg);
    else if (arg.rfind("--restart=", 0) == 0) cl.restart = arg.substr(10);
    else if (arg == "--job-end-margin") cl.jobEndMargin = parseSeconds(arg, value(arg));
    else if (arg.rfind("--job-end-margin=", 0) == 0) cl.jobEndMargin = parseSeconds("--job-end-margin", arg.substr(17));
    else if (arg == "--set") cl.overrides.push_back(value(arg));
    else if (arg.rfind("--set=", 0) == 0) cl.overrides.push_back(arg.substr(6));
    else if (arg.rfind("--kokkos-", 0) == 0) {
      cl.kokkosOptions.push_back(arg);
      if (arg == "--kokkos-help") cl.kokkosHelp = true;
    } else if (!arg.empty() && arg[0] == '-') throw InputError(arg + ": unknown option (see contessa --help)");
    else {
      requireInput(cl.deck.empty(), arg + ": only one deck per run (already given: " + cl.deck + ")");
      cl.deck = arg;
    }
  }
  requireInput(cl.help || cl.version || cl.kokkosHelp || cl.deckReference || !cl.deck.empty(),
               "no deck given (usage: contessa DECK.xml; see --help)");
  return cl;
}

}  // namespace contessa::app
