#pragma once
// Phase timers behind `contessa --timers`: wall time and call counts per phase of a run (start-up,
// element kernels, assembly, MUMPS, output, ...), printed as one table at the end. Off by default
// and free when off: a Scope then costs one test of a global flag, no clock read, no allocation.
//
// The accounting is exclusive: a Scope opened inside another pauses the outer phase, so the phases
// add up to the wall time since the process started (everything not in a named phase is `Other`).
#include <array>
#include <cstdio>
#include <string>

#include <mpi.h>

namespace contessa::timers {

enum class Phase : int {
  Startup,             ///< process start (exec, dynamic loading), MPI_Init, Kokkos
  Setup,               ///< deck, mesh, partition, maps, graph, solver set-up
  ElementResidual,     ///< element kernels in residual-only passes
  ElementJacobian,     ///< element kernels in passes with the tangent
  Assembly,            ///< zeroing, scatter outside the element loop, Dirichlet rows, Export to owned rows
  Contact,             ///< contact search, contact elements and their scatter
  GraphRebuild,        ///< the matrix graph rebuilt when the contact left its reserved couplings
  MumpsInput,          ///< MUMPS' distributed input (pattern, values)
  MumpsAnalysis,       ///< MUMPS JOB=1 (ordering, symbolic)
  MumpsFactorization,  ///< MUMPS JOB=2
  MumpsSolve,          ///< MUMPS JOB=3 with the right-hand side gathered to and scattered from the host
  IterativeSetup,      ///< iterative solver: preconditioner set-up (MueLu hierarchy, Ifpack2 factorisation)
  IterativeSolve,      ///< iterative solver: the Krylov iterations with the preconditioner applied
  Output,              ///< Exodus, history CSV, stresses, gathers to rank 0
  Reactions,           ///< reaction forces for the output
  Other,               ///< NOX/LOCA and everything else
  Count
};
constexpr int kNumPhases = static_cast<int>(Phase::Count);

/// Table label of a phase.
const char* phaseName(Phase phase);

namespace detail {
extern bool gEnabled;
void enter(Phase phase, Phase& parent);
void leave(Phase parent);
}  // namespace detail

inline bool enabled() { return detail::gEnabled; }

/// Switches the timers on; the time since the process started counts as Startup until the next
/// switchTo(). Call first thing in main (before MPI_Init) when `--timers` is given.
void enable();

/// Moves the top-level phase on (Startup → Setup → Other). Free when off.
void switchTo(Phase phase);

/// Times its own lifetime as `phase` (nested scopes pause the enclosing phase).
class Scope {
 public:
  explicit Scope(Phase phase) {
    if (detail::gEnabled) {
      active_ = true;
      detail::enter(phase, parent_);
    }
  }
  ~Scope() {
    if (active_) detail::leave(parent_);
  }
  Scope(const Scope&) = delete;
  Scope& operator=(const Scope&) = delete;

 private:
  bool active_ = false;
  Phase parent_ = Phase::Other;
};

/// Seconds and entry counts per phase on this process, up to now.
struct Totals {
  std::array<double, kNumPhases> seconds{};
  std::array<long, kNumPhases> counts{};
  double total = 0;  ///< wall seconds since the process started
};
Totals localTotals();

/// The table, as printed (`ranks` > 1: the figures are maxima over the ranks).
std::string formatTable(const Totals& totals, int ranks);

/// Collective over `comm`: the maximum of every figure over the ranks, printed by rank 0 to `out`.
/// Does nothing (and communicates nothing) when the timers are off.
void printTable(MPI_Comm comm, std::FILE* out);

}  // namespace contessa::timers
