#include "common/PhaseTimers.hpp"

#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iterator>
#include <sstream>

namespace contessa::timers {

namespace {

using Clock = std::chrono::steady_clock;

struct State {
  Totals totals;
  Phase current = Phase::Startup;
  Clock::time_point last{}, processStart{};
};
State& state() {
  static State s;
  return s;
}

// Seconds since this process was created (exec and dynamic loading happen before main): Linux keeps
// the start time in /proc/self/stat (field 22, clock ticks since boot, i.e. CLOCK_BOOTTIME). Its
// resolution is one tick (10 ms); 0 if it cannot be read.
double secondsSinceProcessStart() {
  std::ifstream in("/proc/self/stat");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto close = text.rfind(')');  // field 2, the command name, may contain spaces
  if (close == std::string::npos) return 0.0;
  std::istringstream fields(text.substr(close + 1));
  std::string field;
  // After ')' come field 3 (state) ... field 22 (starttime): skip 19, read the 20th.
  for (int i = 0; i < 19 && (fields >> field); ++i) {
  }
  unsigned long long ticks = 0;
  if (!(fields >> ticks)) return 0.0;
  timespec now{};
  if (clock_gettime(CLOCK_BOOTTIME, &now) != 0) return 0.0;
  const double started = static_cast<double>(ticks) / static_cast<double>(sysconf(_SC_CLK_TCK));
  return std::max(0.0, static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec) - started);
}

int index(Phase p) { return static_cast<int>(p); }

// Charges the time since the last switch to the current phase.
Clock::time_point charge() {
  auto& s = state();
  const auto now = Clock::now();
  s.totals.seconds[index(s.current)] += std::chrono::duration<double>(now - s.last).count();
  s.last = now;
  return now;
}

}  // namespace

namespace detail {
bool gEnabled = false;

void enter(Phase phase, Phase& parent) {
  charge();
  auto& s = state();
  parent = s.current;
  s.current = phase;
  ++s.totals.counts[index(phase)];
}

void leave(Phase parent) {
  charge();
  state().current = parent;
}
}  // namespace detail

const char* phaseName(Phase phase) {
  switch (phase) {
    case Phase::Startup: return "process start, MPI_Init, Kokkos";
    case Phase::Setup: return "set-up: deck, mesh, partition, graph";
    case Phase::ElementResidual: return "element kernels, residual passes";
    case Phase::ElementJacobian: return "element kernels, Jacobian passes";
    case Phase::Assembly: return "assembly: scatter, Dirichlet, Export";
    case Phase::Contact: return "contact: search, elements, scatter";
    case Phase::GraphRebuild: return "matrix graph rebuilds (contact)";
    case Phase::MumpsInput: return "MUMPS input (pattern, values)";
    case Phase::MumpsAnalysis: return "MUMPS analysis (JOB=1)";
    case Phase::MumpsFactorization: return "MUMPS factorisation (JOB=2)";
    case Phase::MumpsSolve: return "MUMPS solve (JOB=3, rhs to/from host)";
    case Phase::IterativeSetup: return "iterative: preconditioner set-up";
    case Phase::IterativeSolve: return "iterative: Krylov iterations";
    case Phase::Output: return "output: Exodus, CSV, stresses";
    case Phase::Reactions: return "reactions for output";
    case Phase::Other: return "NOX/LOCA and everything else";
    case Phase::Count: break;
  }
  return "?";
}

void enable() {
  auto& s = state();
  const auto now = Clock::now();
  const auto sinceStart = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(secondsSinceProcessStart()));
  s.processStart = now - sinceStart;
  s.last = s.processStart;
  s.current = Phase::Startup;
  s.totals.counts[index(Phase::Startup)] = 1;
  detail::gEnabled = true;
}

void switchTo(Phase phase) {
  if (!detail::gEnabled) return;
  charge();
  state().current = phase;
  ++state().totals.counts[index(phase)];
}

Totals localTotals() {
  Totals t;
  if (!detail::gEnabled) return t;
  const auto now = charge();
  t = state().totals;
  t.total = std::chrono::duration<double>(now - state().processStart).count();
  return t;
}

std::string formatTable(const Totals& totals, int ranks) {
  std::ostringstream os;
  char line[160];
  os << "contessa: phase timers (wall seconds since the process started"
     << (ranks > 1 ? "; each figure the maximum over " + std::to_string(ranks) + " ranks" : std::string()) << ")\n";
  std::snprintf(line, sizeof line, "  %-40s %9s %6s %7s\n", "phase", "s", "%", "count");
  os << line;
  for (int p = 0; p < kNumPhases; ++p) {
    const double pct = totals.total > 0 ? 100.0 * totals.seconds[p] / totals.total : 0.0;
    std::snprintf(line, sizeof line, "  %-40s %9.4f %6.1f %7ld\n", phaseName(static_cast<Phase>(p)), totals.seconds[p],
                  pct, totals.counts[p]);
    os << line;
  }
  std::snprintf(line, sizeof line, "  %-40s %9.4f %6.1f\n", "total", totals.total, 100.0);
  os << line;
  return os.str();
}

void printTable(MPI_Comm comm, std::FILE* out) {
  if (!detail::gEnabled) return;
  const Totals mine = localTotals();
  Totals all;
  MPI_Reduce(mine.seconds.data(), all.seconds.data(), kNumPhases, MPI_DOUBLE, MPI_MAX, 0, comm);
  MPI_Reduce(mine.counts.data(), all.counts.data(), kNumPhases, MPI_LONG, MPI_MAX, 0, comm);
  MPI_Reduce(&mine.total, &all.total, 1, MPI_DOUBLE, MPI_MAX, 0, comm);
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  if (rank == 0) {
    std::fputs(formatTable(all, size).c_str(), out);
    std::fflush(out);
  }
}

}  // namespace contessa::timers
