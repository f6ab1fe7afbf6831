#pragma once
// SIGTERM, SIGUSR1 and SIGINT ask the run to stop cleanly: the handler only records the signal (async-
// signal-safe); the continuation looks at it after each increment (Checkpoint.hpp), all ranks agree, and
// the run writes its restart file and exits with status 4. A second signal of the same kind while the
// first is pending ends the process as the signal would (the user insists).
namespace contessa::app {

/// Installs the handlers (once, before the run).
void installStopSignalHandlers();
/// The signal received (SIGTERM, SIGUSR1, SIGINT), or 0.
int pendingStopSignal();

}  // namespace contessa::app
