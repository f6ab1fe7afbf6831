#include "StopSignals.hpp"

#include <csignal>
#include <initializer_list>

namespace contessa::app {

namespace {

volatile std::sig_atomic_t pending = 0;

extern "C" void recordStopSignal(int signal) {
  if (pending == signal) {
    // Asked twice: leave as the signal's default action would (status 128 + N for the scheduler).
    // sigaction and raise are async-signal-safe (std::signal is not listed by POSIX).
    struct sigaction fallback {};
    fallback.sa_handler = SIG_DFL;
    sigemptyset(&fallback.sa_mask);
    sigaction(signal, &fallback, nullptr);
    std::raise(signal);
    return;
  }
  pending = signal;
}

}  // namespace

void installStopSignalHandlers() {
  struct sigaction action {};
  action.sa_handler = recordStopSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // system calls in progress (writes, MPI) go on
  for (int signal : {SIGTERM, SIGUSR1, SIGINT}) sigaction(signal, &action, nullptr);
}

int pendingStopSignal() { return static_cast<int>(pending); }

}  // namespace contessa::app
